#!/usr/bin/env bash
# granpen-cli's contract with its user, every subcommand:
#   --help exits 0 and lists the options (from the one parser);
#   a bad option, or a value against its meaning, exits 2 naming the option;
#   an output that is one of the inputs is refused, the input byte-identical;
#   an output into a missing folder or under a file is a named error, exit 1;
#   an unreadable input creates nothing; no raw C++ exception text reaches the user;
#   bad values of every kind (negative counts, zero widths, empty ranges, empty names)
#   and outputs where nothing can be created are named, with the right exit status.
# usage: cli_contract.sh GRANPEN_CLI WORK_DIR TRACE AVE_TIME DUMP DUMP_TRACE
set -u
CLI=$1 W=$2 TRACE=$3 AVE=$4 DUMP=$5 DTRACE=$6
INPUTS=$(cd "$(dirname "$0")/../../../inputs" && pwd)    # the decks' presets, for granpen sweep
rm -rf "$W" && mkdir -p "$W" || exit 1
fails=0 cases=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# expect STATUS ERR_REGEX CMD...: the exit status and stderr (extended regex)
expect() {
  local want=$1 re=$2; shift 2
  cases=$((cases + 1))
  "$@" > "$W/out" 2> "$W/err"
  local rc=$?
  [ "$rc" = "$want" ] || { fail "exit $rc, expected $want: $*"; cat "$W/err"; return; }
  grep -Eq -- "$re" "$W/err" || { fail "stderr does not match '$re': $*"; cat "$W/err"; }
  # the C++ library's own texts never reach the user
  if grep -Eq 'terminate called|what\(\)|basic_string|std::|stod|stoi|bad_alloc' "$W/err"; then
    fail "raw C++ text in stderr: $*"; cat "$W/err"
  fi
}

# same INPUT COPY: the input is byte-identical to its copy taken before
same() { cmp -s "$1" "$2" || fail "$1 changed"; }

# an instrument file (t, F, x at 100 cm/s) and its mapping, for granpen import
awk 'BEGIN { print "t,F,x"; for (i = 1; i <= 400; i++) { t = i * 1e-4; x = -0.5 + 100 * t
  printf "%.6f,%.10g,%.10g\n", t, (x > 0 ? 5000 * x : 0), x } }' > "$W/lab.csv"
printf 'time = t\nforce = F\nforce_unit = dyne\ndisplacement = x\nposition_unit = cm\nsurface = 0\n' > "$W/lab.map"
IMPORT=(import "$W/lab.csv" --mapping "$W/lab.map" --D 2 --g 981)

# ---- --help from the parser: exit 0, the option list with one of each's options
for sc in "convert --sign" "check --help" "fit --zmin" "calibration --zmin" "collapse --band" \
          "sweep --jobs" "flow --voronoi" "momentum --thresholds" "plot --no-run" "gap --scenario" \
          "import --mapping"; do
  set -- $sc
  cases=$((cases + 1))
  "$CLI" "$1" --help > "$W/out" 2>&1 || fail "$1 --help exits $?"
  grep -q "^Options:" "$W/out" && grep -q -- "$2" "$W/out" || fail "$1 --help does not list $2"
done

# ---- usage errors: exit 2, the option named
for sc in convert check fit calibration collapse sweep flow momentum plot gap import; do
  expect 2 "unknown option '--no-such-option'" "$CLI" "$sc" x --no-such-option 1
done
expect 2 "--sign must be \+1 or -1, got '2'" "$CLI" convert "$AVE" --v0 100 --dt 2e-6 --D 2 --g 981 --out "$W/c.csv" --sign 2
expect 2 "--step0 must be a timestep" "$CLI" convert "$AVE" --v0 100 --dt 2e-6 --D 2 --g 981 --out "$W/c.csv" --step0 -5
expect 2 "--v0 must be > 0, got '0'" "$CLI" convert "$AVE" --v0 0 --dt 2e-6 --D 2 --g 981 --out "$W/c.csv"
expect 2 "--units" "$CLI" convert "$AVE" --v0 100 --dt 2e-6 --D 2 --g 981 --out "$W/c.csv" --units furlong
expect 2 "--out is required" "$CLI" convert "$AVE" --v0 100 --dt 2e-6 --D 2 --g 981
expect 2 "--zmax needs a number, got 'deep'" "$CLI" fit "$TRACE" --zmax deep
expect 2 "--mu must be > 0, got '-1'" "$CLI" fit "$TRACE" --mu -1
expect 2 "--zmin needs a number, got 'nan'" "$CLI" calibration "$W" --zmin nan
expect 2 "--band must be > 0" "$CLI" collapse "$TRACE" --band -1
expect 2 "--jobs" "$CLI" sweep x.sweep --jobs 0
expect 2 "--ranks" "$CLI" gap --scenario tiny --real x --out y --ranks 0
expect 2 "--dr must be > 0" "$CLI" flow "$DUMP" --dr 0
expect 2 "--axis needs 2 values" "$CLI" momentum "$DUMP" --trace "$DTRACE" --axis 1
expect 2 "--tbin must be > 0" "$CLI" plot peak "$TRACE" --out "$W/p" --tbin 0
expect 2 "usage: granpen check" "$CLI" check
expect 2 "usage: granpen import" "$CLI" import
# whole numbers (counts, run numbers) are named with their range, never CLI11's own text
expect 2 "--run must be a whole number from 1 to 1000000000, got '-1'" "$CLI" "${IMPORT[@]}" --out "$W/imp" --run -1
expect 2 "--jobs must be a whole number from 1 to 1000000, got '1.5'" "$CLI" sweep x.sweep --jobs 1.5
expect 2 "--checkpoint must be a whole number from 1 to 1000000, got '-5'" "$CLI" sweep x.sweep --checkpoint -5
expect 2 "--only must be a whole number from 0 to 1000000, got '-2'" "$CLI" sweep x.sweep --only -2
expect 2 "--jobs must be a whole number from 1 to 1024, got '5000'" "$CLI" gap --scenario tiny --real x --out y --jobs 5000
# zero widths, empty ranges, out-of-range values
expect 2 "--edge needs WR > 0 and WZ > 0" "$CLI" flow "$DUMP" --edge 0 0.1
expect 2 "--rod-type must be a positive integer" "$CLI" flow "$DUMP" --rod-type 1e300
expect 2 "--steps '5:1': LAST is before FIRST" "$CLI" flow "$DUMP" --steps 5:1
expect 2 "--thresholds: .*strictly decreasing" "$CLI" momentum "$DUMP" --trace "$DTRACE" --thresholds 0.1 0.2 0.01 0.001
expect 2 "--kz-zmin must be below --kz-zmax" "$CLI" collapse "$TRACE" --kz-zmin 5 --kz-zmax 5
expect 2 "--zmin must be below --zmax" "$CLI" calibration "$W" --zmin 3 --zmax 1
expect 2 "--csv needs a name" "$CLI" collapse "$TRACE" --csv ""
# --ensemble's options (fit, collapse, plot): their ranges, and none without --ensemble
expect 2 "--bootstrap must be a whole number from 20 to 1000000, got '0'" "$CLI" fit "$TRACE" --ensemble --bootstrap 0
expect 2 "--bootstrap must be a whole number from 20 to 1000000, got '19'" "$CLI" collapse "$TRACE" --ensemble --bootstrap 19
expect 2 "--ensemble-bin must be > 0, got '-1'" "$CLI" collapse "$TRACE" --ensemble --ensemble-bin -1
expect 2 "--ensemble-bin must be > 0, got '0'" "$CLI" plot force "$TRACE" --out "$W/p" --ensemble --ensemble-bin 0
expect 2 "--ensemble-bin needs a number, got 'inf'" "$CLI" fit "$TRACE" --ensemble --ensemble-bin inf
expect 2 "--ensemble-csv needs --ensemble" "$CLI" fit "$TRACE" --ensemble-csv "$W/e.csv"
expect 2 "--ensemble-csv needs a name" "$CLI" fit "$TRACE" --ensemble --ensemble-csv ""
expect 2 "--bootstrap needs --ensemble" "$CLI" collapse "$TRACE" --bootstrap 50
expect 2 "--ensemble-bin needs --ensemble" "$CLI" plot peak "$TRACE" --out "$W/p" --ensemble-bin 0.1
expect 2 "give --ensemble or --each, not both" "$CLI" plot force "$TRACE" --out "$W/p" --ensemble --each
expect 2 "--ensemble is for force, ratio, peak and kz" "$CLI" plot flow "$W" --out "$W/p" --ensemble
[ -e "$W/e.csv" ] && fail "fit wrote $W/e.csv on a usage error"
expect 2 "--out needs a name" "$CLI" convert "$AVE" --v0 100 --dt 2e-6 --D 2 --g 981 --out ""
expect 2 "--D must be > 0, got '0'" "$CLI" "${IMPORT[@]}" --out "$W/imp" --D 0
expect 2 "--run" "$CLI" "${IMPORT[@]}" --out "$W/imp" --run 0
expect 2 "--units" "$CLI" "${IMPORT[@]}" --out "$W/imp" --units imperial
expect 2 "--mapping is required" "$CLI" import "$W/lab.csv" --out "$W/imp" --D 2 --g 981
expect 2 "--out is required" "$CLI" import "$W/lab.csv" --mapping "$W/lab.map" --D 2 --g 981
[ -e "$W/imp" ] && fail "import created $W/imp on a usage error"

# ---- an output that is an input: refused, the input untouched
cp "$TRACE" "$W/t.csv" && cp "$TRACE" "$W/t.orig"
expect 1 "--json .*t\.csv is the input" "$CLI" fit "$W/t.csv" --json "$W/t.csv"; same "$W/t.csv" "$W/t.orig"
expect 1 "--csv .*t\.csv is the input" "$CLI" fit "$W/t.csv" --csv "$W/./t.csv"; same "$W/t.csv" "$W/t.orig"
expect 1 "--json .*t\.csv is the input" "$CLI" collapse "$W" --json "$W/t.csv"; same "$W/t.csv" "$W/t.orig"
expect 1 "--csv .*t\.csv is the input" "$CLI" collapse "$W/t.csv" --csv "$W/t.csv"; same "$W/t.csv" "$W/t.orig"
expect 1 "--ensemble-csv .*t\.csv is the input" "$CLI" fit "$W/t.csv" --ensemble --ensemble-csv "$W/t.csv"; same "$W/t.csv" "$W/t.orig"
ln -sf "$W/t.csv" "$W/link.csv"
expect 1 "--json .*link\.csv is the input" "$CLI" fit "$W/t.csv" --json "$W/link.csv"; same "$W/t.csv" "$W/t.orig"
cp "$AVE" "$W/ave.txt" && cp "$AVE" "$W/ave.orig"
expect 1 "--out .*ave\.txt is the input" "$CLI" convert "$W/ave.txt" --v0 100 --dt 2e-6 --D 2 --g 981 --out "$W/ave.txt"
same "$W/ave.txt" "$W/ave.orig"
mkdir -p "$W/sw/beds" "$W/sw/traces" && cp "$TRACE" "$W/sw/traces/calibration.csv"
expect 1 "calibration\.csv is the input" "$CLI" calibration "$W/sw" --out "$W/sw/traces"; same "$W/sw/traces/calibration.csv" "$TRACE"
mkdir -p "$W/fl" && cp "$DUMP" "$W/fl/flow_fields.csv"
expect 1 "flow_fields\.csv is the input" "$CLI" flow "$W/fl/flow_fields.csv" --out "$W/fl"; same "$W/fl/flow_fields.csv" "$DUMP"
mkdir -p "$W/mo" && cp "$DTRACE" "$W/mo/momentum_drag.csv"
expect 1 "momentum_drag\.csv is the input" "$CLI" momentum "$DUMP" --trace "$W/mo/momentum_drag.csv" --out "$W/mo"
same "$W/mo/momentum_drag.csv" "$DTRACE"
mkdir -p "$W/pf" && echo '{}' > "$W/pf/flow.json" && cp "$W/pf/flow.json" "$W/pf.orig"
expect 1 "flow\.json is the input" "$CLI" plot flow "$W/pf" --out "$W/pf"; same "$W/pf/flow.json" "$W/pf.orig"
echo "name = x" > "$W/s.sweep" && cp "$W/s.sweep" "$W/s.orig"
expect 1 "--slurm .*s\.sweep is the input" "$CLI" sweep "$W/s.sweep" --slurm "$W/s.sweep"; same "$W/s.sweep" "$W/s.orig"
expect 2 "--out .* is the input --real" "$CLI" gap --scenario tiny --real "$W/sw" --out "$W/sw/"
# import: a trace DIR/NAME.csv that is the instrument file itself, or the mapping
mkdir -p "$W/im" && cp "$W/lab.csv" "$W/im/lab.csv" && cp "$W/lab.csv" "$W/im.orig"
expect 1 "--out .*lab\.csv is the input" "$CLI" import "$W/im/lab.csv" --mapping "$W/lab.map" --D 2 --g 981 --out "$W/im"
same "$W/im/lab.csv" "$W/im.orig"
cp "$W/lab.map" "$W/im/m.csv" && cp "$W/lab.map" "$W/map.orig"
expect 1 "--out .*m\.csv is the input" "$CLI" import "$W/lab.csv" "$W/im/m.csv" --mapping "$W/im/m.csv" --D 2 --g 981 --out "$W/im"
same "$W/im/m.csv" "$W/map.orig"

# ---- outputs that cannot be written: named, exit 1, nothing left behind
expect 1 "cannot write $W/missing/c\.json: No such file or directory" "$CLI" collapse "$TRACE" --json "$W/missing/c.json"
expect 1 "cannot write $W/missing/c\.csv: No such file or directory" "$CLI" collapse "$TRACE" --csv "$W/missing/c.csv"
expect 1 "cannot write $W/t\.orig/f\.json: Not a directory" "$CLI" fit "$TRACE" --json "$W/t.orig/f.json"
expect 1 "cannot write $W/missing/x\.csv" "$CLI" convert "$AVE" --v0 100 --dt 2e-6 --D 2 --g 981 --out "$W/missing/x.csv"
expect 1 "cannot create $W/t\.orig/o" "$CLI" flow "$DUMP" --trace "$DTRACE" --voronoi none --out "$W/t.orig/o"
expect 1 "cannot create $W/t\.orig/i" "$CLI" "${IMPORT[@]}" --out "$W/t.orig/i"
[ -e "$W/missing" ] && fail "$W/missing was created"
ls -a "$W" | grep -q '\.tmp' && fail "a temporary was left in $W"

# ---- outputs where nothing can be created (a read-only folder; as root, which writes
# through permissions, a folder under /proc): named with the path, exit 1
RO="$W/ro"; mkdir -p "$RO"; chmod 555 "$RO"
[ "$(id -u)" = 0 ] && RO=/proc/granpen_contract_ro
expect 1 "cannot write $RO/f\.json: " "$CLI" fit "$TRACE" --json "$RO/f.json"
expect 1 "cannot write $RO/c\.csv: " "$CLI" collapse "$TRACE" --csv "$RO/c.csv"
expect 1 "cannot write $RO/c\.csv: " "$CLI" convert "$AVE" --v0 100 --dt 2e-6 --D 2 --g 981 --out "$RO/c.csv"
expect 1 "cannot create $RO/i: " "$CLI" "${IMPORT[@]}" --out "$RO/i"
expect 1 "cannot create $RO/f: " "$CLI" flow "$DUMP" --trace "$DTRACE" --voronoi none --out "$RO/f"
expect 1 "cannot create $RO/m: " "$CLI" momentum "$DUMP" --trace "$DTRACE" --out "$RO/m"
expect 1 "cannot create $RO/p: " "$CLI" plot peak "$TRACE" --out "$RO/p" --no-run
printf 'name = ro\npreset = tiny\nseeds = 1\nv0 = 100\n' > "$W/ro.sweep"
expect 1 "cannot write $RO/s\.sh: " "$CLI" sweep "$W/ro.sweep" --inputs "$INPUTS" --slurm "$RO/s.sh"
expect 1 "cannot create folder $RO" "$CLI" sweep "$W/ro.sweep" --inputs "$INPUTS" --lmp /bin/true --out "$RO/runs"
chmod 755 "$W/ro"

# ---- an unreadable input creates nothing
expect 1 "$W/nonexistent: not a readable folder" "$CLI" calibration "$W/nonexistent"
[ -e "$W/nonexistent" ] && fail "calibration created $W/nonexistent"
expect 1 "no figure made" "$CLI" plot peak "$W/no-such.csv" --out "$W/plots"
[ -e "$W/plots" ] && fail "plot created $W/plots"
expect 1 "no-such\.dump" "$CLI" flow "$W/no-such.dump" --out "$W/flows"
[ -e "$W/flows" ] && fail "flow created $W/flows"
expect 1 "no-such\.txt" "$CLI" convert "$W/no-such.txt" --v0 100 --dt 2e-6 --D 2 --g 981 --out "$W/n.csv"
[ -e "$W/n.csv" ] && fail "convert created $W/n.csv"
expect 1 "no-such\.csv" "$CLI" import "$W/no-such.csv" --mapping "$W/lab.map" --D 2 --g 981 --out "$W/imports"
[ -e "$W/imports" ] && fail "import created $W/imports"
expect 1 "no-such\.map" "$CLI" import "$W/lab.csv" --mapping "$W/no-such.map" --D 2 --g 981 --out "$W/imports"
[ -e "$W/imports" ] && fail "import created $W/imports"
expect 1 "no-such\.sweep: cannot open sweep file" "$CLI" sweep "$W/no-such.sweep" --out "$W/runs"
[ -e "$W/runs" ] && fail "sweep created $W/runs"
expect 1 "no-such\.csv: cannot open trace file" "$CLI" momentum "$DUMP" --trace "$W/no-such.csv" --out "$W/moms"
[ -e "$W/moms" ] && fail "momentum created $W/moms"
# and a good import works (the contract's cases are not all refusals)
cases=$((cases + 1))
"$CLI" "${IMPORT[@]}" --out "$W/imported" > "$W/out" 2> "$W/err" || { fail "a good import exits $?"; cat "$W/err"; }
[ -s "$W/imported/lab.csv" ] || fail "import wrote no $W/imported/lab.csv"

# ---- issue 36: the new surfaces (import, --ensemble, gap before it simulates), a case
# class by class; each a named error, its exit status, nothing written
# class 2: a FIFO (or a folder) where a regular file is needed is refused, not blocked on
# (timeout: before, each of these waited for a writer forever)
mkfifo "$W/fifo"
expect 1 "fifo: a FIFO \(a named pipe" timeout 20 "$CLI" import "$W/fifo" --mapping "$W/lab.map" --D 2 --g 981 --out "$W/i2"
expect 1 "fifo: a FIFO" timeout 20 "$CLI" import "$W/lab.csv" --mapping "$W/fifo" --D 2 --g 981 --out "$W/i2"
expect 1 "fifo: a FIFO" timeout 20 "$CLI" check "$W/fifo"
expect 1 "fifo: a FIFO" timeout 20 "$CLI" fit "$W/fifo"    # (fit records a failed trace in its --json, by design)
expect 2 "--scenario .*fifo: a FIFO" timeout 20 "$CLI" gap --scenario "$W/fifo" --prepare-only --v0 100 \
  --inputs "$INPUTS" --cache "$W/gc" --lmp /bin/false
[ -e "$W/i2" ] || [ -e "$W/gc" ] && fail "written after a FIFO input"
# --ensemble-bin: the bins it makes are bounded (before: no bound, gigabytes, "out of memory")
expect 1 "--ensemble-bin 1e-09 cm makes .* bins .* more than 100000" "$CLI" fit "$TRACE" --ensemble --ensemble-bin 1e-9 --json "$W/e2.json"
expect 1 "--ensemble-bin 1e-07 cm makes" "$CLI" collapse "$TRACE" --ensemble --ensemble-bin 1e-7 --json "$W/e2.json"
[ -e "$W/e2.json" ] && fail "written after --ensemble-bin out of bounds"
# class 3: every value that reaches a gap plan checked before anything starts or is written
GAP=(gap --inputs "$INPUTS" --cache "$W/gc" --lmp /bin/false)
expect 2 "--v0: 'abc' is not a number" "$CLI" "${GAP[@]}" --scenario tiny --prepare-only --v0 abc
expect 2 "--v0: -50 cm/s is outside what scenario 'tiny' can run" "$CLI" "${GAP[@]}" --scenario tiny --slurm "$W/g.sh" --v0 -50
expect 2 "--v0: 0 cm/s is outside" "$CLI" "${GAP[@]}" --scenario tiny --slurm "$W/g.sh" --v0 "100 0"
expect 2 "--v0: 'abc' is not a number" "$CLI" "${GAP[@]}" --scenario tiny --slurm "$W/g.sh" --v0 abc
sed 's/^variable lat .*/variable lat index -0.5/' "$INPUTS/presets/tiny.lmp" > "$W/neglat.lmp"
expect 2 "neglat\.lmp: 'lat' must be > 0, got -0\.5" "$CLI" "${GAP[@]}" --scenario "$W/neglat.lmp" --prepare-only --v0 100 --budget 0
sed 's/^variable dt_push .*/variable dt_push index -1e-6/' "$INPUTS/presets/tiny.lmp" > "$W/negdt.lmp"
expect 2 "negdt\.lmp: 'dt_push' must be > 0" "$CLI" "${GAP[@]}" --scenario "$W/negdt.lmp" --slurm "$W/g.sh" --v0 100
[ -e "$W/g.sh" ] || [ -e "$W/gc" ] && fail "gap wrote or started on a bad value"
# class 4: an ensemble mixes no materials; two outputs never share a file
{ printf '# granpen-trace v1\n# units = cgs\n# v0 = 100\n# D = 2\n# g = 981\n# rho_g = 2.5\nt,z,F\n'
  for i in $(seq 0 40); do echo "$((i + 1))e-4,$(awk "BEGIN{print -0.5 + 0.05 * $i}"),$((i * 10))"; done; } > "$W/m1.csv"
sed 's/rho_g = 2.5/rho_g = 1.5/' "$W/m1.csv" > "$W/m2.csv"
sed '/rho_g/d' "$W/m1.csv" > "$W/m3.csv"
expect 1 "--ensemble: .*m1\.csv \(d_g = not given, rho_g = 2\.5, mu = not given\) and .*m2\.csv .* different grains" \
  "$CLI" fit "$W/m1.csv" "$W/m2.csv" --ensemble --json "$W/e3.json"
expect 1 "different grains" "$CLI" collapse "$W/m1.csv" "$W/m3.csv" --ensemble --json "$W/e3.json"
expect 1 "--json .*e3\.json and --csv .*e3\.json are the same file" "$CLI" fit "$TRACE" --json "$W/e3.json" --csv "$W/e3.json"
expect 1 "--json .*e3\.json and --ensemble-csv .*e3\.json are the same file" "$CLI" fit "$TRACE" --ensemble --json "$W/e3.json" --ensemble-csv "$W/./e3.json"
expect 1 "--csv .*e3\.json and --json .*e3\.json are the same file" "$CLI" collapse "$TRACE" --csv "$W/e3.json" --json "$W/e3.json"
[ -e "$W/e3.json" ] && fail "written after a refused ensemble or a shared output"
# NUL bytes in a trace's field: refused by check (strtod stopped at the NUL before)
{ printf '# granpen-trace v1\n# units = cgs\n# v0 = 100\n# D = 2\n# g = 981\nt,z,F\n'
  for i in $(seq 1 12); do printf '%s,%s,1\0003\n' "$i" "$i"; done; } > "$W/nul.csv"
expect 1 "nul\.csv:7: a NUL byte at byte 6 of the line" "$CLI" check "$W/nul.csv"
# class 5: what import writes passes check: a header number out of a trace's range is named
expect 1 "lab\.csv \(its trace's header\):[0-9]+: header v0 is too large" "$CLI" "${IMPORT[@]}" --v0 1e304 --out "$W/i5"
expect 1 "lab\.csv \(its trace's header\):[0-9]+: header D is too large" "$CLI" import "$W/lab.csv" --mapping "$W/lab.map" --D 1e305 --g 981 --v0 100 --out "$W/i5"
cp "$W/lab.csv" "$W/line
break.csv"
expect 1 "line\\\\nbreak\.csv: a line break in the input's name" "$CLI" import "$W/line
break.csv" --mapping "$W/lab.map" --D 2 --g 981 --out "$W/i5"
[ -e "$W/i5" ] && fail "import wrote $W/i5 on a refused header"
# class 7: the messages
printf '\xef\xbb\xbft,F,x\n' > "$W/bom.csv" && tail -n +2 "$W/lab.csv" >> "$W/bom.csv"
cases=$((cases + 1))
"$CLI" import "$W/bom.csv" --mapping "$W/lab.map" --D 2 --g 981 --out "$W/i7" > "$W/out" 2> "$W/err" \
  || { fail "a byte-order mark before the column names: exit $?"; cat "$W/err"; }
mkdir -p "$W/mapdir"
expect 1 "mapdir: a folder, not a regular file" "$CLI" import "$W/lab.csv" --mapping "$W/mapdir" --D 2 --g 981 --out "$W/i8"
awk 'NR == 300 { sub(/,/, ",1,") } { print }' "$W/lab.csv" > "$W/split.csv"    # a row of 4 fields
expect 1 "split\.csv:300: row has 4 fields" "$CLI" import "$W/lab.csv" "$W/split.csv" --mapping "$W/lab.map" --D 2 --g 981 --v0 100 --out "$W/a/b/c"
[ -e "$W/a" ] && fail "a failed import into --out a/b/c left $(cd "$W" && find a | tr '\n' ' ')"
for sc in "check -- $TRACE" "fit -- $TRACE" "collapse -- $TRACE"; do
  cases=$((cases + 1))
  "$CLI" $sc > "$W/out" 2> "$W/err" || { fail "'--' as the end of options: $sc exits $?"; cat "$W/err"; }
done
expect 2 "--effects: 'sidewalls' given twice" "$CLI" "${GAP[@]}" --scenario tiny --prepare-only --v0 100 --effects sidewalls,polydispersity,sidewalls
sed 's/^variable D .*/variable D index 2cm/' "$INPUTS/presets/tiny.lmp" > "$W/twocm.lmp"
expect 2 "'D' is not a number: 2cm" "$CLI" "${GAP[@]}" --scenario "$W/twocm.lmp" --prepare-only --v0 100

# ---- granpen parting: named refusals, an input never overwritten, no contact named
cp "$TRACE" "$W/part_a.csv"
expect 2 "--window: must be a time above 0" "$CLI" parting "$TRACE" "$W/part_a.csv" --window 0
expect 2 "--threshold: must be above 0" "$CLI" parting "$TRACE" "$W/part_a.csv" --threshold -1
expect 2 "--sustain" "$CLI" parting "$TRACE" "$W/part_a.csv" --sustain 0
expect 1 "--json .*part_a\.csv.*refusing to overwrite" "$CLI" parting "$TRACE" "$W/part_a.csv" --json "$W/part_a.csv"
same "$W/part_a.csv" "$TRACE"
awk -F, 'BEGIN { OFS = "," } /^#/ || $1 == "t" { print; next } { $3 = 0; print }' "$TRACE" > "$W/part_none.csv"
expect 1 "part_none\.csv: no contact" "$CLI" parting "$TRACE" "$W/part_none.csv" --json "$W/part.json"
[ -e "$W/part.json" ] && fail "parting wrote $W/part.json for a trace without contact"
expect 1 "part_missing\.csv" "$CLI" parting "$TRACE" "$W/part_missing.csv"

# ---- granpen arrival: named refusals, the rings' files named when missing
expect 2 "--factor: must lie above 1" "$CLI" arrival "$W/part_a.csv" --factor 1
expect 1 "part_a\.csv\.arrival\.info: cannot open" "$CLI" arrival "$W/part_a.csv" --json "$W/arr.json"
[ -e "$W/arr.json" ] && fail "arrival wrote $W/arr.json without its rings"
printf 'step0 = 0\ndt = 2e-6\nradii = 1.5\nwidth = 0.5\nlayer = 1.5\n' > "$W/part_a.csv.arrival.info"
expect 1 "--json .*part_a\.csv\.arrival\.info.*refusing to overwrite" "$CLI" arrival "$W/part_a.csv" --json "$W/part_a.csv.arrival.info"
expect 1 "part_none\.csv: no contact" "$CLI" arrival "$W/part_none.csv"

# ---- a library exception becomes a named error (collapse on a header with v0 = 0)
{ printf '# granpen-trace v1\n# units = cgs\n# v0 = 0\n# D = 2\n# g = 981\nt,z,F\n'
  for i in $(seq 0 20); do echo "$i,$i,$i"; done; } > "$W/v0zero.csv"
expect 1 "^granpen collapse: (error: )?.*v0zero\.csv" "$CLI" collapse "$W/v0zero.csv"

echo "granpen-cli contract: $cases cases, $fails failed"
[ "$fails" = 0 ]
