#!/bin/bash
# selfsim preview SELFSIM SRC: 3D as it is and growth as growth, measured from the pixels
# (tests/cli/preview_pixels.py). ABOP's Figure 2.6 tree (examples/lsystem_tree3d.lua) stands upright in the
# front view with a trunk as wide as its `width` says, and so does the run's ParaView view; --up turns it; --field picks the colouring and a name
# not there is one line naming what the file holds; an SVG keeps its stroke colours; a series drawn with
# --steps has one camera and one legend at every step (step 1's drawing lies where step 2 draws it), an APNG
# of one frame per step and a filmstrip; the plain preview of a series is its last step in that camera.
# Skips (77) when there is no Xvfb or no VTK Python to measure with.
selfsim=$1
src=$2
source "$src/tests/robustness/lib.sh"
command -v Xvfb >/dev/null || { echo "skipped: no Xvfb"; exit 77; }
python=$("$src/tests/viewer/vtk_python.sh") || { echo "skipped: no VTK Python"; exit 77; }
pixels() { $python "$src/tests/cli/preview_pixels.py" "$@"; }  # unquoted: it may be "env PYTHONPATH=..."
fails() { ! "$@" >/dev/null 2>&1; }  # fails COMMAND...: the command fails
preview() { env -u DISPLAY "$selfsim" preview "$@" >"$tmp/out" 2>"$tmp/err"; code=$?; }

# ABOP Fig. 2.6 at a small level: upright, its trunk the widest (width 10 of the tips' 10*0.707^5).
"$selfsim" run "$src/examples/lsystem_tree3d.lua" --set level=6 -o "$tmp/tree" -q 2>"$tmp/run_err"
check "tree recipe runs ($(head -1 "$tmp/run_err"))" test -s "$tmp/tree/lsystem_tree3d.vtp"
tree=$tmp/tree/lsystem_tree3d.vtp
preview "$tree" -o "$tmp/up"
check "tree: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
check "tree: 1200x600" grep -q "(1200x600)" "$tmp/out"
check "tree: upright in the front view, a wide trunk in the middle" pixels upright "$tmp/up/lsystem_tree3d.png" 8
preview "$tree" -o "$tmp/side" --up z
check "--up z: the tree seen along its axis is not upright" fails pixels upright "$tmp/side/lsystem_tree3d.png"
preview "$tree" -o "$tmp/yup" --up y
check "--up y: the same as the tree's own up" pixels same_views "$tmp/up/lsystem_tree3d.png" "$tmp/yup/lsystem_tree3d.png"

# A print (.3mf) stands on its build plate, +z up: the tree printed as a tube (turned to stand along z) is
# upright with no --up.
"$selfsim" run "$src/examples/print_tree.lua" --set level=4 --set size=20 -o "$tmp/print" -q 2>"$tmp/run_err"
check "print tree runs ($(head -1 "$tmp/run_err"))" test -s "$tmp/print/tree.3mf"
preview "$tmp/print/tree.3mf" -o "$tmp/print"
check "tree.3mf: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
check "tree.3mf: upright in the front view" pixels upright "$tmp/print/tree.png"
# The print check's marked mesh (a `wall` field) is a print too: z up, as its .3mf.
cat >"$tmp/print/marked.lua" <<'LUA'
local tree = lsystem { axiom = "F[+F][-F]F[+F]F", rules = { F = "F[+F]F" }, angle = 25 }
local c = solid.size(tree:curve(2), 20)
local t = solid.tube(c, { method = "grid", radius = 0.5, check = false }):transform { rotate = 90, axis = { 1, 0, 0 } }
local _, marked = solid.check(solid.place(t))
save(marked, "marked.vtp")
LUA
"$selfsim" run "$tmp/print/marked.lua" -o "$tmp/print" -q 2>"$tmp/run_err"
preview "$tmp/print/marked.vtp" -o "$tmp/print"
check "marked.vtp: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
check "marked.vtp: upright in the front view" pixels upright "$tmp/print/marked.png"

# The run's ParaView view agrees: upright, when pvbatch is there to render it.
if command -v pvbatch >/dev/null 2>&1; then
  check "view.py: the tree's up axis" grep -q '"up": 1' "$tmp/tree/view.py"
  check "view.py renders" "$src/tests/viewer/check_view.sh" "$tmp/tree/view.py" "$tmp/tree/view.png"
  check "view.py: upright" pixels upright_view "$tmp/tree/view.png"
fi

# The colouring: branch_order by default (the same picture as asking for it), another with --field.
preview "$tree" -o "$tmp/order" --field branch_order
check "--field branch_order: exit 0" test "$code" = 0
check "default colouring is branch_order" cmp -s "$tmp/up/lsystem_tree3d.png" "$tmp/order/lsystem_tree3d.png"
preview "$tree" -o "$tmp/level" --field level
check "--field level: another picture" pixels differ "$tmp/up/lsystem_tree3d.png" "$tmp/level/lsystem_tree3d.png"
preview "$tree" -o "$tmp/bad" --field nosuch
check "--field nosuch: exit 1" test "$code" = 1
check "--field nosuch: one line" test "$(wc -l <"$tmp/err")" = 1
check "--field nosuch: names the file and its fields ($(head -1 "$tmp/err"))" grep -q \
  "^selfsim preview: cannot preview '$tree': --field: no field named 'nosuch'; it holds .*branch_order.*width" "$tmp/err"
check "--field nosuch: no PNG" test ! -e "$tmp/bad/lsystem_tree3d.png"
run_selfsim preview "$tree" --field
check "--field without a name: usage exit 2" test "$code" = 2
run_selfsim preview "$tree" --up w
check "--up w: usage exit 2" test "$code" = 2
check "--up w: says what it takes" grep -q "^selfsim: --up expects x, y or z, got 'w'" "$tmp/err"

# An SVG's own stroke colours, set on a group and in a style attribute.
cat >"$tmp/two.svg" <<'SVG'
<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100"><g stroke="#ff0000" fill="none"
><path d="M10 10 L90 90"/></g><path style="fill:none; stroke: blue" d="M10 90 L90 10"/></svg>
SVG
preview "$tmp/two.svg" -o "$tmp/svg"
check "svg: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
check "svg: its red stroke" pixels colour "$tmp/svg/two.png" 255 0 0
check "svg: its blue stroke" pixels colour "$tmp/svg/two.png" 0 0 255
preview "$tmp/two.svg" -o "$tmp/svg_bad" --field color
check "svg --field color (3 components): exit 1, one line" test "$code" = 1 -a "$(wc -l <"$tmp/err")" = 1
check "svg --field color: says why" grep -q "'color' has 3 components" "$tmp/err"

# A grammar's colour index (') colours the preview by value, as the SVG it strokes: each stroke colour of the
# SVG is drawn in the .vtp's preview (indices 2, 3, 4: by rank they would take the first three colours).
cat >"$tmp/index.lua" <<'LUA'
local c = lsystem { axiom = "'(2)X", rules = { X = "F[+'X][-'X]FX", F = "FF" }, angle = 25 }:curve(3)
save(c, "index.vtp"); save(c, "index.svg")
LUA
"$selfsim" run "$tmp/index.lua" -o "$tmp/index" -q 2>"$tmp/run_err"
preview "$tmp/index/index.vtp" -o "$tmp/index_png"
check "colour index: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
strokes=$(grep -o 'stroke="#[0-9a-f]*"' "$tmp/index/index.svg" | sort -u | sed 's/stroke="#\(..\)\(..\)\(..\)"/\1 \2 \3/')
check "colour index: the SVG has three stroke colours" test "$(echo "$strokes" | wc -l)" = 3
while read -r r g b; do
  check "colour index: #$r$g$b in the preview" pixels colour "$tmp/index_png/index.png" $((16#$r)) $((16#$g)) $((16#$b))
done <<<"$strokes"

# A growing 3D series: step 2 holds step 1 and a branch; `age` grows only in step 2. Written by hand so
# that step 1's geometry is exactly inside step 2's.
vtp() {  # vtp FILE POINTS AGES CONNECTIVITY OFFSETS NPOINTS NLINES
  cat >"$1" <<XML
<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
<PolyData><Piece NumberOfPoints="$6" NumberOfVerts="0" NumberOfLines="$7" NumberOfStrips="0" NumberOfPolys="0">
<PointData><DataArray type="Float64" Name="age" format="ascii">$3</DataArray></PointData>
<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">$2</DataArray></Points>
<Lines><DataArray type="Int64" Name="connectivity" format="ascii">$4</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">$5</DataArray></Lines>
</Piece></PolyData></VTKFile>
XML
}
mkdir -p "$tmp/g/growth"
vtp "$tmp/g/growth/s1.vtp" "0 0 0  0 1 0.3  0.2 1.5 0.5" "0 0 0" "0 1 2" "3" 3 1
vtp "$tmp/g/growth/s2.vtp" "0 0 0  0 1 0.3  0.2 1.5 0.5  0 1 0.3  1 2 1" "0 0 0 1 2" "0 1 2 3 4" "3 5" 5 2
cat >"$tmp/g/growth.pvd" <<'PVD'
<?xml version="1.0"?>
<VTKFile type="Collection" version="0.1"><Collection>
<DataSet timestep="1" file="growth/s1.vtp"/><DataSet timestep="2" file="growth/s2.vtp"/>
</Collection></VTKFile>
PVD
preview "$tmp/g/growth.pvd" --steps -o "$tmp/steps"
check "series --steps: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
check "series --steps: three lines" test "$(grep -c '^wrote ' "$tmp/out")" = 3
check "series --steps: the filmstrip" grep -q "^wrote $tmp/steps/growth.steps.png (.*, 2 steps)" "$tmp/out"
check "series --steps: the animation" grep -q "^wrote $tmp/steps/growth.apng (1200x600, 2 frames)" "$tmp/out"
check "series --steps: the still" grep -q "^wrote $tmp/steps/growth.png (1200x600, the last of 2 steps)" "$tmp/out"
frames=$(pixels frames "$tmp/steps/growth.apng" "$tmp/frames")
check "APNG: valid, acTL says 2 frames ($frames)" test "$frames" = 2
check "steps share one camera and one legend" pixels same_camera "$tmp/frames/frame_0.png" "$tmp/frames/frame_1.png"
check "the still is the last step in the series' camera" pixels same_views "$tmp/steps/growth.png" \
  "$tmp/frames/frame_1.png"
preview "$tmp/g/growth.pvd" -o "$tmp/plain"
check "series without --steps: the still alone" test "$(grep -c '^wrote ' "$tmp/out")" = 1 -a \
  ! -e "$tmp/plain/growth.apng" -a ! -e "$tmp/plain/growth.steps.png"
# (--steps smooths its dozen pictures by FXAA, the still alone by 8 samples a pixel: the same drawing, not
# the same bytes.)
check "series without --steps: the same camera" pixels same_camera "$tmp/plain/growth.png" "$tmp/steps/growth.png" \
  drawing
# A frame is titled with the file's name alone ("growth.pvd"), its caption saying the step: the still's title,
# "growth.pvd (last of 2 steps)", on every frame contradicted all but the last.
check "a frame's title is the name alone" pixels title_shorter "$tmp/frames/frame_0.png" "$tmp/plain/growth.png"
# --steps among other files: the series get their filmstrip and animation, a single file its PNG alone.
preview "$tmp/g/growth/s1.vtp" "$tmp/g/growth.pvd" --steps -o "$tmp/mixed"
check "--steps with a single file: its PNG alone" test -e "$tmp/mixed/s1.png" -a ! -e "$tmp/mixed/s1.apng" -a \
  ! -e "$tmp/mixed/s1.steps.png"
check "--steps with a single file: the series' three" test -e "$tmp/mixed/growth.apng" -a -e "$tmp/mixed/growth.steps.png"

# Each step alone is fitted to itself: step 1 is then not where step 2 draws it (what --steps avoids).
preview "$tmp/g/growth/s1.vtp" -o "$tmp/alone"
check "a step alone has a camera of its own" fails pixels same_camera "$tmp/alone/s1.png" "$tmp/frames/frame_1.png"
# A step without the field the others are coloured by is still drawn (in the plain colour), in place.
sed 's|<PointData>.*</PointData>||' "$tmp/g/growth/s1.vtp" >"$tmp/g/growth/bare.vtp"
sed 's/s1.vtp/bare.vtp/' "$tmp/g/growth.pvd" >"$tmp/g/bare.pvd"
preview "$tmp/g/bare.pvd" --steps -o "$tmp/bare"
check "a step without the field: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
pixels frames "$tmp/bare/bare.apng" "$tmp/bare_frames" >/dev/null
check "a step without the field: drawn, in place" pixels same_camera "$tmp/bare_frames/frame_0.png" \
  "$tmp/bare_frames/frame_1.png"

# A series whose step is missing: one line naming it, nothing written.
sed 's/s1.vtp/gone.vtp/' "$tmp/g/growth.pvd" >"$tmp/g/broken.pvd"
preview "$tmp/g/broken.pvd" --steps -o "$tmp/broken"
check "missing step: exit 1, one line ($(head -1 "$tmp/err"))" test "$code" = 1 -a "$(wc -l <"$tmp/err")" = 1
check "missing step: names it" grep -q "cannot read '$tmp/g/growth/gone.vtp'" "$tmp/err"
check "missing step: nothing written" test ! -e "$tmp/broken"
# A folder in the way of the animation (or the still): one line, and none of the three written (the
# filmstrip was written before the animation's name was found taken).
mkdir -p "$tmp/taken/growth.apng"
preview "$tmp/g/growth.pvd" --steps -o "$tmp/taken"
check "a folder named growth.apng: exit 1, one line ($(head -1 "$tmp/err"))" test "$code" = 1 -a \
  "$(wc -l <"$tmp/err")" = 1
check "a folder named growth.apng: says so" grep -q "cannot write '$tmp/taken/growth.apng': a folder" "$tmp/err"
check "a folder named growth.apng: no filmstrip, no still" test ! -e "$tmp/taken/growth.steps.png" -a \
  ! -e "$tmp/taken/growth.png"

# A long series: the filmstrip shows 48 of its 60 steps (10 columns of 300 px; all 60 would take 11), the
# animation every step. (Thousands of cells made a picture wider than OpenGL draws.)
{
  echo '<?xml version="1.0"?><VTKFile type="Collection" version="0.1"><Collection>'
  for t in $(seq 1 60); do echo "<DataSet timestep=\"$t\" file=\"growth/s$((t % 2 + 1)).vtp\"/>"; done
  echo '</Collection></VTKFile>'
} >"$tmp/g/long.pvd"
preview "$tmp/g/long.pvd" --steps -o "$tmp/long"
check "60 steps: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
check "60 steps: a filmstrip of 48 cells ($(grep steps.png "$tmp/out"))" grep -q \
  "^wrote $tmp/long/long.steps.png (3000x[0-9]*, 60 steps)" "$tmp/out"
check "60 steps: an animation of 60 frames" grep -q "^wrote $tmp/long/long.apng (1200x600, 60 frames)" "$tmp/out"
# Any size draws: a drawing thousands of units across, flat or 3D, and one a millionth of a unit (the views were
# placed before they had anything to draw, so VTK kept its default clipping range, 0.1 to 1000, and a drawing a
# few hundred units across came out blank).
cat >"$tmp/sizes.lua" <<'LUA'
local curves = require "selfsim.curves"
save(curves.dragon():curve(6):transform { scale = 5000 }, "flat_big.vtp")
save(curves.dragon():curve(6):transform { scale = 1e-6 }, "flat_tiny.vtp")
save(volume.sphere { center = { 0, 0, 0 }, radius = 400 }, "ball_big.vtp")
save(volume.sphere { center = { 1e4, 0, 0 }, radius = 1e-3 }, "ball_far_tiny.vtp")
LUA
"$selfsim" run "$tmp/sizes.lua" -o "$tmp/sizes" -q 2>"$tmp/run_err"
for f in flat_big flat_tiny ball_big ball_far_tiny; do
  preview "$tmp/sizes/$f.vtp" -o "$tmp/sizes_png"
  check "$f: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
  check "$f: drawn, not blank" pixels drawing "$tmp/sizes_png/$f.png" 0.01
done
# One run's names never overwrite each other: growth.steps.vtp's PNG would be growth.pvd's filmstrip, in
# either order (the later file's took the name, silently: four wrote lines, three files).
cp "$tmp/g/growth/s1.vtp" "$tmp/g/growth.steps.vtp"
for order in "growth.pvd growth.steps.vtp" "growth.steps.vtp growth.pvd"; do
  rm -rf "$tmp/names"
  # shellcheck disable=SC2086
  preview $(printf "$tmp/g/%s " $order) --steps -o "$tmp/names"
  check "$order: exit 0 ($(head -1 "$tmp/err"))" test "$code" = 0
  check "$order: four files for four wrote lines" test "$(find "$tmp/names" -type f | wc -l)" = 4 -a \
    "$(grep -c '^wrote ' "$tmp/out")" = 4
done
# A drawing wider than a 32-bit float holds: one line saying so, no PNG (it was a blank picture and exit 0).
vtp "$tmp/g/huge.vtp" "0 0 0  0 1e200 0.3  0.2 1.5 1e200" "0 0 0" "0 1 2" "3" 3 1
preview "$tmp/g/huge.vtp" -o "$tmp/huge"
check "1e200 across: exit 1, one line ($(head -1 "$tmp/err"))" test "$code" = 1 -a "$(wc -l <"$tmp/err")" = 1
check "1e200 across: says why" grep -q "too large to draw (an extent of 1e+200; the renderer draws in 32-bit" "$tmp/err"
check "1e200 across: no PNG" test ! -e "$tmp/huge/huge.png"
finish
