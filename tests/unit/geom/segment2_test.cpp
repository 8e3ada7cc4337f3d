// The squared 2D distances that bound an exclusion surface's terms (segment2.h), against the 3D distances
// of distance3.h in the plane z = 0 (another implementation: projection and edge clamping in 3D).
#include "kernels/geom/segment2.h"

#include <gtest/gtest.h>

#include <random>

#include "kernels/geom/distance3.h"

using namespace selfsim;

namespace {

Vec3 lift(Vec2 p) { return {p.x, p.y, 0}; }

}  // namespace

TEST(Segment2, SquaredDistancesMatchThePlaneCaseOfThe3DOnes) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-1, 1);
  int inside = 0, crossing = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const Vec2 p{coordinate(random), coordinate(random)}, a{coordinate(random), coordinate(random)},
        b{coordinate(random), coordinate(random)}, c{coordinate(random), coordinate(random)};
    const double pt = point_triangle_distance(lift(p), lift(a), lift(b), lift(c));
    EXPECT_NEAR(point_triangle_distance2(p, a, b, c), pt * pt, 1e-12) << trial;
    inside += pt == 0;
    const double ss = segment_segment_distance(lift(p), lift(a), lift(b), lift(c));
    EXPECT_NEAR(segment_distance2(p, a, b, c), ss * ss, 1e-12) << trial;
    crossing += segment_distance2(p, a, b, c) == 0;
    const double ps = point_segment_distance(lift(p), lift(a), lift(b));
    EXPECT_NEAR(point_segment_distance2(p, a, b), ps * ps, 1e-12) << trial;
  }
  EXPECT_GT(inside, 1000);    // points inside their triangle were tried
  EXPECT_GT(crossing, 1000);  // and crossing segments
}

TEST(Segment2, AFlatTriangleIsItsEdges) {
  // Three points on a line: nothing off the line is inside, and a point on the line beyond them is at its
  // distance from the nearest end.
  EXPECT_DOUBLE_EQ(point_triangle_distance2({0, 1}, {-1, 0}, {0, 0}, {1, 0}), 1);
  EXPECT_DOUBLE_EQ(point_triangle_distance2({3, 0}, {-1, 0}, {0, 0}, {1, 0}), 4);
  EXPECT_DOUBLE_EQ(point_triangle_distance2({2, 2}, {1, 1}, {1, 1}, {1, 1}), 2);
}
