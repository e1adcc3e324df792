#!/usr/bin/env bash
# Speed of the LAMMPS dump reader (analysis/io/dump_reader) against the shell's
# fastest way through the same bytes, in one run: granpen::DumpReader reading every
# frame of a ~500 MB text dump (1e5 grains per frame, LAMMPS's `dump custom` layout
# and default %g formats) against `cat FILE | wc -l`, and the same dump gzipped against
# `zcat FILE.gz | wc -l`. Rounds alternate the four; ratios (reader time / shell time)
# are per round, then the median. MB/s are of the text the files hold.
#   bench/dump_read.sh [BUILD_DIR] [REPEAT] [MEGABYTES]      (./granpen build first)
set -euo pipefail
BUILD=$(realpath "${1:-$(dirname "${BASH_SOURCE[0]}")/../build}")
REPEAT=${2:-3}
MB=${3:-500}
LMP=unused    # common.sh's bench bed is not needed here
. "$(dirname "${BASH_SOURCE[0]}")/common.sh"
cmake --build "$BUILD" --target dump_read_bench >/dev/null
BENCH="$BUILD/tests/analysis/io/dump_read_bench"    # target of tests/analysis/io/CMakeLists.txt
DIR="$WORK/dump"
mkdir -p "$DIR"
TXT="$DIR/big_${MB}MB.dump" GZ="$DIR/big_${MB}MB.dump.gz"
if [ ! -f "$TXT" ]; then
  "$BENCH" make "$TXT.part" 100000 "$MB"
  mv "$TXT.part" "$TXT"
fi
if [ ! -f "$GZ" ]; then
  echo "gzipping the dump (once, level 6 as dump custom/gz writes, about a minute)"
  gzip -6 -c "$TXT" > "$GZ.part"
  mv "$GZ.part" "$GZ"
fi
bytes=$(stat -c %s "$TXT")
echo "dump: $TXT, $bytes bytes ($(stat -c %s "$GZ") gzipped), $(grep -c "ITEM: TIMESTEP" "$TXT") frames of 100000 grains"

now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN{printf "%.4f", b-a}'; }
mbs() { awk -v n="$bytes" -v s="$1" 'BEGIN{printf "%.0f", n/s/1e6}'; }
run_reader() {    # run_reader FILE: seconds, after checking that every frame was read
  local t0 t1 out
  t0=$(now); out=$("$BENCH" read "$1"); t1=$(now)
  case "$out" in "frames $nframes atoms "*) ;; *) echo "reader: unexpected output: $out" >&2; exit 1 ;; esac
  secs "$t0" "$t1"
}
run_shell() {    # run_shell CAT FILE: seconds of CAT FILE | wc -l
  local t0 t1 n
  t0=$(now); n=$("$1" "$2" | wc -l); t1=$(now)
  [ "$n" = "$nlines" ] || { echo "$1 $2 | wc -l: $n lines, expected $nlines" >&2; exit 1; }
  secs "$t0" "$t1"
}
nframes=$(grep -c "ITEM: TIMESTEP" "$TXT")
nlines=$(wc -l < "$TXT")    # also brings the files into the page cache
cat "$GZ" > /dev/null

r_txt=() r_gz=()
for r in $(seq 1 "$REPEAT"); do
  cat_s=$(run_shell cat "$TXT")
  rd_s=$(run_reader "$TXT")
  zcat_s=$(run_shell zcat "$GZ")
  rdz_s=$(run_reader "$GZ")
  r_txt+=("$(ratio "$rd_s" "$cat_s")")
  r_gz+=("$(ratio "$rdz_s" "$zcat_s")")
  echo "round $r/$REPEAT: text: reader $rd_s s ($(mbs "$rd_s") MB/s), cat|wc -l $cat_s s ($(mbs "$cat_s") MB/s), ratio ${r_txt[-1]};" \
    "gzip: reader $rdz_s s ($(mbs "$rdz_s") MB/s), zcat|wc -l $zcat_s s ($(mbs "$zcat_s") MB/s), ratio ${r_gz[-1]}"
done
echo "text dump, reader / cat|wc -l: ratios $(printf '%s\n' "${r_txt[@]}" | sort -g | tr '\n' ' ')median $(median "${r_txt[@]}")"
echo "gzip dump, reader / zcat|wc -l: ratios $(printf '%s\n' "${r_gz[@]}" | sort -g | tr '\n' ' ')median $(median "${r_gz[@]}")"
