// Tile similarity classes of a developing surface (seed 002 §4.2). Every tile of the control mesh is
// similar to every other, but once Loop subdivision smooths it, a tile's shape depends on its neighbourhood
// within the stencils' reach (and on how near the boundary it is), so tiles fall into classes of similar
// shapes; the paper colours its renders by class and reports 131 classes for the dragon, 135 for the
// terdragon, 125 for the Koch snowflake and 1487 for the Gosper curve once the count stops growing.
//
// Two tiles are in one class when a similarity (rotation, reflection, uniform scale and translation) maps
// one onto the other point for point, to a billionth of the tile's size. (With reflections the unsmoothed
// tiles of the dragon, terdragon and snowflake are one class, as §4.2 says; the smoothed counts are the
// paper's with or without them. A Gosper tile and its mirror image run in opposite directions, and the fans
// of 3 and 4 triangles that triangulate a tile of 7 fine segments do not map onto each other: its unsmoothed
// tiles are two classes.) The
// points compared are, for every tile alike, its smoothed control points and the points subdivision made
// near them; each tile is put in its own frame (origin at its coarse segment's first end a, x towards the
// other end e, the tile's middle fine point f_s in the xy plane, scaled so |e − a| = 1), so similar tiles
// have equal coordinates.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"

namespace selfsim::develop {

// How to find tile t of a surface: its faces are [t·faces, (t + 1)·faces), consecutive in an order every
// tile shares (the control mesh's, each face followed by its descendants: loop_subdivision.h), and
// reference[t] holds the point indices of its a, f_s and e.
struct TileLayout {
  std::size_t faces = 0;
  std::size_t stride = 1;  // faces to skip between sampled faces (4^(k−1) after k rounds of Loop: one face
                           // of each round-one child, so the samples are the same for every k ≥ 1)
  std::vector<std::array<std::uint32_t, 3>> reference;
};

// The class of every tile, numbered from 0 in order of each class's first tile.
std::vector<std::int32_t> tile_classes(const Mesh& surface, const TileLayout& layout, Progress& progress);

}  // namespace selfsim::develop
