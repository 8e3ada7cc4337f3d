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
# children PID [TEXT]: the ids of PID's own child processes (those whose command line holds TEXT). Tests look
# only at processes they started: a pattern (pgrep -f) also matches any other selfsim on the machine.
children() {
  local c
  for c in $(pgrep -P "$1"); do
    if [ -z "${2:-}" ] || grep -qaF -- "$2" "/proc/$c/cmdline" 2>/dev/null; then echo "$c"; fi
  done
}
# running PID TEXT: whether that process still runs with TEXT in its command line (not a zombie, not an id
# taken again by another program).
running() { grep -qaF -- "$2" "/proc/$1/cmdline" 2>/dev/null; }
