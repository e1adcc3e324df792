#!/usr/bin/env bash
# The package's examples (examples/PACKAGES/granpen) in LAMMPS's layout and by the rules of
# its doc/src/Modify_requirements.rst ("Examples"):
#   layout: inputs named in.NAME, each with reference logs log.DDMonYY.NAME.g++.1 and .g++.4
#     (the same date for both); no other files than inputs, logs and a README;
#   inputs: no log, echo, package, suffix or processors command (processors * * 1, to keep
#     empty volumes out of the decomposition, is allowed), no include of a file outside the
#     folder, no CPU or wall-clock time (cpu, tpcpu, spcpu, cpuremain) in thermo_style;
#   --current LMP: each input run on 1 rank by LMP (in a scratch folder) prints the thermo rows
#     of its .g++.1 log: the reference logs are those of the current code.
#   --write LMP DATE: (re)make the logs with LMP (1 rank, and 4 with mpirun --oversubscribe)
#     after a change that alters them; removes the old ones.
#   lammps_examples.sh [--self-test] [--current LMP | --write LMP DDMonYY] EXAMPLES_DIR
# Exit: 0 all hold, 1 a breach (each printed), 2 usage.
set -uo pipefail
mode=layout lmp= date=
case "${1:-}" in
  --self-test) mode=self; shift ;;
  --current) mode=current; lmp=$2; shift 2 ;;
  --write) mode=write; lmp=$2; date=$3; shift 3 ;;
esac
[ "$mode" = self ] || { [ $# -eq 1 ] && [ -d "$1" ]; } || { sed -n '2,16p' "$0"; exit 2; }
[ "$mode" = self ] || set -- "$(cd "$1" && pwd)"
[ -z "$lmp" ] || lmp=$(cd "$(dirname "$lmp")" && pwd)/$(basename "$lmp")

layout() {    # DIR: prints each breach; status 1 if any
  local dir=$1 bad=0 f name logs d1 d4
  local inputs=("$dir"/in.*)
  [ -e "${inputs[0]}" ] || { echo "$dir: no input named in.*"; return 1; }
  for f in "$dir"/*; do
    case $(basename "$f") in
      in.*|log.*.g++.1|log.*.g++.4|README) ;;
      *) echo "$f: neither an input in.NAME, a log log.DATE.NAME.g++.N nor the README"; bad=1 ;;
    esac
  done
  for f in "${inputs[@]}"; do
    name=${f##*/in.}
    d1=$(cd "$dir" && ls log.*."$name".g++.1 2>/dev/null | sed -E 's/^log\.([0-9]{1,2}[A-Z][a-z]{2}[0-9]{2})\..*/\1/')
    d4=$(cd "$dir" && ls log.*."$name".g++.4 2>/dev/null | sed -E 's/^log\.([0-9]{1,2}[A-Z][a-z]{2}[0-9]{2})\..*/\1/')
    if [ -z "$d1" ] || [ -z "$d4" ] || [ "$d1" != "$d4" ] || [ "$(echo "$d1" | wc -l)" != 1 ]; then
      echo "$f: needs one log.DDMonYY.$name.g++.1 and one .g++.4 of the same date (has: ${d1:-none} / ${d4:-none})"; bad=1
    fi
    # the commands the requirements forbid, and time in thermo output
    awk -v f="$f" '
      { sub(/#.*/, "") }
      $1 ~ /^(log|echo|package|suffix)$/ { print f ":" FNR ": the command " $1 " is not allowed in an example"; bad = 1 }
      $1 == "processors" && !($2 == "*" && $3 == "*" && $4 == "1") {
        print f ":" FNR ": processors other than * * 1 is not allowed in an example"; bad = 1 }
      $1 == "include" && $2 ~ /\// { print f ":" FNR ": include of a file outside the example folder"; bad = 1 }
      $1 == "thermo_style" { inthermo = 1 }
      inthermo {
        for (i = 1; i <= NF; i++) if ($i ~ /^(cpu|tpcpu|spcpu|cpuremain)$/) {
          print f ":" FNR ": thermo output of " $i " (CPU or wall-clock time)"; bad = 1 }
        if ($NF != "&") inthermo = 0
      }
      END { exit bad }' "$f" || bad=1
  done
  return $bad
}

thermo_rows() {    # LOG: the numeric thermo rows (step first), one per line
  awk '/^ *Step /{on = 1; next} /^Loop time/{on = 0} on && $1 ~ /^[0-9]+$/' "$1"
}

current() {    # DIR LMP: rerun each input on 1 rank, compare its thermo rows with the .g++.1 log
  local dir=$1 lmp=$2 bad=0 f name ref work
  work=$(mktemp -d "${TMPDIR:-/tmp}/granpen-examples.XXXXXX")
  for f in "$dir"/in.*; do
    name=${f##*/in.}
    ref=$(ls "$dir"/log.*."$name".g++.1 | head -1)
    (cd "$work" && cp "$f" . && "$lmp" -in "in.$name" -log "log.$name" -screen none) ||
      { echo "$f: the run failed (log: $work/log.$name)"; bad=1; continue; }
    # the same binary on 1 rank repeats the run to the last digit; another compiler or
    # libm may not, and the granular dynamics amplify that: then remake the logs (--write)
    if diff <(thermo_rows "$ref") <(thermo_rows "$work/log.$name") > "$work/$name.diff"; then
      echo "ok: $name: $(thermo_rows "$ref" | wc -l) thermo rows as in $(basename "$ref")"
    else
      echo "$f: thermo rows differ from $(basename "$ref") (the code changed them: remake the logs with --write):"
      head -6 "$work/$name.diff"; bad=1
    fi
  done
  [ "$bad" = 0 ] && rm -rf "$work"
  return $bad
}

write_logs() {    # DIR LMP DATE
  local dir=$1 lmp=$2 date=$3 f name
  [[ $date =~ ^[0-9]{1,2}[A-Z][a-z]{2}[0-9]{2}$ ]] || { echo "DATE must be like 28Nov26"; return 2; }
  for f in "$dir"/in.*; do
    name=${f##*/in.}
    rm -f "$dir"/log.*."$name".g++.[14]
    (cd "$dir" && nice -n 5 "$lmp" -in "in.$name" -log "log.$date.$name.g++.1" -screen none &&
      nice -n 5 mpirun -np 4 --oversubscribe "$lmp" -in "in.$name" -log "log.$date.$name.g++.4" -screen none) ||
      { echo "$f: the run failed"; return 1; }
    echo "wrote log.$date.$name.g++.1 and .g++.4"
  done
}

self_test() {
  local t; t=$(mktemp -d "${TMPDIR:-/tmp}/lammps_examples.XXXXXX")
  trap 'rm -rf "$t"' RETURN
  mkdir "$t/good" "$t/bad"
  printf 'processors * * 1\nthermo_style custom step atoms &\n   ke\nrun 10\n' > "$t/good/in.a"
  touch "$t/good/log.1Jan26.a.g++.1" "$t/good/log.1Jan26.a.g++.4"
  layout "$t/good" > "$t/good.out" || { echo "SELF-TEST FAILED: good example rejected:"; cat "$t/good.out"; return 1; }
  printf 'log my.log\nprocessors 2 2 1\nsuffix omp\nthermo_style custom step &\n  cpuremain\ninclude ../x.lmp\n' > "$t/bad/in.b"
  touch "$t/bad/log.1Jan26.b.g++.1" "$t/bad/log.2Jan26.b.g++.4" "$t/bad/out.csv"
  printf 'run 1\n' > "$t/bad/in.c"
  layout "$t/bad" > "$t/bad.out" && { echo "SELF-TEST FAILED: bad examples accepted"; return 1; }
  for want in "in.b:1: the command log" "in.b:2: processors" "in.b:3: the command suffix" \
      "in.b:5: thermo output of cpuremain" "in.b:6: include" "out.csv: neither" \
      "in.b: needs one" "in.c: needs one"; do
    grep -qF "$want" "$t/bad.out" || { echo "SELF-TEST FAILED: '$want' not reported:"; cat "$t/bad.out"; return 1; }
  done
  echo "self-test passed: 8 breaches reported, a good example accepted"
}

case $mode in
  self) self_test ;;
  layout) layout "$1" && echo "ok: $(ls "$1"/in.* | wc -l) examples in LAMMPS's layout, with logs, nothing forbidden" ;;
  current) layout "$1" && current "$1" "$lmp" ;;
  write) write_logs "$1" "$lmp" "$date" ;;
esac
