// The exclusion curve at level k is its points of level <= k, in order, path by path, with their fields.
#include "kernels/exclusion/curve_at_level.h"

#include <gtest/gtest.h>

#include "kernels/base/error.h"
#include "kernels/exclusion/exclusion_curve.h"

using namespace selfsim;

TEST(CurveAtLevel, KeepsThePointsOfLevelUpToKInOrder) {
  Polyline c;
  c.points = {{0, 0}, {0.5, 0.2}, {1, 0}, {2, 0}, {2.5, 1}, {3, 0}};
  c.path_ends = {3, 6};
  c.point_fields.set(int_field("level", {0, 2, 0, 0, 1, 0}));
  c.cell_fields.set(int_field("curve", {1, 2}));
  const Polyline one = exclusion::curve_at_level(c, 1, no_progress());
  ASSERT_EQ(one.points.size(), 5u);
  EXPECT_EQ(one.path_ends, (std::vector<std::size_t>{2, 5}));
  EXPECT_EQ(one.points[3].y, 1);
  EXPECT_EQ(one.point_fields.find("level")->at(3), 1);
  EXPECT_EQ(one.cell_fields.find("curve")->at(1), 2);
}

TEST(CurveAtLevel, EachLevelOfAGrownCurveDoublesItsSegmentsAndStaysInPlace) {
  const Region region({std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  exclusion::CurveOptions opt;
  opt.levels = 6;
  const exclusion::CurveResult r =
      exclusion::exclusion_curve(region, Polyline::single({{0, 0}, {1, 1}}), opt, no_progress());
  for (int k = 0; k <= 6; ++k) {
    const Polyline at = exclusion::curve_at_level(r.curve, k, no_progress());
    EXPECT_EQ(at.segments(), std::size_t{1} << k) << k;
  }
  // A run of 4 levels placed the same points as the first 4 levels of this one.
  opt.levels = 4;
  const exclusion::CurveResult four =
      exclusion::exclusion_curve(region, Polyline::single({{0, 0}, {1, 1}}), opt, no_progress());
  const Polyline at4 = exclusion::curve_at_level(r.curve, 4, no_progress());
  ASSERT_EQ(at4.points.size(), four.curve.points.size());
  for (std::size_t i = 0; i < at4.points.size(); ++i) EXPECT_EQ(at4.points[i], four.curve.points[i]) << i;
}

TEST(CurveAtLevel, RefusesACurveWithoutLevels) {
  EXPECT_THROW(exclusion::curve_at_level(Polyline::single({{0, 0}, {1, 0}}), 0, no_progress()), Error);
}
