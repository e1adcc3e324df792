# Shared by the *_can_fail.sh scripts that run a check script on stand-ins (sourced; the
# caller defines fail and WORK): expect_exit NAME RC PATTERN COMMAND...: COMMAND exits RC and
# prints PATTERN; its output is kept in $WORK/out and shown when it does not.
expect_exit() {
  local name=$1 want=$2 pattern=$3 rc=0
  shift 3
  "$@" > "$WORK/out" 2>&1 || rc=$?
  [ "$rc" = "$want" ] || { cat "$WORK/out"; fail "$name exited $rc, not $want"; }
  grep -q -- "$pattern" "$WORK/out" || { cat "$WORK/out"; fail "$name did not say '$pattern'"; }
  echo "$name $want: $(grep -- "$pattern" "$WORK/out" | head -1)"
}
