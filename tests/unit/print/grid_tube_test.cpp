// Tubes on a distance grid: every point within the radius of the curve. A straight path is a capsule of the
// right volume; a hairpin that the mitred tube refuses, a branch point and two paths crossing each become one
// closed solid that does not cross itself.
#include "kernels/print/grid_tube.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"

using namespace selfsim;
using namespace selfsim::print;

namespace {

void expect_one_closed_solid(const Mesh& m) {
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.closed()) << t.first_problem;
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.euler(), 2);  // a sphere's topology: no handle where arms merge
  EXPECT_GT(enclosed_volume(m), 0);
  EXPECT_FALSE(first_intersection(m, no_progress()));
}

}  // namespace

TEST(GridTube, AStraightPathIsACapsule) {
  const Mesh m = grid_tube(Polyline3::single({{0, 0, 0}, {10, 0, 0}}), {.radius = 1}, no_progress());
  expect_one_closed_solid(m);
  const double pi = std::numbers::pi, want = pi * 10 + 4 * pi / 3;  // a cylinder and two half balls
  // At a voxel of a quarter radius the mesher's flat facets cut inside the round wall: 3% of the volume,
  // under 2% of the radius.
  EXPECT_NEAR(enclosed_volume(m), want, 0.05 * want);
  const BBox3 b = m.bbox();
  EXPECT_NEAR(b.min.x, -1, 0.05);
  EXPECT_NEAR(b.max.x, 11, 0.05);
  EXPECT_NEAR(b.max.y, 1, 0.05);
}

TEST(GridTube, HairpinsBranchesAndCrossingPathsMerge) {
  // A 179-degree turn: the mitred tube refuses it (over 170 degrees), the grid's is one solid.
  expect_one_closed_solid(grid_tube(Polyline::single({{0, 0}, {10, 0}, {0, 0.1745}}), {.radius = 0.5}, no_progress()));
  // A branch: a second path starting on the first one's middle point, as a plant's turtle writes it.
  Polyline branched = Polyline::single({{0, 0}, {5, 0}, {10, 0}});
  branched.points.push_back({5, 0});
  branched.points.push_back({5, 5});
  branched.path_ends.push_back(5);
  ASSERT_TRUE(branched.paths_consistent());
  expect_one_closed_solid(grid_tube(branched, {.radius = 0.5}, no_progress()));
}

TEST(GridTube, RefusesBadOptionsEmptyCurvesAndBigGrids) {
  const Polyline3 c = Polyline3::single({{0, 0, 0}, {10, 0, 0}});
  EXPECT_THROW(grid_tube(c, {.radius = 0}, no_progress()), Error);
  EXPECT_THROW(grid_tube(c, {.radius = NAN}, no_progress()), Error);
  EXPECT_THROW(grid_tube(c, {.radius = 1, .voxel = 2}, no_progress()), Error);
  EXPECT_THROW(grid_tube(c, {.radius = 1, .adaptivity = -1}, no_progress()), Error);
  EXPECT_THROW(grid_tube(Polyline3::single({{1, 1, 1}, {1, 1, 1}}), {.radius = 1}, no_progress()), Error);
  GridTubeOptions small{.radius = 1};
  small.budget.limit = 1000;
  EXPECT_THROW(grid_tube(c, small, no_progress()), BudgetError);
  // Many short segments far apart are as many balls (12 million points at radius 2, voxel 0.1): predicted
  // from their count, not their length (a hundredth of a millimetre in all), and refused before any work.
  Polyline3 dots;
  for (int i = 0; i < 400; ++i) {
    dots.points.push_back({5.0 * (i % 20), 5.0 * (i / 20), 0});
    dots.points.push_back({5.0 * (i % 20) + 1e-4, 5.0 * (i / 20), 0});
    dots.path_ends.push_back(dots.points.size());
  }
  GridTubeOptions balls{.radius = 2, .voxel = 0.1};
  balls.budget.limit = 2e6;
  EXPECT_THROW(grid_tube(dots, balls, no_progress()), BudgetError);
}
