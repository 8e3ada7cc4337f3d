// Whether a mesh meets itself: the first pair of triangles that intersect or touch without being neighbours.
// Exclusion surfaces (seed 004) must never touch themselves and a thickened developing surface (seed 002)
// must not fold through itself, so their tests need a check exact enough to see two triangles share a
// single coordinate and fast enough for millions of triangles: O(F) expected, with a uniform grid
// over the triangles' bounding boxes, then an exact-to-rounding distance test per candidate pair.
//
// Tolerance: two triangles meet when the distance between them is at most 1e-9 times the diagonal of the
// mesh's bounding box (all points, used or not). Rounding does not hide a touch, and a gap of a few billionths
// of the mesh's size is still a gap, at any scale and any distance from the origin.
//
// Neighbours: triangles that share point indices meet there by construction, which is the mesh's
// connectivity, not a collision. They are reported when they also meet elsewhere: sharing a corner, when a
// ray from it lies in both (they cross, or overlap in one plane); sharing an edge, when they fold onto each
// other (their third corners on one side of the edge, within the tolerance of one plane). Two triangles that
// share only a coordinate, through different point indices, are tested as any others, and touch.
//
// Degenerate (zero-area) triangles are kept and tested as what they are: the segment or point their corners
// span (a triangle counts as flat when its height is below 1e-12 of its longest edge). A triangle that
// names one point twice is such a segment.
//
// Cost: the grid's cells are twice the median triangle's size, doubled while a few huge triangles would make
// more than 8 (cell, triangle) insertions a triangle, so memory is predicted and O(F): 24 bytes a triangle
// for its box and 16 an insertion while they are sorted, about 60 bytes a triangle on a typical surface
// (2.3 insertions each) and never more than about 150. Time is O(F) when triangles are small beside the
// mesh; many long slivers crossing one region (a fan of thousands) make their cells' pairs quadratic.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/vec3.h"

namespace selfsim {

struct TrianglePair {
  std::uint32_t first = 0, second = 0;  // 0-based triangle indices, first < second
  Vec3 where;                           // a point of both (to within the tolerance): a crossing or the touch
};

// The first pair (smallest `first`, then smallest `second`) of triangles of m that intersect or touch other
// than along the corners they share (see above); std::nullopt when there is none. The answer does not depend on the
// number of threads. Throws Error for a non-finite point or an index out of range (naming it, counted from 1 as
// Mesh::validate does), and Cancelled when progress says stop.
std::optional<TrianglePair> first_intersection(const Mesh& m, Progress& progress);

// Every pair that meets, as first_intersection tests them, sorted, up to `limit` of them (then some `limit`
// of them: whole batches of the grid's cells are searched until that many are found, so which ones does not
// depend on the threads, and the time is at most first_intersection's when there are few). The print check
// tells crossings from touches by them (kernels/print/self_contact.h).
std::vector<TrianglePair> intersecting_pairs(const Mesh& m, std::size_t limit, Progress& progress);

// Every pair that meets, sorted into kinds by `kind`: it returns a kind from 0 to kinds - 1, or -1 for a pair
// to leave out (neither kept nor counted). It is called from several threads at once, so it must only read.
// Each kind keeps up to `limit` pairs, sorted (as intersecting_pairs picks them), and the search goes on while
// any kind has fewer: a pair of a rare kind is never hidden behind `limit` of a common one (the print check's
// crossings behind thousands of touches). Memory is bounded by `limit` pairs a kind (and a batch's); the time
// is at most a whole search's, O(F) as first_intersection's (with `kind` once a meeting pair).
// (Both in mesh_contact_pairs.cpp.)
std::vector<std::vector<TrianglePair>> classified_pairs(const Mesh& m, std::size_t limit, int kinds,
                                                        const std::function<int(std::uint32_t, std::uint32_t)>& kind,
                                                        Progress& progress);

}  // namespace selfsim
