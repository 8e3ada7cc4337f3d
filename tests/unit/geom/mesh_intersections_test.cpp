// Hand-made pairs of triangles whose contact is known (crossing, touching at a corner, an edge on a face,
// coplanar overlap, gaps on either side of the tolerance, degenerate triangles), closed meshes that must be
// clean, random soups checked against an all-pairs loop with a textbook separating-axis test, and a large
// flat grid with intruders, which exercises the grid, the batches and the threads.
#include "kernels/geom/mesh_intersections.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>

#include "kernels/base/error.h"

using namespace selfsim;

namespace {

// Appends a triangle with three new points of its own (no index shared with anything).
void add(Mesh& m, Vec3 a, Vec3 b, Vec3 c) {
  const auto n = static_cast<std::uint32_t>(m.points.size());
  m.points.insert(m.points.end(), {a, b, c});
  m.triangles.push_back({n, n + 1, n + 2});
}

// The horizontal right triangle with legs 2 at the origin: the first triangle of most cases below.
Mesh floor_triangle() {
  Mesh m;
  add(m, {0, 0, 0}, {2, 0, 0}, {0, 2, 0});
  return m;
}

// The regular icosahedron: 12 points, 20 faces, closed.
Mesh icosahedron() {
  const double g = std::numbers::phi;
  Mesh m;
  m.points = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
              {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  m.triangles = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  return m;
}

// A torus (radii 1 and 0.3) as an n × k grid of quads, two triangles each: closed, curved everywhere.
Mesh torus(std::uint32_t n, std::uint32_t k) {
  Mesh m;
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < k; ++j) {
      const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / k;
      m.points.push_back(
          {(1 + 0.3 * std::cos(v)) * std::cos(u), (1 + 0.3 * std::cos(v)) * std::sin(u), 0.3 * std::sin(v)});
    }
  auto at = [&](std::uint32_t i, std::uint32_t j) { return (i % n) * k + j % k; };
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < k; ++j) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// The unit-spaced n × n square grid in z = 0, two triangles a square: square (x, y) holds triangles
// 2 (y n + x) (lower right) and 2 (y n + x) + 1 (upper left).
Mesh flat_grid(std::uint32_t n) {
  Mesh m;
  for (std::uint32_t y = 0; y <= n; ++y)
    for (std::uint32_t x = 0; x <= n; ++x) m.points.push_back({double(x), double(y), 0});
  auto at = [&](std::uint32_t x, std::uint32_t y) { return y * (n + 1) + x; };
  for (std::uint32_t y = 0; y < n; ++y)
    for (std::uint32_t x = 0; x < n; ++x) {
      m.triangles.push_back({at(x, y), at(x + 1, y), at(x + 1, y + 1)});
      m.triangles.push_back({at(x, y), at(x + 1, y + 1), at(x, y + 1)});
    }
  return m;
}

// A small upright triangle piercing the interior of the lower-right triangle of square (x, y) of a flat grid
// (near its corner (x + 1, y)) and of nothing else.
void add_spike(Mesh& m, double x, double y) {
  add(m, {x + 0.7, y + 0.2, -0.5}, {x + 0.8, y + 0.2, -0.5}, {x + 0.75, y + 0.2, 0.5});
}

std::optional<TrianglePair> run(const Mesh& m) { return first_intersection(m, no_progress()); }

// Whether two triangles in general position intersect, by the textbook separating-axis test without any
// tolerance (the two normals and the nine edge cross products): a reference that shares no code with the
// kernel's distance test.
bool reference_intersect(const Mesh& m, const Triangle& s, const Triangle& t) {
  const std::array<Vec3, 3> a{m.points[s[0]], m.points[s[1]], m.points[s[2]]};
  const std::array<Vec3, 3> b{m.points[t[0]], m.points[t[1]], m.points[t[2]]};
  auto apart = [&](Vec3 axis) {
    double alo = dot(a[0], axis), ahi = alo, blo = dot(b[0], axis), bhi = blo;
    for (int k = 1; k < 3; ++k) {
      alo = std::min(alo, dot(a[k], axis)), ahi = std::max(ahi, dot(a[k], axis));
      blo = std::min(blo, dot(b[k], axis)), bhi = std::max(bhi, dot(b[k], axis));
    }
    return ahi < blo || bhi < alo;
  };
  if (apart(cross(a[1] - a[0], a[2] - a[0])) || apart(cross(b[1] - b[0], b[2] - b[0]))) return false;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (apart(cross(a[(i + 1) % 3] - a[i], b[(j + 1) % 3] - b[j]))) return false;
  return true;
}

}  // namespace

TEST(MeshIntersections, ClosedMeshesHaveNone) {
  EXPECT_FALSE(run(icosahedron()));
  EXPECT_FALSE(run(torus(96, 40)));
  EXPECT_FALSE(run(flat_grid(30)));
}

TEST(MeshIntersections, EmptyAndSingleTriangleHaveNone) {
  EXPECT_FALSE(run(Mesh{}));
  EXPECT_FALSE(run(floor_triangle()));
}

TEST(MeshIntersections, CrossingTrianglesMeetOnTheirCommonLine) {
  Mesh m = floor_triangle();
  add(m, {0.5, 0.25, -1}, {0.5, 0.25, 1}, {0.5, 1.25, 0.3});  // upright in the plane x = 0.5
  const auto hit = run(m);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->first, 0u);
  EXPECT_EQ(hit->second, 1u);
  // On the floor triangle (z = 0, inside x + y <= 2) and in the upright one's plane, inside it.
  EXPECT_NEAR(hit->where.z, 0, 1e-12);
  EXPECT_NEAR(hit->where.x, 0.5, 1e-12);
  EXPECT_GE(hit->where.y, 0.25 - 1e-12);
  EXPECT_LE(hit->where.x + hit->where.y, 2 + 1e-12);
  EXPECT_LE(hit->where.y, 0.25 + 1 / 1.3 + 1e-12);  // where the upright one's lower edge leaves z = 0
}

TEST(MeshIntersections, TouchingAtOneCoordinateMeets) {
  Mesh m = floor_triangle();
  add(m, {2, 0, 0}, {3, 0, 1}, {3, 1, -1});  // its own copy of the floor's corner (2, 0, 0)
  const auto hit = run(m);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->first, 0u);
  EXPECT_EQ(hit->second, 1u);
  EXPECT_NEAR(norm(hit->where - Vec3{2, 0, 0}), 0, 1e-12);
}

TEST(MeshIntersections, CornerOnAFaceMeets) {
  Mesh m = floor_triangle();
  add(m, {0.5, 0.5, 0}, {1, 0.5, 1}, {0.5, 1, 1});
  const auto hit = run(m);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(norm(hit->where - Vec3{0.5, 0.5, 0}), 0, 1e-12);
}

TEST(MeshIntersections, EdgeLyingOnAFaceMeets) {
  Mesh m = floor_triangle();
  add(m, {0.25, 0.25, 0}, {1, 0.25, 0}, {0.5, 0.25, 1});  // upright, its lower edge in the floor
  const auto hit = run(m);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->where.z, 0, 1e-12);
  EXPECT_NEAR(hit->where.y, 0.25, 1e-12);
}

TEST(MeshIntersections, EdgeCrossingAnEdgeMeets) {
  Mesh m = floor_triangle();
  add(m, {1, 1, -1}, {1, 1, 1}, {1.5, 1.5, 0});  // its edge x = y = 1 meets the floor's hypotenuse at z = 0
  const auto hit = run(m);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(norm(hit->where - Vec3{1, 1, 0}), 0, 1e-12);
}

TEST(MeshIntersections, CoplanarOverlapsMeet) {
  Mesh star = floor_triangle();
  add(star, {1.5, 1.5, 0}, {-0.5, 0.5, 0}, {0.5, -0.5, 0});  // edges crossing edges
  EXPECT_TRUE(run(star));
  Mesh inside = floor_triangle();
  add(inside, {0.2, 0.2, 0}, {0.6, 0.2, 0}, {0.2, 0.6, 0});  // wholly inside, no edge crossing
  const auto hit = run(inside);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->where.z, 0, 1e-12);
}

TEST(MeshIntersections, NearMissesDoNot) {
  Mesh above = floor_triangle();
  add(above, {0.5, 0.5, 1e-3}, {1, 0.5, 1}, {0.5, 1, 1});  // a corner just over the floor
  EXPECT_FALSE(run(above));
  Mesh beside = floor_triangle();
  add(beside, {1.001, 1.001, 0}, {3, 1, 0}, {1, 3, 0});  // coplanar, just past the hypotenuse
  EXPECT_FALSE(run(beside));
  Mesh edges = floor_triangle();
  add(edges, {1, 1, -1}, {1, 1, 1}, {1.5, 1.5, 0});
  for (auto& p : {3u, 4u, 5u}) edges.points[p] += Vec3{1e-3, 1e-3, 0};  // its edge just off the hypotenuse
  EXPECT_FALSE(run(edges));
}

TEST(MeshIntersections, GapsWithinTheToleranceMeet) {
  // The diagonal is about 3.5, so the tolerance is about 3.5e-9: a gap of 1e-12 is rounding, 1e-7 is not.
  Mesh close = floor_triangle();
  add(close, {0.5, 0.5, 1e-12}, {1, 0.5, 1}, {0.5, 1, 1});
  EXPECT_TRUE(run(close));
  Mesh apart = floor_triangle();
  add(apart, {0.5, 0.5, 1e-7}, {1, 0.5, 1}, {0.5, 1, 1});
  EXPECT_FALSE(run(apart));
}

TEST(MeshIntersections, NeighboursMeetOnlyWhereTheyShare) {
  // A fan, a strip and a closed surface: neighbours meet only at their shared corners and edges.
  Mesh fan;
  fan.points.push_back({0, 0, 0.3});
  for (int k = 0; k < 7; ++k) fan.points.push_back({std::cos(k * 0.9), std::sin(k * 0.9), 0.1 * (k % 2)});
  for (std::uint32_t k = 1; k < 7; ++k) fan.triangles.push_back({0, k, k + 1});
  EXPECT_FALSE(run(fan));
  EXPECT_FALSE(run(flat_grid(5)));
  // Two triangles on one edge folded flat onto each other meet beyond their edge.
  Mesh folded;
  folded.points = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1.5, 0}};
  folded.triangles = {{0, 1, 2}, {1, 0, 3}};
  const auto fold = run(folded);
  ASSERT_TRUE(fold);
  EXPECT_EQ(fold->second, 1u);
  // Two on one corner, one crossing the other, meet along a segment from it; a fan whose second triangle
  // turns back over the first, in one plane, too.
  Mesh corner;
  corner.points = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {1, 1, 1}, {0.5, 0.5, -1}};
  corner.triangles = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_TRUE(run(corner));
  Mesh back;
  back.points = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 2, 0}, {1.5, 0.2, 0}};
  back.triangles = {{0, 1, 2}, {0, 3, 4}};  // share corner 0 only; 4 lies inside the first triangle's wedge
  EXPECT_TRUE(run(back));
}

TEST(MeshIntersections, TheFirstPairIsTheLeast) {
  // Triangle 1 meets 4 and 7, triangle 2 meets 5 and 0 meets nothing: the answer is (1, 4), not (1, 7) or
  // (2, 5). Triangles 0, 3 and 6 are far apart.
  Mesh m;
  add(m, {10, 10, 10}, {11, 10, 10}, {10, 11, 10});          // 0
  add(m, {0, 0, 0}, {4, 0, 0}, {0, 4, 0});                   // 1
  add(m, {20, 0, 0}, {22, 0, 0}, {20, 2, 0});                // 2
  add(m, {-10, 10, 10}, {-11, 10, 10}, {-10, 11, 10});       // 3
  add(m, {0.5, 0.5, -1}, {0.7, 0.5, -1}, {0.6, 0.5, 1});     // 4: through 1
  add(m, {20.5, 0.5, -1}, {20.7, 0.5, -1}, {20.6, 0.5, 1});  // 5: through 2
  add(m, {10, -10, 10}, {11, -10, 10}, {10, -11, 10});       // 6
  add(m, {0.2, 0.2, -1}, {0.3, 0.2, -1}, {0.25, 0.2, 1});    // 7: through 1
  const auto hit = run(m);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->first, 1u);
  EXPECT_EQ(hit->second, 4u);
}

TEST(MeshIntersections, DegenerateTrianglesAreTheirSegments) {
  Mesh segment = floor_triangle();
  add(segment, {0.5, 0.5, -1}, {0.5, 0.5, 1}, {0.5, 0.5, 0.25});  // collinear: a segment through the floor
  const auto hit = run(segment);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(norm(hit->where - Vec3{0.5, 0.5, 0}), 0, 1e-12);
  Mesh point = floor_triangle();
  add(point, {0.5, 0.5, 0}, {0.5, 0.5, 0}, {0.5, 0.5, 0});  // three copies of a point of the floor
  EXPECT_TRUE(run(point));
  Mesh repeated = floor_triangle();
  repeated.points.insert(repeated.points.end(), {{0.5, 0.5, 1}, {0.5, 0.5, -1}});
  repeated.triangles.push_back({3, 4, 4});  // one point twice: the segment 3-4, through the floor
  EXPECT_TRUE(run(repeated));
  Mesh clear = floor_triangle();
  add(clear, {0.5, 0.5, 0.1}, {0.5, 0.5, 1}, {0.5, 0.5, 0.5});
  add(clear, {5, 5, 5}, {5, 5, 5}, {5, 5, 5});
  EXPECT_FALSE(run(clear));
}

TEST(MeshIntersections, FindsTheOneIntruderInALargeGrid) {
  Mesh m = flat_grid(317);  // 200,978 triangles
  const std::uint32_t target = 2 * (250 * 317 + 123);
  add_spike(m, 123, 250);
  const auto hit = run(m);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->first, target);
  EXPECT_EQ(hit->second, m.triangles.size() - 1);
  EXPECT_NEAR(hit->where.z, 0, 1e-9);
}

TEST(MeshIntersections, TheLeastFirstWinsAcrossBatches) {
  // The last triangle pierces an early grid triangle, the one before it a late one: the early one wins.
  Mesh m = flat_grid(317);
  add_spike(m, 5, 300);
  add_spike(m, 7, 2);
  const std::uint32_t last = static_cast<std::uint32_t>(m.triangles.size() - 1);
  const auto hit = run(m);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->first, 2u * (2 * 317 + 7));
  EXPECT_EQ(hit->second, last);
}

TEST(MeshIntersections, ToleranceScalesWithTheMesh) {
  // The corner touch and the gap of a thousandth, a millionth of the size and a million units from the
  // origin: the same answers.
  for (double scale : {1e-6, 1.0, 1e6}) {
    const Vec3 far = Vec3::all(1e6);
    Mesh touch;
    add(touch, far + scale * Vec3{0, 0, 0}, far + scale * Vec3{2, 0, 0}, far + scale * Vec3{0, 2, 0});
    add(touch, far + scale * Vec3{2, 0, 0}, far + scale * Vec3{3, 0, 1}, far + scale * Vec3{3, 1, -1});
    EXPECT_TRUE(run(touch)) << scale;
    Mesh gap = touch;
    gap.points[3] += scale * Vec3{1e-3, 0, 0};
    EXPECT_FALSE(run(gap)) << scale;
  }
}

// Whether two triangles sharing one corner meet beyond it: each cut short of the corner (at 1e-3 of its
// sides, a quad as two triangles) and the pieces tested with the reference.
bool reference_beyond_corner(const Mesh& m, const Triangle& s, const Triangle& t) {
  auto pieces = [&](const Triangle& a, std::uint32_t v) {
    int k = 0;
    while (a[k] != v) ++k;
    const Vec3 p = m.points[a[k]], x = m.points[a[(k + 1) % 3]], y = m.points[a[(k + 2) % 3]];
    const Vec3 px = p + 1e-3 * (x - p), py = p + 1e-3 * (y - p);
    return std::array<std::array<Vec3, 3>, 2>{{{px, x, y}, {px, y, py}}};
  };
  std::uint32_t v = 0;
  for (std::uint32_t p : s)
    if (p == t[0] || p == t[1] || p == t[2]) v = p;
  Mesh pair;
  for (const auto& piece : pieces(s, v))
    for (const auto& other : pieces(t, v)) {
      pair.points = {piece[0], piece[1], piece[2], other[0], other[1], other[2]};
      if (reference_intersect(pair, {0, 1, 2}, {3, 4, 5})) return true;
    }
  return false;
}

TEST(MeshIntersections, RandomSoupsAgreeWithBruteForce) {
  // Small random triangles (general position: no touching by chance), some sharing a corner with the one
  // before; the first pair must be the one an all-pairs loop with the reference test finds (for corner
  // sharers: whether they meet beyond the corner).
  std::mt19937_64 random(2024);
  auto uniform = [&] { return double(random() >> 11) * 0x1p-53; };
  for (int round = 0; round < 40; ++round) {
    Mesh m;
    const double size = 0.05 + 0.1 * uniform();
    Vec3 c;
    for (std::uint32_t i = 0; i < 300; ++i) {
      if (i % 3 != 0) c = {uniform(), uniform(), uniform()};  // else beside the triangle before, sharing a corner
      auto near = [&] { return c + size * Vec3{uniform() - 0.5, uniform() - 0.5, uniform() - 0.5}; };
      const auto n = static_cast<std::uint32_t>(m.points.size());
      m.points.insert(m.points.end(), {near(), near(), near()});
      m.triangles.push_back({i % 3 == 0 && i > 0 ? n - 1 : n, n + 1, n + 2});
    }
    std::optional<std::pair<std::uint32_t, std::uint32_t>> want;
    for (std::uint32_t i = 0; i < m.triangles.size() && !want; ++i)
      for (std::uint32_t j = i + 1; j < m.triangles.size() && !want; ++j) {
        const Triangle &s = m.triangles[i], &t = m.triangles[j];
        const bool shared = s[0] == t[0] || s[0] == t[1] || s[0] == t[2] || s[1] == t[0] || s[1] == t[1] ||
                            s[1] == t[2] || s[2] == t[0] || s[2] == t[1] || s[2] == t[2];
        if (shared ? reference_beyond_corner(m, s, t) : reference_intersect(m, s, t)) want = {i, j};
      }
    const auto hit = run(m);
    ASSERT_EQ(bool(hit), bool(want)) << round;
    if (hit) {
      EXPECT_EQ(hit->first, want->first) << round;
      EXPECT_EQ(hit->second, want->second) << round;
    }
  }
}

TEST(MeshIntersections, ThreadsDoNotChangeTheAnswer) {
  Mesh m = flat_grid(200);
  for (double x : {150.0, 20.0, 90.0, 3.0}) add_spike(m, x, 180 - x);
  const auto many = run(m);
  std::optional<TrianglePair> one;
  {
    tbb::global_control serial(tbb::global_control::max_allowed_parallelism, 1);
    one = run(m);
  }
  ASSERT_TRUE(many && one);
  EXPECT_EQ(many->first, one->first);
  EXPECT_EQ(many->second, one->second);
  EXPECT_EQ(many->where, one->where);
}

TEST(MeshIntersections, NonFinitePointsAreErrors) {
  Mesh m = floor_triangle();
  add(m, {5, 5, 5}, {6, 5, 5}, {5, std::numeric_limits<double>::quiet_NaN(), 5});
  try {
    run(m);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "point 6 has non-finite coordinates");
  }
}

TEST(MeshIntersections, IndicesOutOfRangeAreErrors) {
  Mesh m = floor_triangle();
  m.triangles.push_back({0, 1, 7});
  EXPECT_THROW(run(m), Error);
}

TEST(MeshIntersections, StopsWhenCancelled) {
  struct Stop : Progress {
    bool cancelled() override { return true; }
  } stop;
  EXPECT_THROW(first_intersection(flat_grid(10), stop), Cancelled);
}
