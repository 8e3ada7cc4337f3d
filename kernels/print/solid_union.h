// One solid from several (issue 40): the union of closed solids, and one solid with others cut away.
//
// Exact where the meshes allow it: solids that do not touch themselves (each tested whole before the exact
// result is taken) and whose triangles do not meet (tested pair by pair, on the triangles
// that reach where the two boxes overlap) are joined as they are (triangles, points and the fields all of
// them have), a solid wholly inside another is dropped from a union, and a cut wholly inside the solid it is
// taken from (touching nothing) becomes a sealed cavity, its triangles turned inwards. Otherwise on an OpenVDB grid:
// each solid's level set, combined (csgUnion, csgDifference) and meshed back, as a volume's boundary is (level_set.h:
// the lattice moved when the mesher makes a degenerate surface, the result closed and not crossing itself), at a stated
// voxel.
#pragma once

#include <span>
#include <string>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"

namespace selfsim::print {

struct UnionOptions {
  // The grid's, when one is needed; 0: union_voxel. At most a quarter of the thinnest side of any solid's
  // box (a coarser grid loses solids: two 10 mm cubes on a 10 mm grid made one), refused when given.
  double voxel = 0;
  PointBudget budget;
};

struct UnionResult {
  Mesh solid;  // closed, facing outwards
  bool exact = false;
  double voxel = 0;  // the grid's, when not exact
  std::string how;   // "exact (3 disjoint solids)", "on a 0.1 mm grid (solids 1 and 2 meet)"
};

// The default voxel: a quarter of the thinnest side of any solid's box, and at most 0.2 mm (half a 0.4 mm
// nozzle: finer than a print resolves is not needed).
double union_voxel(std::span<const Mesh* const> solids);

// Budget points (16 bytes) solid_union or solid_difference of `solids` (all of them, the solid cut from among
// them) holds besides its grid, whose own prediction volume_boundary checks against the budget less these:
// a copy of every solid turned outwards, and beside it either the exact result or, while two solids are
// tested for meeting, a copy of their triangles near where their boxes overlap and first_intersection's
// index (at most about 150 bytes a triangle, mesh_intersections.h), or that index over one whole solid while
// it is tested for touching itself. Bounded by every solid's whole size.
double union_work_size(std::span<const Mesh* const> solids);

// The union of `solids` (at least one; each closed, of either facing). Throws Error naming the first solid
// that is not closed ("solid 2 is not closed: ..."), Error naming 'voxel' when it is too coarse, BudgetError for a grid
// over the budget (predicted before any work), Error when the grid's surface is empty or not closed, Cancelled on a
// stop.
UnionResult solid_union(std::span<const Mesh* const> solids, const UnionOptions& opt, Progress& progress);

// `from` less every one of `cuts`. The same errors, and Error when nothing is left (`from` wholly inside a cut,
// or the grid's result empty: at a voxel a quarter of `from`'s thinnest side, the cuts cover it).
UnionResult solid_difference(const Mesh& from, std::span<const Mesh* const> cuts, const UnionOptions& opt,
                             Progress& progress);

}  // namespace selfsim::print
