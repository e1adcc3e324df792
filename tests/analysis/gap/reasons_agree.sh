#!/bin/sh
# granpen gap: every reason report.md prints must agree with its own numbers (issue 37,
# section 4: "Nearest candidate: friction, rejected because its likelihood ratio 119.4 is
# below its threshold 15.1" contradicted itself). Checks, in each report given, every
# sentence of the forms the verdict's record writes (gap_verdict.cpp, shortfall_text and the
# verdict notes):
#   likelihood ratio A is (below|not above) its threshold B   -> A <= B
#   likelihood ratio A is above its threshold B                -> A > B
#   likelihood ratio A against (a|its) threshold (of) B        -> A > B (a detection)
#   explains A of the gap (B needed)                           -> A < B
#   does not predict the speeds left out (A, B needed)         -> A < B
#   NAME has A more evidence                                   -> A > 0
# Numbers are compared as printed (one decimal for ratios, two for fractions): a tie at the
# printed precision passes the <= checks. Prints each contradiction and exits 1 on any;
# exits 2 when no report is given or a file cannot be read.
#   tests/analysis/gap/reasons_agree.sh REPORT.md...
[ $# -gt 0 ] || { echo "reasons_agree: no report given" >&2; exit 2; }
bad=0 checked=0
for f in "$@"; do
  [ -r "$f" ] || { echo "reasons_agree: cannot read $f" >&2; exit 2; }
  out=$(awk -v file="$f" '
    function check(ok, what) { n++; if (!ok) { print file ": " what; bad++ } }
    {
      line = $0
      while (match(line, /likelihood ratio -?[0-9]+(\.[0-9]+)? is (below|not above) its threshold -?[0-9]+(\.[0-9]+)?/)) {
        s = substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH)
        k = split(s, w, " "); check(w[3] + 0 <= w[k] + 0, s)
      }
      line = $0
      while (match(line, /likelihood ratio -?[0-9]+(\.[0-9]+)? is above its threshold -?[0-9]+(\.[0-9]+)?/)) {
        s = substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH)
        k = split(s, w, " "); check(w[3] + 0 > w[k] + 0, s)
      }
      line = $0
      while (match(line, /likelihood ratio -?[0-9]+(\.[0-9]+)? against (a threshold of|its threshold) -?[0-9]+(\.[0-9]+)?/)) {
        s = substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH)
        k = split(s, w, " "); check(w[3] + 0 > w[k] + 0, s)
      }
      line = $0
      while (match(line, /explains -?[0-9]+(\.[0-9]+)? of the gap \([0-9]+(\.[0-9]+)? needed\)/)) {
        s = substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH)
        split(s, w, " "); t = w[6]; sub(/^\(/, "", t); check(w[2] + 0 < t + 0, s)
      }
      line = $0
      while (match(line, /does not predict the speeds left out \(-?[0-9]+(\.[0-9]+)?, [0-9]+(\.[0-9]+)? needed\)/)) {
        s = substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH)
        split(s, w, " "); a = w[8]; sub(/^\(/, "", a); sub(/,$/, "", a); check(a + 0 < w[9] + 0, s)
      }
      line = $0
      while (match(line, /has -?[0-9]+(\.[0-9]+)? more evidence/)) {
        s = substr(line, RSTART, RLENGTH); line = substr(line, RSTART + RLENGTH)
        split(s, w, " "); check(w[2] + 0 > 0, s)
      }
    }
    END { printf "#checked %d\n", n }' "$f") || exit 2
  printf '%s\n' "$out" | grep -v '^#checked' | grep . && bad=1
  checked=$((checked + $(printf '%s\n' "$out" | sed -n 's/^#checked //p')))
done
echo "reasons_agree: $# report(s), $checked reason(s) checked"
[ "$bad" = 0 ]
