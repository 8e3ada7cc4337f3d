#!/usr/bin/env bash
# A sweep's previews are drawn by children in batches (sweep_collect.cpp draw_previews):
# - however many runs and however long their paths, each child's command line fits the kernel's limit on
#   arguments (one child for all previews could not start past ~2 MB: the sweep ended with exit 2 after its
#   runs, leaving no sheets); a batch that fails is a warning and its cells say "no preview";
# - each batch has the run's --timeout once per preview in it, not once for all the sweep's previews.
# usage: sweep_previews.sh SELFSIM SOURCE_DIR
selfsim=$1
src=$2
source "$src/tests/robustness/lib.sh"
cd "$tmp" || exit 1
cat >m.lua <<'LUA'
local curves = require "selfsim.curves"
local level = param("level", 1, { min = 1, max = 900 })
save(develop(curves.dragon(), { levels = 1 + level % 3, smooth = 1 }), "m.vtp")
LUA

# 800 runs collected in an output folder ~3,000 bytes deep: about 2.5 MB of preview arguments together.
# The runs' folders are made here (as GNU parallel would leave them), each with a file that cannot be read,
# so no preview is drawn and no display is needed.
deep=.
for i in $(seq 13); do deep="$deep/$(printf "%0230d" "$i")"; done
/usr/bin/python3 - "$deep/sw" <<'PY'
import os, sys
for i in range(1, 801):
    d = os.path.join(sys.argv[1], f"level={i}")
    os.makedirs(d)
    open(os.path.join(d, "m.stl"), "w").write("not a mesh\n")
    open(os.path.join(d, "selfsim.exit"), "w").write("0\n")
PY
(ulimit -s 8192 && run_selfsim sweep m.lua -o "$deep/sw" --set level=1..800 --collect -q && echo "$code" >code)
code=$(cat code)
check "800 previews with long paths: the sweep ends well (exit $code: $(grep -v 'cannot read' err | head -1))" \
  test "$code" = 0
check "the sheet is written" test -s "$deep/sw/sheet_m.stl.svg"
check "its cells say no preview" test "$(grep -c '>no preview<' "$deep/sw/sheet_m.stl.svg")" = 800
check "a warning says so" grep -q 'warning: some previews could not be drawn' err
rm -rf ./0*

# A --timeout each preview fits but all of them together do not: the child drawing them is held (SIGSTOP)
# past the run's --timeout, which one child for all previews under one --timeout did not survive.
[ -n "${DISPLAY:-}" ] || command -v Xvfb >/dev/null || {
  echo "skipped the timeout case: no X display and no Xvfb"
  finish
  exit
}
# Stops the sweep's own preview child (a child of pid $1) as soon as it appears, setting held to its pid; held
# only once seen stopped, so a child that had already ended is tried again. Returns when the sweep ends.
hold_preview() {
  while kill -0 "$1" 2>/dev/null && [ -z "$held" ]; do
    for c in $(pgrep -P "$1"); do
      if grep -qaF preview "/proc/$c/cmdline" 2>/dev/null && kill -STOP "$c" 2>/dev/null; then
        for _ in $(seq 100); do
          [ "$(awk '{print $3}' "/proc/$c/stat" 2>/dev/null)" = T ] && held=$c && break
          sleep 0.05
        done
      fi
    done
    sleep 0.02
  done
}

run_selfsim sweep m.lua -o tw --set level=1..4 --no-sheet -q --timeout 5
check "four runs: $(first_err)" test "$code" = 0
held=
for _ in 1 2 3 4 5; do # a preview that ends before it is seen is drawn again
  "$selfsim" sweep m.lua -o tw --set level=1..4 --collect -q --timeout 5 >out 2>err &
  sweep=$!
  hold_preview "$sweep"
  if [ -n "$held" ]; then
    sleep 6 # past the run's --timeout of 5 s, within the batch's 4 x 5 s
    kill -CONT "$held"
  fi
  wait "$sweep"
  code=$?
  [ -n "$held" ] && break
done
check "the preview child was held" test -n "$held"
check "the collect ends well (exit $code: $(first_err))" test "$code" = 0
check "every cell has its preview" test "$(grep -c '<image' tw/sheet_m.vtp.svg)" = 4
check "no cell says no preview" test "$(grep -c 'no preview' tw/sheet_m.vtp.svg)" = 0

# SIGTERM to a sweep (local, then --collect) while its preview child is held stopped: the sweep wakes the
# child to end it (SIGTERM, SIGCONT) and ends with 130, instead of waiting on a child that never finishes
# (--collect was ended by the signal, leaving its preview child stopped for ever).
for how in local collect; do
  if [ "$how" = local ]; then
    "$selfsim" sweep m.lua -o st --set level=1..2 -q >out 2>err &
  else
    "$selfsim" sweep m.lua -o tw --set level=1..4 --collect -q >out 2>err &
  fi
  sweep=$!
  held=
  hold_preview "$sweep"
  if [ -z "$held" ]; then
    wait "$sweep"
    echo "note: the $how preview ended before it was seen; its SIGTERM case was not tried"
    continue
  fi
  kill -TERM "$sweep"
  for _ in $(seq 600); do kill -0 "$sweep" 2>/dev/null || break; sleep 0.05; done
  kill -0 "$sweep" 2>/dev/null && kill -CONT "$held" # let it end; the check below then fails
  wait "$sweep"
  code=$?
  check "$how: SIGTERM during a held preview ends the sweep with 130 (got $code)" test "$code" = 130
  stat=$(awk '{print $3}' "/proc/$held/stat" 2>/dev/null)
  check "$how: the preview child ended with it (state '$stat')" test -z "$stat" -o "$stat" = Z
  kill -CONT "$held" 2>/dev/null
done
finish
