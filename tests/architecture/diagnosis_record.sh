#!/bin/sh
# diagnosis_record.sh: the gap diagnosis's stages talk through typed results, not through one
# mutable record (issue 32). The Diagnosis is assembled once, after the last stage
# (analysis/gap/gap_result.h, assemble_diagnosis), and the report is a function of it
# (gap_report.h): no other header of analysis/gap may declare a function that takes a
# Diagnosis by reference (`Diagnosis &`, const or not). Comments do not count.
#   diagnosis_record.sh [--self-test] [ROOT]
# Exit: 0 none, 1 some, 2 usage.
set -u
root=.
self_test=no
allowed="analysis/gap/gap_result.h analysis/gap/gap_report.h"
while [ $# -gt 0 ]; do
  case "$1" in
    --self-test) self_test=yes; shift ;;
    -h|--help) sed -n '2,8p' "$0"; exit 0 ;;
    -*) echo "diagnosis_record.sh: unknown option $1" >&2; exit 2 ;;
    *) root=$1; shift ;;
  esac
done

# the headers of ROOT's analysis/gap but the record's and the report's that take a Diagnosis&:
# "path:line: text"
check() {
  croot=$1
  [ -d "$croot/analysis/gap" ] || { echo "diagnosis_record.sh: no analysis/gap under $croot" >&2; return 2; }
  files=$(cd "$croot" && find analysis/gap -name '*.h' | sort)
  [ -n "$files" ] || { echo "diagnosis_record.sh: no headers in $croot/analysis/gap" >&2; return 2; }
  (cd "$croot" && awk -v allowed="$allowed" '
    BEGIN { n = split(allowed, a, " "); for (i = 1; i <= n; i++) ok[a[i]] = 1 }
    FNR == 1 { incomment = 0 }
    ok[FILENAME] { next }
    {
      line = $0
      # block comments, then line comments: said, not declared
      if (incomment) { if (sub(/.*\*\//, "", line)) incomment = 0; else next }
      while (match(line, /\/\*/)) {
        rest = substr(line, RSTART + 2)
        if (match(rest, /\*\//)) line = substr(line, 1, index(line, "/*") - 1) substr(rest, RSTART + 2)
        else { line = substr(line, 1, index(line, "/*") - 1); incomment = 1 }
      }
      sub(/\/\/.*/, "", line)
      if (line ~ /(^|[^A-Za-z0-9_])Diagnosis[ \t]*&/) { print FILENAME ":" FNR ": " $0; bad++ }
    }
    END {
      if (bad) { printf "%d declaration(s) taking a Diagnosis& outside the record and the report (stages return typed results; assemble_diagnosis makes the record)\n", bad; exit 1 }
      print "ok: no header of analysis/gap but the record and the report takes a Diagnosis&"
    }' $files)
}

if [ "$self_test" = yes ]; then
  # a fixture tree: the record and the report take it (fine); a stage that returns a typed
  # result, a comment and a name that only ends in Diagnosis (fine); then a stage that fills
  # the record, and one that reads it by const reference, each fail alone
  t=$(mktemp -d) || exit 2
  trap 'rm -rf "$t"' EXIT
  mkdir -p "$t/analysis/gap"
  echo "Diagnosis assemble_diagnosis(const WhereResult &w); void record_verdict(const V &v, Diagnosis &d);" \
    > "$t/analysis/gap/gap_result.h"
  echo "void write_gap_output(const Diagnosis &d, const std::string &out);" > "$t/analysis/gap/gap_report.h"
  { echo "WhereResult where_stage(const Features &f);"
    echo "// once: void gap_curves(const Features &f, Diagnosis &d);"
    echo "/* and: void regimes(Diagnosis &d); */"
    echo "void other(const FitDiagnosis &x);"; } > "$t/analysis/gap/gap_where.h"
  out=$(check "$t" 2>&1) || { echo "$out"; echo "SELF-TEST FAILED: the record and the report alone fail"; exit 1; }
  echo "void how_blind(const Features &f, Diagnosis &d);" > "$t/analysis/gap/gap_limits.h"
  out=$(check "$t" 2>&1); rc=$?
  echo "$out"
  case "$out" in *"analysis/gap/gap_limits.h:1: void how_blind(const Features &f, Diagnosis &d);"*) ;;
    *) echo "SELF-TEST FAILED: a stage filling the record not found"; exit 1 ;; esac
  [ $rc -eq 1 ] || { echo "SELF-TEST FAILED: exit $rc with a Diagnosis&, 1 expected"; exit 1; }
  echo "bool confirms(const Diagnosis& d, double chi2a);" > "$t/analysis/gap/gap_limits.h"
  check "$t" > /dev/null 2>&1 && { echo "SELF-TEST FAILED: a const Diagnosis& not found"; exit 1; }
  echo "self-test passed: the check fails when a stage's header takes the Diagnosis"
  exit 0
fi

check "$root"
