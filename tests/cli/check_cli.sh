#!/usr/bin/env bash
# The command line's contract: exit codes 0 / 1 / 2, help and version, diff and info on real files.
# usage: check_cli.sh SELFSIM SOURCE_DIR
set -uo pipefail
selfsim=$1 src=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
expect() {  # expect CODE DESCRIPTION -- COMMAND...
  local want=$1 what=$2
  shift 3
  "$@" >"$tmp/out" 2>"$tmp/err"
  local got=$?
  if [ "$got" != "$want" ]; then
    echo "FAIL: $what: exit $got, expected $want"; cat "$tmp/err"; failures=$((failures + 1))
  fi
}
contains() {  # contains FILE TEXT DESCRIPTION
  if ! grep -qF -- "$2" "$1"; then echo "FAIL: $3: no '$2' in $(head -c 300 "$1")"; failures=$((failures + 1)); fi
}

expect 0 "help" -- "$selfsim" --help
contains "$tmp/out" "selfsim run RECIPE.lua" "help lists run"
expect 0 "version" -- "$selfsim" --version
contains "$tmp/out" "selfsim 0." "version"
expect 2 "no command" -- "$selfsim"
expect 2 "unknown command" -- "$selfsim" frobnicate
contains "$tmp/err" "unknown command 'frobnicate'" "unknown command message"
expect 2 "missing recipe" -- "$selfsim" run "$tmp/nope.lua"
contains "$tmp/err" "cannot open recipe" "missing recipe message"
# A FIFO as the recipe is refused in one line that says so, never waited on (opening it would wait for a writer).
mkfifo "$tmp/fifo.lua"
for command in run params; do
  expect 2 "$command on a FIFO recipe" -- timeout 60 "$selfsim" "$command" "$tmp/fifo.lua"
  contains "$tmp/err" "selfsim: cannot open recipe '$tmp/fifo.lua': is a FIFO, not a regular file" "$command on a FIFO"
  [ "$(wc -l <"$tmp/err")" = 1 ] || { echo "FAIL: $command on a FIFO: not one line"; failures=$((failures + 1)); }
done
expect 2 "bad --max-points" -- "$selfsim" run "$src/examples/plant.lua" --max-points lots
# A recipe without `run`, or without its `.lua`: the command meant (issue 21).
mkdir -p "$tmp/meant" && printf 'print("ran")\n' >"$tmp/meant/dragon.lua"
expect 2 "recipe without run" -- bash -c 'cd "$1" && "$2" dragon.lua' _ "$tmp/meant" "$selfsim"
contains "$tmp/err" "selfsim: unknown command 'dragon.lua'; to run a recipe: selfsim run dragon.lua" "recipe without run"
expect 2 "recipe without run, with flags" -- bash -c 'cd "$1" && "$2" dragon.lua --set "name=a b" -q' _ "$tmp/meant" "$selfsim"
contains "$tmp/err" "to run a recipe: selfsim run dragon.lua --set 'name=a b' -q" "recipe without run keeps the flags"
expect 2 "recipe name without .lua" -- bash -c 'cd "$1" && "$2" run dragon -q' _ "$tmp/meant" "$selfsim"
contains "$tmp/err" "selfsim: cannot open recipe 'dragon': no such file; to run dragon.lua: selfsim run dragon.lua -q" \
  "recipe name without .lua"
[ -e "$tmp/meant/out" ] && { echo "FAIL: a usage error made an output folder"; failures=$((failures + 1)); }

# A developing surface thickened beyond the gaps between its parts only warns, naming where.
printf 'local curves = require "selfsim.curves"\ndevelop(curves.dragon(), { levels = 7, smooth = 2, corner_shift = 0.1, thickness = 0.6 })\n' >"$tmp/thick.lua"
expect 0 "too thick a solid only warns" -- "$selfsim" run "$tmp/thick.lua" -o "$tmp/thick"
contains "$tmp/err" "develop: the thickened solid meets itself (triangle 226 (level 2, tile 4) meets triangle 242" "thickness warning"
printf 'local curves = require "selfsim.curves"\ndevelop(curves.dragon(), { levels = 7, smooth = 2, corner_shift = 0.1, thickness = 0.2 })\n' >"$tmp/thin.lua"
expect 0 "a thin solid" -- "$selfsim" run "$tmp/thin.lua" -o "$tmp/thin"
grep -v "saved nothing" "$tmp/err" | grep -q . && { echo "FAIL: a thin solid warned: $(cat "$tmp/err")"; failures=$((failures + 1)); }

# A real run, then info and diff on what it wrote.
expect 0 "run plant" -- "$selfsim" run "$src/examples/plant.lua" -o "$tmp/a" --set level=2
contains "$tmp/out" "wrote $tmp/a/plant.vtp (26 points)" "run reports its files"
expect 0 "run plant again" -- "$selfsim" run "$src/examples/plant.lua" -o "$tmp/b" --set level=2 -q
[ -s "$tmp/out" ] && { echo "FAIL: -q printed $(cat "$tmp/out")"; failures=$((failures + 1)); }
expect 0 "run plant level 3" -- "$selfsim" run "$src/examples/plant.lua" -o "$tmp/c" --set level=3 -q
expect 0 "unused --set only warns" -- "$selfsim" run "$src/examples/plant.lua" -o "$tmp/d" --set level=1 --set levl=3 -q
contains "$tmp/err" "--set levl=3 was not read" "unused --set warning"
contains "$tmp/err" "(did you mean 'level'?)" "unused --set suggests the param read"
# A run that saves nothing says so on exit, once, on stderr, and still exits 0 (a recipe may only print); a
# run that saves, or gives a result(), does not; nor does `params`, nor a failed run (its error is the line).
mkdir -p "$tmp/nothing" && printf 'local n = param("n", 2)\nprint(n)\n' >"$tmp/nothing/r.lua"
expect 0 "a run that saves nothing" -- bash -c 'cd "$1" && "$2" run r.lua -o out -q' _ "$tmp/nothing" "$selfsim"
[ "$(cat "$tmp/err")" = 'selfsim: warning: r.lua saved nothing (call save(value, "name.ext") to write a file)' ] ||
  { echo "FAIL: saved nothing: stderr was '$(cat "$tmp/err")'"; failures=$((failures + 1)); }
expect 0 "params of a recipe that saves nothing" -- "$selfsim" params "$tmp/nothing/r.lua"
[ -s "$tmp/err" ] && { echo "FAIL: params warned: $(cat "$tmp/err")"; failures=$((failures + 1)); }
printf 'result("n", 2)\n' >"$tmp/nothing/res.lua"
expect 0 "a run with only a result" -- "$selfsim" run "$tmp/nothing/res.lua" -o "$tmp/nothing/res" -q
[ -s "$tmp/err" ] && { echo "FAIL: a run with a result warned: $(cat "$tmp/err")"; failures=$((failures + 1)); }
expect 0 "a run that saves" -- "$selfsim" run "$src/examples/plant.lua" -o "$tmp/saves" --set level=1 -q
[ -s "$tmp/err" ] && { echo "FAIL: a run that saves warned: $(cat "$tmp/err")"; failures=$((failures + 1)); }
printf 'print(1)\nerror("no")\n' >"$tmp/nothing/fails.lua"
expect 1 "a failed run" -- "$selfsim" run "$tmp/nothing/fails.lua" -o "$tmp/nothing/fails" -q
grep -q "saved nothing" "$tmp/err" && { echo "FAIL: a failed run said saved nothing"; failures=$((failures + 1)); }
expect 0 "run --help" -- "$selfsim" run --help
contains "$tmp/out" "selfsim run RECIPE.lua" "run --help prints the help"
expect 2 "misspelt run flag" -- "$selfsim" run "$src/examples/plant.lua" --out "$tmp/x"
contains "$tmp/err" "unknown option '--out' for run (did you mean '--output'?)" "run flag suggestion"
expect 2 "misspelt command" -- "$selfsim" rnu "$src/examples/plant.lua"
contains "$tmp/err" "unknown command 'rnu' (did you mean 'run'?)" "command suggestion"

expect 0 "info" -- "$selfsim" info "$tmp/a/plant.vtp"
contains "$tmp/out" "points: 26" "info points"
contains "$tmp/out" "cells: 8" "info cells"
contains "$tmp/out" "point field: arclength" "info fields"
expect 0 "diff same" -- "$selfsim" diff "$tmp/a/plant.vtp" "$tmp/b/plant.vtp"
expect 0 "diff same svg" -- "$selfsim" diff "$tmp/a/plant.svg" "$tmp/b/plant.svg"
expect 1 "diff different" -- "$selfsim" diff "$tmp/a/plant.vtp" "$tmp/c/plant.vtp"
contains "$tmp/out" "point count differs" "diff message"
expect 2 "diff missing file" -- "$selfsim" diff "$tmp/a/plant.vtp" "$tmp/none.vtp"
expect 2 "diff bad tolerance" -- "$selfsim" diff "$tmp/a/plant.vtp" "$tmp/b/plant.vtp" --tol x

# Files are reported as they are written: a later error does not hide the ones already there.
printf '%s\n' 'save(polyline { { 0, 0 }, { 1, 0 } }, "a.svg")' 'print("between")' 'error("late")' >"$tmp/late.lua"
expect 1 "error after a save" -- "$selfsim" run "$tmp/late.lua" -o "$tmp/late"
contains "$tmp/out" "wrote $tmp/late/a.svg (2 points)" "the file written before the error is reported"
contains "$tmp/out" "between" "print output too"

# A second save to a written name fails and leaves the first file as it was (issue 21).
printf '%s\n' 'save(polyline { { 0, 0 }, { 1, 0 } }, "a.vtp")' 'save(polyline { { 0, 0 }, { 1, 0 }, { 2, 1 } }, "./a.vtp")' >"$tmp/twice.lua"
expect 1 "saving one name twice" -- "$selfsim" run "$tmp/twice.lua" -o "$tmp/twice" -q
contains "$tmp/err" "twice.lua:2: save: './a.vtp' was already written by line 1 of this run" "saving one name twice"
expect 0 "the first file stays" -- "$selfsim" info "$tmp/twice/a.vtp"
contains "$tmp/out" "points: 2" "the first file stays"
[ "$(ls -A "$tmp/twice")" = "a.vtp" ] || { echo "FAIL: saving twice left $(ls -A "$tmp/twice")"; failures=$((failures + 1)); }

# Warnings and numbers: ABOP's 3D symbols draw a 3D curve, or are named once when dimension = 2 forces the
# 2D turtle; a default written with a point takes any number, a whole default only whole numbers.
cat >"$tmp/abop.lua" <<'LUA'
local g = lsystem { axiom = "A", rules = { A = "F[&FA]/////[&FA]" }, angle = 22.5 }
local flat = lsystem { axiom = "A", rules = { A = "F[&FA]/////[&FA]" }, angle = 22.5, dimension = 2 }
print(g:curve(2), flat:curve(2):paths(), param("angle", 60.0), param("count", 60))
LUA
expect 0 "3D symbols only warn" -- "$selfsim" run "$tmp/abop.lua" -o "$tmp/abop" --set angle=22.5
contains "$tmp/out" "Curve3(" "3D symbols draw a Curve3"
contains "$tmp/err" "the 2D turtle ignores the 3D turtle commands '&', '/'" "3D symbols warning"
contains "$tmp/out" "22.5" "a number default takes 22.5"
expect 1 "a whole default refuses 22.5" -- "$selfsim" run "$tmp/abop.lua" -o "$tmp/abop" --set count=22.5
contains "$tmp/err" "abop.lua:3: param: --set count=22.5: 'count' is an integer parameter: expected a whole number such as 60 (a default written 60.0 takes any number)" "a whole default refuses 22.5"

# Meshes: info tells a closed surface from an open one, diff names the first differing cell.
cat >"$tmp/tet.lua" <<'LUA'
local m = mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
                 triangles = { { 1, 3, 2 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 1, 4 } } }
save(m, "tet.stl"); save(m, "tet.vtp")
save(mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } },
            triangles = { { 1, 3, 2 }, { 1, 2, 4 }, { 2, 3, 4 } } }, "open.vtu")
LUA
expect 0 "run mesh recipe" -- "$selfsim" run "$tmp/tet.lua" -o "$tmp/m" -q
expect 0 "info stl" -- "$selfsim" info "$tmp/m/tet.stl"
contains "$tmp/out" "surface: closed manifold, 1 component, 0 boundary loops, Euler characteristic 2" "info closed"
expect 0 "info vtu" -- "$selfsim" info "$tmp/m/open.vtu"
contains "$tmp/out" "surface: manifold with boundary, 1 component, 1 boundary loop, Euler characteristic 1" "info open"
# Two tetrahedra passing through each other: closed and manifold by their connectivity, but the surface
# crosses itself, and info says so (issue 21: it called such a mesh a closed manifold).
cat >"$tmp/fold.lua" <<'LUA'
save(mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
                       { 0.2, 0.2, 0.2 }, { 1.2, 0.2, 0.2 }, { 0.2, 1.2, 0.2 }, { 0.2, 0.2, 1.2 } },
            triangles = { { 1, 3, 2 }, { 1, 2, 4 }, { 2, 3, 4 }, { 3, 1, 4 },
                          { 5, 7, 6 }, { 5, 6, 8 }, { 6, 7, 8 }, { 7, 5, 8 } } }, "fold.stl")
LUA
expect 0 "run fold recipe" -- "$selfsim" run "$tmp/fold.lua" -o "$tmp/m" -q
expect 0 "info fold" -- "$selfsim" info "$tmp/m/fold.stl"
contains "$tmp/out" "surface: closed manifold that crosses itself, 2 components" "info crossing"
contains "$tmp/out" "first crossing: triangles" "info crossing pair"
expect 0 "info stl again" -- "$selfsim" info "$tmp/m/tet.stl"
if grep -q "crossing" "$tmp/out"; then echo "FAIL: info tet names a crossing"; failures=$((failures + 1)); fi
expect 1 "diff meshes" -- "$selfsim" diff "$tmp/m/tet.vtp" "$tmp/m/open.vtu"
contains "$tmp/out" "cell count differs: 4 vs 3" "diff meshes message"

# The print check from the command line (issue 25): a 20 mm cube passes, a 0.3 mm plate does not (exit 1,
# its finding), an open surface is an error (exit 2); .3mf files read back for info and diff. (Not a
# tetrahedron, though the file keeps its name: its sharp tips are thinner than 0.8 mm, which the check
# finds on its 4 triangles too.)
cat >"$tmp/print.lua" <<'LUA'
local cube = solid.size(mesh { points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 }, { 1, 1, 0 }, { 0, 0, 1 }, { 1, 0, 1 },
                                          { 0, 1, 1 }, { 1, 1, 1 } },
                               triangles = { { 1, 3, 4 }, { 1, 4, 2 }, { 5, 6, 8 }, { 5, 8, 7 }, { 1, 2, 6 }, { 1, 6, 5 },
                                             { 3, 7, 8 }, { 3, 8, 4 }, { 1, 5, 7 }, { 1, 7, 3 }, { 2, 4, 8 },
                                             { 2, 8, 6 } } }, 20)
save(cube, "tet.3mf")
save(solid.relief(polygon { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 0, 10 } }, { height = 0.3, check = false }), "plate.stl")
save(polyline { { 0, 0 }, { 10, 0 }, { 10, 10 } }, "curve.vtp")
LUA
expect 0 "run print recipe" -- "$selfsim" run "$tmp/print.lua" -o "$tmp/p" -q
expect 0 "info --print passes" -- "$selfsim" info --print "$tmp/p/tet.3mf"
contains "$tmp/out" "print check (fdm): passes: closed" "print check passes"
expect 1 "info --print thin" -- "$selfsim" info --print "$tmp/p/plate.stl" --profile sla
contains "$tmp/out" "walls thinner than 0.4 mm" "print check thin walls"
contains "$tmp/out" "  - may fail: walls thinner than 0.4 mm" "info --print lists each problem with its severity"
expect 2 "info --print open" -- "$selfsim" info --print "$tmp/m/open.vtu"
contains "$tmp/err" "the mesh is open" "print check open"
expect 1 "info --print, flags after the file" -- "$selfsim" info "$tmp/p/plate.stl" --print --profile sla
contains "$tmp/out" "walls thinner than 0.4 mm" "print check flags after the file"
expect 1 "info --print, profile before the file" -- "$selfsim" info --print --profile sla "$tmp/p/plate.stl"
expect 2 "info two files" -- "$selfsim" info --print "$tmp/p/plate.stl" "$tmp/p/tet.3mf"
contains "$tmp/err" "info --print expects one file (and optionally --profile fdm|sla), got 2" "info two files message"
expect 2 "info --print curve" -- "$selfsim" info --print "$tmp/p/curve.vtp"
contains "$tmp/err" "it holds curves (polylines), not a solid's surface: make a solid of it first" "print check curve"
expect 2 "info --print bad profile" -- "$selfsim" info --print "$tmp/p/tet.3mf" --profile laser
# A grid over the budget: the check says so and names the flags that measure it, which info --print takes
# (the 20 mm cube's grid is 1.5 million points at a 0.15 mm voxel, 0.8 million at 0.2 mm).
expect 1 "info --print over --max-points" -- "$selfsim" info --print "$tmp/p/tet.3mf" --max-points 1e6 --voxel 0.15
contains "$tmp/out" "walls and gaps not measured" "info --print over --max-points: not measured"
contains "$tmp/out" "info --print's --voxel; or a larger --max-points" "info --print over --max-points: the flags"
expect 0 "info --print --voxel" -- "$selfsim" info --print --voxel 0.2 "$tmp/p/tet.3mf" --max-points 1e6
contains "$tmp/out" "passes: closed, 20 x 20 x 20 mm" "info --print --voxel: measured"
expect 0 "info --print --max-points" -- "$selfsim" info --print "$tmp/p/tet.3mf" --max-points 3e6
contains "$tmp/out" "walls >= 1.2 mm" "info --print --max-points: measured"
expect 2 "info --print --voxel too large" -- "$selfsim" info --print "$tmp/p/tet.3mf" --voxel 0.3
contains "$tmp/err" "--voxel expects a size in mm from 0.001 to 0.2 mm (half the fdm profile's least wall or gap), got '0.3'" \
  "info --print --voxel too large: message"
expect 2 "info --voxel without --print" -- "$selfsim" info "$tmp/p/tet.3mf" --voxel 0.2
contains "$tmp/err" "--voxel is for info --print FILE" "info --voxel without --print: message"
expect 2 "info --print --max-points without a value" -- "$selfsim" info --print "$tmp/p/tet.3mf" --max-points
# An unknown flag is named with the flags info --print takes (it read as a second and third file).
expect 2 "info --print unknown flag" -- "$selfsim" info --print "$tmp/p/tet.3mf" --bed 200,200,200
contains "$tmp/err" "unknown option '--bed' for info --print; it takes --profile fdm|sla, --voxel MM, --max-points N, --timeout S" \
  "info --print unknown flag: message"
# Ctrl-C stops info --print as it stops a run: one line, exit 130, no report (it ran on for minutes and printed
# it). A hollow ball of 716,400 triangles checks for seconds; started in the background, the check inherits
# SIGINT ignored, so only its own handler stops it. The signal goes once /proc says the handler is in place.
/usr/bin/python3 - "$tmp/ball.stl" <<'PY'
import math, struct, sys
n = 300  # rings; 2n segments
def p(r, i, j):
    if i == 0 or i == n: return (0.0, 0.0, r if i == 0 else -r)
    t, f = math.pi * i / n, math.pi * (j % (2 * n)) / n
    return (r * math.sin(t) * math.cos(f), r * math.sin(t) * math.sin(f), r * math.cos(t))
tris = []
for r, inward in ((50.0, False), (49.7, True)):
    for i in range(n):
        for j in range(2 * n):
            a, b, c, d = p(r, i, j), p(r, i + 1, j), p(r, i + 1, j + 1), p(r, i, j + 1)
            for t in ((a, b, d) if i > 0 else None, (b, c, d) if i < n - 1 else None):
                if t: tris.append((t[0], t[2], t[1]) if inward else t)
with open(sys.argv[1], 'wb') as f:
    f.write(b'\0' * 80 + struct.pack('<I', len(tris)))
    for t in tris: f.write(struct.pack('<12fH', 0, 0, 0, *t[0], *t[1], *t[2], 0))
PY
"$selfsim" info --print "$tmp/ball.stl" >"$tmp/out" 2>"$tmp/err" &
info_pid=$!
# Until the exec: the shell's child before it has a SIGINT handler of its own, which would take the signal.
selfsim_exe=$(readlink -f "$selfsim")
for _ in $(seq 1 3000); do
  caught=$(awk '/^SigCgt:/ {print $2}' "/proc/$info_pid/status" 2>/dev/null) || break
  [ "$(readlink -f "/proc/$info_pid/exe" 2>/dev/null)" = "$selfsim_exe" ] && [ -n "$caught" ] &&
    (( 16#$caught & 2 )) && break  # bit 1: SIGINT
  sleep 0.02
done
kill -INT "$info_pid" 2>/dev/null
timeout 60 tail --pid="$info_pid" -f /dev/null
if kill -0 "$info_pid" 2>/dev/null; then
  echo "FAIL: info --print ran on after SIGINT"; kill -KILL "$info_pid"; failures=$((failures + 1))
fi
wait "$info_pid"
got=$?
[ "$got" = 130 ] || { echo "FAIL: info --print after SIGINT: exit $got, expected 130"; failures=$((failures + 1)); }
[ "$(cat "$tmp/err")" = "selfsim info: interrupted" ] || { echo "FAIL: info --print after SIGINT: '$(cat "$tmp/err")'"; failures=$((failures + 1)); }
[ -s "$tmp/out" ] && { echo "FAIL: info --print after SIGINT printed a report"; failures=$((failures + 1)); }
# --timeout as for run: one line, exit 1, no report.
expect 1 "info --print --timeout" -- "$selfsim" info --print "$tmp/ball.stl" --timeout 0.2
[ "$(cat "$tmp/err")" = "selfsim info: stopped: --timeout of 0.2 s reached" ] || { echo "FAIL: info --print --timeout: '$(cat "$tmp/err")'"; failures=$((failures + 1)); }
[ -s "$tmp/out" ] && { echo "FAIL: info --print --timeout printed a report"; failures=$((failures + 1)); }
rm -f "$tmp/ball.stl"
# preview's refusal of a .vdb root tile says "raise it with --max-points", which preview takes (a 4096^3
# tile in 653 bytes, written by OpenVDB's Python module where it is installed).
if /usr/bin/python3 "$src/tests/robustness/vdb_tiles.py" "$tmp" tiles_root.vdb 2>/dev/null; then
  expect 1 "preview --max-points" -- "$selfsim" preview "$tmp/tiles_root.vdb" -o "$tmp/pv" --max-points 1000
  contains "$tmp/err" "would make 301989888 points, over the limit of 1000 (raise it with --max-points)" \
    "preview --max-points: the limit given"
fi
expect 0 "info 3mf" -- "$selfsim" info "$tmp/p/tet.3mf"
contains "$tmp/out" "surface: closed manifold, 1 component" "info 3mf closed"
expect 0 "diff 3mf" -- "$selfsim" diff "$tmp/p/tet.3mf" "$tmp/p/tet.3mf"
# A unit the 3MF specification does not have was read as millimetres: one line naming file and unit.
/usr/bin/python3 - "$tmp/p/tet.3mf" "$tmp/p/furlong.3mf" <<'PY'
import sys, zipfile
with zipfile.ZipFile(sys.argv[1]) as a, zipfile.ZipFile(sys.argv[2], "w", zipfile.ZIP_DEFLATED) as b:
    for n in a.namelist():
        data = a.read(n)
        if n.endswith(".model"):
            data = data.replace(b'unit="millimeter"', b'unit="furlong"', 1)
            assert b'unit="furlong"' in data
        b.writestr(n, data)
PY
expect 2 "info 3mf in furlongs" -- "$selfsim" info "$tmp/p/furlong.3mf"
contains "$tmp/err" "cannot read '$tmp/p/furlong.3mf': the unit 'furlong' is not a 3MF unit; expected one of 'micron', 'millimeter', 'centimeter', 'inch', 'foot', 'meter'" "unknown 3mf unit"
[ "$(wc -l <"$tmp/err")" = 1 ] || { echo "FAIL: unknown 3mf unit: not one line: $(cat "$tmp/err")"; failures=$((failures + 1)); }

echo "$failures failures"
[ "$failures" = 0 ]
