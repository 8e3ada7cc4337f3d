// Tubes round polylines, as the studio's view draws a curve's widths: rings of the asked radius round each
// point, perpendicular to the line, not twisting along a straight one, joined by two triangles a side.
#include "kernels/io/view/tube_rings.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace selfsim;

namespace {

using V = std::array<double, 3>;

double distance(const V& a, const V& b) { return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

}  // namespace

TEST(TubeRings, RingsOfTheirRadiusRoundEachPointJoinedSideBySide) {
  const std::vector<V> line{{0, 0, 0}, {0, 1, 0}, {1, 1, 0}};  // up, then right: a bend
  const std::vector<double> radii{0.1, 0.05, 0.02};
  std::vector<V> rings;
  std::vector<std::uint32_t> triangles;
  EXPECT_EQ(io::tube_rings(line, radii, 8, 100, rings, triangles), 24u);
  ASSERT_EQ(rings.size(), 24u);
  EXPECT_EQ(triangles.size(), 3u * 2 * 8 * 2);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t k = 0; k < 8; ++k) EXPECT_NEAR(distance(rings[8 * i + k], line[i]), radii[i], 1e-12);
  // The first ring lies across the line (y = 0), the last across its last segment (x = 1).
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_NEAR(rings[k][1], 0, 1e-12);
    EXPECT_NEAR(rings[16 + k][0], 1, 1e-12);
  }
  for (std::uint32_t t : triangles) {
    EXPECT_GE(t, 100u);  // counted from `first`
    EXPECT_LT(t, 124u);
  }
}

TEST(TubeRings, AStraightLineDoesNotTwist) {
  const std::vector<V> line{{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, 5}};
  const std::vector<double> radii(4, 1.0);
  std::vector<V> rings;
  std::vector<std::uint32_t> triangles;
  io::tube_rings(line, radii, 6, 0, rings, triangles);
  for (std::size_t i = 1; i < 4; ++i)
    for (std::size_t k = 0; k < 6; ++k) {
      EXPECT_NEAR(rings[6 * i + k][0], rings[k][0], 1e-12);
      EXPECT_NEAR(rings[6 * i + k][1], rings[k][1], 1e-12);
    }
}

TEST(TubeRings, NothingForAPointOrCoincidentPoints) {
  std::vector<V> rings;
  std::vector<std::uint32_t> triangles;
  const std::vector<double> radii{1, 1, 1};
  EXPECT_EQ(io::tube_rings(std::vector<V>{{1, 2, 3}}, radii, 8, 0, rings, triangles), 0u);
  EXPECT_EQ(io::tube_rings(std::vector<V>{{1, 2, 3}, {1, 2, 3}}, radii, 8, 0, rings, triangles), 0u);
  EXPECT_TRUE(rings.empty());
  EXPECT_TRUE(triangles.empty());
  // A repeated point inside a line takes its neighbour's direction: every ring still has its radius.
  const std::vector<V> line{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}};
  const std::vector<double> four(4, 0.5);
  EXPECT_EQ(io::tube_rings(line, four, 8, 0, rings, triangles), 32u);
  for (std::size_t r = 0; r < rings.size(); ++r) EXPECT_NEAR(distance(rings[r], line[r / 8]), 0.5, 1e-12);
}
