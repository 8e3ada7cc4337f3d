#!/usr/bin/env bash
# .vdb level sets with active tiles, made by OpenVDB itself (vdb_tiles.py, python3-openvdb): a cube held
# by tiles of a level-1 internal node (8^3 voxels each) and by one tile of a level-2 node (128^3), both
# kinds beside a leaf's voxels in one grid, and a sphere filled with 64 active tiles, read by volume.vdb, load, info and preview as their surfaces and
# voxels; a root tile (2^36 voxels) refused by the budget before anything is meshed or voxelised; grids
# inside out or far from the origin refused saying so, an inside going on into inactive values not called
# inside out. Skips (77) without python3-openvdb.
# usage: vdb_tiles.sh SELFSIM SOURCE_DIR
selfsim=$1 src=$2
source "$(dirname "$0")/lib.sh"
/usr/bin/python3 -c 'import pyopenvdb' 2>/dev/null || { echo "skipped: no python3-openvdb"; exit 77; }
/usr/bin/python3 "$src/tests/robustness/vdb_tiles.py" "$tmp" || { echo "FAIL: vdb_tiles.py"; exit 1; }

cat >"$tmp/tiles.lua" <<'LUA'
-- The cube [-1, 1]^3 held by tiles: the region's box is the cube's, every point of its surface lies on a
-- face (its edges' and corners' points up to half a voxel in), and the voxels come back, one a voxel.
for _, f in ipairs { { "tiles_level1.vdb", 16 }, { "tiles_level2.vdb", 128 } } do
  local name, across = f[1], f[2]
  local region = volume.vdb(name)
  local box = region:bbox()
  for axis = 1, 3 do
    assert(math.abs(box.min[axis] + 1) < 1e-5 and math.abs(box.max[axis] - 1) < 1e-5, name .. " bbox " .. axis)
  end
  local m = load(name)
  assert(m:points() > 6 * (across - 2) ^ 2, name .. ": " .. m:points() .. " points")
  for i = 1, m:points() do
    local p = m:point(i)
    local c = math.max(math.abs(p[1]), math.abs(p[2]), math.abs(p[3]))
    assert(c < 1 + 1e-5 and c > 1 - 1 / across, name .. " point " .. i .. " at " .. c)
  end
end
-- Tiles of both internal levels and a leaf's voxels side by side: one region, the three blocks' box.
local mixed = volume.vdb("tiles_mixed.vdb"):bbox()
for axis, want in ipairs { { -1, 1 + 12 / 64 }, { -1, 1 }, { -1, 1 } } do
  assert(math.abs(mixed.min[axis] - want[1]) < 1e-5 and math.abs(mixed.max[axis] - want[2]) < 1e-5, "mixed " .. axis)
end
-- Grown inside the level-1 cube with its walls measured on its voxels (the tiles made voxels): every
-- point stays inside.
local f = exclusion.surface { region = volume.vdb("tiles_level1.vdb"), walls = "grid",
                              start = { { -.5, -.4, 0 }, { .5, -.4, 0 }, { 0, .5, 0 } },
                              radius = 0.15, factor = 0.8, levels = 2 }
for i = 1, f:points() do
  local p = f:point(i)
  assert(math.max(math.abs(p[1]), math.abs(p[2]), math.abs(p[3])) < 1, "grown point " .. i .. " outside")
end
-- The hostile test's sphere, filled with 64 active tiles: its surface is the unit sphere's.
local ball = volume.vdb("sphere_tiles.vdb")
for axis = 1, 3 do
  assert(math.abs(ball:bbox().min[axis] + 1) < 0.03 and math.abs(ball:bbox().max[axis] - 1) < 0.03, "ball bbox")
end
local s = load("sphere_tiles.vdb")
for i = 1, s:points() do
  local p = s:point(i)
  local r = math.sqrt(p[1] ^ 2 + p[2] ^ 2 + p[3] ^ 2)
  assert(math.abs(r - 1) < 0.025, "sphere point " .. i .. " at radius " .. r)
end
LUA
run_selfsim run "$tmp/tiles.lua" -o "$tmp/out_tiles" -q
check "tiles read as their regions (exit $code: $(head -c 600 "$tmp/err"))" [ "$code" = 0 ]

run_selfsim info "$tmp/sphere_tiles.vdb"
check "info on the sphere with tiles" grep -q "class: level set" "$tmp/out"

# A block filled with tiles weighs its outer faces, not every tile's: its 6 x 256^2 points and their
# triangles fit 2e6 points (every tile's faces would make 33 million).
echo 'load("tiles_filled.vdb")' >"$tmp/filled.lua"
run_selfsim run "$tmp/filled.lua" -o "$tmp/out_filled" -q --max-points 2e6
check "a block filled with tiles fits its surface's budget (exit $code: $(head -c 300 "$tmp/err"))" [ "$code" = 0 ]

# A root tile: 2^36 voxels and a surface of 6 x 4096^2, refused at once by the budget.
refused() {  # refused RECIPE_TEXT EXPECTED_TEXT [ARGS...]
  local text=$1 want=$2
  shift 2
  printf '%s\n' "$text" >"$tmp/refused.lua"
  SECONDS=0
  run_selfsim run "$tmp/refused.lua" -o "$tmp/out_refused" -q "$@"
  local what="$text $* (exit $code, ${SECONDS}s: $(head -c 400 "$tmp/err"))"
  check "$what: exit 1" [ "$code" = 1 ]
  check "$what: one line" [ "$(wc -l <"$tmp/err")" = 1 ]
  check "$what: says '$want'" grep -qF "$want" "$tmp/err"
  check "$what: at once" [ "$SECONDS" -lt 20 ]
}
refused 'volume.vdb("tiles_root.vdb")' \
  "the surface of the 1 active tile of grid 'cube' in 'tiles_root.vdb' would make 301989888 points"
refused 'load("tiles_root.vdb")' "the surface of the 1 active tile of grid 'cube' in 'tiles_root.vdb'"
refused 'volume.vdb("tiles_root.vdb")' \
  "the voxels of grid 'cube' in 'tiles_root.vdb' (its 1 active tile as voxels) would make 68719476736 points" \
  --max-points 1e9
refused 'volume.vdb("tiles_root.vdb")' \
  "cannot read 'tiles_root.vdb': grid 'cube' has 68719476736 active voxels (its 1 active tile as voxels), over the reading limit" \
  --max-points 1e12
# Grids wrong in a way the mesh would only show as crossings: said as what is wrong with the grid.
refused 'volume.vdb("inside_out_sphere.vdb")' "cannot read 'inside_out_sphere.vdb': grid 'sphere' is inside out"
# An active tile inside beside an inactive one inside: not inside out (negating it, as that message said,
# would truly invert it). Its surface lies in inactive values, beyond the inactive tile, so its mesh is open.
printf 'volume.vdb("inside_inactive.vdb")\n' >"$tmp/inactive.lua"
run_selfsim run "$tmp/inactive.lua" -o "$tmp/out_inactive" -q
check "inside going on into an inactive tile is not inside out: $(head -c 400 "$tmp/err")" \
  sh -c '[ "$1" -le 1 ] && ! grep -q "inside out" "$2"' - "$code" "$tmp/err"
# The same in a leaf's voxels, which OpenVDB meshes inactive or not: read as the closed box it is.
echo 'local m = load("inside_inactive_voxels.vdb") assert(m:points() > 8)' >"$tmp/inactive_voxels.lua"
run_selfsim run "$tmp/inactive_voxels.lua" -o "$tmp/out_inactive_voxels" -q
check "inside going on into inactive voxels is read (exit $code: $(head -c 400 "$tmp/err"))" [ "$code" = 0 ]
refused 'load("far_small_blobs.vdb")' "cannot read 'far_small_blobs.vdb': grid 'cube' lies 536870919 voxels from the origin"

if command -v Xvfb >/dev/null; then
  run_selfsim preview "$tmp/sphere_tiles.vdb" -o "$tmp/previews"
  check "preview of the sphere with tiles (exit $code: $(head -c 300 "$tmp/err"))" test "$code" = 0 -a -s "$tmp/previews/sphere_tiles.png"
fi
finish
