#!/usr/bin/env bash
# Replays every input in a folder through a fuzz target, one process per input, and fails if any of them
# crashes, hangs (past FUZZ_TIMEOUT seconds), leaks or trips one of the target's checks.
# usage: replay.sh BINARY DIR      (BINARY is build-fuzz/fuzz/fuzz_<target>, libFuzzer or replay driver)
# With SIGNATURES=FILE, appends "signature<TAB>input" for each failing input (fuzz/run.sh dedups with it).
set -uo pipefail
here=$(cd "$(dirname "$0")" && pwd)
# shellcheck source=fuzz/lib.sh
source "$here/lib.sh"
binary=$1 dir=$2
target=$(basename "$binary")
target=${target#fuzz_}
fuzz_export_env "$target"
# shellcheck disable=SC2207
flags=($(fuzz_flags "$target"))
scratch=$(mktemp -d)
log=$scratch/log
trap 'rm -rf "$scratch"' EXIT
export TMPDIR=$scratch  # the targets' scratch files, left behind by an input that crashes

passed=0 failed=0
shopt -s nullglob
for input in "$dir"/*; do
  [ -f "$input" ] || continue
  case $(basename "$input") in README* | *.md) continue ;; esac
  timeout -k 5 $((FUZZ_TIMEOUT * 3 + 30)) "$binary" "${flags[@]}" "$input" >"$log" 2>&1
  code=$?
  if [ "$code" = 0 ]; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    [ "$code" = 124 ] || [ "$code" = 137 ] && echo "ERROR: libFuzzer: timeout (killed by replay.sh)" >>"$log"
    sig=$(signature "$log")
    echo "FAIL: $input: $sig"
    [ -n "${SIGNATURES:-}" ] && printf '%s\t%s\n' "$sig" "$input" >>"$SIGNATURES"
  fi
done
echo "$target regressions: $passed passed, $failed failed"
[ "$failed" = 0 ]
