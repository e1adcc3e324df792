#!/bin/sh
# verdict_owner.sh: the gap diagnosis's verdict has one owner, analysis/gap/gap_verdict.cpp
# (decide_verdict holds every rule, record_verdict writes it; issue 32). Fails when any other
# C++ file under analysis/ assigns a verdict: a member `verdict` assigned (`.verdict =`,
# `->verdict =`), or a decided verdict (Verdict::explained, tie, unexplained, scale_only, pair) assigned to
# anything. Comparisons (==, !=) and comments do not count; `Verdict::none` as a declaration's
# default is no decision.
#   verdict_owner.sh [--self-test] [ROOT]
# Exit: 0 the owner alone, 1 another file assigns, 2 usage.
set -u
root=.
self_test=no
owner=analysis/gap/gap_verdict.cpp
while [ $# -gt 0 ]; do
  case "$1" in
    --self-test) self_test=yes; shift ;;
    -h|--help) sed -n '2,9p' "$0"; exit 0 ;;
    -*) echo "verdict_owner.sh: unknown option $1" >&2; exit 2 ;;
    *) root=$1; shift ;;
  esac
done

# the assignments of a verdict in ROOT's analysis/ outside the owner: "path:line: text"
check() {
  croot=$1
  [ -f "$croot/$owner" ] || { echo "verdict_owner.sh: no $owner under $croot" >&2; return 2; }
  files=$(cd "$croot" && find analysis -name '*.cpp' -o -name '*.h' | sort)
  (cd "$croot" && awk -v owner="$owner" '
    FILENAME == owner { next }
    {
      line = $0
      sub(/\/\/.*/, "", line)                       # a comment says, it does not assign
      if (line ~ /(\.|->)verdict[ \t]*=([^=]|$)/ ||
          line ~ /(^|[^=!<>])=[ \t]*Verdict::(explained|tie|unexplained|scale_only|pair)/) {
        print FILENAME ":" FNR ": " $0; bad++
      }
    }
    END {
      if (bad) { printf "%d assignment(s) of the verdict outside %s (decide_verdict and record_verdict are its one owner)\n", bad, owner; exit 1 }
      print "ok: only " owner " assigns the verdict"
    }' $files)
}

if [ "$self_test" = yes ]; then
  # a fixture tree: the owner assigns (fine); comparisons and comments elsewhere (fine);
  # then a member assignment, and a decided verdict assigned to a local, each fail alone
  t=$(mktemp -d) || exit 2
  trap 'rm -rf "$t"' EXIT
  mkdir -p "$t/analysis/gap"
  { echo "void record_verdict(Diagnosis &d) { d.verdict = v.verdict; }"; echo "x = Verdict::tie;"; } > "$t/$owner"
  { echo "struct Diagnosis { Verdict verdict = Verdict::none; };"
    echo "bool e = d.verdict == Verdict::explained, n = d.verdict != Verdict::tie;"
    echo "// d.verdict = Verdict::unexplained (said, not done)"; } > "$t/analysis/gap/reader.cpp"
  out=$(check "$t" 2>&1) || { echo "$out"; echo "SELF-TEST FAILED: the owner alone fails"; exit 1; }
  echo "d.verdict = Verdict::unexplained;" > "$t/analysis/gap/confirm.cpp"
  out=$(check "$t" 2>&1); rc=$?
  echo "$out"
  case "$out" in *"analysis/gap/confirm.cpp:1: d.verdict = Verdict::unexplained;"*) ;; *) echo "SELF-TEST FAILED: a member assignment not found"; exit 1 ;; esac
  [ $rc -eq 1 ] || { echo "SELF-TEST FAILED: exit $rc with an assignment, 1 expected"; exit 1; }
  echo "const Verdict v = Verdict::explained;" > "$t/analysis/gap/confirm.cpp"
  check "$t" > /dev/null 2>&1 && { echo "SELF-TEST FAILED: a decided verdict assigned to a local not found"; exit 1; }
  echo "self-test passed: the check fails when a file but the owner assigns the verdict"
  exit 0
fi

check "$root"
