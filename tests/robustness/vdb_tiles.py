#!/usr/bin/python3
"""Writes .vdb level sets made with OpenVDB's own Python module (python3-openvdb), for vdb_tiles.sh and the
committed test files: regions held by active tiles at every level of a float grid's tree (a tile of 8^3
voxels in a level-1 internal node, 128^3 in a level-2 one, 4096^3 at the root), as Houdini and Blender
write them, and grids that are wrong in ways the reader names (inside out, far from the world or the index origin).

usage: vdb_tiles.py DIR [NAME...]   (every file when no NAME is given)
"""
import sys

import pyopenvdb as vdb


def cube(side, value=None, background=None, at=(0, 0, 0)):
    """A level set of the cube [-1, 1]^3 held by one block of `side`^3 active voxels (all tiles when side is
    a multiple of 8 and `at` is aligned to it), `side` voxels across: -background inside, background
    outside, so its surface lies on the block's faces."""
    voxel = 2.0 / side
    bg = 3 * voxel if background is None else background
    g = vdb.FloatGrid(bg)
    g.gridClass = vdb.GridClass.LEVEL_SET
    g.name = "cube"
    g.fill(at, tuple(a + side - 1 for a in at), -bg if value is None else value, True)
    t = vdb.createLinearTransform(voxelSize=voxel)
    # The block's faces lie half a voxel beyond its outer voxels' centres: centre it on the origin.
    t.translate(tuple(-(a + (side - 1) / 2) * voxel for a in at))
    g.transform = t
    return g


def mixed():
    """Active values at three levels side by side along x: a tile of 128^3 voxels (a level-2 node's),
    beside it one of 8^3 (a level-1 node's), beside that 4^3 voxels of a leaf; voxel 1/64. One region
    from x = -1 to 1 + 12/64, its box's y and z from -1 to 1 at the big tile."""
    g = cube(128)
    bg = g.background
    g.fill((128, 0, 0), (135, 7, 7), -bg, True)
    g.fill((136, 0, 0), (139, 3, 3), -bg, True)
    return g


def filled():
    """A block of 256^3 voxels off the nodes' alignment (from index 8): one tile of a level-2 node inside,
    28,672 tiles of level-1 nodes around it. Its surface is its 6 x 256^2 outer faces (and the big tile's
    faces, which the small tiles beside it hide from view but not from the prediction); the tiles' faces
    all together would be 30 times more."""
    g = vdb.FloatGrid(3.0)
    g.gridClass = vdb.GridClass.LEVEL_SET
    g.name = "block"
    g.fill((8, 8, 8), (263, 263, 263), -3.0, True)
    return g


def sphere_with_tiles():
    """The hostile test's file: a sphere's level set (radius 1, 40 voxels) whose inside is filled with
    active tiles, OpenVDB's own fill(..., active=True): 64 tiles of 8^3 voxels."""
    g = vdb.createLevelSetSphere(radius=1.0, voxelSize=0.025, halfWidth=3.0)
    g.name = "sphere"
    g.fill((-16, -16, -16), (15, 15, 15), -g.background, True)
    return g


def inside_out_sphere():
    """A sphere's level set with every value negated (mapAll), the background left positive: negative
    just outside its band."""
    g = vdb.createLevelSetSphere(radius=1.0, voxelSize=0.1, halfWidth=3.0)
    g.name = "sphere"
    g.mapAll(lambda v: -v)
    return g


def inside_inactive():
    """An active tile of 8^3 voxels at -background beside an inactive one at -background (along +x): the
    inside goes on into inactive values, as a level set's inside does. Not inside out: its active values
    never cross to the outside, and negating them would truly invert it."""
    g = cube(8)
    g.fill((8, 0, 0), (15, 7, 7), -g.background, False)
    return g


def inside_inactive_voxels():
    """The same in a leaf's voxels: 4^3 active voxels at -background, beyond them along +x 2 x 4 x 4
    inactive ones at -background (voxel 1/4). OpenVDB meshes a leaf's inactive values too: a closed box."""
    g = cube(8)
    bg = g.background
    g.clear()
    access = g.getAccessor()
    for x in range(6):
        for y in range(4):
            for z in range(4):
                access.setValueOn((x, y, z), -bg) if x < 4 else access.setValueOff((x, y, z), -bg)
    return g


def far_blobs(side):
    """Two cubes of tiles at index -2^29 and +2^29 (voxel 1), where single-precision positions are 64
    voxels apart: `side` 8 (level-1 tiles) or 4096 (root tiles: a file of a few hundred bytes)."""
    g = cube(side, at=(2**29, 0, 0))
    g.fill((-2**29, 0, 0), (-2**29 + side - 1,) + (side - 1,) * 2, -g.background, True)
    g.transform = vdb.createLinearTransform(voxelSize=1.0)
    return g


files = {
    "tiles_level1.vdb": lambda: cube(16),  # 8 tiles of a level-1 internal node
    "tiles_level2.vdb": lambda: cube(128),  # 1 tile of a level-2 internal node
    "tiles_root.vdb": lambda: cube(4096),  # 1 root tile: 2^36 voxels
    "tiles_mixed.vdb": mixed,
    "tiles_filled.vdb": filled,
    "sphere_tiles.vdb": sphere_with_tiles,
    # Positive inside, negative outside; one root tile, so that the file is small.
    "inside_out.vdb": lambda: cube(4096, value=0.001, background=-0.001),
    "inside_out_sphere.vdb": inside_out_sphere,
    "inside_inactive.vdb": inside_inactive,
    "inside_inactive_voxels.vdb": inside_inactive_voxels,
    "far_blobs.vdb": lambda: far_blobs(4096),
    "far_small_blobs.vdb": lambda: far_blobs(8),
    # A root tile past index 2^30, its transform bringing it back around the world origin.
    "far_index.vdb": lambda: cube(4096, at=(2**30 + 4096, 0, 0)),
}

if __name__ == "__main__":
    out = sys.argv[1]
    for name in sys.argv[2:] or files:
        vdb.write(out + "/" + name, grids=[files[name]()])
