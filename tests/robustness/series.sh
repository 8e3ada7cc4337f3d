#!/usr/bin/env bash
# ParaView time series (kernels/io/view/series_file.h) and the run's view.py (kernels/io/view/paraview_view.h), read
# back the way ParaView reads them: the .pvd names exactly its steps with their times, the .vtp.series
# likewise, VTK's own reader reads each step with the points the recipe's level had; a series written again
# into the same folder names only its new steps and removes its old extra ones, leaving other files alone;
# the series file is written after its steps; bad times and names fail in one line writing nothing; a steps
# folder that is a link out of the output folder is refused; view.py names every dataset as it should.
# usage: series.sh SELFSIM SOURCE_DIR
selfsim=$1 src=$2
source "$(dirname "$0")/lib.sh"
py=/usr/bin/python3
cd "$tmp" || exit 1

# The recipe: a dragon's levels as .pvd and .vtp.series, a plain list with its own times both ways, and
# each level's point count printed ("points K N") to compare with what VTK reads.
cat >growth.lua <<'EOF'
local curves = require "selfsim.curves"
local n = param("levels", 5)
local c = curves.dragon():curve { level = n }
for k, v in ipairs(c:levels()) do print("points " .. (k - 1) .. " " .. v:points()) end
save(c:levels(), "growth.pvd")
save(c, "growth2.vtp.series")
local l0, l1 = c:level(0), c:level(1)
print("morph " .. l0:points() .. " " .. l1:points() .. " " .. c:points())
save({ l0, l1, c, times = { 0, 0.25, 1.5 } }, "morph.pvd")
save({ l0, l1, c, times = { -1, 0.125, 1e3 } }, "morph2.vtp.series")
EOF

# check.py OUT NAME TIMES COUNTS: the series file OUT/NAME names exactly stem/stem_NNN.vtp for each time in
# TIMES (comma-separated), in order, each there and (with VTK's Python) read with the point count in
# COUNTS; the series file is newer than every step; no other step-named file is left in the steps folder
# (a link is left alone, never followed).
cat >check.py <<'EOF'
import json, os, re, sys, xml.etree.ElementTree as ET
out, name, times, counts = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4]
times = [float(t) for t in times.split(",")]
counts = [int(c) for c in counts.split(",")]
path = os.path.join(out, name)
stem = name[:-4] if name.endswith(".pvd") else name[:-len(".vtp.series")]
if name.endswith(".pvd"):
    root = ET.parse(path).getroot()
    assert root.tag == "VTKFile" and root.get("type") == "Collection", root.attrib
    sets = root.findall("./Collection/DataSet")
    steps = [(float(d.get("timestep")), d.get("file")) for d in sets]
else:
    doc = json.load(open(path))
    assert doc["file-series-version"] == "1.0", doc
    steps = [(float(f["time"]), f["name"]) for f in doc["files"]]
assert len(steps) == len(times), f"{name}: {len(steps)} steps, expected {len(times)}"
assert [t for t, _ in steps] == times, f"{name}: times {[t for t, _ in steps]}, expected {times}"
width = max(3, len(str(len(times) - 1)))
for i, (_, f) in enumerate(steps):
    want = f"{stem}/{stem}_{i:0{width}d}.vtp"
    assert f == want, f"{name}: step {i} is {f}, expected {want}"
    assert os.path.isfile(os.path.join(out, f)), f"{name}: step {f} missing"
series_time = os.stat(path).st_mtime_ns
for _, f in steps:
    assert os.stat(os.path.join(out, f)).st_mtime_ns <= series_time, f"{name}: {f} written after the series"
named = {os.path.basename(f) for _, f in steps}
for leaf in os.listdir(os.path.join(out, stem)):
    if re.fullmatch(re.escape(stem) + r"_[0-9]+\.vtp", leaf) and not os.path.islink(os.path.join(out, stem, leaf)):
        assert leaf in named, f"{name}: stale step {stem}/{leaf} left"
try:
    import vtkmodules.all as vtk
except ImportError:
    print("vtk: skipped (no vtkmodules)")
    sys.exit(0)
vtk.vtkObject.GlobalWarningDisplayOff()
for (_, f), n in zip(steps, counts):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(os.path.join(out, f))
    r.Update()
    got = r.GetOutput().GetNumberOfPoints()
    assert got == n, f"{name}: VTK reads {got} points in {f}, the recipe's level has {n}"
print("vtk: read")
EOF
# series_ok DESCRIPTION OUT NAME TIMES COUNTS
series_ok() {
  local what=$1
  shift
  if ! $py check.py "$@" >"$tmp/py" 2>&1; then
    echo "  $(tail -1 "$tmp/py")"
    check "$what" false
  else
    check "$what" true
    grep -q "vtk: skipped" "$tmp/py" && echo "note: $what: VTK's reader not tried (no vtkmodules for $py)"
  fi
  return 0
}
# counts from the recipe's own print: "points K N" lines, comma-separated, and the morph line
counts() { sed -n 's/^points [0-9]* //p' "$tmp/out" | paste -sd, -; }
morph_counts() { sed -n 's/^morph //p' "$tmp/out" | tr ' ' ,; }

# --- A 6-step series, both forms.
run_selfsim run growth.lua -o series_out
check "first run exits 0 ($(first_err))" [ "$code" = 0 ]
six=$(counts)
check "the recipe printed 6 levels ($six)" [ "$(echo "$six" | tr ',' '\n' | wc -l)" = 6 ]
check "the levels grow (2,3,5,9,17,33: $six)" [ "$six" = "2,3,5,9,17,33" ]
series_ok ".pvd: 6 steps, times 0..5, files there, read by VTK" series_out growth.pvd 0,1,2,3,4,5 "$six"
series_ok ".vtp.series: 6 steps, times 0..5, files there, read by VTK" series_out growth2.vtp.series 0,1,2,3,4,5 "$six"
series_ok ".pvd with times = {...}" series_out morph.pvd 0,0.25,1.5 "$(morph_counts)"
series_ok ".vtp.series with times = {...}" series_out morph2.vtp.series -1,0.125,1000 "$(morph_counts)"
check "times written as given in the .pvd" grep -q 'timestep="0.25"' series_out/morph.pvd
check "times written as given in the .series" grep -q '"time" : 0.125' series_out/morph2.vtp.series
check "view.py written" [ -f series_out/view.py ]

# --- Again with fewer levels into the same folder: only the new steps; the old extra ones gone, files of
# the user's (not stem_DIGITS.vtp) left alone.
echo notes >series_out/growth/notes.txt
echo mine >series_out/growth/growth_final.vtp
echo mine >series_out/growth/growth_5.txt
echo mine >series_out/growth/growth2_003.vtp  # the other series' name, in this series' folder
mkdir -p outside
echo victim >outside/victim.vtp
ln -s "$tmp/outside/victim.vtp" series_out/growth2/growth2_009.vtp  # a stale step name that is a link out
run_selfsim run growth.lua -o series_out --set levels=2
check "second run exits 0 ($(first_err))" [ "$code" = 0 ]
three=$(counts)
check "the recipe printed 3 levels ($three)" [ "$three" = "2,3,5" ]
series_ok ".pvd rewritten with 3 steps" series_out growth.pvd 0,1,2 "$three"
series_ok ".vtp.series rewritten with 3 steps" series_out growth2.vtp.series 0,1,2 "$three"
for k in 3 4 5; do
  check "stale growth/growth_00$k.vtp removed" [ ! -e series_out/growth/growth_00$k.vtp ]
  check "stale growth2/growth2_00$k.vtp removed" [ ! -e series_out/growth2/growth2_00$k.vtp ]
done
check "growth/notes.txt kept" [ "$(cat series_out/growth/notes.txt 2>/dev/null)" = notes ]
check "growth/growth_final.vtp kept" [ "$(cat series_out/growth/growth_final.vtp 2>/dev/null)" = mine ]
check "growth/growth_5.txt kept" [ -f series_out/growth/growth_5.txt ]
check "growth/growth2_003.vtp (another series' name) kept" [ -f series_out/growth/growth2_003.vtp ]
check "a stale step that is a link out: its target untouched" [ "$(cat outside/victim.vtp)" = victim ]
check "morph.pvd rewritten the same" grep -q 'timestep="1.5"' series_out/morph.pvd

# --- The series file is written after its steps: a run killed while writing big steps leaves a series
# file that names only steps that are there (the old one, or the new one whole), and no partial files.
run_selfsim run growth.lua -o kill --set levels=5
"$selfsim" run growth.lua -o kill -q --set levels=22 >/dev/null 2>"$tmp/kill_err" &
pid=$!
for _ in $(seq 1 2000); do
  [ -e kill/growth/growth_019.vtp ] && break
  kill -0 "$pid" 2>/dev/null || break
  sleep 0.005
done
kill -TERM "$pid" 2>/dev/null
wait "$pid"
kill_code=$?
check "killed run: exit 130 or finished (exit $kill_code)" [ "$kill_code" = 130 -o "$kill_code" = 0 ]
$py - kill <<'EOF' >"$tmp/py" 2>&1
import os, sys, xml.etree.ElementTree as ET, json
out = sys.argv[1]
for name in ("growth.pvd", "growth2.vtp.series"):
    p = os.path.join(out, name)
    if not os.path.exists(p):
        continue
    if name.endswith(".pvd"):
        files = [d.get("file") for d in ET.parse(p).getroot().findall("./Collection/DataSet")]
    else:
        files = [f["name"] for f in json.load(open(p))["files"]]
    assert len(files) in (6, 23), f"{name} names {len(files)} steps"
    for f in files:
        assert os.path.isfile(os.path.join(out, f)), f"{name} names {f}, which is not there"
for d, _, leaves in os.walk(out):
    for leaf in leaves:
        assert leaf.endswith((".vtp", ".pvd", ".series", ".py")), f"partial file {os.path.join(d, leaf)}"
EOF
check "killed run: every series file names only steps that are there ($(tail -1 "$tmp/py"))" [ $? = 0 ]
check "killed run: growth.pvd still there" [ -f kill/growth.pvd ]

# --- One-line errors, exit 1, nothing written.
bad() {  # bad DESCRIPTION PATTERN LUA
  local what=$1 pattern=$2
  printf '%s\n' "$3" >bad.lua
  rm -rf bad_out
  run_selfsim run bad.lua -o bad_out
  check "$what: exit 1 (got $code)" [ "$code" = 1 ]
  check "$what: one line on stderr ($(wc -l <"$tmp/err") lines)" [ "$(wc -l <"$tmp/err")" = 1 ]
  check "$what: message ($(first_err))" grep -q "^bad.lua:2: save: $pattern" "$tmp/err"
  check "$what: nothing written" [ -z "$(find bad_out -type f 2>/dev/null)" ]
}
bad "times decreasing" "the times of a series must increase: step 3 has 1 after 2" 'local a = polyline { { 0, 0 }, { 1, 0 } }
save({ a, a, a, times = { 0, 2, 1 } }, "t.pvd")'
bad "times repeated" "the times of a series must increase: step 2 has 1 after 1" 'local a = polyline { { 0, 0 }, { 1, 0 } }
save({ a, a, times = { 1, 1 } }, "t.vtp.series")'
bad "a NaN time" "entry 2 of 'times' must be a finite number" 'local a = polyline { { 0, 0 }, { 1, 0 } }
save({ a, a, times = { 0, 0/0 } }, "t.pvd")'
bad "a bare .series" "'x.series': ParaView picks a .series file's reader" 'local a = polyline { { 0, 0 }, { 1, 0 } }
save({ a, a }, "x.series")'
bad "a .svg.series" "'x.svg.series': ParaView picks" 'local a = polyline { { 0, 0 }, { 1, 0 } }
save({ a, a }, "x.svg.series")'

# --- A steps folder that is a link out of the output folder: refused, nothing written there.
rm -rf outside && mkdir -p outside link_out
ln -s "$tmp/outside" link_out/growth
run_selfsim run growth.lua -o link_out --set levels=2
check "steps folder linked out: exit 1 (got $code)" [ "$code" = 1 ]
check "steps folder linked out: message ($(first_err))" grep -q "growth.pvd'.*symbolic link" "$tmp/err"
check "steps folder linked out: nothing written outside ($(ls -A outside))" [ -z "$(ls -A outside)" ]
check "steps folder linked out: no series file" [ ! -e link_out/growth.pvd ]
# A series file that is a link out: replaced by the file, its target untouched.
rm -rf link_file && mkdir -p link_file && echo victim >outside/victim.pvd
ln -s "$tmp/outside/victim.pvd" link_file/growth.pvd
run_selfsim run growth.lua -o link_file --set levels=2
check "series file linked out: target untouched" [ "$(cat outside/victim.pvd)" = victim ]
check "series file linked out: nothing else written outside ($(ls -A outside))" [ "$(ls -A outside)" = victim.pvd ]

# --- view.py: every dataset named, a develop mesh's tile_class categorical, a volume a region, a series a
# series.
cat >view.lua <<'EOF'
local curves = require "selfsim.curves"
local d = develop(curves.dragon(), { levels = 5, smooth = 2, corner_shift = 0.1, stencil = "bounded" })
save(d, "dragon.vtp")
save(d, "dragon.stl")  -- not VTK: not in the view
save(volume.sphere { center = { 0, 0, 0 }, radius = 1 }, "region.vtp")
local c = curves.dragon():curve { level = 4 }
save(c, "growth.pvd")
save(c, "curve.vtu")
save(c, "sub/curve.vtp")
save(c:levels(), "grow2.vtp.series")
EOF
cat >view.py <<'EOF'
import ast, sys
text = open(sys.argv[1]).read()
start = text.index("SELFSIM_VIEW = ") + len("SELFSIM_VIEW = ")
lines = text[start:].split("\n")
end = next(i for i, l in enumerate(lines) if l == "}")
view = ast.literal_eval("\n".join(lines[: end + 1]))
by_file = {d["file"]: d for d in view["datasets"]}
want = {"dragon.vtp", "region.vtp", "growth.pvd", "curve.vtu", "sub/curve.vtp", "grow2.vtp.series"}
assert set(by_file) == want, f"datasets {sorted(by_file)}, expected {sorted(want)}"
assert len(view["datasets"]) == len(want), "a dataset named twice"
d = by_file["dragon.vtp"]
assert d["field"] == "tile_class" and d["categorical"] is True and d["role"] == "surface", d
assert d["association"] == "CELLS" and d["categories"] == list(range(31)), d
assert by_file["region.vtp"]["role"] == "region", by_file["region.vtp"]
for f in ("growth.pvd", "grow2.vtp.series"):
    assert by_file[f]["series"] is True and by_file[f]["role"] == "curve", by_file[f]
for f in ("dragon.vtp", "region.vtp", "curve.vtu", "sub/curve.vtp"):
    assert by_file[f]["series"] is False, by_file[f]
assert by_file["growth.pvd"]["name"] == "growth" and by_file["sub/curve.vtp"]["name"] == "curve"
assert view["dimension"] == 3, view["dimension"]
EOF
run_selfsim run view.lua -o view_out
check "view recipe exits 0 ($(first_err))" [ "$code" = 0 ]
$py view.py view_out/view.py >"$tmp/py" 2>&1
check "view.py names every dataset as it should ($(tail -1 "$tmp/py"))" [ $? = 0 ]
run_selfsim run view.lua -o no_view --no-view
check "--no-view: exit 0" [ "$code" = 0 ]
check "--no-view: no view.py" [ ! -e no_view/view.py ]
check "--no-view: the files still written" [ -f no_view/growth.pvd ]
# A failing recipe (error after a save) leaves the previous view.py as it was.
cp view_out/view.py view_before.py
before=$(stat -c %Y.%y view_out/view.py)
cat >fail.lua <<'EOF'
save(polyline { { 0, 0 }, { 1, 0 } }, "other.vtp")
error("stop here")
EOF
run_selfsim run fail.lua -o view_out
check "failing recipe: exit 1" [ "$code" = 1 ]
check "failing recipe: its file was written" [ -f view_out/other.vtp ]
check "failing recipe: view.py unchanged" cmp -s view_out/view.py view_before.py
check "failing recipe: view.py not rewritten" [ "$(stat -c %Y.%y view_out/view.py)" = "$before" ]
# A run without VTK outputs writes no view.py.
printf 'save(polyline { { 0, 0 }, { 1, 0 } }, "a.svg")\n' >svg.lua
run_selfsim run svg.lua -o svg_out
check "no VTK output: no view.py" [ "$code" = 0 -a ! -e svg_out/view.py ]

finish
