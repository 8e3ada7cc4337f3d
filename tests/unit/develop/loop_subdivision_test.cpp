// Loop subdivision: the weights (partition of unity, Loop's β), the closed-form counts, topology kept, corners
// kept, boundaries refined as cubic B-splines, fields carried.
#include "kernels/develop/loop_subdivision.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../lsystem/table1.h"
#include "kernels/develop/control_mesh.h"
#include "kernels/geom/error.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/lsystem/turtle2d.h"

using namespace selfsim;
using namespace selfsim::develop;

namespace {

Mesh control(const lsystem::Grammar& g, int top) {
  std::vector<Polyline> levels;
  for (int l = 0; l <= top; ++l) levels.push_back(lsystem::turtle2d(g, {.level = l}, no_progress()));
  std::vector<const Polyline*> p;
  for (const Polyline& c : levels) p.push_back(&c);
  return control_mesh(p, {}, no_progress());
}

Mesh octahedron() {
  Mesh m;
  m.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

}  // namespace

TEST(Loop, BetaIsLoopsWeight) {
  EXPECT_DOUBLE_EQ(loop_beta(6), 1.0 / 16);  // regular points: the box spline
  EXPECT_DOUBLE_EQ(loop_beta(3), 3.0 / 16);
}

TEST(Loop, WeightsArePartitionsOfUnity) {
  // A constant field stays constant, and a translated mesh subdivides to the translated result, at
  // interior, boundary and corner points alike (the dragon's control mesh has all three).
  Mesh m = control(table1::dragon(), 5);
  m.point_fields.set(real_field("one", std::vector<double>(m.points.size(), 1)));
  Mesh moved = m;
  for (Vec3& p : moved.points) p = p + Vec3{3, -2, 5};
  const Mesh s = loop_subdivide(m, {.steps = 2}, no_progress());
  const Mesh t = loop_subdivide(moved, {.steps = 2}, no_progress());
  const Field* one = s.point_fields.find("one");
  ASSERT_NE(one, nullptr);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    EXPECT_NEAR(one->at(i), 1, 1e-14) << i;
    EXPECT_LT(norm(t.points[i] - (s.points[i] + Vec3{3, -2, 5})), 1e-12) << i;
  }
}

TEST(Loop, CountsFollowTheClosedFormsAndTopologyIsKept) {
  for (const Mesh& m : {control(table1::dragon(), 6), control(table1::koch_snowflake(), 3), octahedron()}) {
    const MeshTopology before = mesh_topology(m);
    for (int steps : {1, 2, 3}) {
      const Mesh s = loop_subdivide(m, {.steps = steps}, no_progress());
      EXPECT_EQ(static_cast<double>(s.points.size() + s.faces()), loop_size(m, steps));
      EXPECT_EQ(s.faces(), m.faces() << (2 * steps));
      const MeshTopology after = mesh_topology(s);
      EXPECT_TRUE(after.manifold()) << after.first_problem;
      EXPECT_EQ(after.euler(), before.euler());
      EXPECT_EQ(after.boundary_loops, before.boundary_loops);
      EXPECT_EQ(after.components, before.components);
    }
  }
}

TEST(Loop, OctahedronPointsMoveTowardsTheLimitSphere) {
  // A regular closed mesh of valence 4: every old point moves inwards by the same amount, and the surface
  // stays symmetric.
  const Mesh s = loop_subdivide(octahedron(), {.steps = 1}, no_progress());
  const double r = norm(s.points[0]);
  for (std::size_t i = 0; i < 6; ++i) EXPECT_NEAR(norm(s.points[i]), r, 1e-15);
  EXPECT_LT(r, 1);
  const double beta = loop_beta(4);
  EXPECT_NEAR(r, 1 - 4 * beta, 1e-15);  // (1 − 4β)·v + β·(four neighbours summing to 0)
}

TEST(Loop, CornersStayAndBoundariesAreCubicBSplines) {
  const Mesh m = control(table1::dragon(), 3);
  // Point 0 is level 0's start: kept when named a corner, moved along the boundary otherwise.
  const Mesh kept = loop_subdivide(m, {.steps = 2, .corners = {0}}, no_progress());
  EXPECT_EQ(kept.points[0], m.points[0]);
  const Mesh s = loop_subdivide(m, {.steps = 1}, no_progress());
  EXPECT_NE(s.points[0], m.points[0]);
  // The finest level's last point lies in one triangle: a corner whatever the caller says.
  EXPECT_EQ(s.points[m.points.size() - 1], m.points.back());
  // A boundary point moves as a cubic B-spline point: 3/4 of itself and 1/8 of each boundary neighbour.
  // Level 0's end (point 1) has the boundary neighbours level 0's start (point 0) and level 1's end (point 4).
  const Vec3 spline = 0.75 * m.points[1] + 0.125 * (m.points[0] + m.points[4]);
  EXPECT_LT(norm(s.points[1] - spline), 1e-15);
  // Face fields pass to the four children.
  const Field* tile = s.face_fields.find("tile");
  for (std::size_t f = 0; f < m.faces(); ++f)
    for (std::size_t c = 0; c < 4; ++c) EXPECT_EQ(tile->at(4 * f + c), m.face_fields.find("tile")->at(f));
}

TEST(Loop, Errors) {
  Mesh bowtie;
  bowtie.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}};
  bowtie.triangles = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_THROW(loop_subdivide(bowtie, {.steps = 1}, no_progress()), Error);
  EXPECT_THROW(loop_subdivide(octahedron(), {.steps = 13}, no_progress()), Error);
  LoopOptions big{.steps = 8};
  big.budget.limit = 1000;
  EXPECT_THROW(loop_subdivide(octahedron(), big, no_progress()), BudgetError);
}
