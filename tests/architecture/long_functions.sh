#!/bin/sh
# long_functions.sh: lists the C++ functions longer than a limit (150 lines, from the line
# of the opening brace to that of the closing one) in src/, launcher/ and analysis/, and fails
# when any is not excused. Excused: a LAMMPS style's constructor in src/ (it parses the
# style's arguments: Name::Name(LAMMPS *lmp, int narg, char **arg)), and the functions in
# the allow-list file (one "path function" a line, # comments), which lists those still
# being split elsewhere; an entry that is no longer long is reported as stale. --under DIR
# (repeatable) checks those folders of ROOT only (analysis/gap holds its functions to 100).
#   long_functions.sh [--limit N] [--under DIR]... [--allow FILE] [--self-test] [ROOT]
# Exit: 0 none unexcused, 1 some, 2 usage. Needs only sh and awk.
set -u
limit=150
allow=
under=
root=.
self_test=no
while [ $# -gt 0 ]; do
  case "$1" in
    --limit) limit=$2; shift 2 ;;
    --allow) allow=$2; shift 2 ;;
    --under) under="$under $2"; shift 2 ;;
    --self-test) self_test=yes; shift ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    -*) echo "long_functions.sh: unknown option $1" >&2; exit 2 ;;
    *) root=$1; shift ;;
  esac
done
here=$(cd "$(dirname "$0")" && pwd)

# every function definition of a file: "path name first last signature_line", first and
# last the lines of its braces
scan() {
  awk '
  function reset() { pending = ""; pstart = 0 }
  function kind(p,   q) {
    if (p ~ /(^|[^A-Za-z0-9_])namespace([^A-Za-z0-9_]|$)/ || p ~ /extern[ \t]*""/) return "ns"
    if (p ~ /(^|[^A-Za-z0-9_])(class|struct|union|enum)([^A-Za-z0-9_]|$)/ && p !~ /\)/) return "class"
    q = p; sub(/\(.*/, "", q)
    if (p !~ /operator/ && q ~ /=/) return "init"
    # a member initialised with braces in the initialiser list of a constructor: x{0.0}
    if (p ~ /\)[ \t]*:/ && p ~ /[,:][ \t]*[A-Za-z_][A-Za-z0-9_]*[ \t]*$/) return "meminit"
    if (p ~ /\(/) return "func"
    return "other"
  }
  function fname(p) {
    sub(/\(.*/, "", p); sub(/[ \t]+$/, "", p)
    if (match(p, /[A-Za-z_~][A-Za-z0-9_:~]*$/)) return substr(p, RSTART)
    return "?"
  }
  FNR == 1 { depth = 0; infunc = 0; incomment = 0; reset() }
  {
    line = $0
    if (!incomment && line ~ /^[ \t]*#/) next
    # strip comments, string and character literals (their braces do not count)
    code = ""; i = 1; n = length(line)
    while (i <= n) {
      c = substr(line, i, 1); c2 = substr(line, i, 2)
      if (incomment) { if (c2 == "*/") { incomment = 0; i += 2 } else i++; continue }
      if (c2 == "/*") { incomment = 1; i += 2; continue }
      if (c2 == "//") break
      if (c == "\"" || c == "\047") {
        q = c; i++
        while (i <= n && substr(line, i, 1) != q) { if (substr(line, i, 1) == "\\") i++; i++ }
        i++; code = code q q; continue
      }
      code = code c; i++
    }
    for (i = 1; i <= length(code); i++) {
      c = substr(code, i, 1)
      if (c == "{") {
        k = infunc ? "inner" : kind(pending)
        stack[++depth] = k
        if (k == "meminit") { pending = pending c; continue }
        if (k == "func") { infunc = depth; fstart = FNR; fsig = pstart ? pstart : FNR; fn = fname(pending) }
        reset()
      } else if (c == "}") {
        if (depth > 0 && stack[depth] == "meminit") { depth--; pending = pending c; continue }
        if (depth > 0 && infunc == depth) { print FILENAME, fn, fstart, FNR, fsig; infunc = 0 }
        if (depth > 0) depth--
        reset()
      } else if (c == ";") {
        reset()
      } else {
        if (pending == "" && c ~ /[^ \t]/) pstart = FNR
        if (pending != "" || c ~ /[^ \t]/) pending = pending c
      }
    }
    if (pending != "") pending = pending " "
  }' "$@"
}

# the report for ROOT: prints the long functions, returns 1 when one is not excused
check() {
  croot=$1 callow=$2
  dirs=${under:-src launcher analysis}
  files=$(cd "$croot" && find $dirs -name '*.cpp' -o -name '*.h' 2>/dev/null | sort)
  [ -n "$files" ] || { echo "long_functions.sh: no C++ files under $croot: $dirs" >&2; return 2; }
  (cd "$croot" && scan $files) | awk -v limit="$limit" -v allowfile="$callow" -v root="$croot" '
    BEGIN {
      if (allowfile != "") {
        while ((getline l < allowfile) > 0) {
          sub(/#.*/, "", l); if (split(l, f, /[ \t]+/) < 2) { if (f[1] != "") print "long_functions: " allowfile ": bad line: " l > "/dev/stderr"; continue }
          allowed[f[1] " " f[2]] = 1
        }
      }
    }
    {
      len = $4 - $3 + 1
      if (len <= limit) { short[$1 " " $2] = 1; next }
      ctor = 0
      if ($1 ~ /^src\// && split($2, parts, "::") == 2 && parts[1] == parts[2]) {
        cmd = "sed -n " $5 "," $5 + 2 "p " root "/" $1; sig = ""
        while ((cmd | getline s) > 0) sig = sig s
        close(cmd)
        if (sig ~ /LAMMPS \*[a-z]*, *int [a-z]*, *char \*\*[a-z]*/) ctor = 1
      }
      key = $1 " " $2
      if (ctor) status = "excused (a LAMMPS style constructor parsing its arguments)"
      else if (key in allowed) { status = "allowed (being split elsewhere)"; used[key] = 1 }
      else { status = "TOO LONG"; bad++ }
      printf "%5d lines  %s:%d  %s  %s\n", len, $1, $5, $2, status
      total++
    }
    END {
      for (k in allowed) if (!(k in used)) print "note: stale allow-list entry (no longer over " limit " lines, or gone): " k
      printf "%d function(s) over %d lines, %d not excused\n", total, limit, bad
      exit bad ? 1 : 0
    }'
}

if [ "$self_test" = yes ]; then
  # a fixture tree: a 151-line function fails; allowed, it passes; a style constructor
  # (with a member initialised by braces) passes; a 150-line function, a namespace, a
  # class and braces in strings and comments do not count
  t=$(mktemp -d) || exit 2
  trap 'rm -rf "$t"' EXIT
  mkdir -p "$t/src" "$t/analysis/core" "$t/launcher"
  body() { i=0; while [ $i -lt "$1" ]; do echo "  x += \"}\"; // {"; i=$((i + 1)); done; }
  { echo "namespace granpen {"; echo "struct S {"; echo "  int f() { return 1; }"; echo "};";
    echo "double long_one(int a,"; echo "                int b)"; echo "{"; body 148; echo "  return 0;"; echo "}";
    echo "int just_150()"; echo "{"; body 148; echo "}"; echo "}    // namespace granpen"; } > "$t/analysis/core/k.cpp"
  { echo "Foo::Foo(LAMMPS *lmp, int narg, char **arg) :"; echo "    Compute(lmp, narg, arg), a{0.0, 1.0}, b(2)"; echo "{";
    body 200; echo "}"; } > "$t/src/foo.cpp"
  out=$(check "$t" "" 2>&1); rc=$?
  echo "$out"
  case "$out" in *"151 lines  analysis/core/k.cpp:5  long_one  TOO LONG"*) ;; *) echo "SELF-TEST FAILED: the long function not found"; exit 1 ;; esac
  case "$out" in *just_150*) echo "SELF-TEST FAILED: a 150-line function reported"; exit 1 ;; esac
  case "$out" in *"Foo::Foo  excused"*) ;; *) echo "SELF-TEST FAILED: the style constructor not excused"; exit 1 ;; esac
  [ $rc -eq 1 ] || { echo "SELF-TEST FAILED: exit $rc with a long function, 1 expected"; exit 1; }
  echo "analysis/core/k.cpp long_one" > "$t/allow"
  check "$t" "$t/allow" > /dev/null 2>&1 || { echo "SELF-TEST FAILED: an allowed function still fails"; exit 1; }
  # --under: a folder held to a lower limit sees its own functions only
  mkdir -p "$t/analysis/gap"
  { echo "int gap_101()"; echo "{"; body 99; echo "}"; echo "int gap_100()"; echo "{"; body 98; echo "}"; } > "$t/analysis/gap/g.cpp"
  out=$(under=" analysis/gap" limit=100 check "$t" "" 2>&1); rc=$?
  echo "$out"
  case "$out" in *"101 lines  analysis/gap/g.cpp:1  gap_101  TOO LONG"*) ;; *) echo "SELF-TEST FAILED: --under missed the long function"; exit 1 ;; esac
  case "$out" in *long_one*|*gap_100*) echo "SELF-TEST FAILED: --under reported a function it should not"; exit 1 ;; esac
  [ $rc -eq 1 ] || { echo "SELF-TEST FAILED: --under exit $rc with a long function, 1 expected"; exit 1; }
  echo "self-test passed: the check fails on a long function and passes once it is excused"
  exit 0
fi

check "$root" "$allow"
