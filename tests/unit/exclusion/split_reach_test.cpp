// The per-obstacle limits of a split (seed 004): checked against the definition by sampling the move.
#include "kernels/exclusion/split_reach.h"

#include <gtest/gtest.h>

#include <random>

#include "kernels/geom/segment2.h"

using namespace selfsim;
using namespace selfsim::exclusion;

namespace {

// The terms exact mode watches, at a point position p: p to the obstacle, and each obstacle end (other than
// a or b) to each new segment.
std::vector<double> terms(const SplitFrame& f, Vec2 p, Vec2 u, Vec2 v) {
  std::vector<double> out{point_segment_distance(p, u, v)};
  for (Vec2 w : {u, v})
    if (w != f.a && w != f.b)
      out.insert(out.end(), {point_segment_distance(w, f.a, p), point_segment_distance(w, p, f.b)});
  return out;
}

}  // namespace

TEST(SplitReach, ExactLimitsAreValidAndMaximal) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> coordinate(-1, 1), radius(0.02, 0.4);
  int blocked = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const Vec2 a{coordinate(random), coordinate(random)}, b{coordinate(random), coordinate(random)};
    const Vec2 u{coordinate(random), coordinate(random)}, v{coordinate(random), coordinate(random)};
    const double r = radius(random);
    const SplitFrame f(a, b);
    Reach reach;
    limit_exact(f, u, v, r, reach);
    const std::vector<double> start = terms(f, f.m, u, v);
    for (const double side : {1.0, -1.0}) {
      const double limit = side > 0 ? reach.positive : reach.negative;
      const double end = std::isfinite(limit) ? limit : 4.0;
      // Valid: along the whole move no term is below r, or below where it started if that was less.
      for (int k = 1; k <= 200; ++k) {
        const std::vector<double> now = terms(f, f.at(side * end * k / 200 * (1 - 1e-7)), u, v);
        for (std::size_t i = 0; i < now.size(); ++i)
          ASSERT_GE(now[i], std::min(r, start[i]) * (1 - 1e-6))
              << "trial " << trial << " side " << side << " term " << i;
      }
      // Maximal: a little farther, some term is below its limit.
      if (std::isfinite(limit) && limit > 0) {
        ++blocked;
        const std::vector<double> past = terms(f, f.at(side * (limit + 1e-4)), u, v);
        bool below = false;
        for (std::size_t i = 0; i < past.size(); ++i) below |= past[i] < std::min(r, start[i]);
        EXPECT_TRUE(below) << "trial " << trial << " side " << side << " could have gone farther than " << limit;
      }
    }
  }
  EXPECT_GT(blocked, 1000);  // the sample exercised the limits, not only obstacles too far to matter
}

// The shortcuts that skip an obstacle, or one of its terms, when the limits found so far already stop both
// sides before it could: measuring obstacles one after another from given limits must give exactly the
// smallest of those limits and of each obstacle's own.
TEST(SplitReach, ObstaclesInTurnGiveTheSmallestOfTheirOwnLimits) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> coordinate(-1, 1), radius(0.02, 0.4), given(0, 1.5);
  int narrowed = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    const SplitFrame f({coordinate(random), coordinate(random)}, {coordinate(random), coordinate(random)});
    const double r = radius(random);
    Reach together{given(random), given(random)};
    Reach smallest = together;
    for (int k = 0; k < 4; ++k) {
      const Vec2 u{coordinate(random), coordinate(random)}, v{coordinate(random), coordinate(random)};
      Reach own;
      limit_exact(f, u, v, r, own);
      smallest = {std::min(smallest.positive, own.positive), std::min(smallest.negative, own.negative)};
      const Reach before = together;
      limit_exact(f, u, v, r, together);
      narrowed += together.positive < before.positive || together.negative < before.negative;
    }
    ASSERT_EQ(together.positive, smallest.positive) << "trial " << trial;
    ASSERT_EQ(together.negative, smallest.negative) << "trial " << trial;
  }
  EXPECT_GT(narrowed, 1000);  // the obstacles did narrow given limits, not only fail to reach them
}

TEST(SplitReach, NeighbourMeetingAtAnEndIsExceptedThere) {
  // The split segment (0,0)-(1,0) and its neighbour from (1,0) up to (1,1): the neighbour's shared end is
  // not a term, so the point moves up until the new segment from b comes within r of the neighbour's other
  // end or the point within r of the neighbour.
  const SplitFrame f({0, 0}, {1, 0});
  Reach reach;
  limit_exact(f, {1, 0}, {1, 1}, 0.1, reach);
  EXPECT_TRUE(std::isinf(reach.negative));
  // The point (0.5, t) never comes within 0.1 of the vertical neighbour (it stays 0.5 away); its far end
  // (1,1) is 0.5 / sqrt(0.25 + t²) from the new segment (0.5,t)-(1,0), which is 0.1 at t = sqrt(24.75).
  EXPECT_NEAR(reach.positive, std::sqrt(24.75), 1e-9);
}

TEST(SplitReach, VertexModeStopsBeforeACrossingAndAtTangents) {
  const SplitFrame f({0, 0}, {1, 0});
  Reach crossing;
  limit_vertex(f, {0, 0.5}, {1, 0.5}, 0.1, crossing);  // crosses the bisector at t = 0.5, square on
  EXPECT_NEAR(crossing.positive, 0.4, 1e-12);
  EXPECT_TRUE(std::isinf(crossing.negative));
  Reach disc;
  limit_vertex(f, {0.25, 0.5}, {0.25, 0.5}, 0.1, disc);  // a point on a's side: the tangent from a
  const double angle = std::atan2(0.5, 0.25) - std::asin(0.1 / std::hypot(0.25, 0.5));
  EXPECT_NEAR(disc.positive, 0.5 * std::tan(angle), 1e-12);
}
