// Loop subdivision: the weights (partition of unity, Loop's β), the closed-form counts, topology kept, corners
// kept, boundaries refined as cubic B-splines, fields carried.
#include "kernels/develop/loop_subdivision.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "../lsystem/table1.h"
#include "kernels/base/error.h"
#include "kernels/develop/control_mesh.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/lsystem/turtle/turtle2d.h"

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

TEST(Loop, BoundedMasksArePartitionsOfUnityWithNonNegativeWeights) {
  for (std::size_t n = 3; n <= 40; ++n) {
    const EdgeMask mask = bounded_edge_mask(n);
    ASSERT_EQ(mask.ring.size(), n);
    double sum = mask.centre;
    EXPECT_GE(mask.centre, 0) << n;
    for (double w : mask.ring) {
      EXPECT_GE(w, -1e-15) << n;
      sum += w;
    }
    EXPECT_NEAR(sum, 1, 1e-14) << n;
    const double beta = bounded_beta(n);
    EXPECT_GT(beta, 0) << n;
    EXPECT_GE(1 - static_cast<double>(n) * beta, 0) << n;
  }
}

TEST(Loop, BoundedMaskIsTheRegularRuleAtValenceSixAndClassicBelow) {
  const EdgeMask six = bounded_edge_mask(6);
  const std::vector<double> regular{0.375, 0.125, 0, 0, 0, 0.125};
  EXPECT_NEAR(six.centre, 0.375, 1e-15);
  for (std::size_t k = 0; k < 6; ++k) EXPECT_NEAR(six.ring[k], regular[k], 1e-15) << k;
  // The n = 6 formula of the n >= 7 branch gives the same (the mask equation's roots -1, -1/2, -1/2).
  EXPECT_DOUBLE_EQ(bounded_beta(6), loop_beta(6));
  EXPECT_DOUBLE_EQ(bounded_beta(5), loop_beta(5));
}

TEST(Loop, BoundedMaskHasTheEigenvaluesItPromises) {
  // The ring's Fourier modes k = 1, 2, 3 are scaled by L, L^2 and c3 < L^2 (classic Loop's mode 2 exceeds
  // L^2 from valence 7 on: unbounded curvature), and the constant mode's second eigenvalue is L^2 too.
  for (std::size_t n = 7; n <= 30; ++n) {
    const double pi = std::numbers::pi, l = 0.375 + 0.25 * std::cos(2 * pi / static_cast<double>(n));
    const EdgeMask mask = bounded_edge_mask(n);
    auto mode = [&](int k) {
      double s = 0;
      for (std::size_t j = 0; j < n; ++j)
        s += mask.ring[j] * std::cos(2 * pi * k * static_cast<double>(j) / static_cast<double>(n));
      return s;
    };
    EXPECT_NEAR(mode(1), l, 1e-14) << n;
    EXPECT_NEAR(mode(2), l * l, 1e-14) << n;
    EXPECT_LT(mode(3), l * l) << n;
    EXPECT_GT(0.375 + 0.25 * std::cos(4 * pi / static_cast<double>(n)), l * l) << n;  // why the variant exists
    EXPECT_NEAR(1 - static_cast<double>(n) * bounded_beta(n) - mask.centre, l * l, 1e-14) << n;
  }
}

TEST(Loop, BoundedVariantKeepsConstantsAndOnlyMovesPointsNearValenceSevenOrMore) {
  Mesh m = control(table1::dragon(), 5);
  m.point_fields.set(real_field("one", std::vector<double>(m.points.size(), 1)));
  const Mesh classic = loop_subdivide(m, {.steps = 1}, no_progress());
  const Mesh bounded = loop_subdivide(m, {.steps = 1, .bounded = true}, no_progress());
  ASSERT_EQ(classic.points.size(), bounded.points.size());
  const Field* one = bounded.point_fields.find("one");
  std::size_t moved = 0;
  for (std::size_t i = 0; i < bounded.points.size(); ++i) {
    EXPECT_NEAR(one->at(i), 1, 1e-14) << i;
    if (norm(bounded.points[i] - classic.points[i]) > 1e-12) ++moved;
  }
  EXPECT_GT(moved, 0u);  // the dragon's control mesh has interior points of valence 7
  EXPECT_LT(moved, bounded.points.size());
  // The octahedron has valence 4 only: the same result.
  const Mesh a = loop_subdivide(octahedron(), {.steps = 2}, no_progress());
  const Mesh b = loop_subdivide(octahedron(), {.steps = 2, .bounded = true}, no_progress());
  for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i], b.points[i]);
}
