#include "kernels/exclusion/surface_net.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "kernels/region/box_mesh.h"
#include "kernels/region/volume.h"
#include "kernels/region/wall_grid.h"

namespace selfsim::exclusion {
namespace {  // The same with the walls measured on a distance grid: the walls' steps depend only on the move.
TEST(Surfaces, ParallelRoundsEqualMovingOneAfterAnotherWithGridWalls) {
  const Volume ball = Volume::sphere({0, 0, 0}, 1);
  const WallGrid walls(ball, 0.03, 0.4, {}, no_progress());
  const Mesh boundary = sphere_mesh({0, 0, 0}, 1, 0.03 / 4);
  Mesh start;
  start.points = {{-.6, -.4, 0}, {.6, -.4, 0}, {0, .6, 0}};
  start.triangles = {{0, 1, 2}};
  auto grown = [&](bool speculate) {
    Surfaces s(boundary, start, 1 << 16, 1 << 16);
    s.set_round_cells(0.3);
    s.set_neighbourhood(6, 0.01);
    s.set_walls(&walls);
    double r = 0.2;
    for (int level = 1; level <= 5; ++level, r *= 0.8) {
      LevelReport report;
      s.subdivide(level, r);
      s.grow(r, report, no_progress(), speculate);
    }
    return s.result().points;
  };
  const std::vector<Vec3> one_by_one = grown(false), in_rounds = grown(true);
  ASSERT_EQ(one_by_one.size(), in_rounds.size());
  for (std::size_t i = 0; i < one_by_one.size(); ++i) {
    ASSERT_EQ(one_by_one[i].x, in_rounds[i].x) << i;
    ASSERT_EQ(one_by_one[i].y, in_rounds[i].y) << i;
    ASSERT_EQ(one_by_one[i].z, in_rounds[i].z) << i;
  }
}

}  // namespace
}  // namespace selfsim::exclusion

namespace selfsim::exclusion {
namespace {

// Rounds measured in parallel and checked give exactly what moving each point in turn gives: a move whose
// measured box an earlier move of its round changed is measured again.
TEST(Surfaces, ParallelRoundsEqualMovingOneAfterAnother) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  Mesh start;
  start.points = {{.2, .2, .5}, {.8, .2, .5}, {.5, .8, .5}};
  start.triangles = {{0, 1, 2}};
  auto grown = [&](bool speculate, double neighbourhood) {
    Surfaces s(cube, start, 1 << 16, 1 << 16);
    s.set_round_cells(0.3);  // small cells: moves of one round often meet, and must be measured again
    s.set_neighbourhood(neighbourhood, 0.01);
    double r = 0.1;
    std::size_t stuck = 0;
    for (int level = 1; level <= 6; ++level, r *= 0.8) {
      LevelReport report;
      s.subdivide(level, r);
      s.grow(r, report, no_progress(), speculate);
      stuck += report.stuck;
    }
    if (neighbourhood == 0) {
      EXPECT_GT(stuck, 100u);  // the strict rule: many stuck, the neighbourhood's few
    }
    return s.result().points;
  };
  // The strict rule, the neighbourhood of 6 radii along the surface, and the whole surface.
  for (const double neighbourhood : {0.0, 6.0, HUGE_VAL}) {
    const std::vector<Vec3> one_by_one = grown(false, neighbourhood), in_rounds = grown(true, neighbourhood);
    ASSERT_EQ(one_by_one.size(), in_rounds.size());
    for (std::size_t i = 0; i < one_by_one.size(); ++i) {
      ASSERT_EQ(one_by_one[i].x, in_rounds[i].x) << i << " neighbourhood " << neighbourhood;
      ASSERT_EQ(one_by_one[i].y, in_rounds[i].y) << i << " neighbourhood " << neighbourhood;
      ASSERT_EQ(one_by_one[i].z, in_rounds[i].z) << i << " neighbourhood " << neighbourhood;
    }
  }
}

}  // namespace
}  // namespace selfsim::exclusion
