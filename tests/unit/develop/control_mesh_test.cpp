// Seed 002 §2 and §3.2: level stacks at self-similar heights and the control mesh of tiles, counted by closed
// forms, with the topology the paper says (a disk for open curves, an annulus for closed ones).
#include "kernels/develop/control_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../lsystem/table1.h"
#include "kernels/base/error.h"
#include "kernels/develop/level_stack.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/lsystem/turtle/turtle2d.h"

using namespace selfsim;
using namespace selfsim::develop;

namespace {

std::vector<Polyline> levels_of(const lsystem::Grammar& g, int top) {
  std::vector<Polyline> out;
  for (int l = 0; l <= top; ++l) out.push_back(lsystem::turtle2d(g, {.level = l}, no_progress()));
  return out;
}

std::vector<const Polyline*> pointers(const std::vector<Polyline>& v) {
  std::vector<const Polyline*> p;
  for (const Polyline& c : v) p.push_back(&c);
  return p;
}

}  // namespace

TEST(LevelStack, SelfSimilarHeights) {
  const auto dragon = levels_of(table1::dragon(), 6);
  const std::vector<double> z = level_heights(pointers(dragon), 0.5);
  ASSERT_EQ(z.size(), 7u);
  EXPECT_EQ(z[0], 0);
  EXPECT_NEAR(z[1], -0.5, 1e-12);  // level 0 is one unit segment
  for (std::size_t l = 1; l + 1 < z.size(); ++l)
    EXPECT_NEAR((z[l + 1] - z[l]) / (z[l] - z[l - 1]), std::sqrt(0.5), 1e-12) << l;
  const auto ter = levels_of(table1::terdragon(), 4);
  const std::vector<double> t = level_heights(pointers(ter), 1);
  EXPECT_NEAR((t[3] - t[2]) / (t[2] - t[1]), 1 / std::sqrt(3.0), 1e-12);
  EXPECT_THROW(level_heights(pointers(dragon), 0), Error);
  EXPECT_THROW(level_heights(pointers(dragon), NAN), Error);
}

TEST(LevelStack, BranchingOfTheCurvesThatRefineSegmentBySegment) {
  EXPECT_EQ(refinement_branching(pointers(levels_of(table1::dragon(), 5))), 2);
  EXPECT_EQ(refinement_branching(pointers(levels_of(table1::terdragon(), 4))), 3);
  EXPECT_EQ(refinement_branching(pointers(levels_of(table1::koch_snowflake(), 3))), 4);
  EXPECT_EQ(refinement_branching(pointers(levels_of(table1::gosper(), 3))), 7);
  // The arrowhead is an edge-replacement curve too (three segments for one, alternating sides), so its
  // normalised levels share their vertices; Hilbert levels are not made segment by segment.
  EXPECT_EQ(refinement_branching(pointers(levels_of(table1::arrowhead(), 5))), 3);
  EXPECT_THROW(refinement_branching(pointers(levels_of(table1::hilbert(), 3))), Error);
}

TEST(ControlMesh, DragonIsADiskOfThreeTriangleTiles) {
  const int top = 7;
  const auto levels = levels_of(table1::dragon(), top);
  const Mesh m = control_mesh(pointers(levels), {}, no_progress());
  std::size_t points = 0, faces = 0;
  for (int l = 0; l <= top; ++l) points += (std::size_t{1} << l) + 1;
  for (int l = 0; l < top; ++l) faces += 3 * (std::size_t{1} << l);
  EXPECT_EQ(m.points.size(), points);
  EXPECT_EQ(m.faces(), faces);
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.manifold()) << t.first_problem;
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_EQ(t.euler(), 1);  // a disk
  EXPECT_NO_THROW(m.validate());
  // Tiles are numbered from 0 level by level: 2^top − 1 of them, one per coarse segment.
  EXPECT_EQ(m.face_fields.find("tile")->at(m.faces() - 1), double((std::size_t{1} << top) - 2));
  EXPECT_EQ(m.point_fields.find("level")->at(m.points.size() - 1), top);
}

TEST(ControlMesh, TerdragonAndGosperTilesHaveOnePlusBTriangles) {
  for (auto [g, b] : {std::pair{table1::terdragon(), 3}, std::pair{table1::gosper(), 7}}) {
    const auto levels = levels_of(g, 3);
    const Mesh m = control_mesh(pointers(levels), {}, no_progress());
    std::size_t faces = 0;
    for (int l = 0; l < 3; ++l)
      faces += levels[static_cast<std::size_t>(l)].segments() * (1 + static_cast<std::size_t>(b));
    EXPECT_EQ(m.faces(), faces) << b;
    const MeshTopology t = mesh_topology(m);
    EXPECT_TRUE(t.manifold()) << t.first_problem;
    EXPECT_EQ(t.euler(), 1) << b;
  }
}

TEST(ControlMesh, ClosedLevelsMakeAnAnnulus) {
  const auto levels = levels_of(table1::koch_snowflake(), 4);
  const Mesh m = control_mesh(pointers(levels), {}, no_progress());
  std::size_t points = 0;
  for (int l = 0; l <= 4; ++l) points += 3 * (std::size_t{1} << (2 * l));  // a loop's end point once
  EXPECT_EQ(m.points.size(), points);
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.manifold()) << t.first_problem;
  EXPECT_EQ(t.boundary_loops, 2u);
  EXPECT_EQ(t.euler(), 0);  // an annulus
}

TEST(ControlMesh, CornerShiftMovesInnerPointsTowardsTheirNeighbours) {
  const auto levels = levels_of(table1::dragon(), 3);
  const Mesh plain = control_mesh(pointers(levels), {}, no_progress());
  const Mesh shifted = control_mesh(pointers(levels), {.corner_shift = 0.2}, no_progress());
  // Level 1 is points 2, 3, 4: its ends stay, its middle moves a fifth of the way to their midpoint.
  EXPECT_EQ(shifted.points[2], plain.points[2]);
  EXPECT_EQ(shifted.points[4], plain.points[4]);
  const Vec3 mid = 0.5 * (plain.points[2] + plain.points[4]);
  EXPECT_LT(norm(shifted.points[3] - (plain.points[3] + 0.2 * (mid - plain.points[3]))), 1e-15);
  EXPECT_THROW(control_mesh(pointers(levels), {.corner_shift = 0.7}, no_progress()), Error);
}
