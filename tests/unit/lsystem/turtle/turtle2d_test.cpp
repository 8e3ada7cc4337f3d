#include "kernels/lsystem/turtle/turtle2d.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>

#include "../table1.h"
#include "kernels/base/error.h"
#include "kernels/lsystem/production_count.h"
#include "kernels/lsystem/rewrite.h"

using namespace selfsim;
using namespace selfsim::lsystem;

namespace {

Polyline at(const Grammar& g, int level, bool normalize = true) {
  return turtle2d(g, {.level = level, .normalize = normalize}, no_progress());
}

double shoelace_area(std::span<const Vec2> p) {
  double twice = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i) twice += cross(p[i], p[i + 1]);
  return twice / 2;
}

}  // namespace

TEST(Turtle, OpenCurvesRunFromOriginToUnit) {
  for (auto g : {table1::dragon(), table1::terdragon(), table1::hilbert(), table1::arrowhead(), table1::koch(),
                 table1::gosper()})
    for (int n = 0; n <= 9; ++n) {
      const Polyline c = at(g, n);
      ASSERT_EQ(c.paths(), 1u);
      EXPECT_NEAR(norm(c.points.front()), 0, 1e-12) << g.axiom << " level " << n;
      EXPECT_NEAR(norm(c.points.back() - Vec2{1, 0}), 0, 1e-9) << g.axiom << " level " << n;
    }
}

TEST(Turtle, SegmentsOfALevelHaveEqualLength) {
  const Polyline c = at(table1::gosper(), 5);
  const double first = norm(c.points[1] - c.points[0]);
  for (std::size_t i = 1; i < c.points.size(); ++i) ASSERT_NEAR(norm(c.points[i] - c.points[i - 1]), first, 1e-12);
  // Normalised, level n's step is the chord over |chord of the unnormalised curve| = 7^(-n/2).
  EXPECT_NEAR(first, std::pow(7.0, -2.5), 1e-12);
}

TEST(Turtle, HilbertVisitsEveryCellOnce) {
  for (int n = 0; n <= 6; ++n) {
    const int k = n + 1, side = 1 << k;
    const Polyline c = at(table1::hilbert(), n);
    ASSERT_EQ(c.points.size(), static_cast<std::size_t>(side) * side);
    std::set<std::pair<long, long>> cells;
    for (Vec2 p : c.points) {
      const double x = p.x * (side - 1), y = p.y * (side - 1);
      ASSERT_NEAR(x, std::round(x), 1e-9);
      ASSERT_NEAR(y, std::round(y), 1e-9);
      const long i = std::lround(x), j = std::lround(y);
      ASSERT_TRUE(i >= 0 && i < side && j >= 0 && j < side) << i << "," << j;
      cells.insert({i, j});
    }
    EXPECT_EQ(cells.size(), static_cast<std::size_t>(side) * side);
  }
}

TEST(Turtle, KochSnowflakePerimeterAndArea) {
  const double triangle = std::sqrt(3.0) / 4;  // unit sides
  for (int n = 0; n <= 8; ++n) {
    const Polyline c = at(table1::koch_snowflake(), n);
    EXPECT_NEAR(norm(c.points.back() - c.points.front()), 0, 1e-12);
    EXPECT_NEAR(c.length(), 3 * std::pow(4.0 / 3.0, n), 1e-9);
    // Area after n steps: triangle * (1 + 3/5 (1 - (4/9)^n)), counterclockwise so positive.
    EXPECT_NEAR(shoelace_area(c.points), triangle * (1 + 0.6 * (1 - std::pow(4.0 / 9.0, n))), 1e-9);
  }
  EXPECT_NEAR(shoelace_area(at(table1::koch_snowflake(), 10).points) / triangle, 8.0 / 5.0, 1e-3);
}

TEST(Turtle, ClosedCurvesKeepShrinkAndStartAngle) {
  Grammar square{
      .axiom = "F+F+F+F", .rules = {{'F', "F+F-F-FF+F+F-F"}}, .angle = 90, .start_angles = {30}, .shrink = 0.25};
  const Polyline c = at(square, 2);
  EXPECT_NEAR(norm(c.points[1] - c.points[0]), 1.0 / 16, 1e-12);
  const Vec2 d = c.points[1] - c.points[0];
  EXPECT_NEAR(std::atan2(d.y, d.x), 30 * std::numbers::pi / 180, 1e-12);
}

TEST(Turtle, StartAngleListIsCycledByLevel) {
  Grammar g = table1::arrowhead();
  g.start_angles = {0, 60};
  g.shrink = 0.5;
  for (int n = 0; n <= 7; ++n) {
    const Polyline c = at(g, n, /*normalize=*/false);
    EXPECT_NEAR(norm(c.points.back() - Vec2{1, 0}), 0, 1e-9) << n;  // odd levels turned back onto the x axis
  }
}

TEST(Turtle, BranchesBecomeSeparatePaths) {
  Grammar g{.axiom = "F[+F]F[-F]F", .angle = 90, .start_angles = {0}};
  const Polyline c = at(g, 0, false);
  ASSERT_EQ(c.paths(), 3u);  // main+first branch, stem+second branch, last stem segment
  EXPECT_EQ(c.segments(), 5u);
  EXPECT_EQ(c.path(2).front(), (Vec2{2, 0}));
  EXPECT_NEAR(norm(c.path(0).back() - Vec2{1, 1}), 0, 1e-12);
}

TEST(Turtle, MoveSymbolsBreakThePath) {
  Grammar g{.axiom = "FfF", .angle = 90};
  const Polyline c = at(g, 0, false);
  ASSERT_EQ(c.paths(), 2u);
  EXPECT_EQ(c.path(1).front(), (Vec2{2, 0}));
}

TEST(Turtle, PerSymbolAnglesAndIrrationalTurns) {
  Grammar g{.axiom = "FAFAFAF", .angle = 90, .angles = {{'A', 100 * std::numbers::sqrt2}}};
  const Polyline c = at(g, 0, false);
  const double a = 100 * std::numbers::sqrt2 * std::numbers::pi / 180;
  Vec2 expected{1, 0};
  for (int i = 1; i <= 3; ++i) expected = expected + polar(i * a);
  EXPECT_NEAR(norm(c.points.back() - expected), 0, 1e-12);
}

TEST(Turtle, RefusesLevelsOverTheLimitBeforeWork) {
  try {
    turtle2d(table1::dragon(), {.level = 40, .budget = {1e6}}, no_progress());
    FAIL() << "expected an error";
  } catch (const BudgetError& e) {
    EXPECT_NE(std::string(e.what()).find("1099511627777 points"), std::string::npos) << e.what();
  }
}

TEST(Turtle, UnbalancedBracketIsAnError) { EXPECT_THROW(at(Grammar{.axiom = "F]F"}, 0), Error); }

TEST(Turtle, CancellationStopsTheKernel) {
  struct StopAtOnce : Progress {
    bool cancelled() override { return true; }
  } stop;
  EXPECT_THROW(turtle2d(table1::dragon(), {.level = 22}, stop), Cancelled);
}

TEST(Turtle, RewritingWithoutDrawingIsStillCancellable) {
  struct StopAtOnce : Progress {
    bool cancelled() override { return true; }
  } stop;
  // 2^25 rules expanded and not one segment: only the rewrite count can notice the cancellation (the
  // brackets keep X out of the precomputed blocks, which would otherwise make this instant).
  EXPECT_THROW(turtle2d(Grammar{.axiom = "X", .rules = {{'X', "X[]X"}}}, {.level = 25}, stop), Cancelled);
  EXPECT_THROW(turtle2d(Grammar{.axiom = "X", .rules = {{'X', "XX"}}}, {.level = 60}, no_progress()), Error);
}

// Cancels only once the turtle has started walking, after the prediction: what the walk itself checks.
struct StopOnceWalking : Progress {
  bool walking = false;
  void start(const char*) override { walking = true; }
  bool cancelled() override { return walking; }
};

TEST(Turtle, TurnsThatDrawNothingAreCheckedPerSymbol) {
  // 4 million turns, one rule frame per level and no point: only a per-symbol check can notice the stop.
  StopOnceWalking stop;
  const Grammar turns{.axiom = "X", .rules = {{'X', "X" + std::string(65536, '+')}}};
  EXPECT_THROW(turtle2d(turns, {.level = 64}, stop), Cancelled);
  EXPECT_EQ(turtle2d(turns, {.level = 64}, no_progress()).points.size(), 0u);
}

TEST(Turtle, PredictionIsCancellable) {
  struct StopAtOnce : Progress {
    bool cancelled() override { return true; }
  } stop;
  EXPECT_THROW(predict_counts(table1::dragon(), 200, stop), Cancelled);
}

TEST(Turtle, HugeAnglesAreReducedExactly) {
  // 360 * 2^40 + 90 degrees is a quarter turn: exactly representable, so the curve must equal angle 90's.
  const double turns = 360.0 * std::ldexp(1.0, 40) + 90;
  Grammar big = table1::dragon(), plain = table1::dragon();
  big.angle = turns;
  const Polyline a = turtle2d(big, {.level = 10}, no_progress()), b = turtle2d(plain, {.level = 10}, no_progress());
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i], b.points[i]) << i;
}

TEST(Turtle, OpenBranchesAreBudgeted) {
  // X -> 20000 '[', X, 20000 ']' has 20000 x level branches open at once (and as many breaks); each saved
  // state costs two points of the budget.
  const Grammar open{.axiom = "X", .rules = {{'X', std::string(20000, '[') + "X" + std::string(20000, ']')}}};
  EXPECT_THROW(turtle2d(open, {.level = 20, .budget = {1e6}}, no_progress()), BudgetError);
  EXPECT_NO_THROW(turtle2d(open, {.level = 12, .budget = {1e6}}, no_progress()));
}

TEST(Turtle, BudgetCountsThePointsPathBreaksAdd) {
  // Four paths of one segment: 4 segments but 8 points (found by the grammar fuzzer).
  const Grammar broken{.axiom = "FfFfFfFf"};
  EXPECT_THROW(turtle2d(broken, {.level = 0, .budget = {5}}, no_progress()), BudgetError);
  EXPECT_EQ(turtle2d(broken, {.level = 0, .budget = {9}}, no_progress()).points.size(), 8u);
}

TEST(Turtle, BudgetCountsHeldPoints) {
  // 1025 points fit a limit of 2000, but not beside 1000 points already held.
  EXPECT_NO_THROW(turtle2d(table1::dragon(), {.level = 10, .budget = {2000, 0}}, no_progress()));
  EXPECT_THROW(turtle2d(table1::dragon(), {.level = 10, .budget = {2000, 1000}}, no_progress()), BudgetError);
}

TEST(Turtle, ExpandStringOfTheDragon) {
  EXPECT_EQ(expand_string(table1::dragon(), 2, 100), "FX-YF-FX+YF");
  EXPECT_THROW(expand_string(table1::dragon(), 30, 1e6), Error);
}

TEST(Grammar, ValidationNamesTheField) {
  auto message = [](Grammar g) {
    try {
      g.validate();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(Grammar{}).find("'axiom'"), std::string::npos);
  EXPECT_NE(message(Grammar{.axiom = "F", .angle = NAN}).find("'angle'"), std::string::npos);
  EXPECT_NE(message(Grammar{.axiom = "F", .shrink = 0}).find("'shrink'"), std::string::npos);
  EXPECT_NE(message(Grammar{.axiom = "F", .start_angles = {0, NAN}}).find("'start_angle'"), std::string::npos);
  EXPECT_EQ(message(Grammar{.axiom = "F", .start_angles = {}}), "");  // none given: the turtle's default
}

TEST(Turtle, BranchedSystemsCarryBranchOrderAndRootDistance) {
  // F[+F]F: a stem of two steps with a branch at its middle; normalised, the stem runs (0,0) → (1,0). The
  // branch continues the first path; the stem's second step starts a new one at (1/2, 0).
  const Polyline c = turtle2d(Grammar{.axiom = "F[+F]F", .angle = 90}, {.level = 0, .normalize = true}, no_progress());
  ASSERT_EQ(c.points.size(), 5u);
  const Field* depth = c.point_fields.find("branch_order");
  const Field* root = c.point_fields.find("root_distance");
  ASSERT_NE(depth, nullptr);
  ASSERT_NE(root, nullptr);
  const std::vector<std::int32_t> want_depth{0, 0, 1, 0, 0};
  const std::vector<double> want_root{0, 0.5, 1, 0.5, 1};  // unit steps scaled by the normalisation
  EXPECT_EQ(std::vector<std::int32_t>(depth->ints().begin(), depth->ints().end()), want_depth);
  EXPECT_EQ(std::vector<double>(root->reals().begin(), root->reals().end()), want_root);
  // Unbranched curves stay as they were: only the level.
  EXPECT_EQ(turtle2d(table1::dragon(), {.level = 5}, no_progress()).point_fields.list.size(), 1u);
}
