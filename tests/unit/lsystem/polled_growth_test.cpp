#include "kernels/lsystem/polled_growth.h"

#include <gtest/gtest.h>

#include <numeric>

#include "kernels/base/budget.h"
#include "kernels/lsystem/rule_parser.h"
#include "kernels/lsystem/turtle/module_turtle.h"
#include "module_grammar.h"

using namespace selfsim;
using namespace selfsim::lsystem;

namespace {

// Says stop from its n-th look on.
struct StopAfter : Progress {
  int left;
  explicit StopAfter(int n) : left(n) {}
  bool cancelled() override { return --left < 0; }
};

}  // namespace

// A vector of several pieces grows piece by piece, looking for a stop between them; what it holds is kept.
TEST(PolledGrowth, CopiesInPiecesThatLookForAStop) {
  std::vector<int> v(3 * growth_piece);
  std::iota(v.begin(), v.end(), 0);
  StopAfter stop(2);
  EXPECT_THROW(grow_polled(v, v.size() + 1, 10 * growth_piece, stop), Cancelled);
  EXPECT_EQ(v.size(), 3 * growth_piece);  // untouched by the stopped growth
  grow_polled(v, v.size() + 1, 10 * growth_piece, no_progress());
  EXPECT_EQ(v.capacity(), 6 * growth_piece);
  EXPECT_EQ(v[growth_piece + 5], static_cast<int>(growth_piece + 5));
  v.resize(6 * growth_piece);
  grow_polled(v, v.size() + 1, 7 * growth_piece, no_progress());
  EXPECT_EQ(v.capacity(), 7 * growth_piece);  // twice would pass the cap
}

// The module turtle's points never take more room than the budget allows (doubling took up to twice it).
TEST(PolledGrowth, TurtleHoldsNoMoreThanTheBudget) {
  Grammar g = test::module_grammar("FFFFFFFFFFA(1)", {"A(x) : x > 0 -> A(x) F A(x)"});
  TurtleOptions opt;
  opt.level = 11;  // 10 + 2^11 - 1 steps: 2058 points
  opt.budget = PointBudget{3000, 0};
  const Polyline c = module_turtle2d(g, opt, no_progress());
  EXPECT_EQ(c.points.size(), 2058u);
  EXPECT_LE(c.points.capacity(), 3001u);
}
