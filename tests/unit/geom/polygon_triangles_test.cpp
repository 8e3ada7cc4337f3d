#include "kernels/geom/polygon_triangles.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernels/base/error.h"

namespace selfsim {
namespace {

// The triangles' areas, each signed along `normal`.
double signed_area(std::span<const Vec3> p, const std::vector<std::array<std::size_t, 3>>& t, Vec3 normal) {
  double a = 0;
  for (const auto& c : t) a += 0.5 * dot(cross(p[c[1]] - p[c[0]], p[c[2]] - p[c[0]]), normal);
  return a;
}

TEST(PolygonTriangles, ConvexPolygonsAreFannedFromTheirFirstCorner) {
  const std::vector<Vec3> quad{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<std::array<std::size_t, 3>> t;
  polygon_triangles(quad, t);
  EXPECT_EQ(t, (std::vector<std::array<std::size_t, 3>>{{0, 1, 2}, {0, 2, 3}}));
}

// A star of 5 points in a tilted plane, walked either way round: n - 2 triangles covering it once, each
// turning as the polygon does.
TEST(PolygonTriangles, ConcavePolygonsAreCutIntoEarsThatCoverThemOnce) {
  const Vec3 u = normalized(Vec3{1, 0, 1}), v{0, 1, 0}, n = cross(u, v);
  std::vector<Vec3> star;
  for (int k = 0; k < 10; ++k) {
    const double angle = std::numbers::pi * k / 5, r = k % 2 ? 0.4 : 1;
    star.push_back(Vec3{5, 5, 5} + r * std::cos(angle) * u + r * std::sin(angle) * v);
  }
  // The star's area: ten triangles from the centre.
  const double want = 10 * 0.5 * 1 * 0.4 * std::sin(std::numbers::pi / 5);
  for (const bool reversed : {false, true}) {
    std::vector<Vec3> p = star;
    if (reversed) std::reverse(p.begin(), p.end());
    std::vector<std::array<std::size_t, 3>> t;
    polygon_triangles(p, t);
    ASSERT_EQ(t.size(), 8u);
    const Vec3 facing = reversed ? -1.0 * n : n;
    EXPECT_NEAR(signed_area(p, t, facing), want, 1e-12);
    for (const auto& c : t) EXPECT_GT(dot(cross(p[c[1]] - p[c[0]], p[c[2]] - p[c[0]]), facing), 0);
  }
}

TEST(PolygonTriangles, CrossingPolygonsAreRefused) {
  // A bowtie with a notch: no ear can be cut without leaving it crossing.
  const std::vector<Vec3> bow{{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {1, 1.5, 0}, {0, 2, 0}};
  std::vector<std::array<std::size_t, 3>> t;
  EXPECT_THROW(polygon_triangles(bow, t), Error);
  // A pentagram turns left at every corner but winds twice: not convex, and it crosses itself.
  std::vector<Vec3> pentagram;
  for (int k = 0; k < 5; ++k)
    pentagram.push_back({std::cos(4 * std::numbers::pi * k / 5), std::sin(4 * std::numbers::pi * k / 5), 0});
  EXPECT_THROW(polygon_triangles(pentagram, t), Error);
}

}  // namespace
}  // namespace selfsim
