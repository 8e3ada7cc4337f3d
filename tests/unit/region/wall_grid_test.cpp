#include "kernels/region/wall_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace selfsim {
namespace {

std::shared_ptr<const Volume> shared(Volume v) { return std::make_shared<const Volume>(std::move(v)); }

Vec3 random_point(std::mt19937& rng, Vec3 lo, Vec3 hi) {
  std::uniform_real_distribution<double> u(0, 1);
  return {lo.x + u(rng) * (hi.x - lo.x), lo.y + u(rng) * (hi.y - lo.y), lo.z + u(rng) * (hi.z - lo.z)};
}

// Inside a sphere the grid reads the distance to its surface within its error bound (and the quarter voxel
// within which the sphere is meshed), down to the depth asked for; outside it reads negative.
TEST(WallGrid, ASphereReadsItsDistanceWithinTheBound) {
  const double voxel = 0.05, depth = 0.3;
  const WallGrid g(Volume::sphere({0, 0, 0}, 1), voxel, depth, {}, no_progress());
  EXPECT_NEAR(g.error(), std::sqrt(3.0) / 2 * voxel, 1e-15);
  std::mt19937 rng(7);
  int inside = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 p = random_point(rng, Vec3::all(-1.1), Vec3::all(1.1));
    const double truth = 1 - norm(p);
    if (truth > depth || truth < -2 * voxel) continue;
    ++inside;
    EXPECT_NEAR(g.clearance(p), truth, g.error() + voxel / 4 + 1e-6) << p.x << " " << p.y << " " << p.z;
  }
  EXPECT_GT(inside, 500);
  EXPECT_GE(g.clearance({0, 0, 0}), depth);  // deeper than asked: at least that deep
  EXPECT_LT(g.clearance({0, 0, 1.05}), 0);
}

// The interpolated clearance changes by at most WallGrid::slope times the distance moved, what the growth's
// steps rely on.
TEST(WallGrid, ClearanceChangesNoFasterThanItsSlope) {
  const double voxel = 0.04;
  const auto ball = shared(Volume::sphere({0.3, 0, 0}, 0.7));
  const auto box = shared(Volume::box({-1, -0.5, -0.5}, {0.2, 0.5, 0.5}));
  const WallGrid g(Volume::combine(Volume::Kind::unite, {ball, box}), voxel, 0.3, {}, no_progress());
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0, 1);
  for (int i = 0; i < 20000; ++i) {
    const Vec3 p = random_point(rng, {-1, -0.6, -0.6}, {1, 0.6, 0.6});
    const Vec3 q = p + 0.3 * voxel * Vec3{n(rng), n(rng), n(rng)};
    EXPECT_LE(std::abs(g.clearance(p) - g.clearance(q)), WallGrid::slope * norm(p - q) * (1 + 1e-5) + 1e-6);
  }
}

// A difference reads the distance to what it takes away too, within the bound, not only that part's band.
TEST(WallGrid, ADifferenceReadsBothItsWalls) {
  const double voxel = 0.05;
  const Vec3 c{1, 1, 2};
  const Volume v = Volume::combine(Volume::Kind::subtract,
                                   {shared(Volume::box({0, 0, 0}, {2, 2, 2})), shared(Volume::sphere(c, 0.5))});
  const WallGrid g(v, voxel, 0.5, {}, no_progress());
  std::mt19937 rng(11);
  int measured = 0;
  for (int i = 0; i < 4000; ++i) {
    const Vec3 p = random_point(rng, {0, 0, 0}, {2, 2, 2});
    const double walls = std::min({p.x, p.y, p.z, 2 - p.x, 2 - p.y, 2 - p.z}), hole = norm(p - c) - 0.5;
    if (hole < 0) continue;
    const double truth = std::min(walls, hole);
    if (truth > 0.5) continue;
    ++measured;
    EXPECT_NEAR(g.clearance(p), truth, g.error() + voxel / 4 + 1e-6);
  }
  EXPECT_GT(measured, 1000);
}

// Where two parts of a union touch there is no wall: the grid measures the union's own surface again, not
// the least of its parts' distances (which reads 0 along the shared face).
TEST(WallGrid, TwoBoxesSideBySideHaveNoWallBetweenThem) {
  const double voxel = 0.05;
  const Volume v = Volume::combine(
      Volume::Kind::unite, {shared(Volume::box({0, 0, 0}, {1, 1, 1})), shared(Volume::box({1, 0, 0}, {2, 1, 1}))});
  const WallGrid g(v, voxel, 0.5, {}, no_progress());
  for (const double x : {0.9, 1.0, 1.1}) EXPECT_NEAR(g.clearance({x, 0.5, 0.5}), 0.5, g.error() + 1e-6) << x;
  EXPECT_NEAR(g.clearance({1, 0.3, 0.5}), 0.3, g.error() + 1e-6);
}

// Seen in another frame, q = s·(p − c), the same walls read s times the clearance.
TEST(WallGrid, AnotherFrameScalesTheClearance) {
  const WallGrid g(Volume::box({0, 0, 0}, {4, 2, 2}), 0.1, 0.5, {}, no_progress());
  const Vec3 c{2, 1, 1};
  const double s = 0.25;
  const WallGrid local = g.in_frame(c, s);
  EXPECT_NEAR(local.error(), s * g.error(), 1e-15);
  for (const Vec3 p : {Vec3{0.3, 0.4, 1.1}, Vec3{3.9, 1, 1}, Vec3{2, 1.7, 0.2}})
    EXPECT_NEAR(local.clearance(s * (p - c)), s * g.clearance(p), 1e-12);
  EXPECT_NEAR(g.clearance({0.3, 1, 1}), 0.3, g.error());
}

TEST(WallGrid, ALargeGridIsRefusedBeforeItIsBuilt) {
  const Volume v = Volume::sphere({0, 0, 0}, 1);
  EXPECT_GT(WallGrid::size(v, 0.01, 0.5), WallGrid::size(v, 0.01, 0.1));
  PointBudget small;
  small.limit = 1000;
  EXPECT_THROW(WallGrid(v, 0.01, 0.5, small, no_progress()), BudgetError);
}

// A crafted .vdb's voxels scattered far apart would each take a tree node of every size: refused first.
TEST(WallGrid, ScatteredFileVoxelsAreRefusedBeforeTheyAreBuilt) {
  Volume v = Volume::closed_mesh(sphere_mesh({0, 0, 0}, 1, 0.01), no_progress());
  GridSamples s;
  s.voxel = 0.05;
  s.background = 0.15;
  for (std::int32_t i = 0; i < 2000; ++i) s.index.push_back({i * 5000, -i * 5000, i * 4099}), s.value.push_back(-0.1f);
  v.samples = std::make_shared<const GridSamples>(s);
  EXPECT_GT(WallGrid::size(v, 0.05, 0.2), 2000 * 300e3 / 16);
  PointBudget budget;
  budget.limit = 1e7;
  EXPECT_THROW(WallGrid(v, 0.05, 0.2, budget, no_progress()), BudgetError);
}

}  // namespace
}  // namespace selfsim
