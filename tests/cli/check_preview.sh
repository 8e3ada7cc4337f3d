#!/bin/bash
# selfsim preview SELFSIM SRC: a PNG of one file of every format, with DISPLAY unset so that selfsim starts
# its own Xvfb; each PNG has the expected size, is not blank and has more than one colour (read by VTK's
# own Python). Then the errors: unknown extension, missing file, no display and no Xvfb. Skips (77) when
# there is no Xvfb or no VTK Python to check with.
selfsim=$1
src=$2
source "$src/tests/robustness/lib.sh"
export SELFSIM_TEST_MARK=$tmp  # inherited by the Xvfbs this test's runs start: how they are known below
command -v Xvfb >/dev/null || { echo "skipped: no Xvfb"; exit 77; }
# VTK's Python (python3-vtk9) or ParaView's, whichever is installed.
python=$("$src/tests/viewer/vtk_python.sh") || { echo "skipped: no VTK Python"; exit 77; }

cat >"$tmp/all.lua" <<'LUA'
local curves = require "selfsim.curves"
local c = curves.dragon():curve{ level = 8 }
save(c, "curve.vtp"); save(c, "curve.svg")
local s = develop(curves.dragon(), { levels = 4, smooth = 2 })
save(s, "mesh.vtp"); save(s, "mesh.vtu"); save(s, "mesh.stl"); save(s, "mesh.obj"); save(s, "mesh.ply")
save(solid.thicken(solid.size(s, 40), { thickness = 1.5, check = false }), "solid.3mf")  -- the solid a user prints
save(volume.sphere{ center = {0, 0, 0}, radius = 1 }, "sphere.vdb")
LUA
"$selfsim" run "$tmp/all.lua" -o "$tmp/in" -q 2>"$tmp/run_err"
check "recipe runs" test -s "$tmp/in/sphere.vdb"

# png_ok FILE W H: exists, W x H, more than one colour, not all background.
png_ok() {
  $python - "$@" <<'PY'  # unquoted: it may be "env PYTHONPATH=... /usr/bin/python3"
import sys
from vtkmodules.vtkIOImage import vtkPNGReader
from vtkmodules.util.numpy_support import vtk_to_numpy
path, w, h = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
r = vtkPNGReader(); r.SetFileName(path); r.Update()
img = r.GetOutput(); dims = img.GetDimensions()
if (dims[0], dims[1]) != (w, h): sys.exit(f"{path}: {dims[0]}x{dims[1]}, expected {w}x{h}")
px = vtk_to_numpy(img.GetPointData().GetScalars())[:, :3]
colours = {tuple(p) for p in px[:: max(1, len(px) // 200000)]}
drawn = (px.min(axis=1) < 200).mean()
if len(colours) < 8 or drawn < 0.01: sys.exit(f"{path}: {len(colours)} colours, {drawn:.3%} drawn")
PY
}

sizes="curve.vtp:800:800 curve.svg:800:800 mesh.vtp:1200:600 mesh.vtu:1200:600 mesh.stl:1200:600 mesh.obj:1200:600 mesh.ply:1200:600 solid.3mf:1200:600 sphere.vdb:1200:600"
for entry in $sizes; do
  IFS=: read -r name w h <<<"$entry"
  env -u DISPLAY "$selfsim" preview "$tmp/in/$name" -o "$tmp/png/${name#*.}" >"$tmp/out" 2>"$tmp/err"
  code=$?
  png="$tmp/png/${name#*.}/${name%.*}.png"
  check "$name: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
  check "$name: one line 'wrote $png'" grep -q "^wrote $png ($w""x$h" "$tmp/out"
  check "$name: picture" png_ok "$png" "$w" "$h"
done

# Default folder: beside the input.
env -u DISPLAY "$selfsim" preview "$tmp/in/curve.vtp" >"$tmp/out" 2>"$tmp/err"
check "beside the input" test -s "$tmp/in/curve.png"

# Several files at once: one line each.
env -u DISPLAY "$selfsim" preview "$tmp/in/curve.vtp" "$tmp/in/mesh.ply" -o "$tmp/many" >"$tmp/out" 2>"$tmp/err"
check "two files, two lines" test "$(grep -c '^wrote ' "$tmp/out")" = 2

# No Xvfb process is left behind by this test's runs: known by the SELFSIM_TEST_MARK they inherited (any
# other Xvfb on the machine, another test's or a user's, is not this test's business).
no_own_xvfb() {
  local p
  for p in $(pgrep -u "$(id -u)" -x Xvfb); do
    grep -qzx "SELFSIM_TEST_MARK=$tmp" "/proc/$p/environ" 2>/dev/null && return 1
  done
  return 0
}
check "no Xvfb left" no_own_xvfb

# A sweep's contact sheet holds pictures (<image>), no path: preview says it is for a browser.
printf '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink"><image href="a/c.svg"/><image href="b/c.svg"/></svg>\n' >"$tmp/sheet_c.svg"
run_selfsim preview "$tmp/sheet_c.svg" -o "$tmp/bad"
check "contact sheet: exit 1" test "$code" = 1
check "contact sheet: says so ($(head -1 "$tmp/err"))" grep -q "^selfsim preview: cannot read '$tmp/sheet_c.svg': a contact sheet of 2 pictures .*open it in a browser" "$tmp/err"

# Errors: one line naming the file, exit 1; usage errors exit 2.
echo hello >"$tmp/x.txt"
run_selfsim preview "$tmp/x.txt" -o "$tmp/bad"
check "unknown extension: exit 1" test "$code" = 1
check "unknown extension: message" grep -q "^selfsim preview: cannot read '$tmp/x.txt': expected a " "$tmp/err"
check "unknown extension: one line" test "$(wc -l <"$tmp/err")" = 1
run_selfsim preview "$tmp/missing.vtp" -o "$tmp/bad"
check "missing file: exit 1" test "$code" = 1
check "missing file: message" grep -q "^selfsim preview: cannot read '$tmp/missing.vtp': no such file" "$tmp/err"
printf 'not a vdb' >"$tmp/bad.vdb"
run_selfsim preview "$tmp/bad.vdb" -o "$tmp/bad"
check "crafted .vdb: exit 1, one line" test "$code" = 1 -a "$(wc -l <"$tmp/err")" = 1
check "crafted .vdb: message" grep -q "^selfsim preview: cannot read '$tmp/bad.vdb': " "$tmp/err"
check "no PNG for bad inputs" test ! -e "$tmp/bad/x.png" -a ! -e "$tmp/bad/bad.png"
run_selfsim preview
check "no file: usage exit 2" test "$code" = 2
run_selfsim preview "$tmp/in/curve.vtp" --bogus
check "unknown option: usage exit 2" test "$code" = 2

# The run's limits (the studio and sweeps pass theirs): --max-memory too small for the renderer and a
# --timeout long past are one line each and leave no PNG; bad values are usage errors naming the flag.
run_selfsim preview "$tmp/in/mesh.vtp" -o "$tmp/lim" --max-memory 16M
check "--max-memory 16M: exit 1 ($(first_err))" test "$code" = 1
check "--max-memory 16M: one line" test "$(wc -l <"$tmp/err")" = 1
# Whatever the renderer meets at a limit too small (a crash, VTK's "ran out of memory" or "Unable to
# allocate"), the line says the limit may be why ("ran out of memory" alone did not).
for m in 70M 80M 90M 100M; do
  run_selfsim preview "$tmp/in/curve.vtp" -o "$tmp/lim" --max-memory $m
  [ "$code" = 0 ] || check "--max-memory $m: names the limit ($(first_err))" grep -q "perhaps --max-memory $m" "$tmp/err"
done
# The --timeout case is held, not raced: DISPLAY names an X server of ours that takes the connection and
# never answers, so the preview waits in XOpenDisplay (after its timer started) until the timer ends it.
/usr/bin/python3 -c '
import socket, sys, time
for n in range(50, 1000):
    s = socket.socket()
    try:
        s.bind(("127.0.0.1", 6000 + n))
    except OSError:
        s.close()
        continue
    s.listen(8)
    print(n, flush=True)
    break
time.sleep(600)' >"$tmp/silent_x" &
silent_x=$!
for _ in $(seq 600); do [ -s "$tmp/silent_x" ] && break; sleep 0.05; done
DISPLAY="127.0.0.1:$(cat "$tmp/silent_x")" run_selfsim preview "$tmp/in/mesh.vtp" -o "$tmp/lim" --timeout 1
kill "$silent_x"
wait "$silent_x" 2>/dev/null
check "--timeout reached: exit 1 ($(first_err))" test "$code" = 1
check "--timeout reached: message" grep -q "^selfsim preview: --timeout of 1 s reached" "$tmp/err"
check "no PNG past the limits" test ! -e "$tmp/lim/mesh.png"
run_selfsim preview "$tmp/in/mesh.vtp" --max-memory 1K
check "--max-memory 1K: usage error naming it" grep -q "^selfsim: --max-memory expects a size" "$tmp/err"
run_selfsim preview "$tmp/in/mesh.vtp" --timeout -1
check "--timeout -1: usage error naming it" grep -q -- "--timeout" "$tmp/err"
run_selfsim preview --as only.png
check "--as without a file: usage exit 2" test "$code" = 2

# No display and no Xvfb on PATH.
mkdir -p "$tmp/bin"
env -u DISPLAY PATH="$tmp/bin" "$selfsim" preview "$tmp/in/curve.vtp" -o "$tmp/nox" >"$tmp/out" 2>"$tmp/err"
code=$?
check "no Xvfb: exit 1" test "$code" = 1
check "no Xvfb: message" test "$(cat "$tmp/err")" = \
  "selfsim preview: no X display and no Xvfb to start one; install it: apt-get install xvfb"
# A DISPLAY that cannot be connected to is the same as none.
DISPLAY=:987 PATH="$tmp/bin" "$selfsim" preview "$tmp/in/curve.vtp" -o "$tmp/nox" >"$tmp/out" 2>"$tmp/err"
check "unreachable DISPLAY, no Xvfb: message" grep -q "no X display and no Xvfb" "$tmp/err"

# info on a .vdb: its grid.
run_selfsim info "$tmp/in/sphere.vdb"
check "info .vdb" grep -q "class: level set" "$tmp/out"
check "info .vdb: world bbox" grep -q "world bbox: " "$tmp/out"
finish
