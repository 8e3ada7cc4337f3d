// Seed 002 §3.1: the smoothed level curves (midpoints, ends, circular arcs, straight lines kept straight), the
// zipper between rows, and the surface's rows, counts, topology and orientation, for curves whose levels
// refine segment by segment (dragon, Koch snowflake) and for the Hilbert curve, whose levels do not.
#include "kernels/develop/bezier_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "../lsystem/table1.h"
#include "kernels/base/error.h"
#include "kernels/develop/control_mesh.h"
#include "kernels/develop/develop.h"
#include "kernels/develop/level_stack.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/lsystem/turtle/turtle2d.h"

using namespace selfsim;
using namespace selfsim::develop;

namespace {

std::vector<Polyline> levels_of(const lsystem::Grammar& g, int first, int last) {
  std::vector<Polyline> out;
  for (int l = first; l <= last; ++l) out.push_back(lsystem::turtle2d(g, {.level = l}, no_progress()));
  return out;
}

std::vector<const Polyline*> pointers(const std::vector<Polyline>& v) {
  std::vector<const Polyline*> p;
  for (const Polyline& c : v) p.push_back(&c);
  return p;
}

// The sum of the triangles' area normals: which way a surface faces, on the whole.
Vec3 vector_area(const Mesh& m) {
  Vec3 sum;
  for (const Triangle& t : m.triangles) sum += area_normal(m, t);
  return sum;
}

void expect_topology(const Mesh& m, long long euler, std::size_t loops) {
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.manifold()) << t.first_problem;
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.vertices, m.points.size());
  EXPECT_EQ(t.euler(), euler);
  EXPECT_EQ(t.boundary_loops, loops);
  EXPECT_NO_THROW(m.validate());
}

struct Counting : Progress {
  int steps = 0;
  double last = 0;
  int cancel_after = -1;
  void fraction(double done) override {
    ++steps;
    last = done;
  }
  bool cancelled() override { return cancel_after >= 0 && steps > cancel_after; }
};

}  // namespace

TEST(SmoothedLevel, PassesThroughMidpointsAndEnds) {
  const std::vector<Vec2> pts{{0, 0}, {1, 0}, {1, 1}, {2, 1.5}, {2.5, 0.5}, {1.5, -0.5}};
  for (bool closed : {false, true}) {
    std::vector<Vec2> p = pts;
    if (closed) p.push_back(p.front());
    const Polyline c = Polyline::single(p);
    const std::size_t n = p.size() - 1;
    for (std::size_t j = 0; j < n; ++j) {
      const Vec2 mid = 0.5 * (p[j] + p[j + 1]);
      const double t = (static_cast<double>(j) + 0.5) / static_cast<double>(n);
      EXPECT_LT(norm(smoothed_level_point(c, t) - mid), 1e-12) << closed << " " << j;
    }
    if (!closed) {
      EXPECT_LT(norm(smoothed_level_point(c, 0) - p.front()), 1e-15);
      EXPECT_LT(norm(smoothed_level_point(c, 1) - p.back()), 1e-15);
    } else {  // a loop: t = 0 and t = 1 are the same point, on the arc at the start corner
      EXPECT_LT(norm(smoothed_level_point(c, 0) - smoothed_level_point(c, 1)), 1e-12);
    }
  }
  EXPECT_THROW(smoothed_level_point(Polyline::single(pts), 1.5), Error);
}

TEST(SmoothedLevel, CornersFollowCircularArcs) {
  // Segments of length 1 meeting at turning angle φ: tangent points h = 1/2 from the corner, radius
  // h/tan(φ/2), centre on the normal at the first midpoint. The piece's middle (t = 1/2) is within 0.1%.
  for (double degrees : {90.0, 60.0, 30.0, 120.0}) {
    const double phi = degrees * std::numbers::pi / 180, h = 0.5, r = h / std::tan(phi / 2);
    const Polyline c = Polyline::single({{0, 0}, {1, 0}, {1 + std::cos(phi), std::sin(phi)}});
    const Vec2 centre{0.5, r};
    EXPECT_NEAR(norm(smoothed_level_point(c, 0.5) - centre), r, 1e-3 * r) << degrees;
    if (degrees <= 90) {  // the whole piece, u ∈ [1/2, 3/2], for angles up to a right angle
      for (double u = 0.5; u <= 1.5; u += 1.0 / 64)
        EXPECT_NEAR(norm(smoothed_level_point(c, u / 2) - centre), r, 1e-3 * r) << degrees << " " << u;
    }
  }
  // A full reversal has no arc: the handles shrink to nothing (k → 0), never NaN.
  const Polyline back = Polyline::single({{0, 0}, {1, 0}, {0.2, 0}});
  for (double t = 0; t <= 1; t += 1.0 / 32) EXPECT_TRUE(is_finite(smoothed_level_point(back, t))) << t;
}

TEST(SmoothedLevel, StraightStaysStraight) {
  const Polyline c = Polyline::single({{0, 0}, {0.3, 0.6}, {1, 2}, {1.5, 3}});
  const Vec2 along{1, 2};
  for (double t = 0; t <= 1; t += 1.0 / 100) EXPECT_NEAR(cross(smoothed_level_point(c, t), along), 0, 1e-12) << t;
}

TEST(ZipRows, JoinsRowsOfDifferentCountsIntoAStrip) {
  for (bool closed : {false, true}) {
    Mesh m;
    std::vector<double> upper, lower;
    for (int k = 0; k < 5; ++k) upper.push_back(k / (closed ? 5.0 : 4.0));
    for (int k = 0; k < 13; ++k) lower.push_back(k / (closed ? 13.0 : 12.0) + (closed ? 0.01 : 0));
    // On a cylinder: all the way round for closed rows, a third of the way for open ones.
    const double turn = closed ? 2 * std::numbers::pi : 2;
    for (double t : upper) m.points.push_back({std::cos(turn * t), std::sin(turn * t), 0});
    for (double t : lower) m.points.push_back({std::cos(turn * t), std::sin(turn * t), -1});
    m.triangles.resize(closed ? 18 : 16);
    zip_rows(upper, 0, lower, 5, closed, m.triangles);
    expect_topology(m, closed ? 0 : 1, closed ? 2 : 1);
    // Every triangle faces the same way: ∂f/∂s × ∂f/∂t, outwards from the cylinder here.
    for (const Triangle& t : m.triangles) {
      const Vec3 c = (m.points[t[0]] + m.points[t[1]] + m.points[t[2]]) / 3;
      EXPECT_GT(dot(area_normal(m, t), Vec3{c.x, c.y, 0}), 0) << closed;
    }
  }
  std::vector<Triangle> wrong(3);
  EXPECT_THROW(zip_rows(std::vector<double>{0, 1}, 0, std::vector<double>{0, 1}, 2, false, wrong), Error);
}

TEST(BezierSurface, CountsByFormula) {
  // Level 0: one segment (2 pieces, 8 intervals at resolution 4); level 1: two (3 pieces, 12 intervals).
  // Gap 1, level 1's spacing 0.5/4: 8 row steps. Points 9 + 8·13, triangles 8 + 12 + 7·24.
  const std::vector<Polyline> levels{Polyline::single({{0, 0}, {1, 0}}), Polyline::single({{0, 0}, {0.5, 0}, {1, 0}})};
  EXPECT_EQ(bezier_size(pointers(levels), {}), 113 + 188);
  const Mesh m = bezier_surface(pointers(levels), {}, no_progress());
  EXPECT_EQ(m.points.size(), 113u);
  EXPECT_EQ(m.faces(), 188u);
  for (const Vec3& p : m.points) EXPECT_EQ(p.y, 0);  // straight levels make a flat surface
  expect_topology(m, 1, 1);
}

TEST(BezierSurface, DragonIsADiskThroughEveryLevel) {
  const auto levels = levels_of(table1::dragon(), 0, 6);
  const auto ptrs = pointers(levels);
  for (int resolution : {1, 4}) {
    const BezierOptions opt{.height = 0.5, .resolution = resolution};
    Counting progress;
    const Mesh m = bezier_surface(ptrs, opt, progress);
    EXPECT_EQ(static_cast<double>(m.points.size() + m.faces()), bezier_size(ptrs, opt));
    expect_topology(m, 1, 1);
    EXPECT_EQ(progress.last, 1);
    EXPECT_GT(progress.steps, 2 * 6);  // one a row, at least two rows a band

    // The points whose level field is an integer i form level i's row: at height z_i, on level i's smoothed
    // curve (through all its segment midpoints), R·(n + 1) + 1 of them.
    const std::vector<double> z = level_heights(ptrs, opt.height);
    const Field* level = m.point_fields.find("level");
    ASSERT_NE(level, nullptr);
    ASSERT_NE(m.face_fields.find("level"), nullptr);
    for (std::size_t l = 0; l < levels.size(); ++l) {
      std::vector<Vec3> row;
      for (std::size_t k = 0; k < m.points.size(); ++k)
        if (level->at(k) == static_cast<double>(l)) row.push_back(m.points[k]);
      EXPECT_EQ(row.size(), static_cast<std::size_t>(resolution) * (levels[l].segments() + 1) + 1) << l;
      for (const Vec3& p : row) EXPECT_EQ(p.z, z[l]) << l;
      const auto pts = levels[l].path(0);
      for (std::size_t j = 0; j + 1 < pts.size(); ++j) {
        const Vec2 mid = 0.5 * (pts[j] + pts[j + 1]);
        double nearest = 1;
        for (const Vec3& p : row) nearest = std::min(nearest, norm(Vec2{p.x, p.y} - mid));
        EXPECT_LT(nearest, 1e-12) << l << " " << j;
      }
    }
  }
}

TEST(BezierSurface, FacesTheWayTheControlMeshDoes) {
  const auto levels = levels_of(table1::dragon(), 0, 4);
  const Mesh bezier = bezier_surface(pointers(levels), {}, no_progress());
  const Mesh control = control_mesh(pointers(levels), {}, no_progress());
  const Vec3 a = vector_area(bezier), b = vector_area(control);
  EXPECT_GT(dot(a, b), 0.5 * norm(a) * norm(b));
  // Flat levels along +x: the surface is the plane y = 0, facing −y (to the right of the direction of travel).
  const std::vector<Polyline> flat{Polyline::single({{0, 0}, {1, 0}}), Polyline::single({{0, 0}, {0.5, 0}, {1, 0}})};
  EXPECT_LT(vector_area(bezier_surface(pointers(flat), {}, no_progress())).y, 0);
  EXPECT_LT(vector_area(control_mesh(pointers(flat), {}, no_progress())).y, 0);
}

TEST(BezierSurface, HilbertLevelsNeedNotNest) {
  const auto levels = levels_of(table1::hilbert(), 1, 3);  // 15, 63, 255 segments
  const auto ptrs = pointers(levels);
  EXPECT_THROW(refinement_branching(ptrs), Error);  // the control mesh cannot take them
  const Mesh m = bezier_surface(ptrs, {}, no_progress());
  EXPECT_EQ(static_cast<double>(m.points.size() + m.faces()), bezier_size(ptrs, {}));
  expect_topology(m, 1, 1);
  const std::vector<double> z = level_heights(ptrs, 1);
  EXPECT_EQ(m.bbox().max.z, 0);
  EXPECT_EQ(m.bbox().min.z, z.back());
}

TEST(BezierSurface, ClosedLevelsMakeAnAnnulus) {
  const auto levels = levels_of(table1::koch_snowflake(), 0, 3);
  const auto ptrs = pointers(levels);
  ASSERT_TRUE(closed_levels(ptrs));
  const BezierOptions opt{.resolution = 3};
  const Mesh m = bezier_surface(ptrs, opt, no_progress());
  EXPECT_EQ(static_cast<double>(m.points.size() + m.faces()), bezier_size(ptrs, opt));
  expect_topology(m, 0, 2);
  const Field* level = m.point_fields.find("level");
  std::size_t top = 0;  // a closed row has no repeated seam point: R·n samples
  for (std::size_t k = 0; k < m.points.size(); ++k) top += level->at(k) == 0;
  EXPECT_EQ(top, 3u * 3);
}

TEST(BezierSurface, RefusesBadLevelsNamingTheProblem) {
  const Polyline a = Polyline::single({{0, 0}, {1, 0}}), b = Polyline::single({{0, 0}, {0.5, 0.5}, {1, 0}});
  const Polyline point = Polyline::single({{0, 0}});
  const Polyline repeated = Polyline::single({{0, 0}, {0.5, 0.5}, {0.5, 0.5}, {1, 0}});
  const Polyline loop = Polyline::single({{0, 0}, {1, 0}, {0, 1}, {0, 0}});
  auto message = [](std::vector<const Polyline*> levels, const BezierOptions& opt = {}) {
    try {
      bezier_surface(levels, opt, no_progress());
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({&a, &point}).find("level 1 has no segment"), std::string::npos);
  EXPECT_NE(message({&a, &repeated}).find("level 1 has a zero-length segment (its points 2 and 3"), std::string::npos);
  EXPECT_NE(message({&a, &loop}).find("all open or all closed"), std::string::npos);
  EXPECT_NE(message({&a}).find("at least two levels"), std::string::npos);
  EXPECT_NE(message({&a, &b}, {.resolution = 0}).find("option 'resolution'"), std::string::npos);
  EXPECT_NE(message({&a, &b}, {.resolution = 65}).find("option 'resolution'"), std::string::npos);
  EXPECT_NE(message({&a, &b}, {.height = 0}).find("option 'height'"), std::string::npos);
  EXPECT_NE(message({&a, &b}, {.height = NAN}).find("option 'height'"), std::string::npos);
}

TEST(BezierSurface, RefusesOverBudgetBeforeAnyWork) {
  const auto levels = levels_of(table1::hilbert(), 0, 3);
  const auto ptrs = pointers(levels);
  const double size = bezier_size(ptrs, {});
  BezierOptions opt;
  opt.budget.limit = size - 1;
  EXPECT_THROW(bezier_surface(ptrs, opt, no_progress()), BudgetError);
  opt.budget.limit = size;
  EXPECT_NO_THROW(bezier_surface(ptrs, opt, no_progress()));
  // Far more rows than memory could hold: refused at once, not attempted.
  EXPECT_THROW(bezier_surface(ptrs, {.height = 1e200}, no_progress()), BudgetError);
}

TEST(BezierSurface, StopsWhenCancelled) {
  const auto levels = levels_of(table1::dragon(), 0, 5);
  Counting progress;
  progress.cancel_after = 3;
  EXPECT_THROW(bezier_surface(pointers(levels), {}, progress), Cancelled);
}

TEST(BezierSurface, ThickenedThroughDevelopIsAClosedSolid) {
  // Route 2 by develop_surface: the predicted size is exact, the solid closed and consistently oriented (a
  // sphere for open levels, a torus for the snowflake's closed ones), the thickness shrinking down the stack.
  struct Case {
    lsystem::Grammar g;
    int first, last;
    long long euler;
  };
  for (const Case& c : {Case{table1::hilbert(), 0, 3, 2}, Case{table1::koch_snowflake(), 0, 3, 0}}) {
    const auto levels = levels_of(c.g, c.first, c.last);
    DevelopOptions opt;
    opt.method = Method::bezier;
    opt.thickness = 0.02;
    opt.thickness_rate = 0.7;
    const Mesh m = develop_surface(pointers(levels), opt, no_progress());
    const BezierCounts n = bezier_counts(pointers(levels), {.height = 1, .resolution = 4});
    EXPECT_EQ(static_cast<double>(m.points.size() + m.faces()), 2 * (n.points + n.triangles + n.boundary_edges));
    const MeshTopology t = mesh_topology(m);
    EXPECT_TRUE(t.closed()) << t.first_problem;
    EXPECT_EQ(t.euler(), c.euler);
    const Field* thickness = m.point_fields.find("thickness");
    ASSERT_NE(thickness, nullptr);
    EXPECT_NEAR(thickness->at(0), 0.02, 1e-15);  // level 0's row starts the mesh
    EXPECT_NEAR(thickness->at(m.points.size() / 2 - 1), 0.02 * std::pow(0.7, c.last), 1e-12);  // the finest's
  }
}
