#!/bin/sh
# cli_vs_core.sh: lines of code (not blank, not only a comment) of analysis/cli/ and of
# analysis/core/; exit 1 while the CLI has as many or more (issue 17: a thin CLI, the
# computing in core). ctest architecture_cli_smaller_than_core, with a self-test.
#   cli_vs_core.sh [--self-test] [ROOT]
# Exit: 0 the CLI is smaller, 1 it is not, 2 usage. Needs only sh, find and awk.
set -u
root=.
self_test=no
while [ $# -gt 0 ]; do
  case "$1" in
    --self-test) self_test=yes; shift ;;
    -h|--help) sed -n '2,6p' "$0"; exit 0 ;;
    -*) echo "cli_vs_core.sh: unknown option $1" >&2; exit 2 ;;
    *) root=$1; shift ;;
  esac
done

# lines of code of the .cpp and .h files in ROOT/DIR (code_lines.sh: comments, string
# literals' text and blank lines do not count)
. "$(dirname "$0")/code_lines.sh"
loc() { code_lines "$1" "" "$2" | wc -l | tr -d ' '; }

check() {
  [ -d "$1/analysis/cli" ] && [ -d "$1/analysis/core" ] || { echo "cli_vs_core.sh: $1 has no analysis/cli and analysis/core" >&2; return 2; }
  cli=$(loc "$1" analysis/cli) core=$(loc "$1" analysis/core)
  echo "lines of code: analysis/cli $cli, analysis/core $core"
  if [ "$cli" -lt "$core" ]; then echo "ok: the CLI is smaller than core"; return 0; fi
  echo "the CLI has $((cli - core)) more lines of code than core: it computes what core should"
  return 1
}

if [ "$self_test" = yes ]; then
  # a fixture tree: core 3 lines of code; a CLI of 2 passes, however many comments and
  # blank lines it has; a CLI of 3 (as many) or 4 fails with exit 1
  tmp=$(mktemp -d) || exit 2
  trap 'rm -rf "$tmp"' EXIT
  t="$tmp/tree"
  mkdir -p "$t/analysis/cli" "$t/analysis/core"
  printf 'int a;\n/* a\n   block */\nint b; // c\n\nint c;\n' > "$t/analysis/core/k.cpp"
  printf '// one\n// two\n/* three\n four */\nint main();\n\n\n' > "$t/analysis/cli/main.cpp"
  printf 'int x;  /* inline */\n' > "$t/analysis/cli/x.h"
  out=$(check "$t") || { echo "$out"; echo "SELF-TEST FAILED: a CLI of 2 lines against core's 3 fails"; exit 1; }
  case "$out" in *"analysis/cli 2, analysis/core 3"*) ;; *) echo "$out"; echo "SELF-TEST FAILED: wrong counts"; exit 1 ;; esac
  printf 'int y;\n' > "$t/analysis/cli/y.h"
  check "$t" > /dev/null; rc=$?
  [ $rc -eq 1 ] || { echo "SELF-TEST FAILED: a CLI as large as core gives exit $rc, 1 expected"; exit 1; }
  printf 'int z;\n' > "$t/analysis/cli/z.h"
  out=$(check "$t"); rc=$?
  echo "$out"
  case "$out" in *"the CLI has 1 more lines of code than core"*) ;; *) echo "SELF-TEST FAILED: a larger CLI not reported"; exit 1 ;; esac
  [ $rc -eq 1 ] || { echo "SELF-TEST FAILED: exit $rc, 1 expected"; exit 1; }
  echo "self-test passed: the check fails when the CLI is not smaller than core"
  exit 0
fi

check "$root"
