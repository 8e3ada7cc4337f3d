// Seed 002 §1 (Figures 2 and 4): corners rounded by arcs tangent at half the shorter segment, so a curve of
// equal segments becomes a union of arcs through the segment midpoints.
#include "kernels/develop/rounded_corners.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "../lsystem/table1.h"
#include "kernels/base/error.h"
#include "kernels/lsystem/turtle/turtle2d.h"

using namespace selfsim;
using namespace selfsim::develop;

TEST(RoundedCorners, ARightAngleBecomesAQuarterCircleThroughTheMidpoints) {
  const Polyline c = Polyline::single({{0, 0}, {2, 0}, {2, 2}});
  const Polyline r = rounded_corners(c, {.samples = 8}, no_progress());
  ASSERT_EQ(r.points.size(), 2u + 9u);  // the two ends and 8 arc segments
  EXPECT_EQ(r.points[0], (Vec2{0, 0}));
  EXPECT_NEAR(r.points[1].x, 1, 1e-15);  // the arc starts at the first segment's midpoint
  EXPECT_NEAR(r.points[9].y, 1, 1e-15);  // and ends at the second's
  for (std::size_t k = 1; k <= 9; ++k) EXPECT_NEAR(norm(r.points[k] - Vec2{1, 1}), 1, 1e-14) << k;  // radius 1
}

TEST(RoundedCorners, TheTerdragonBecomesAUnionOfArcsOfOneRadius) {
  // 120° turns on unit segments: arcs of radius (1/2)/tan(60°) about centres the arcs keep.
  const Polyline c = lsystem::turtle2d(table1::terdragon(), {.level = 3}, no_progress());
  const Polyline r = rounded_corners(c, {.samples = 6}, no_progress());
  const double seg = c.length() / static_cast<double>(c.segments());
  const double radius = seg / 2 / std::tan(std::numbers::pi / 3);
  // Every point but the two ends lies on an arc: the turn between consecutive segments stays 1/samples of a
  // quarter turn or less, and the length is the arcs' plus the two half segments at the ends.
  const double corners = static_cast<double>(c.segments() - 1);
  // Each 120° arc is drawn as 8 chords of 15° (6 a quarter turn).
  const double chord = 2 * radius * std::sin(std::numbers::pi / 24);
  EXPECT_NEAR(r.length(), corners * 8 * chord + seg, 1e-12 * r.length());
  for (std::size_t k = 1; k + 2 < r.points.size(); ++k) {
    const Vec2 a = r.points[k + 1] - r.points[k], b = r.points[k + 2] - r.points[k + 1];
    EXPECT_LE(std::atan2(std::abs(cross(a, b)), dot(a, b)), std::numbers::pi / 2 / 6 + 1e-9) << k;
  }
}

TEST(RoundedCorners, LoopsAreRoundedAllRoundAndStayClosed) {
  const Polyline square = Polyline::single({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}});
  const Polyline r = rounded_corners(square, {.samples = 4}, no_progress());
  EXPECT_EQ(r.points.front(), r.points.back());
  EXPECT_EQ(r.points.size(), 4u * 4u + 1u);  // arcs meet at the midpoints: one point there
  // Four quarter circles of radius 1/2, each drawn as 4 chords.
  EXPECT_NEAR(r.length(), 16 * 2 * 0.5 * std::sin(std::numbers::pi / 16), 1e-14);
}

TEST(RoundedCorners, StraightAndUTurnCornersKeepTheirPoint) {
  const Polyline c = Polyline::single({{0, 0}, {1, 0}, {2, 0}, {1, 0}});
  const Polyline r = rounded_corners(c, {}, no_progress());
  ASSERT_EQ(r.points.size(), 4u);
  EXPECT_EQ(r.points[1], (Vec2{1, 0}));
  EXPECT_EQ(r.points[2], (Vec2{2, 0}));
}

TEST(RoundedCorners, Errors) {
  const Polyline stuck = Polyline::single({{0, 0}, {1, 0}, {1, 0}, {1, 1}});
  EXPECT_THROW(rounded_corners(stuck, {}, no_progress()), Error);
  EXPECT_THROW(rounded_corners(stuck, {.samples = 0}, no_progress()), Error);
  const Polyline c = Polyline::single({{0, 0}, {1, 0}, {1, 1}});
  RoundOptions small{.samples = 8};
  small.budget.limit = 10;
  EXPECT_THROW(rounded_corners(c, small, no_progress()), BudgetError);
}

// A curve 1e-320 across (subnormal numbers) rounds as one of size 1 does, scaled (issue 21: it was called
// "too large to round", its reciprocal lengths overflowing).
TEST(RoundedCorners, TinyCurvesRoundToo) {
  const double s = 1e-320;
  const Polyline r =
      rounded_corners(Polyline::single({{0, 0}, {2 * s, 0}, {2 * s, 2 * s}}), {.samples = 8}, no_progress());
  ASSERT_EQ(r.points.size(), 11u);
  EXPECT_TRUE(r.finite());
  EXPECT_NEAR(r.points[1].x, s, 0.01 * s);
  EXPECT_NEAR(r.points[9].y, s, 0.01 * s);
}
