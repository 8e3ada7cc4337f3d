# Shared by the robustness scripts: `source "$(dirname "$0")/lib.sh"` after setting selfsim and src.
# check DESCRIPTION CONDITION...: counts a pass when the command succeeds, prints the failure otherwise.
set -uo pipefail
passed=0 failed=0
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
check() {
  local what=$1
  shift
  if "$@"; then passed=$((passed + 1)); else echo "FAIL: $what"; failed=$((failed + 1)); fi
}
# run_selfsim ARGS...: runs selfsim, stdout to $tmp/out, stderr to $tmp/err, exit code in $code.
run_selfsim() {
  "$selfsim" "$@" >"$tmp/out" 2>"$tmp/err"
  code=$?
}
first_err() { head -1 "$tmp/err"; }
finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" = 0 ]
}
