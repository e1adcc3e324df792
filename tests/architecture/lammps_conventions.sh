#!/bin/sh
# lammps_conventions.sh: src/ (the GRANPEN package) follows the naming and header rules of
# LAMMPS's doc/src/Modify_requirements.rst and Modify_style.rst:
#   - a style "some/name" of kind Fix or Compute lives in fix_some_name.h/.cpp (a command
#     "some_name" in some_name.h/.cpp), its class is FixSomeName (SomeName), its name is
#     lower case letters, digits and slashes (a command's: and underscores, as create_atoms);
#   - every header has the include guard LMP_<FILE NAME>_H;
#   - no header has a using statement (namespace, declaration or alias);
#   - no file uses iostreams (<iostream>, <fstream>, <sstream>, ...): I/O is C stdio;
#   - a style's header includes no library header (only C++ standard headers in <>, as
#     <vector>): a library (Voro++) is used through the implementation file (PIMPL);
#   - every error->all/one/warning message of a style's .cpp starts the LAMMPS way: "Fix
#     some/name ...", "Compute some/name ...", "Some_name ..." for a command, or "Illegal
#     <style> command" / "Unknown <style> keyword".
# Lists each breach and fails.
#   lammps_conventions.sh [--self-test] [ROOT]
# Exit: 0 none, 1 some (or no style found), 2 usage. Needs sh, sed and awk.
set -u
root=.
self_test=no
while [ $# -gt 0 ]; do
  case "$1" in
    --self-test) self_test=yes; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    -*) echo "lammps_conventions.sh: unknown option $1" >&2; exit 2 ;;
    *) root=$1; shift ;;
  esac
done

camel() {    # some/name or some_name -> SomeName
  echo "$1" | awk -F'[/_]' '{ s = ""; for (i = 1; i <= NF; i++) s = s toupper(substr($i, 1, 1)) substr($i, 2); print s }'
}

# the error messages of FILE that do not start with one of the PREFIXES (| separated)
bad_messages() {    # FILE PREFIXES
  awk -v prefixes="$2" '
  BEGIN { n = split(prefixes, p, "|") }
  # a call whose message is on the next line: join the two
  pending { line = pending $0; pending = ""; check(line); next }
  /error->(all|one|warning)\(/ {
    if ($0 ~ /error->(all|one|warning)\([^"]*$/ && $0 !~ /\);/) { pending = $0; lineno = FNR; next }
    lineno = FNR; check($0)
  }
  function check(s,   m, i) {
    if (!match(s, /error->(all|one|warning)\([^"]*"/)) return
    m = substr(s, RSTART + RLENGTH)
    for (i = 1; i <= n; i++) if (index(m, p[i]) == 1) return
    printf "%s:%d: error message \"%s\n", FILENAME, lineno, substr(m, 1, 60)
  }
  ' "$1"
}

run() {    # DIR: 0 when src/ there follows the conventions
  dir=$1 fails=0 nstyles=0
  report() { echo "$*"; fails=$((fails + 1)); }
  ios=$(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*<(iostream|fstream|sstream|ostream|istream|iomanip)>' \
    "$dir"/*.cpp "$dir"/*.h 2>/dev/null)
  [ -z "$ios" ] || { echo "$ios" | sed 's|$|  (iostreams: LAMMPS does I/O with C stdio)|'; fails=$((fails + 1)); }
  for h in "$dir"/*.h; do
    [ -f "$h" ] || continue
    base=$(basename "$h" .h)
    guard=LMP_$(echo "$base" | tr 'a-z' 'A-Z')_H
    grep -q "^#ifndef $guard\$" "$h" && grep -q "^#define $guard\$" "$h" ||
      report "$h: include guard is not $guard"
    grep -nE '^[[:space:]]*using[[:space:]]' "$h" | sed "s|^|$h:|; s|\$|  (a using statement in a header)|" |
      while read -r l; do echo "$l"; done | grep . && fails=$((fails + 1))
    styles=$(sed -n -E 's/^(Fix|Compute|Command)Style\(([^,]+),([A-Za-z0-9_]+)\);.*/\1 \2 \3/p' "$h")
    [ -n "$styles" ] || continue
    libs=$(grep -nE '^[[:space:]]*#[[:space:]]*include[[:space:]]*<[^>]*[./+][^>]*>' "$h")
    [ -z "$libs" ] || { echo "$libs" | sed "s|^|$h:|; s|\$|  (a library header in a style's header)|"; fails=$((fails + 1)); }
    echo "$styles" | {
      bad=0
      while read -r kind name class; do
        lkind=$(echo "$kind" | tr 'A-Z' 'a-z')
        if [ "$kind" = Command ]; then
          file=$name want_class=$(camel "$name") re='^[a-z][a-z0-9_]*$'
          prefixes="$(echo "$name" | awk '{ print toupper(substr($0, 1, 1)) substr($0, 2) }') |$(echo "$name" | awk '{ print toupper(substr($0, 1, 1)) substr($0, 2) }'):|Illegal $name command|Unknown $name keyword"
        else
          file=${lkind}_$(echo "$name" | tr '/' '_') want_class=$kind$(camel "$name") re='^[a-z][a-z0-9/]*$'
          prefixes="$kind $name |$kind $name:|Illegal $lkind $name command|Unknown $lkind $name keyword"
        fi
        echo "$name" | grep -qE "$re" || { echo "$h: style name $name is not lower case letters, digits and slashes"; bad=1; }
        [ "$base" = "$file" ] || { echo "$h: $lkind $name belongs in $file.h and $file.cpp"; bad=1; }
        [ "$class" = "$want_class" ] || { echo "$h: $lkind $name's class is $class, not $want_class"; bad=1; }
        cpp=$dir/$base.cpp
        if [ -f "$cpp" ]; then
          msgs=$(bad_messages "$cpp" "$prefixes")
          [ -z "$msgs" ] || { echo "$msgs" | sed "s|\$|  (not \"$(echo "$prefixes" | sed 's/|/", "/g')\")|"; bad=1; }
        else
          echo "$h: no $cpp"; bad=1
        fi
      done
      exit $bad
    } || fails=$((fails + 1))
    nstyles=$((nstyles + $(echo "$styles" | grep -c .)))
  done
  if [ "$nstyles" = 0 ]; then echo "lammps_conventions.sh: no style in $dir"; return 1; fi
  [ "$fails" = 0 ] && echo "ok: $nstyles styles in $dir follow LAMMPS's names, guards and error forms"
  [ "$fails" = 0 ]
}

if [ "$self_test" = yes ]; then
  t=$(mktemp -d "${TMPDIR:-/tmp}/lammps_conventions.XXXXXX")
  trap 'rm -rf "$t"' EXIT
  mkdir "$t/good" "$t/bad"
  style_h() {    # FILE KIND NAME CLASS GUARD [EXTRA]
    printf '#ifdef X\n%sStyle(%s,%s);\n#else\n#ifndef %s\n#define %s\n%s\n#endif\n#endif\n' "$2" "$3" "$4" "$5" "$5" "${6:-}" > "$1"
  }
  style_h "$t/good/fix_a_b.h" Fix a/b FixAB LMP_FIX_A_B_H
  printf 'void f() {\n  error->all(FLERR, "Fix a/b needs x");\n  error->all(FLERR,\n     "Illegal fix a/b command");\n}\n' > "$t/good/fix_a_b.cpp"
  style_h "$t/good/make_thing.h" Command make_thing MakeThing LMP_MAKE_THING_H
  printf 'void g() { error->one(FLERR, "Make_thing: {}", x); error->warning(FLERR, "Unknown make_thing keyword: {}", k); }\n' > "$t/good/make_thing.cpp"
  printf '#ifndef LMP_HELPER_H\n#define LMP_HELPER_H\n#endif\n' > "$t/good/helper.h"
  out=$(run "$t/good") || { echo "SELF-TEST FAILED: good files rejected: $out"; exit 1; }
  style_h "$t/bad/fix_c_d.h" Fix c/d FixCd LMP_FIX_C_D_H
  printf 'void f() {\n  error->all(FLERR,\n    "fix c/d: bad");\n}\n' > "$t/bad/fix_c_d.cpp"
  style_h "$t/bad/fix_wrong.h" Fix e/f FixEF LMP_FIX_WRONG_H
  printf 'void f() { error->all(FLERR, "Fix e/f ok"); }\n' > "$t/bad/fix_wrong.cpp"
  style_h "$t/bad/compute_g.h" Compute G ComputeG LMP_COMPUTE_G_H '#include <voro++.hh>'
  printf '#include <sstream>\nvoid f() { error->all(FLERR, "Compute G ok"); }\n' > "$t/bad/compute_g.cpp"
  printf '#ifndef GRANPEN_HELPER_H\n#define GRANPEN_HELPER_H\nusing namespace std;\n#endif\n' > "$t/bad/helper.h"
  printf '#ifndef LMP_ALIAS_H\n#define LMP_ALIAS_H\n  using real = double;\n#endif\n' > "$t/bad/alias.h"
  out=$(run "$t/bad") && { echo "SELF-TEST FAILED: bad files accepted"; exit 1; }
  for want in "fix_c_d.h: fix c/d's class is FixCd, not FixCD" "fix_c_d.cpp:2: error message \"fix c/d: bad" \
      "fix_wrong.h: fix e/f belongs in fix_e_f.h" "style name G is not lower case" "compute_g.h: compute G belongs" \
      "helper.h: include guard is not LMP_HELPER_H" "helper.h:3:using namespace std;" "alias.h:3:  using real" "compute_g.h:6:#include <voro++.hh>" "compute_g.cpp:1:#include <sstream>"; do
    case "$out" in *"$want"*) ;; *) echo "SELF-TEST FAILED: \"$want\" not reported in: $out"; exit 1 ;; esac
  done
  echo "self-test passed: 10 breaches reported, 2 good styles and a helper accepted"
  exit 0
fi

run "$root/src"
