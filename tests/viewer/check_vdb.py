"""Reads the golden exclusion_cube/region.vdb with OpenVDB's own Python module (what Blender and Houdini
read with) and checks it is the unit cube's level set: a grid named 'surface' of class level set, whose
every active voxel holds the signed distance (negative inside) from its world position to the cube, in
world units, to within a tenth of a voxel."""
import pathlib
import sys

import pyopenvdb as vdb

path = pathlib.Path(sys.argv[1]) / "exclusion_cube" / "region.vdb"
grids, _ = vdb.readAll(str(path))
failures = []
if len(grids) != 1:
    sys.exit(f"{path}: {len(grids)} grids, expected 1")
g = grids[0]
voxel = g.transform.voxelSize()[0]
if g.name != "surface" or g.gridClass != "level set":
    failures.append(f"{path}: grid '{g.name}' of class '{g.gridClass}', expected 'surface', 'level set'")


def cube_distance(p):
    outside = [max(-c, c - 1, 0.0) for c in p]
    if any(outside):
        return sum(o * o for o in outside) ** 0.5
    return -min(min(c, 1 - c) for c in p)


checked = 0
for value in g.citerOnValues():
    lo, hi = value["min"], value["max"]
    if lo != hi:
        continue  # a tile
    world = g.transform.indexToWorld(lo)
    want = cube_distance(world)
    if abs(value["value"] - want) > 0.1 * voxel:
        failures.append(f"{path}: {value['value']} at {world}, expected {want}")
        break
    checked += 1
if checked < 1000:
    failures.append(f"{path}: only {checked} active voxels")
for f in failures:
    print(f)
print(f"{checked} voxels checked, {len(failures)} problems")
sys.exit(1 if failures else 0)
