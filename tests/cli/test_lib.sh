# Shared by the cli tests (source it): $selfsim from the first argument, a temporary folder $tmp removed at
# exit, and fail(), which counts failures; a test ends with `finish`.
set -uo pipefail
selfsim=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
finish() {
  echo "$failures failures"
  [ "$failures" = 0 ]
}
