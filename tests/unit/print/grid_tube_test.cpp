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

// Issue 40: a radius per point. The round cone's distance first: the hull of two balls.
TEST(RoundCone, DistanceIsTheHullOfTwoBalls) {
  const RoundSegment cylinder{{0, 0, 0}, {10, 0, 0}, 1, 1};
  EXPECT_NEAR(round_cone_distance(cylinder, {5, 3, 0}), 2, 1e-12);
  EXPECT_NEAR(round_cone_distance(cylinder, {5, 0, 0.5}), -0.5, 1e-12);
  EXPECT_NEAR(round_cone_distance(cylinder, {-3, 0, 0}), 2, 1e-12);  // past the end: the ball's
  // Radii 2 and 1 over a length of 10: the side's slope has sine 0.1. A point on the side's normal through
  // the middle of the side is at the side's distance; beyond each end, the ball's.
  const RoundSegment cone{{0, 0, 0}, {10, 0, 0}, 2, 1};
  const double s = 0.1, c = std::sqrt(1 - s * s);
  const Vec3 touch_a{2 * s, 2 * c, 0}, touch_b{10 + 1 * s, 1 * c, 0};
  const Vec3 middle = 0.5 * (touch_a + touch_b), normal{s, c, 0};
  EXPECT_NEAR(round_cone_distance(cone, middle), 0, 1e-12);
  EXPECT_NEAR(round_cone_distance(cone, middle + 0.7 * normal), 0.7, 1e-12);
  EXPECT_NEAR(round_cone_distance(cone, middle - 0.3 * normal), -0.3, 1e-12);
  EXPECT_NEAR(round_cone_distance(cone, {-5, 0, 0}), 3, 1e-12);
  EXPECT_NEAR(round_cone_distance(cone, {14, 0, 0}), 3, 1e-12);
  EXPECT_NEAR(round_cone_distance(cone, {0, 0, 0}), -2, 1e-12);
  // Not the segment's distance less one radius: at the thin end's side the cone is about 1 thick, not 2.
  EXPECT_NEAR(round_cone_distance(cone, {9, 2, 0}), (9 * s + 2 * c) - 2, 1e-12);
  EXPECT_GT(round_cone_distance(cone, {9, 2, 0}), 0.8);
  // One ball inside the other: the bigger ball.
  const RoundSegment nested{{0, 0, 0}, {0.5, 0, 0}, 2, 1};
  EXPECT_NEAR(round_cone_distance(nested, {0, 5, 0}), 3, 1e-12);
  const RoundSegment nested_b{{0, 0, 0}, {0.5, 0, 0}, 1, 2};
  EXPECT_NEAR(round_cone_distance(nested_b, {0.5, 5, 0}), 3, 1e-12);
}

namespace {

// The largest distance from the x axis of m's points whose x lies within 0.3 of `x` (and within 3 of the
// axis, not on a branch beside it): the tube's radius there.
double radius_near(const Mesh& m, double x) {
  double r = 0;
  for (const Vec3& p : m.points)
    if (std::abs(p.x - x) < 0.3 && std::hypot(p.y, p.z) < 3) r = std::max(r, std::hypot(p.y, p.z));
  return r;
}

}  // namespace

TEST(GridTube, ARadiusPerPointTapers) {
  // A straight path from radius 2 to 0.5: a round cone, thinner at its end; the volume of the hull.
  const Polyline3 c = Polyline3::single({{0, 0, 0}, {5, 0, 0}, {10, 0, 0}});
  const std::vector<double> radii{2, 1.25, 0.5};
  const Mesh m = grid_tube(c, radii, {}, no_progress());
  expect_one_closed_solid(m);
  EXPECT_NEAR(radius_near(m, 2), 2 - 0.15 * 2, 0.1);  // the side at x = 2, within a voxel (0.125)
  EXPECT_NEAR(radius_near(m, 8), 2 - 0.15 * 8, 0.1);
  const BBox3 b = m.bbox();
  EXPECT_NEAR(b.min.x, -2, 0.06);
  EXPECT_NEAR(b.max.x, 10.5, 0.06);
  // A frustum between the balls' touching circles, and the two caps beyond them.
  const double pi = std::numbers::pi, s = 0.15, k = std::sqrt(1 - s * s);
  const double r1 = 2 * k, r2 = 0.5 * k, h = 10 + (0.5 - 2) * s;
  const auto cap = [&](double r, double height) { return pi * height * height * (3 * r - height) / 3; };
  const double want = pi * h * (r1 * r1 + r1 * r2 + r2 * r2) / 3 + cap(2, 2 * (1 + s)) + cap(0.5, 0.5 * (1 - s));
  EXPECT_NEAR(enclosed_volume(m), want, 0.03 * want);
  // The voxel is a quarter of the thinnest radius, coarser only to fit the budget.
  EXPECT_DOUBLE_EQ(grid_tube_voxel(c, radii, {}), 0.125);
  GridTubeOptions tight;
  tight.budget.limit = 2e5;
  EXPECT_GT(grid_tube_voxel(c, radii, tight), 0.125);
  EXPECT_THROW(grid_tube(c, radii, {.voxel = 3}, no_progress()), Error);  // past half the thinnest radius
  EXPECT_THROW(grid_tube(c, std::vector<double>{2, 0, 1}, {}, no_progress()), Error);
  EXPECT_THROW(grid_tube(c, std::vector<double>{2, 1}, {}, no_progress()), Error);
}

TEST(GridTube, ATreeByWidthIsThinnerAtItsTipsThanAtItsTrunk) {
  // A trunk up x, forking twice, each fork's width 0.7 of its parent's, as a plant's '!' sets `width`.
  Polyline3 tree;
  std::vector<double> width;
  const auto path = [&](std::vector<Vec3> p, std::vector<double> w) {
    tree.points.insert(tree.points.end(), p.begin(), p.end());
    width.insert(width.end(), w.begin(), w.end());
    tree.path_ends.push_back(tree.points.size());
  };
  path({{0, 0, 0}, {10, 0, 0}, {20, 0, 0}, {30, 0, 0}}, {3, 3, 2.1, 1.47});
  path({{10, 0, 0}, {18, 6, 0}, {26, 12, 0}}, {2.1, 1.47, 1.03});
  path({{20, 0, 0}, {26, -6, 4}, {32, -12, 8}}, {1.47, 1.03, 0.72});
  ASSERT_TRUE(tree.paths_consistent());
  std::vector<double> radii;
  for (double w : width) radii.push_back(0.5 * w);  // radius = 0.5, by = "width"
  const Mesh m = grid_tube(tree, radii, {}, no_progress());
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.closed()) << t.first_problem;
  EXPECT_EQ(t.components, 1u);
  const double trunk = radius_near(m, 3), tip = radius_near(m, 29.5);
  EXPECT_NEAR(trunk, 1.5, 0.1);
  EXPECT_LT(tip, 0.9);  // 0.74 at x = 29.5 (0.5 from the trunk's end), where one radius would be 1.5
  EXPECT_LT(tip, 0.6 * trunk);
}

TEST(GridTube, RoundConesStopWhenAskedAndPredictTheirBudget) {
  struct Stop : Progress {
    bool cancelled() override { return true; }
  } stop;
  Polyline3 c;
  std::vector<double> radii;
  for (int i = 0; i < 5000; ++i) {
    c.points.push_back({0.01 * i, std::sin(0.01 * i), 0});
    radii.push_back(0.2 + 0.0001 * i);
  }
  c.path_ends.push_back(c.points.size());
  EXPECT_THROW(grid_tube(c, radii, {}, stop), Cancelled);
  GridTubeOptions small{.voxel = 0.05};
  small.budget.limit = 1e5;  // its 4999 cones fit, their grid does not
  try {
    grid_tube(c, radii, small, no_progress());
    ADD_FAILURE() << "not refused";
  } catch (const BudgetError& e) {
    EXPECT_NE(std::string(e.what()).find("a tube on a grid at voxel size 0.05 mm (set a larger 'voxel')"),
              std::string::npos)
        << e.what();
  }
}

TEST(GridTube, RoundConesOverTheBudgetAreRefusedBeforeTheyAreMade) {
  // Three segments 10 m long with radii of a few micrometres: at every voxel tried a million round cones each,
  // 3 million of 64 bytes (192 MB) that were made, at each voxel, before anything was checked. Now counted
  // first: refused by their count, which the message names, at the voxel chosen or at one given.
  const Polyline3 c = Polyline3::single({{0, 0, 0}, {1e4, 0, 0}, {1e4, 1e4, 0}, {0, 1e4, 0}});
  const std::vector<double> radii{0.001, 0.002, 0.001, 0.002};
  for (const double voxel : {0.0, 0.0005}) {
    GridTubeOptions opt{.voxel = voxel};
    opt.budget.limit = 1e7;
    try {
      grid_tube(c, radii, opt, no_progress());
      ADD_FAILURE() << "not refused at voxel " << voxel;
    } catch (const BudgetError& e) {
      EXPECT_NE(
          std::string(e.what()).find("(its 3000000 round cones; set a larger 'voxel') would make 21000000 points"),
          std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(voxel_text(0.0004883), "0.00049 mm");
  EXPECT_EQ(voxel_text(2.6964609481836), "2.7 mm");
}

TEST(GridTube, AVoxelOverHalfTheRadiusIsRefused) {
  // Radius 1 at voxel 1 came out 0.5 across the axis, silently; at half the radius it is within 0.1 of it.
  const Polyline3 c = Polyline3::single({{0, 0, 0}, {30, 0, 0}});
  try {
    grid_tube(c, {.radius = 1, .voxel = 1}, no_progress());
    ADD_FAILURE() << "not refused";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "option 'voxel' must be a positive length at most half the radius (0.5 mm), got 1: "
              "a coarser grid makes the tube thinner");
  }
  EXPECT_NEAR(grid_tube(c, {.radius = 1, .voxel = 0.5}, no_progress()).bbox().max.y, 1, 0.1);
  // With a radius per point, half the thinnest.
  const std::vector<double> radii{2, 0.5};
  EXPECT_THROW(grid_tube(c, radii, {.voxel = 0.3}, no_progress()), Error);
  EXPECT_NO_THROW(grid_tube(c, radii, {.voxel = 0.25}, no_progress()));
}
