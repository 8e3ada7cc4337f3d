// Fractal dimension estimates (seed 004): the line fit, length scaling read from the `level` field, box
// counting.
#include "kernels/analysis/dimension.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernels/base/error.h"
#include "kernels/exclusion/exclusion_curve.h"

using namespace selfsim;
using namespace selfsim::analysis;

TEST(Dimension, LineFitSlopeAndStandardError) {
  const LineFit exact = fit_line({0, 1, 2, 3}, {1, 3, 5, 7});
  EXPECT_DOUBLE_EQ(exact.slope, 2);
  EXPECT_DOUBLE_EQ(exact.intercept, 1);
  EXPECT_DOUBLE_EQ(exact.error, 0);
  // y = x with residuals +1, -1, -1, +1 at x = 0..3: slope 1, sum of squares 4, Sxx 5, se = sqrt(4/2/5).
  const LineFit noisy = fit_line({0, 1, 2, 3}, {1, 0, 1, 4});
  EXPECT_NEAR(noisy.slope, 1.0, 1e-12);
  EXPECT_NEAR(noisy.error, std::sqrt(0.4), 1e-12);
  EXPECT_THROW(fit_line({1, 1}, {0, 2}), Error);
  EXPECT_TRUE(noisy.has_error);
  // Two points: a line through both, no residual degree of freedom, no error (issue 21: it said 0).
  EXPECT_FALSE(fit_line({0, 1}, {0, 2}).has_error);
}

TEST(Dimension, LengthScalingReadsEachLevelFromTheLevelField) {
  // The level-N curve of a breadth-first run is the final curve's points of level <= N: its length from
  // the field matches a run stopped at level N.
  const Region square({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  exclusion::CurveOptions o;
  o.levels = 8;
  const Polyline start = Polyline::single({{0, 0}, {1, 1}});
  const Dimension d = length_scaling(exclusion::exclusion_curve(square, start, o, no_progress()).curve, 0, -1);
  ASSERT_EQ(d.steps.size(), 9u);
  for (int n : {0, 3, 8}) {
    o.levels = n;
    const double length = exclusion::exclusion_curve(square, start, o, no_progress()).curve.length();
    EXPECT_NEAR(d.fit.y[n], std::log(length), 1e-12) << "level " << n;
    EXPECT_NEAR(d.fit.x[n], std::log(std::ldexp(1.0, n) / std::sqrt(2.0)), 1e-12);
  }
  EXPECT_NEAR(d.dimension, d.fit.slope + 1, 1e-15);
  EXPECT_THROW(length_scaling(start, 0, -1), Error);  // no level field
}

TEST(Dimension, BoxCountingOfALineAndOfAFilledSquare) {
  const Dimension line = box_counting(Polyline::single({{0, 0.3}, {1, 0.3}}), 1, 8, no_progress());
  EXPECT_NEAR(line.dimension, 1.0, 1e-12);
  // A zigzag of 64 rows over the unit square: every box of side 1/64 or more is met, so N = 4^k.
  std::vector<Vec2> rows;
  for (int i = 0; i < 64; ++i) {
    const double y = (i + 0.5) / 64;
    rows.push_back({i % 2 ? 1.0 : 0.0, y});
    rows.push_back({i % 2 ? 0.0 : 1.0, y});
  }
  const Dimension filled = box_counting(Polyline::single(rows), 1, 6, no_progress());
  EXPECT_NEAR(filled.dimension, 2.0, 1e-12);
  EXPECT_THROW(box_counting(Polyline::single(rows), 1, 12, no_progress()), Error);
}
