// Thickening on a distance grid (OpenVDB, in the plugin's grid_solid.cpp): the solid is every point within
// half the thickness of the surface — the surface's unsigned distance, meshed back at that value
// (volumeToMesh). Unlike offset sheets (thicken.h) it cannot cross itself: where two parts of the surface
// come closer than the thickness, their solids merge instead of passing through each other, and rims are
// rounded. Any triangle soup works, manifold or not. Detail below a voxel is lost; adaptivity (OpenVDB's,
// in [0, 1]) merges the mesher's small polygons where the surface is flat.
#pragma once

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"

namespace selfsim::print {

struct GridThickenOptions {
  double thickness = 0;   // > 0, in the mesh's units (mm)
  double voxel = 0;       // the grid's; 0 for a quarter of the thickness
  double adaptivity = 0;  // in [0, 1]
  // The surface's area, for the budget; 0: the mesh's own. A curve's segments given as degenerate triangles
  // (grid_tube.h) have none, so their caller says how much sheet their band amounts to.
  double area = 0;
  PointBudget budget;

  // Throws Error naming the option.
  void validate() const;
  double voxel_size() const { return voxel > 0 ? voxel : thickness / 4; }
};

// Budget points the grid and the meshed solid take, predicted before any work.
double grid_thicken_size(const Mesh& m, const GridThickenOptions& opt);

// The closed solid around m. Throws Error for an empty mesh, BudgetError over the budget, Error when
// OpenVDB's mesher does not close the solid (naming the voxel to change), Cancelled when progress says stop.
Mesh thicken_on_grid(const Mesh& m, const GridThickenOptions& opt, Progress& progress);

}  // namespace selfsim::print
