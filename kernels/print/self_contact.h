// Where a solid's surface meets itself, told apart by what a slicer makes of it (issue 40):
//   - a crossing: triangles pass through each other (each has corners strictly on both sides of the other's
//     plane) along lines longer, together, than the nozzle's width: the slicer's layers get the inside wrong
//     there;
//   - a crease: the surface touches itself along an edge or at a point without passing through (thickened
//     sheets meeting at a fold, an OpenVDB mesh's coincident points), or passes through over less than the
//     nozzle's width: a slicer fuses it;
//   - a sealed speck: a closed piece (face-connected component) smaller than the nozzle's spot, across or in
//     area, beside a piece that is not: inside or touching another part, or alone, a slicer fuses or drops it.
// A crossing between two separate closed pieces that face outwards (two solids saved as one mesh, overlapping)
// is an overlap, not a crossing: a slicer (PrusaSlicer 2.5) slices their union. A crossing within one piece,
// or with a piece that is open or faces inwards (a cavity), is a crossing.
// The pairs are those mesh_intersections.h finds, sorted into touches, crossings and overlaps as they are
// found, up to `limit` of each (a mesh touching itself everywhere is judged by the first few thousand
// touches, but its crossings are still found): O(F).
#pragma once

#include <cstddef>
#include <optional>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/mesh_intersections.h"

namespace selfsim::print {

struct SelfContact {
  std::optional<TrianglePair> crossing;  // the first pair passing through, when the crossings count
  double crossing_length = 0;            // mm: the lines along which triangles pass through, summed
  std::size_t crossing_pairs = 0;
  std::optional<Vec3> crease;  // where the surface first touches itself (or crosses over less than a nozzle)
  std::size_t crease_pairs = 0;
  std::size_t specks = 0;               // sealed pieces smaller than the nozzle's spot
  Vec3 speck_where;                     // the largest speck's centre
  double speck_across = 0;              // mm: the largest speck's longest side
  std::optional<TrianglePair> overlap;  // the first pair where separate closed solids pass through each other
  double overlap_length = 0;            // mm, summed as crossing_length; they count past the nozzle's width too
  std::size_t overlap_pairs = 0;
  std::size_t overlap_solids = 0;  // the solids (closed pieces facing outwards) those pairs join
  bool capped = false;             // `limit` touching pairs were found: there may be more creases
  bool crossings_capped = false;   // `limit` crossing or overlapping pairs: their lengths may be longer
};

SelfContact self_contact(const Mesh& m, double nozzle, Progress& progress, std::size_t limit = 4096);

// The length (in m's units) of the line along which triangles a and b pass through each other; 0 when they
// only touch (a corner or an edge on the other's plane, coplanar, or apart).
double crossing_length(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b);

}  // namespace selfsim::print
