#!/usr/bin/env bash
# validation/push_flow.sh on dumps the size of the dg10 flow pushes, in one run: the 20 cm
# box's (535392 grains and the rod, 132 frames, about 4 GB gzipped) against the 10 cm box's
# (133848 grains, the same frames), each command push_flow.sh runs (granpen flow --voronoi
# none, granpen flow --rod-cells over the tip's window, granpen momentum) timed with
# /usr/bin/time -v: wall time, CPU time (user + system: on a shared machine the wall time is
# mostly the share it got) and peak resident memory, and the ratios 20 cm / 10 cm (the
# machine's speed drifts; a ratio within one run does not). Then flow --voronoi none and
# momentum on the first quarter of the 20 cm frames: memory that grows with the number of
# frames (frames held) would show against the whole push.
#   bench/push_flow_size.sh [BUILD_DIR] [WORK_DIR]     (./granpen build first)
# WORK_DIR (default /tmp/granpen-push-flow-size) holds the dumps while it runs (about 6 GB)
# and is deleted at the end. The dumps are synthetic, in inputs/observe/dump.lmp's layout
# (id type x y z vx vy vz radius mass c_stress[1..3], %.9g, one gzip file per frame, sorted
# by id): grains uniform in the bed (0.1 to 9.3 cm, none within 1.05 cm of the rod's axis),
# d_g = 0.2 cm, random velocities and stresses, the same grains in every frame (each frame's
# gzip is the grains' gzip once made, concatenated with the frame's header and its rod: a
# shell of 0.1 cm spheres, D = 2 cm, at 80 cm/s, 0.04 cm deeper each frame, from 0.5 cm above
# the surface to 4.7 cm below it), the trace a committed dg10 push at 80 cm/s.
set -euo pipefail
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
BUILD=$(realpath "${1:-$ROOT/build}")
WORK=${2:-/tmp/granpen-push-flow-size}
FRAMES=${GRANPEN_BENCH_FRAMES:-132}    # fewer for a quick try of the script
QUARTER=$((FRAMES / 4))
TRACE_SRC=$ROOT/data/sims/dg10/dg10_peak/dg10_mu0.3_s1_v80_g981_D2.0.csv
[ -x "$BUILD/analysis/granpen-cli" ] || { echo "push_flow_size.sh: no $BUILD/analysis/granpen-cli (./granpen build)" >&2; exit 2; }
rm -rf "$WORK" && mkdir -p "$WORK"
trap 'rm -rf "$WORK"' EXIT
# a copy of the CLI: a rebuild while this runs does not change what is measured
cp "$BUILD/analysis/granpen-cli" "$WORK/granpen-cli.real"
LOG=${GRANPEN_BENCH_LOG:-$WORK/time.log}    # each call's time -v
# the CLI as push_flow.sh calls it, each call timed (time -v appended to LOG after its name)
cat > "$WORK/granpen-cli" <<EOF
#!/usr/bin/env bash
last=\${@: -1}
echo "== \$1 \${last#$WORK/}" >> "$LOG"
exec /usr/bin/time -v -a -o "$LOG" "$WORK/granpen-cli.real" "\$@"
EOF
chmod +x "$WORK/granpen-cli"
SURFACE=$(awk -F' = ' '$1 == "# surface" { print $2 }' "$TRACE_SRC")

# make_set NAME BOX_CM: WORK/NAME/push.csv and its FRAMES dumps push.csv.STEP.dump.gz
make_set() {
  local name=$1 L=$2 dir=$WORK/$1 n
  mkdir -p "$dir"
  cp "$TRACE_SRC" "$dir/push.csv"
  # the grains, once: ids 1..n, 133848 per 10 x 10 cm (the dg10 bed's density)
  n=$(awk -v L="$L" 'BEGIN { printf "%d", 133848 * (L / 10) * (L / 10) }')
  awk -v n="$n" -v L="$L" 'BEGIN { srand(7); c = L / 2; m = 3 * 4 / 3 * 3.14159265358979 * 0.001; id = 0
    while (id < n) { x = L * rand(); y = L * rand(); if ((x - c)^2 + (y - c)^2 < 1.05^2) continue
      z = 0.1 + 9.2 * rand(); id++
      printf "%d 1 %.9g %.9g %.9g %.9g %.9g %.9g 0.1 %.9g %.9g %.9g %.9g\n", id, x, y, z, rand() - 0.5, rand() - 0.5,
             2 * rand() - 1, m, -1e4 * rand(), -1e4 * rand(), -2e4 * rand() } }' | gzip -6 > "$dir/grains.gz"
  local k step tip nrod
  for ((k = 0; k < FRAMES; k++)); do
    step=$((1000 * k))
    tip=$(awk -v s="$SURFACE" -v k="$k" 'BEGIN { printf "%.9g", s + 0.5 - 0.04 * k }')
    awk -v L="$L" -v tip="$tip" -v id0="$n" 'BEGIN { c = L / 2; pi = 3.14159265358979; id = id0
      for (z = tip + 0.1; z < tip + 10; z += 0.1) for (i = 0; i < 57; i++) { a = 2 * pi * i / 57
        printf "%d 2 %.9g %.9g %.9g 0 0 -80 0.1 1 0 0 0\n", ++id, c + 0.9 * cos(a), c + 0.9 * sin(a), z }
      for (r = 0; r < 0.85; r += 0.2) { m = r > 0 ? int(2 * pi * r / 0.1) : 1
        for (i = 0; i < m; i++) { a = 2 * pi * i / m
          printf "%d 2 %.9g %.9g %.9g 0 0 -80 0.1 1 0 0 0\n", ++id, c + r * cos(a), c + r * sin(a), tip + 0.1 } } }' > "$dir/rod"
    nrod=$(wc -l < "$dir/rod")
    printf 'ITEM: TIMESTEP\n%d\nITEM: NUMBER OF ATOMS\n%d\nITEM: BOX BOUNDS pp pp fm\n0 %s\n0 %s\n0 30\nITEM: ATOMS id type x y z vx vy vz radius mass c_stress[1] c_stress[2] c_stress[3]\n' \
      "$step" $((n + nrod)) "$L" "$L" | gzip -6 > "$dir/head.gz"
    gzip -6 < "$dir/rod" > "$dir/rod.gz"
    cat "$dir/head.gz" "$dir/grains.gz" "$dir/rod.gz" > "$dir/push.csv.$(printf '%08d' "$step").dump.gz"
  done
  rm -f "$dir/rod" "$dir/rod.gz" "$dir/head.gz" "$dir/grains.gz"
  echo "$name: $n grains + $nrod rod atoms, $FRAMES frames, $(du -sm "$dir" | cut -f1) MB"
}

SETS=${GRANPEN_BENCH_SETS:-box10 box20}    # box10 alone for a quick try
for name in $SETS; do make_set "$name" "${name#box}"; done
t0=$(date +%s)
for name in $SETS; do
  GRANPEN_CLI=$WORK/granpen-cli "$ROOT/validation/push_flow.sh" "$WORK/$name/push.csv" "$WORK/$name/out" > /dev/null
done
# the first quarter of the 20 cm frames: memory against the number of frames
q=("$WORK"/box20/push.csv.*.dump.gz)
q=("${q[@]:0:QUARTER}")
[ -d "$WORK/box20" ] && "$WORK/granpen-cli" flow "${q[@]}" --trace "$WORK/box20/push.csv" --voronoi none --out "$WORK/box20/quarter_surface" > /dev/null
[ -d "$WORK/box20" ] && "$WORK/granpen-cli" momentum "${q[@]}" --trace "$WORK/box20/push.csv" --out "$WORK/box20/quarter_momentum" > /dev/null
echo "measured in $(($(date +%s) - t0)) s; load average $(cut -d' ' -f1-3 /proc/loadavg)"
# the table: each call's wall time and peak memory; ratios 20 cm / 10 cm
awk -v frames="$FRAMES" -v quarter="$QUARTER" '/^== / { name = $2 " " $3; next }
     /Elapsed \(wall clock\)/ { n = split($NF, p, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + p[i]; wall[name] = s }
     /User time|System time/ { cpu[name] += $NF }
     /Maximum resident set size/ { mem[name] = $NF / 1024; order[++k] = name }
     END { printf "%-34s %10s %10s %12s\n", "call (set/out)", "wall s", "CPU s", "peak MB"
       for (i = 1; i <= k; i++) if (order[i] !~ /^get /) printf "%-34s %10.1f %10.1f %12.0f\n", order[i], wall[order[i]], cpu[order[i]], mem[order[i]]
       split("surface flow momentum", outs, " ")
       for (i = 1; i <= 3; i++) { a = (outs[i] == "momentum" ? "momentum" : "flow") " box10/out/" outs[i]; b = a; sub("box10", "box20", b)
         if (a in wall && b in wall) printf "20 cm / 10 cm, %-9s wall %.2f, CPU %.2f, memory %.2f\n", outs[i] ":", wall[b] / wall[a], cpu[b] / cpu[a], mem[b] / mem[a] }
       a = "flow box20/out/surface"; b = "flow box20/quarter_surface"
       if (a in mem && b in mem) printf "20 cm, flow --voronoi none: %d frames %.0f MB, %d frames %.0f MB\n", frames, mem[a], quarter, mem[b]
       a = "momentum box20/out/momentum"; b = "momentum box20/quarter_momentum"
       if (a in mem && b in mem) printf "20 cm, momentum: %d frames %.0f MB, %d frames %.0f MB\n", frames, mem[a], quarter, mem[b] }' "$LOG"
