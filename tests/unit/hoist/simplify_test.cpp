#include "kernels/hoist/simplify.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernels/base/error.h"

using namespace selfsim;

namespace {

double distance_to_path(Vec2 p, std::span<const Vec2> path) {
  double best = INFINITY;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Vec2 a = path[i - 1], d = path[i] - a;
    const double len2 = dot(d, d);
    const double w = len2 > 0 ? std::clamp(dot(p - a, d) / len2, 0.0, 1.0) : 0;
    best = std::min(best, norm(p - (a + w * d)));
  }
  return best;
}

}  // namespace

TEST(Simplify, EveryRemovedPointWithinTheTolerance) {
  std::vector<Vec2> wave;
  for (int i = 0; i <= 2000; ++i) wave.push_back({i / 2000.0, 0.1 * std::sin(i / 100.0)});
  Polyline c = Polyline::single(wave);
  std::vector<double> t;
  for (int i = 0; i <= 2000; ++i) t.push_back(i);
  c.point_fields.set(real_field("t", t));
  for (double tol : {1e-2, 1e-4}) {
    const Polyline s = hoist::simplify(c, tol, no_progress());
    EXPECT_LT(s.points.size(), c.points.size() / 4) << tol;
    EXPECT_EQ(s.points.front(), c.points.front());
    EXPECT_EQ(s.points.back(), c.points.back());
    for (Vec2 p : c.points) EXPECT_LE(distance_to_path(p, s.path(0)), tol);
    // Kept points keep their field values.
    const Field* f = s.point_fields.find("t");
    ASSERT_TRUE(f);
    for (std::size_t i = 0; i < s.points.size(); ++i) EXPECT_EQ(s.points[i], c.points[std::size_t(f->at(i))]);
  }
}

TEST(Simplify, StraightRunsBecomeOneSegmentAndClosedPathsStayClosed) {
  Polyline c = Polyline::single({{0, 0}, {1, 0}, {2, 0}, {3, 0}});
  c.points.insert(c.points.end(), {{0, 5}, {1, 5}, {1, 6}, {0.5, 6}, {0, 6}, {0, 5}});
  c.close_path();
  const Polyline s = hoist::simplify(c, 1e-9, no_progress());
  ASSERT_EQ(s.paths(), 2u);
  EXPECT_EQ(s.path(0).size(), 2u);
  EXPECT_EQ(s.path(1).size(), 5u);  // the square's four corners, back to the first
  EXPECT_EQ(s.path(1).front(), s.path(1).back());
  EXPECT_THROW(hoist::simplify(c, 0, no_progress()), Error);
  EXPECT_THROW(hoist::simplify(c, NAN, no_progress()), Error);
}

TEST(Simplify, AClosedPathKeepsATriangle) {
  const Polyline triangle = Polyline::single({{0, 0}, {1, 0}, {1, 1}, {0, 0}});
  const Polyline s = hoist::simplify(triangle, 10, no_progress());
  EXPECT_EQ(s.points.size(), 4u);
  EXPECT_EQ(s.points.front(), s.points.back());
}

namespace selfsim {
namespace {

// The same zigzag at any scale keeps the same points (issue 21: from 1e155 the squared lengths overflowed
// and every point seemed to lie on its chord's first end).
TEST(Simplify, KeepsTheSamePointsAtAnyScale) {
  for (const double scale : {1e-300, 1e-150, 1.0, 1e150, 1e155, 1e300}) {
    const Polyline c = Polyline::single({{0, 0}, {scale, scale}, {2 * scale, 0}, {3 * scale, 0.5 * scale}});
    const Polyline s = hoist::simplify(c, 0.1 * scale, no_progress());
    EXPECT_EQ(s.points.size(), 4u) << scale;
  }
}

}  // namespace
}  // namespace selfsim
