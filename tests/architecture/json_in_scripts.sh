#!/bin/sh
# json_in_scripts.sh: scripts ask the program for values of its JSON outputs (`granpen get
# FILE KEY`, `granpen gap-score`), they do not read the JSON's text (issue 32): its layout is
# the writer's to choose. Fails when a script of validation/, bench/, tests/ or .ci/ (shell
# scripts, and the shell commands of tests/'s CMake files) runs grep, sed or awk on JSON: a
# command of theirs that names a .json file, a variable assigned a .json path in the same
# file, or a JSON member pattern ("key": ), or that reads a .json file piped in by cat, head
# or tail. Their use on granpen get's output, on CSV, on .info files and on logs is fine.
#   json_in_scripts.sh [--self-test] [ROOT]
# Exit: 0 no such read, 1 a script reads JSON's text, 2 usage.
set -u
root=.
self_test=no
while [ $# -gt 0 ]; do
  case "$1" in
    --self-test) self_test=yes; shift ;;
    -h|--help) sed -n '2,10p' "$0"; exit 0 ;;
    -*) echo "json_in_scripts.sh: unknown option $1" >&2; exit 2 ;;
    *) root=$1; shift ;;
  esac
done

# the scripts of ROOT, one path a line
scripts() {
  (cd "$1" && {
    find validation bench tests .ci -type f -name '*.sh' 2>/dev/null
    find .ci -type f ! -name '*.*' 2>/dev/null
    find tests -type f \( -name CMakeLists.txt -o -name '*.cmake' \) 2>/dev/null
  } | grep -v '^tests/architecture/' | sort -u)
}

# the JSON reads in ROOT's scripts: "path:line: text"
check() {
  croot=$1
  [ -d "$croot" ] || { echo "json_in_scripts.sh: no folder $croot" >&2; return 2; }
  files=$(scripts "$croot")
  [ -n "$files" ] || { echo "json_in_scripts.sh: no scripts under $croot" >&2; return 2; }
  n=$(echo "$files" | wc -l)
  # shellcheck disable=SC2086
  (cd "$croot" && awk -v nfiles="$n" '
    # single-quoted text masked (quotes kept) so that the | ; & ( ) in awk programs and grep
    # patterns split nothing; inside "..." a quote is literal, but not inside $( ) within it
    function mask(s,   i, c, out, sq, dq, depth, saved) {
      out = ""; sq = 0; dq = 0; depth = 0
      for (i = 1; i <= length(s); i++) {
        c = substr(s, i, 1)
        if (sq) { out = out (c == "\047" ? c : "_"); if (c == "\047") sq = 0; continue }
        if (c == "\\") { out = out "__"; i++; continue }
        if (c == "\047" && !dq) { sq = 1; out = out c; continue }
        if (c == "\"") { dq = !dq; out = out c; continue }
        if (c == "$" && substr(s, i + 1, 1) == "(") { saved[++depth] = dq; dq = 0; out = out "$("; i++; continue }
        if (c == ")" && depth > 0) { dq = saved[depth--]; out = out c; continue }
        out = out c
      }
      return out
    }
    function is_text_tool(w) { sub(/^.*\//, "", w); return w ~ /^(grep|egrep|fgrep|zgrep|sed|awk|gawk|mawk|nawk)$/ }
    function is_pass_on(w) { sub(/^.*\//, "", w); return w ~ /^(cat|head|tail|zcat)$/ }
    # whether text names JSON: a .json file, a JSON variable, a member pattern
    function names_json(t,   v) {
      if (t ~ /\.json([^A-Za-z0-9_]|$)/) return 1
      if (t ~ /\\?"(\$\{?[A-Za-z0-9_]+\}?|[A-Za-z_][A-Za-z0-9_]*)\\?": /) return 1
      for (v in jvar) if (index(t, "$" v) && (t ~ ("\\$" v "([^A-Za-z0-9_]|$)") || index(t, "${" v "}"))) return 1
      return 0
    }
    # the command word of a segment: leading keywords, ! { and assignments skipped
    function command_word(t,   w) {
      while (1) {
        sub(/^[ \t]+/, "", t)
        if (match(t, /^(!|\{|then|do|else|if|elif|while|until|time|exec|[A-Za-z_][A-Za-z0-9_]*=("[^"]*"|[^ \t]*))([ \t]|$)/)) {
          t = substr(t, RLENGTH + 1); continue
        }
        break
      }
      w = t; sub(/[ \t].*/, "", w); gsub(/["\047]/, "", w)
      return w
    }
    function scan(line, where,   m, i, c, start, seg, w, fed, delim) {
      m = mask(line); start = 1; fed = 0
      for (i = 1; i <= length(m) + 1; i++) {
        c = i <= length(m) ? substr(m, i, 1) : ";"
        if (c !~ /[|;&()`]/) continue
        seg = substr(line, start, i - start); delim = c; start = i + 1
        w = command_word(seg)
        if (w == "") continue
        if (is_text_tool(w) && (names_json(seg) || fed)) { print where ": " line; bad++ }
        fed = delim == "|" && is_pass_on(w) && names_json(seg)
      }
    }
    # each file twice: its JSON variables first, then its commands
    FNR == 1 { file++; pass = (file % 2 == 1) ? 1 : 2; held = ""; if (pass == 1) split("", jvar) }
    {
      text = $0
      if (text ~ /^[ \t]*#/) next
      if (pass == 1) {
        s = text
        while (match(s, /[A-Za-z_][A-Za-z0-9_]*="?[^ \t;|&"]*\.json"?([ \t;|&)]|$)/)) {
          v = substr(s, RSTART, RLENGTH); sub(/=.*/, "", v); jvar[v] = 1; s = substr(s, RSTART + RLENGTH)
        }
        next
      }
      if (held == "") first = FNR
      if (text ~ /\\$/) { held = held substr(text, 1, length(text) - 1) " "; next }
      scan(held text, FILENAME ":" first); held = ""
    }
    END {
      if (bad) { printf "%d read(s) of JSON text by grep, sed or awk in scripts: ask `granpen get FILE KEY` (docs/postprocess.md)\n", bad; exit 1 }
      print "ok: no script of " nfiles " reads JSON with grep, sed or awk"
    }' $(for f in $files; do echo "$f $f"; done))
}

if [ "$self_test" = yes ]; then
  # a fixture tree: asking granpen, and grep/awk on CSV, logs and get's output pass; then each
  # planted read of JSON fails alone
  t=$(mktemp -d) || exit 2
  trap 'rm -rf "$t"' EXIT
  mkdir -p "$t/validation" "$t/bench" "$t/tests/x"
  cat > "$t/validation/ok.sh" <<'EOF'
j=$out/diagnosis.json
v=$("$CLI" get "$j" verdict)
steps=$("$CLI" get "$OUT/flow.json" 'frames[*].timestep' 'frames[*].z_tip' |
        awk -v lo=1 '$2 >= lo { print $1 }')
grep -q "granpen push: done" "push.log" && awk -F, '{ print $2 }' fit.csv | sed 's/x/y/'
echo "no frame ($OUT/surface/flow.json)" >&2
EOF
  out=$(check "$t" 2>&1) || { echo "$out"; echo "SELF-TEST FAILED: a tree that asks granpen fails"; exit 1; }
  for planted in \
    'v=$(grep -o "\"verdict\": [a-z]*" "$OUT/x.json")' \
    "  sed -n 's/^  \"gap_before\": \\(.*\\),\$/\\1/p' \"\$j\"" \
    'put "k = $(awk -v a=1 '\''{ print $2 }'\'' "$dir/momentum.json" | head -1)"' \
    'busy=$(cat "$W"/*/manifest.json | grep -o wall_seconds_run | wc -l)' \
    'grep -q resumed "$OUT/pour_resume/manifest.json" || exit 1' \
    'num() { grep -o "\"$2\": [-0-9.e+]*" "$1" | head -1; }'; do
    printf '%s\n' 'j=$out/diagnosis.json' "$planted" > "$t/bench/planted.sh"
    out=$(check "$t" 2>&1); rc=$?
    case "$out" in *"bench/planted.sh:2: "*) ;; *) echo "$out"; echo "SELF-TEST FAILED: not found: $planted"; exit 1 ;; esac
    [ $rc -eq 1 ] || { echo "SELF-TEST FAILED: exit $rc with a planted read, 1 expected"; exit 1; }
  done
  # a CMake test's shell command
  rm "$t/bench/planted.sh"
  cat > "$t/tests/x/CMakeLists.txt" <<'EOF'
add_test(NAME x COMMAND sh -c "test -d '${D}' && grep -q '\"confirmed\": false' '${D}/diagnosis.json'")
EOF
  check "$t" > /dev/null 2>&1 && { echo "SELF-TEST FAILED: a CMake test's grep of JSON not found"; exit 1; }
  echo "self-test passed: the check fails on each planted read of JSON by grep, sed or awk"
  exit 0
fi

check "$root"
