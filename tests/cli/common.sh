# Shared helpers of the CLI end-to-end tests. Usage: source common.sh "$@" (BIN ROOT)
set -uo pipefail
BIN=$1
ROOT=$2
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
cd "$ROOT"
fails=0
passes=0
pass() { passes=$((passes + 1)); echo "ok: $*"; }
fail() { fails=$((fails + 1)); echo "FAIL: $*"; }
# expect_exit CODE DESCRIPTION -- command...
expect_exit() {
  local code=$1 what=$2; shift 3
  "$@" > "$TMP/stdout" 2> "$TMP/stderr"
  local got=$?
  if [ "$got" -eq "$code" ]; then pass "$what (exit $got)"; else
    fail "$what: expected exit $code, got $got"; sed 's/^/  | /' "$TMP/stderr"; fi
}
finish() {
  echo "$passes passed, $fails failed"
  [ "$fails" -eq 0 ]
}
