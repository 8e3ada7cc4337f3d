// Thickening on a distance grid: a flat square sheet becomes a closed slab with rounded rims, of about
// the sheet's area times the thickness (plus half a cylinder along the rim), facing outwards; two sheets
// closer than the thickness merge into one solid instead of crossing.
#include "kernels/print/grid_thicken.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"

using namespace selfsim;
using namespace selfsim::print;

namespace {

Mesh square(double z, double side = 10) {
  Mesh m;
  m.points = {{0, 0, z}, {side, 0, z}, {side, side, z}, {0, side, z}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

}  // namespace

TEST(GridThicken, ASheetBecomesAClosedSlab) {
  const Mesh solid = thicken_on_grid(square(0), {.thickness = 1}, no_progress());
  const MeshTopology t = mesh_topology(solid);
  EXPECT_TRUE(t.closed());
  EXPECT_EQ(t.euler(), 2);
  EXPECT_FALSE(first_intersection(solid, no_progress()));
  // Every point within 0.5 of the square (Steiner's formula): the slab 10 x 10 x 1, half a cylinder of
  // radius 0.5 along the 40 mm rim, and the corners' quarter spheres making one whole sphere.
  const double r = 0.5, pi = std::numbers::pi, want = 100 * 2 * r + 40 * pi * r * r / 2 + 4 * pi * r * r * r / 3;
  EXPECT_NEAR(enclosed_volume(solid), want, 0.03 * want);
  const BBox3 b = solid.bbox();
  EXPECT_NEAR(b.min.z, -0.5, 0.05);
  EXPECT_NEAR(b.max.z, 0.5, 0.05);
  EXPECT_NEAR(b.min.x, -0.5, 0.05);
}

TEST(GridThicken, CloseSheetsMergeAndAdaptivityMakesFewerTriangles) {
  Mesh two = square(0);
  const Mesh upper = square(0.6);
  two.points.insert(two.points.end(), upper.points.begin(), upper.points.end());
  two.triangles.push_back({4, 5, 6});
  two.triangles.push_back({4, 6, 7});
  const Mesh merged = thicken_on_grid(two, {.thickness = 1}, no_progress());
  EXPECT_TRUE(mesh_topology(merged).closed());
  EXPECT_EQ(mesh_topology(merged).components, 1u);
  EXPECT_FALSE(first_intersection(merged, no_progress()));
  const Mesh coarse = thicken_on_grid(square(0), {.thickness = 1, .adaptivity = 0.5}, no_progress());
  EXPECT_TRUE(mesh_topology(coarse).closed());
  EXPECT_LT(coarse.faces(), thicken_on_grid(square(0), {.thickness = 1}, no_progress()).faces());
}

TEST(GridThicken, RefusesBadOptionsAndBigGrids) {
  EXPECT_THROW(thicken_on_grid(square(0), {.thickness = 0}, no_progress()), Error);
  EXPECT_THROW(thicken_on_grid(square(0), {.thickness = 1, .voxel = 2}, no_progress()), Error);
  EXPECT_THROW(thicken_on_grid(square(0), {.thickness = 1, .adaptivity = 2}, no_progress()), Error);
  GridThickenOptions small{.thickness = 1};
  small.budget.limit = 1000;
  EXPECT_THROW(thicken_on_grid(square(0), small, no_progress()), BudgetError);
}
