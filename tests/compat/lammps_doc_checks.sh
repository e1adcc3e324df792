#!/usr/bin/env bash
# LAMMPS's own checks of a contribution that run without building LAMMPS or its manual, on
# the GRANPEN package laid out as in a LAMMPS tree (src/GRANPEN, doc/src):
#   1. tools/coding_standard/*.py of the tree (whitespace, permissions, homepage, and where
#      the tree has them errordocs, fmtlib, versiontags) on src/ and the doc pages;
#   2. doc/utils/check-styles.py and check-packages.py on a scratch copy of the tree's doc/src
#      with the package's index entries added (tests/compat/lammps_doc_entries.py: the lines a
#      pull request adds, the Packages_details section from docs/lammps/) and the tree's src/
#      with src/GRANPEN; without the entries, check-styles must name the styles (it can fail);
#   3. tests/docs/rst_lammps_checks.py: ASCII, reStructuredText without warnings, spelling
#      against LAMMPS's word list.
# Used by the ctest docs_lammps_doc_checks (Debian's 29Sep2021 tree) and by step 5 of
# check_current_lammps.sh (a current tree).
#   lammps_doc_checks.sh LAMMPS_TREE
# Exit: 0 no finding about GRANPEN, 1 findings, 2 usage.
set -uo pipefail
[ $# -eq 1 ] && [ -f "$1/src/version.h" ] && [ -d "$1/doc/src" ] ||
  { echo "usage: $0 LAMMPS_TREE (a tree with src/version.h and doc/src)"; exit 2; }
tree=$(cd "$1" && pwd)
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/lammps-doc-checks.XXXXXX")
trap 'rm -rf "$work"' EXIT
rc=0
styles_re='granpen|rod/drive|rod/drag|bed/surface|flow/azimuthal|momentum/vbin|create_rod|restore_contact_history'

# 1. coding standard
t=$work/standard
mkdir -p "$t/src/GRANPEN" "$t/doc/src"
cp "$ROOT"/src/* "$t/src/GRANPEN/"; cp "$ROOT"/docs/*.rst "$t/doc/src/"
ran=
for s in whitespace permissions homepage errordocs fmtlib versiontags; do
  [ -f "$tree/tools/coding_standard/$s.py" ] || continue
  ran="$ran $s"
  if out=$(python3 "$tree/tools/coding_standard/$s.py" "$t" 2>&1) && [ -z "$out" ]; then
    echo "ok: coding_standard/$s.py: 0 findings"
  else
    echo "coding_standard/$s.py: findings:"; echo "$out" | sed "s|$t/||g"; rc=1
  fi
done
[ -n "$ran" ] || { echo "no tools/coding_standard/*.py in $tree"; rc=1; }

# 2. the doc index checks: a src/ with the package (hard links: cheap) and doc/src with and
#    without the entries
cp -al "$tree/src" "$work/src" 2>/dev/null || cp -r "$tree/src" "$work/src"
rm -rf "$work/src/GRANPEN"; mkdir "$work/src/GRANPEN"; cp "$ROOT"/src/*.cpp "$ROOT"/src/*.h "$work/src/GRANPEN/"
cp -r "$tree/doc/src" "$work/doc-without"; cp "$ROOT"/docs/*.rst "$work/doc-without/"
cp -r "$work/doc-without" "$work/doc"
python3 "$ROOT/tests/compat/lammps_doc_entries.py" "$ROOT" "$work/doc" || rc=1
for chk in check-styles check-packages; do
  out=$(python3 "$tree/doc/utils/$chk.py" -s "$work/src" -d "$work/doc" 2>&1 | sed -e "s|$work/||g")
  if echo "$out" | grep -Eiq "$styles_re"; then
    echo "$chk.py: findings about GRANPEN:"; echo "$out" | grep -Ei "$styles_re"; rc=1
  else
    echo "ok: $chk.py: no finding about GRANPEN ($(echo "$out" | grep -c .) lines of output, none about it)"
  fi
done
without=$(python3 "$tree/doc/utils/check-styles.py" -s "$work/src" -d "$work/doc-without" 2>&1)
if echo "$without" | grep -q "rod/drive"; then
  echo "ok: without the index entries check-styles.py names $(echo "$without" | grep -Eoc "$styles_re") GRANPEN styles (it can fail)"
else
  echo "check-styles.py did not miss fix rod/drive without the index entries: it does not see src/GRANPEN"; rc=1
fi

# 3. the pages themselves
python3 "$ROOT/tests/docs/rst_lammps_checks.py" "$tree" "$ROOT" || rc=1
[ "$rc" = 0 ] && echo "ok: LAMMPS's doc checks find nothing about GRANPEN ($(sed -n 's/^#define LAMMPS_VERSION "\(.*\)"/\1/p' "$tree/src/version.h"))"
exit $rc
