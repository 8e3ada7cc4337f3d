// The rays of the print check on exact signed distances: a slab's walls read as its thickness, the gap
// between two slabs as its width, thick bodies read as the caps, and the convex edge of a thick box is not
// a thin wall.
#include "kernels/print/wall_rays.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace selfsim;
using namespace selfsim::print;

namespace {

// Signed distance, positive inside, of the slab lo <= z <= hi.
double slab(Vec3 p, double lo, double hi) { return std::min(p.z - lo, hi - p.z); }

Clearance of(double (*f)(Vec3)) {
  return [f](std::span<const Vec3> p, std::span<double> out) {
    for (std::size_t i = 0; i < p.size(); ++i) out[i] = f(p[i]);
  };
}

struct Measured {
  std::vector<double> wall, gap;
};

Measured rays(const std::vector<Vec3>& points, const std::vector<Vec3>& normals, const Clearance& c, RayLimits limits) {
  Measured m{std::vector<double>(points.size()), std::vector<double>(points.size())};
  measure_rays(points, normals, c, limits, m.wall, m.gap, no_progress());
  return m;
}

}  // namespace

TEST(WallRays, ASlabsWallIsItsThickness) {
  // A slab 0.3 thick: from its top face inwards the far side is 0.3 away, whatever the step.
  const auto thin = [](Vec3 p) { return slab(p, 0, 0.3); };
  for (double step : {0.01, 0.07, 0.2}) {
    const Measured m = rays({{0, 0, 0.3}}, {{0, 0, 1}}, of(+thin), {.step = step, .wall_cap = 2, .gap_cap = 1});
    EXPECT_NEAR(m.wall[0], 0.3, 1e-12) << step;  // the distance is linear: interpolation is exact
    EXPECT_EQ(m.gap[0], 1) << step;              // nothing above it: the cap
  }
}

TEST(WallRays, TheGapBetweenTwoSlabsIsItsWidth) {
  // Slabs 0 <= z <= 1 and 1.25 <= z <= 2: from the lower one's top face, a gap of 0.25.
  const auto two = [](Vec3 p) { return std::max(slab(p, 0, 1), slab(p, 1.25, 2)); };
  const Measured m = rays({{0, 0, 1}}, {{0, 0, 1}}, of(+two), {.step = 0.05, .wall_cap = 0.5, .gap_cap = 1});
  EXPECT_NEAR(m.gap[0], 0.25, 1e-12);
  EXPECT_EQ(m.wall[0], 0.5);  // a wall 1 thick reads as the cap
}

TEST(WallRays, ABoxsConvexEdgeIsNotAThinWall) {
  // The unit cube; a point on its top face 0.05 from an edge: the ray inwards runs beside the side face.
  const auto cube = [](Vec3 p) { return std::min({p.x, 1 - p.x, p.y, 1 - p.y, p.z, 1 - p.z}); };
  const Measured m = rays({{0.05, 0.5, 1}}, {{0, 0, 1}}, of(+cube), {.step = 0.02, .wall_cap = 0.8, .gap_cap = 0.4});
  EXPECT_EQ(m.wall[0], 0.8);
  EXPECT_EQ(m.gap[0], 0.4);
}

TEST(WallRays, AWallThinnerThanAStepReadsAsHalfAStep) {
  const auto sheet = [](Vec3 p) { return slab(p, 0, 0.01); };
  const Measured m = rays({{0, 0, 0.01}}, {{0, 0, 1}}, of(+sheet), {.step = 0.1, .wall_cap = 1, .gap_cap = 1});
  EXPECT_DOUBLE_EQ(m.wall[0], 0.05);
}

TEST(WallRays, AZeroNormalReadsAsTheCapsAndManyPointsAgreeWithOne) {
  const auto thin = [](Vec3 p) { return slab(p, 0, 0.3); };
  std::vector<Vec3> points, normals;
  for (int i = 0; i < 5000; ++i) {  // several chunks, in parallel
    points.push_back({i * 0.001, 0, i % 2 == 0 ? 0.3 : 0.0});
    normals.push_back(i % 7 == 0 ? Vec3{} : Vec3{0, 0, i % 2 == 0 ? 1.0 : -1.0});
  }
  const Measured m = rays(points, normals, of(+thin), {.step = 0.05, .wall_cap = 1, .gap_cap = 0.7});
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(m.wall[i], i % 7 == 0 ? 1 : 0.3, 1e-12) << i;
    EXPECT_EQ(m.gap[i], 0.7) << i;
  }
}

TEST(WallRays, RefusesANonPositiveStep) {
  std::vector<double> w(1), g(1);
  EXPECT_THROW(measure_rays(std::vector<Vec3>{{0, 0, 0}}, std::vector<Vec3>{{0, 0, 1}}, of(+[](Vec3) { return 1.0; }),
                            {.step = 0, .wall_cap = 1, .gap_cap = 1}, w, g, no_progress()),
               Error);
}

TEST(WallRays, TheFarFlankOfAGrooveIsNotAGapButFacingWallsAre) {
  // A V-shaped groove opening upwards, 60 degrees wide, the solid below its flanks: the ray from a point on
  // one flank along its normal meets the other flank at 120 degrees to its normal (it does not face back).
  const auto groove = [](Vec3 p) {
    return std::max(0.866025403784 * p.x - 0.5 * p.z, -0.866025403784 * p.x - 0.5 * p.z);
  };
  const Vec3 on{0.05, 0, 0.0866025403784}, n{-0.866025403784, 0, 0.5};
  EXPECT_EQ(rays({on}, {n}, of(+groove), {.step = 0.005, .wall_cap = 1, .gap_cap = 1}).gap[0], 1);
  // Without the facing rule the ray reads the groove's width there.
  EXPECT_NEAR(rays({on}, {n}, of(+groove), {.step = 0.005, .wall_cap = 1, .gap_cap = 1, .gap_facing = -2}).gap[0],
              0.173205080757, 1e-6);
  // A slot 0.3 wide between two blocks: its walls face each other, a gap.
  const auto slot = [](Vec3 p) { return std::max(-p.x, p.x - 0.3); };
  EXPECT_NEAR(rays({{0, 0, 0}}, {{1, 0, 0}}, of(+slot), {.step = 0.01, .wall_cap = 1, .gap_cap = 1}).gap[0], 0.3, 1e-9);
}

TEST(WallRays, AWedgesOtherFaceIsNotAWallUnlessItFaces) {
  // A wedge pointing up with a 60-degree edge (its faces' normals 120 degrees apart), solid below: the ray
  // inwards from one face leaves through the other at 60 degrees to facing along it: not a thin wall.
  const auto wedge = [](Vec3 p) {
    return std::min(-(0.866025403784 * p.x + 0.5 * p.z), -(-0.866025403784 * p.x + 0.5 * p.z));
  };
  const Vec3 n{0.866025403784, 0, 0.5}, on{0.1, 0, -0.173205080757};
  EXPECT_EQ(rays({on}, {n}, of(+wedge), {.step = 0.005, .wall_cap = 1, .gap_cap = 1}).wall[0], 1);
  EXPECT_NEAR(rays({on}, {n}, of(+wedge), {.step = 0.005, .wall_cap = 1, .gap_cap = 1, .wall_facing = -2}).wall[0],
              0.346410161514, 1e-6);
}

TEST(WallRays, ANarrowCreasesBottomIsNotAGapButANarrowWedgeIsAThinWall) {
  // A folded sheet's inner side: a V-groove 30 degrees wide (its flanks' normals 150 degrees apart). Its
  // bottom fills without joining anything: not a gap (gaps count within 20 degrees of facing).
  static const double c = std::cos(0.2617993877991), s = std::sin(0.2617993877991);  // 15 degrees
  const auto groove = [](Vec3 p) { return std::max(c * p.x - s * p.z, -c * p.x - s * p.z); };
  const Vec3 on{0.05 * s, 0, 0.05 * c}, n{-c, 0, s};
  EXPECT_EQ(rays({on}, {n}, of(+groove), {.step = 0.001, .wall_cap = 1, .gap_cap = 1}).gap[0], 1);
  // The same angle as a solid wedge (its edge 30 degrees) is thin near the edge: walls count within 45.
  const auto wedge = [](Vec3 p) { return -std::max(c * p.x - s * p.z, -c * p.x - s * p.z); };
  EXPECT_NEAR(rays({on}, {-1.0 * n}, of(+wedge), {.step = 0.001, .wall_cap = 1, .gap_cap = 1}).wall[0],
              0.05 * std::tan(0.5235987755983), 1e-6);
}
