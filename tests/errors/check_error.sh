#!/usr/bin/env bash
# One error case: NAME.lua must fail with exactly the first line in NAME.expected, the expected exit
# code, and no file left in the output folder (but those named by `-- files:`). Optional header lines:
#   -- args: extra selfsim run arguments        -- exit: expected exit code (default 1)
#   -- files: the files the run writes before it fails (names in the output folder, sorted, space-separated)
# usage: check_error.sh SELFSIM ERRORS_DIR NAME
set -uo pipefail
selfsim=$1 dir=$2 name=$3
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
args=$(sed -n 's/^-- args: //p' "$dir/$name.lua" | head -1)
want_exit=$(sed -n 's/^-- exit: //p' "$dir/$name.lua" | head -1)
want_exit=${want_exit:-1}
want_files=$(sed -n 's/^-- files: //p' "$dir/$name.lua" | head -1)

cd "$dir"
# shellcheck disable=SC2086
"$selfsim" run "$name.lua" -o "$out/o" -q $args 2>"$out/stderr" >/dev/null
code=$?
got=$(head -1 "$out/stderr")
want=$(head -1 "$name.expected")
status=0
if [ "$got" != "$want" ]; then
  printf 'message differs\n  expected: %s\n  got:      %s\n' "$want" "$got"
  status=1
fi
if [ "$code" != "$want_exit" ]; then
  echo "exit code $code, expected $want_exit"
  status=1
fi
if [ -z "$want_files" ]; then
  if [ -d "$out/o" ] && [ -n "$(ls -A "$out/o")" ]; then
    echo "files left in the output folder: $(ls -A "$out/o")"
    status=1
  fi
else
  left=$( [ -d "$out/o" ] && cd "$out/o" && find . -mindepth 1 ! -type d | sed 's|^\./||' | LC_ALL=C sort | tr '\n' ' ')
  if [ "${left% }" != "$want_files" ]; then
    echo "files in the output folder: '${left% }', expected '$want_files'"
    status=1
  fi
fi
[ $status = 0 ] && echo "ok: $got"
exit $status
