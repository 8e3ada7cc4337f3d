// Tubes whose volume has an exact formula (a polygon prism along a straight segment, a mitred square torus,
// an untwisted helix, a tapering frustum chain), frames checked against parallel transport (no twist on an
// open path, the holonomy spread evenly on a closed one), fields carried, every refusal, and sizes against
// tube_size's prediction.
#include "kernels/print/tube.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"
#include "tests/unit/print/lathe_fixture.h"

using namespace selfsim;
using namespace selfsim::print;

namespace {

constexpr double pi = std::numbers::pi;

// The area of the regular polygon of `sides` corners on a circle of radius r: the tube's cross-section.
using lathe_fixture::polygon_area;

// The tube around c with radii r, checked for what every tube must be: valid, closed, manifold, outward,
// and exactly as large as tube_size said.
Mesh built(const Polyline3& c, std::vector<double> r, int sides = 16) {
  TubeOptions opt;
  opt.sides = sides;
  Mesh m = tube(c, r, opt, no_progress());
  EXPECT_NO_THROW(m.validate());
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.closed()) << t.first_problem;
  EXPECT_GT(enclosed_volume(m), 0);
  EXPECT_EQ(static_cast<double>(m.points.size() + m.triangles.size()), tube_size(c, opt));
  return m;
}

Mesh built(const Polyline3& c, double r, int sides = 16) {
  return built(c, std::vector<double>(c.points.size(), r), sides);
}

Polyline3 curve(const std::vector<std::vector<Vec3>>& paths) {
  Polyline3 c;
  for (const auto& p : paths) {
    c.points.insert(c.points.end(), p.begin(), p.end());
    c.close_path();
  }
  return c;
}

// The angle by which a wall's edge from tube point pa (on the ring around centre ca) to tube point pb (on the
// ring around cb) turns about the segment's direction: zero for parallel transport.
double twist(const Mesh& m, Vec3 ca, Vec3 cb, std::size_t pa, std::size_t pb) {
  const Vec3 t = normalized(cb - ca);
  Vec3 da = m.points[pa] - ca, db = m.points[pb] - cb;
  da = da - dot(da, t) * t;
  db = db - dot(db, t) * t;
  return std::atan2(dot(cross(da, db), t), dot(da, db));
}

// The same for ring point 0 of consecutive rings a and b (rings of 16 points, counted from mesh point 0).
double twist(const Mesh& m, std::span<const Vec3> centres, std::size_t a, std::size_t b) {
  return twist(m, centres[a], centres[b], a * 16, b * 16);
}

std::string refusal(const Polyline3& c, std::vector<double> r, int sides = 16) {
  TubeOptions opt;
  opt.sides = sides;
  try {
    tube(c, r, opt, no_progress());
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

std::string refusal(const Polyline3& c, double r) { return refusal(c, std::vector<double>(c.points.size(), r)); }

std::vector<Vec3> helix(int points, double turns) {
  std::vector<Vec3> p;
  for (int i = 0; i < points; ++i) {
    const double a = 2 * pi * turns * i / (points - 1);
    p.push_back({std::cos(a), std::sin(a), 0.8 * turns * i / (points - 1)});
  }
  return p;
}

}  // namespace

TEST(Tube, StraightSegmentIsAPolygonPrism) {
  for (int sides : {3, 7, 16}) {
    for (Vec3 end : {Vec3{3, 0, 0}, Vec3{1, 2, 3}, Vec3{0, 0, -2}}) {
      const Mesh m = built(curve({{{0, 0, 0}, end}}), 0.5, sides);
      EXPECT_EQ(mesh_topology(m).euler(), 2);
      EXPECT_EQ(mesh_topology(m).components, 1u);
      EXPECT_EQ(m.points.size(), 2u * sides + 2);
      EXPECT_EQ(m.triangles.size(), 4u * sides);
      EXPECT_NEAR(enclosed_volume(m), polygon_area(sides, 0.5) * norm(end), 1e-12);
    }
  }
}

TEST(Tube, ClosedSquareIsAMitredTorus) {
  for (double gap : {0.0, 1e-12}) {  // exactly closed, and closed to a rounding error
    const Polyline3 c = curve({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {gap, 0, 0}}});
    const Mesh m = built(c, 0.1);
    EXPECT_EQ(mesh_topology(m).euler(), 0);
    EXPECT_EQ(m.points.size(), 4u * 16);  // no ring for the repeated point, no cap centres
    // Each side is a prism cut by mitre planes through the axis: the section's area times the axis length.
    EXPECT_NEAR(enclosed_volume(m), polygon_area(16, 0.1) * 4, 1e-12);
    // The corner's ring is stretched by 1/cos(45 degrees) in the bend direction, where ring point 0 lies.
    double farthest = 0;
    for (int k = 0; k < 16; ++k) farthest = std::max(farthest, norm(m.points[k] - Vec3{0, 0, 0}));
    EXPECT_NEAR(farthest, 0.1 * std::sqrt(2.0), 1e-12);
  }
}

TEST(Tube, HelixIsUntwistedAndHasThePrismVolume) {
  const std::vector<Vec3> p = helix(91, 3);
  const Polyline3 c = curve({p});
  const Mesh m = built(c, 0.1);  // tube() looked for self-intersections and found none
  EXPECT_EQ(mesh_topology(m).euler(), 2);
  for (std::size_t j = 0; j + 1 < p.size(); ++j) EXPECT_NEAR(twist(m, p, j, j + 1), 0, 1e-12) << j;
  // Mitred prisms of an untwisted tube: exactly the section's area times the length, whatever the bends.
  EXPECT_NEAR(enclosed_volume(m) / (polygon_area(16, 0.1) * c.length()), 1, 1e-12);
}

TEST(Tube, PlanarZigzagKeepsRingPointZeroInItsPlane) {
  std::vector<Vec3> flat;
  for (int i = 0; i < 10; ++i) flat.push_back({0.5 * i, 0.4 * (i % 2), 0});
  const Mesh m = built(curve({flat}), 0.05);
  for (std::size_t i = 0; i < flat.size(); ++i) EXPECT_NEAR(m.points[i * 16].z, 0, 1e-15) << i;

  // The same zigzag tilted: ring point 0 keeps one height over the zigzag's plane (it follows the transported
  // frame, which never turns about the plane's normal).
  const Vec3 n = normalized(Vec3{1, 2, 2}), e1 = normalized(cross(n, Vec3{0, 0, 1})), e2 = cross(n, e1);
  std::vector<Vec3> tilted;
  for (Vec3 q : flat) tilted.push_back(Vec3{3, -1, 2} + q.x * e1 + q.y * e2);
  const Mesh t = built(curve({tilted}), 0.05);
  const double height = dot(t.points[0] - tilted[0], n);
  EXPECT_GT(std::abs(height), 1e-3);  // the frame does start out of the plane, so the check means something
  for (std::size_t i = 0; i < tilted.size(); ++i) EXPECT_NEAR(dot(t.points[i * 16] - tilted[i], n), height, 1e-12);
}

TEST(Tube, ClosedTwistedLoopSpreadsItsHolonomyEvenly) {
  std::vector<Vec3> p;
  const int n = 120;
  for (int i = 0; i <= n; ++i) {
    const double a = 2 * pi * i / n;
    p.push_back({std::cos(a) + 0.3 * std::cos(2 * a), std::sin(a), 0.5 * std::sin(3 * a) + 0.2 * std::cos(a)});
  }
  p.back() = p.front();
  const Mesh m = built(curve({p}), 0.05);
  EXPECT_EQ(mesh_topology(m).euler(), 0);
  const double first = twist(m, p, 0, 1);
  EXPECT_GT(std::abs(first), 1e-4);  // this loop's frame does come back turned
  // By at most half a side over the loop: the seam joins ring point 0 to another point of the first ring.
  EXPECT_LE(std::abs(first) * n, pi / 16 + 1e-12);
  for (int j = 1; j + 1 < n; ++j) EXPECT_NEAR(twist(m, p, j, j + 1), first, 1e-12) << j;
  // The seam's first wall triangle is (last ring's point 0, its point 1, the first ring's point it joins).
  const std::uint32_t joined = m.triangles[2 * 16 * (n - 1) + 1][2];
  EXPECT_NE(joined, 0u);  // this loop's seam does join ring point 0 to another point
  EXPECT_NEAR(twist(m, p[n - 1], p[0], (n - 1) * 16, joined), first, 1e-12);
  // Twisted walls are no longer prisms: a twisted quad's diagonal moves the volume by a fraction of the order
  // of the twist per segment (at most pi / (16 * 120) = 0.0016 radians here).
  EXPECT_NEAR(enclosed_volume(m) / (polygon_area(16, 0.05) * curve({p}).length()), 1, 3e-4);
}

TEST(Tube, RadiiFromAPointFieldTaperAndFieldsAreCarried) {
  Polyline3 c = curve({{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}});
  c.point_fields.set(int_field("level", {0, 1, 2, 3, 4}));
  c.cell_fields.set(int_field("curve", {7}));
  std::vector<double> r;
  for (int level = 0; level < 5; ++level) r.push_back(0.3 * std::pow(0.7, level));
  const Mesh m = built(c, r);
  // Straight and untwisted: a chain of polygon frustums, (r0^2 + r0 r1 + r1^2) / 3 times the area factor.
  double volume = 0;
  for (int i = 0; i < 4; ++i) volume += polygon_area(16, 1) * (r[i] * r[i] + r[i] * r[i + 1] + r[i + 1] * r[i + 1]) / 3;
  EXPECT_NEAR(enclosed_volume(m), volume, 1e-12);

  const Field* level = m.point_fields.find("level");
  const Field* radius = m.point_fields.find("radius");
  ASSERT_TRUE(level && radius);
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t k = 0; k < 16; ++k) {
      const std::size_t q = i * 16 + k;
      EXPECT_EQ(level->at(q), static_cast<double>(i));
      EXPECT_DOUBLE_EQ(radius->at(q), r[i]);
      EXPECT_NEAR(norm(m.points[q] - c.points[i]), r[i], 1e-12);  // straight: every ring is round
    }
  EXPECT_EQ(level->at(80), 0);  // the cap centres
  EXPECT_EQ(level->at(81), 4);
  const Field* path = m.face_fields.find("path");
  const Field* from = m.face_fields.find("curve");
  ASSERT_TRUE(path && from);
  for (std::size_t t = 0; t < m.faces(); ++t) {
    EXPECT_EQ(path->at(t), 0);
    EXPECT_EQ(from->at(t), 7);
  }
}

TEST(Tube, TwoPathsAreTwoComponents) {
  const Polyline3 c = curve({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 0, 1}}});
  const Mesh m = built(c, 0.1);
  const MeshTopology t = mesh_topology(m);
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.euler(), 2);  // a sphere and a torus
  const Field* path = m.face_fields.find("path");
  ASSERT_TRUE(path);
  EXPECT_EQ(path->at(0), 0);
  EXPECT_EQ(path->at(m.faces() - 1), 1);
  EXPECT_EQ(m.points.size(), 3u * 16 + 2 + 3u * 16);
}

TEST(Tube, TwoDimensionalCurveEqualsThreeDimensional) {
  Polyline c2;
  const std::vector<Vec2> zigzag = {{0, 0}, {1, 0.5}, {2, 0}, {3, 0.5}};
  const std::vector<Vec2> square = {{5, 0}, {6, 0}, {6, 1}, {5, 1}, {5, 0}};
  for (const auto* p : {&zigzag, &square}) {
    c2.points.insert(c2.points.end(), p->begin(), p->end());
    c2.close_path();
  }
  c2.point_fields.set(real_field("t", {0, 1, 2, 3, 4, 5, 6, 7, 8}));
  Polyline3 c3;
  for (Vec2 q : c2.points) c3.points.push_back({q.x, q.y, 0});
  c3.path_ends = c2.path_ends;
  c3.point_fields = c2.point_fields;
  std::vector<double> r(9, 0.1);
  r[2] = 0.15;
  const Mesh a = tube(c2, r, {}, no_progress()), b = built(c3, r);
  EXPECT_EQ(tube_size(c2, {}), tube_size(c3, {}));
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i], b.points[i]) << i;
  EXPECT_EQ(a.triangles, b.triangles);
  ASSERT_TRUE(a.point_fields.find("t"));
  EXPECT_EQ(a.point_fields.find("t")->reals()[40], b.point_fields.find("t")->reals()[40]);
}

TEST(Tube, RefusesWithThePlaceNamed) {
  const Polyline3 segment = curve({{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}});
  std::string e = refusal(segment, {0.1, 0, 0.1});
  EXPECT_NE(e.find("path 1, point 2 (1, 0, 0): the radius must be a finite number > 0, got 0"), std::string::npos) << e;
  e = refusal(segment, {0.1, 0.1, std::nan("")});
  EXPECT_NE(e.find("point 3 (2, 0, 0): the radius must be a finite number > 0, got NaN"), std::string::npos) << e;
  e = refusal(segment, {0.1, 0.1});
  EXPECT_NE(e.find("one radius per point: got 2 for 3 points"), std::string::npos) << e;
  e = refusal(segment, {0.1, 0.1, 0.1}, 2);
  EXPECT_EQ(e, "option 'sides' must be an integer in [3, 256], got 2");

  e = refusal(curve({{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}}}), 0.1);
  EXPECT_NE(e.find("path 1, points 2 and 3 are both at (1, 0, 0): a zero-length segment"), std::string::npos) << e;
  e = refusal(curve({{{0, 0, 0}, {1, 0, 0}}, {{4, 5, 6}}}), 0.1);
  EXPECT_NE(e.find("path 2 has a single point (4, 5, 6)"), std::string::npos) << e;

  const double a = 175 * pi / 180;
  e = refusal(curve({{{0, 0, 0}, {1, 0, 0}, {1 + std::cos(a), std::sin(a), 0}}}), 0.01);
  EXPECT_NE(e.find("path 1 turns by 175 degrees at point 2 (1, 0, 0): more than 170"), std::string::npos) << e;
  const Polyline3 corner = curve({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}}});
  EXPECT_EQ(refusal(corner, 0.5), "no error");  // r tan(45 degrees) is just half a segment
  e = refusal(corner, 0.6);
  EXPECT_NE(e.find("the tube would fold at path 1, point 2 (1, 0, 0)"), std::string::npos) << e;
  EXPECT_NE(e.find("turning by 90 degrees"), std::string::npos) << e;

  e = refusal(curve({{{0, 0, 0}, {1, 0, 0}}, {{0, 0.15, 0}, {1, 0.15, 0}}}), 0.1);
  EXPECT_NE(e.find("the tube meets itself near ("), std::string::npos) << e;
  EXPECT_NE(e.find("path 1 segment 1 (points 1 to 2) and path 2"), std::string::npos) << e;
  EXPECT_NE(e.find("closer than their two radii"), std::string::npos) << e;
  e = refusal(curve({{{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, -1, 0}}}), 0.1);
  EXPECT_NE(e.find("path 1 segment 1 (points 1 to 2) and path 1 segment 4 (points 4 to 5)"), std::string::npos) << e;

  e = refusal(curve({{{0, 0, 0}, {1, 0, 0}, {0, 0, 0}}}), 0.1);  // closed: there and back
  EXPECT_NE(e.find("path 1 turns by 180 degrees at point 1 (0, 0, 0)"), std::string::npos) << e;

  Polyline3 bad = segment;
  bad.points[1].y = INFINITY;
  EXPECT_NE(refusal(bad, 0.1).find("path 1, point 2 (1, inf, 0) is not finite"), std::string::npos);
  EXPECT_EQ(refusal(Polyline3{}, std::vector<double>{}), "the curve has no points to make a tube around");
}

TEST(Tube, BudgetIsCheckedBeforeAnyWork) {
  TubeOptions opt;
  const Polyline3 c = curve({helix(1000, 3)});
  EXPECT_EQ(tube_size(c, opt), 1000.0 * 16 + 2 + 2 * 16 * 1000);
  opt.budget.limit = 1000;
  EXPECT_THROW(tube(c, std::vector<double>(1000, 0.01), opt, no_progress()), BudgetError);
}

TEST(Tube, CancelsWhenAsked) {
  struct Stop : Progress {
    bool cancelled() override { return true; }
  } stop;
  const Polyline3 c = curve({helix(10000, 20)});
  EXPECT_THROW(tube(c, std::vector<double>(10000, 0.001), {}, stop), Cancelled);
}

TEST(Tube, ReportsProgressInChunks) {
  struct Record : Progress {
    std::vector<double> seen;
    void fraction(double done) override { seen.push_back(done); }
  } record;
  const Polyline3 c = curve({helix(10000, 20)});
  tube(c, std::vector<double>(10000, 0.001), {}, record);
  ASSERT_GE(record.seen.size(), 3u);  // 160,002 points: two chunks of 65,536, the end of building, the check
  EXPECT_LT(record.seen.size(), 1000u);
  for (std::size_t i = 1; i < record.seen.size(); ++i) EXPECT_GE(record.seen[i], record.seen[i - 1]);
  EXPECT_LE(record.seen.back(), 1);
}
