#!/bin/sh
# cli_vs_core.sh: lines of code (not blank, not only a comment) of analysis/cli/ and of
# analysis/core/; exit 1 while the CLI has as many or more (issue 17: a thin CLI, the
# computing in core). Not yet a ctest: today it fails, until the CLI's computing moves.
#   cli_vs_core.sh [ROOT]
set -u
root=${1:-.}
loc() {
  find "$root/$1" -maxdepth 1 \( -name '*.cpp' -o -name '*.h' \) -exec cat {} + | awk '
    { l = $0
      if (inc) { if (l ~ /\*\//) { sub(/.*\*\//, "", l); inc = 0 } else next }
      while (l ~ /\/\*/) { if (l ~ /\/\*.*\*\//) sub(/\/\*([^*]|\*+[^*\/])*\*+\//, "", l); else { sub(/\/\*.*/, "", l); inc = 1 } }
      sub(/\/\/.*/, "", l)
      if (l ~ /[^ \t]/) n++ }
    END { print n + 0 }'
}
cli=$(loc analysis/cli) core=$(loc analysis/core)
echo "lines of code: analysis/cli $cli, analysis/core $core"
if [ "$cli" -lt "$core" ]; then echo "ok: the CLI is smaller than core"; exit 0; fi
echo "the CLI has $((cli - core)) more lines of code than core: it computes what core should"
exit 1
