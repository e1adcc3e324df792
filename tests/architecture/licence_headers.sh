#!/bin/sh
# licence_headers.sh: every file of src/ (the GRANPEN package) starts with LAMMPS's standard
# header, as doc/src/Modify_requirements.rst asks of contributed sources: the LAMMPS
# copyright and GPL notice (lines 1-12, the text of LAMMPS's own src/*.cpp and *.h; a .h
# opens with "/* -*- c++ -*- ", a .cpp with "/* ---"), an empty line, and a comment block
# with the contributing author line naming "granpen developers". Line 4 may be either
# LAMMPS's 29Sep2021 form ("Steve Plimpton, ...") or its current one ("LAMMPS development
# team: developers@lammps.org"). Lists each file that does not, and fails.
#   licence_headers.sh [--self-test] [ROOT]
# Exit: 0 every file has it, 1 some lack it (or no file found), 2 usage. Needs sh and awk.
set -u
root=.
self_test=no
while [ $# -gt 0 ]; do
  case "$1" in
    --self-test) self_test=yes; shift ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    -*) echo "licence_headers.sh: unknown option $1" >&2; exit 2 ;;
    *) root=$1; shift ;;
  esac
done

# prints "path: what is wrong" when FILE lacks the header
check_file() {
  awk '
  BEGIN {
    dash = "------------------------------------------------------------------------- */"
    want[2] = "   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator"
    want[3] = "   https://www.lammps.org/, Sandia National Laboratories"
    want[5] = ""
    want[6] = "   Copyright (2003) Sandia Corporation.  Under the terms of Contract"
    want[7] = "   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains"
    want[8] = "   certain rights in this software.  This software is distributed under"
    want[9] = "   the GNU General Public License."
    want[10] = ""
    want[11] = "   See the README file in the top-level LAMMPS directory."
    want[12] = dash
    want[13] = ""
    want[14] = "/* ----------------------------------------------------------------------"
  }
  FNR == 1 {
    first = (FILENAME ~ /\.h$/) ? "/* -*- c++ -*- ----------------------------------------------------------" \
                                : "/* ----------------------------------------------------------------------"
    if ($0 != first) bad = "line 1 is not \"" first "\""
  }
  FNR == 4 && !bad && $0 != "   Steve Plimpton, sjplimp@sandia.gov" &&
      $0 != "   LAMMPS development team: developers@lammps.org" {
    bad = "line 4 is neither LAMMPS header form"
  }
  FNR in want && !bad && $0 != want[FNR] { bad = "line " FNR " differs from LAMMPS header: \"" $0 "\"" }
  # the author block: the lines after 14 up to its closing dashes, one naming granpen developers
  FNR > 14 && author == 0 && !bad {
    if ($0 ~ /^   Contributing authors?: .*granpen developers/) author = 1
    else if ($0 == dash) author = -1
  }
  END {
    if (NR == 0) bad = "empty file"
    if (!bad && author != 1) bad = "no \"Contributing author: granpen developers\" block after the header"
    if (bad) { print FILENAME ": " bad; exit 1 }
  }
  ' "$@"
}

run() {    # DIR: 0 when every *.cpp/*.h there has the header
  dir=$1 n=0 failed=0
  for f in "$dir"/*.cpp "$dir"/*.h; do
    [ -f "$f" ] || continue
    n=$((n + 1))
    out=$(check_file "$f") || { echo "$out"; failed=1; }
  done
  if [ "$n" = 0 ]; then echo "licence_headers.sh: no .cpp or .h in $dir"; return 1; fi
  [ "$failed" = 0 ] && echo "ok: all $n files of $dir carry LAMMPS's header and the author line"
  return $failed
}

if [ "$self_test" = yes ]; then
  t=$(mktemp -d "${TMPDIR:-/tmp}/licence_headers.XXXXXX")
  trap 'rm -rf "$t"' EXIT
  mkdir "$t/good" "$t/bad"
  header() {    # FIRST_LINE LINE4
    printf '%s\n' "$1" \
      '   LAMMPS - Large-scale Atomic/Molecular Massively Parallel Simulator' \
      '   https://www.lammps.org/, Sandia National Laboratories' "$2" '' \
      '   Copyright (2003) Sandia Corporation.  Under the terms of Contract' \
      '   DE-AC04-94AL85000 with Sandia Corporation, the U.S. Government retains' \
      '   certain rights in this software.  This software is distributed under' \
      '   the GNU General Public License.' '' \
      '   See the README file in the top-level LAMMPS directory.' \
      '------------------------------------------------------------------------- */' ''
  }
  author() {
    printf '%s\n' '/* ----------------------------------------------------------------------' \
      "   Contributing author: $1" '------------------------------------------------------------------------- */' ''
  }
  cpp='/* ----------------------------------------------------------------------'
  h='/* -*- c++ -*- ----------------------------------------------------------'
  old='   Steve Plimpton, sjplimp@sandia.gov' new='   LAMMPS development team: developers@lammps.org'
  { header "$cpp" "$old"; author "granpen developers"; echo 'int a;'; } > "$t/good/a.cpp"
  { header "$h" "$new"; author "granpen developers"; echo 'int b();'; } > "$t/good/b.h"
  out=$(run "$t/good") || { echo "SELF-TEST FAILED: good files rejected: $out"; exit 1; }
  # each way a file can lack it must be caught, and named
  echo 'int c;' > "$t/bad/none.cpp"
  { header "$cpp" "$old"; echo 'int d;'; } > "$t/bad/noauthor.cpp"
  { header "$cpp" "$old"; author "someone else"; echo 'int e;'; } > "$t/bad/otherauthor.cpp"
  { header "$cpp" "$old"; author "granpen developers"; } | sed 's/Sandia Corporation\.  Under/Sandia Corp. Under/' > "$t/bad/edited.cpp"
  { header "$cpp" "$old"; author "granpen developers"; } > "$t/bad/wrongfirst.h"
  { header "$h" '   Someone, x@y.z'; author "granpen developers"; } > "$t/bad/line4.h"
  out=$(run "$t/bad") && { echo "SELF-TEST FAILED: bad files accepted"; exit 1; }
  for f in none.cpp noauthor.cpp otherauthor.cpp edited.cpp wrongfirst.h line4.h; do
    case "$out" in *"$t/bad/$f: "*) ;; *) echo "SELF-TEST FAILED: $f not reported: $out"; exit 1 ;; esac
  done
  echo "self-test passed: 6 kinds of missing or altered header reported, 2 good files accepted"
  exit 0
fi

run "$root/src"
