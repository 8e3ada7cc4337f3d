#include "kernels/lsystem/compiled_grammar.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernels/lsystem/production_count.h"
#include "kernels/lsystem/rewrite.h"
#include "kernels/lsystem/turtle/turtle2d.h"
#include "table1.h"

using namespace selfsim;
using namespace selfsim::lsystem;

namespace {

// The obvious turtle over the expanded string, with an angle in radians: the reference the streamed,
// block-copying turtle must reproduce. Returns all points, paths concatenated.
std::vector<Vec2> reference(const Grammar& g, int level) {
  const std::string s = expand_string(g, level, 1e8);
  const double step = std::pow(g.shrink, level);
  std::vector<Vec2> pts;
  std::vector<std::pair<Vec2, double>> stack;
  Vec2 pos{};
  double heading = g.start_angle(level) * std::numbers::pi / 180;
  bool open = false;
  for (char c : s) {
    if (g.draws(c)) {
      if (!open) pts.push_back(pos);
      open = true;
      pos += step * polar(heading);
      pts.push_back(pos);
    } else if (c == '[') {
      stack.emplace_back(pos, heading);
    } else if (c == ']') {
      std::tie(pos, heading) = stack.back();
      stack.pop_back();
      open = false;
    } else {
      heading += g.turn_of(c) * std::numbers::pi / 180;
    }
  }
  return pts;
}

}  // namespace

TEST(LatticeBlocks, ChosenDepthStaysWithinLevelAndSize) {
  const Grammar g = table1::dragon();
  const Compiled c(g);
  const LatticeTable t(c, c.lattice(), 0);
  EXPECT_EQ(t.n, 4);
  const LatticeBlocks b(g, c, t, 20, no_progress());
  EXPECT_EQ(b.depth, 10);  // 2^10 = 1024 points per block is the largest allowed
  for (const auto& block : b.blocks) EXPECT_LE(block.points[0].size(), 1024u);
  EXPECT_EQ(LatticeBlocks(g, c, t, 3, no_progress()).depth, 3);
  EXPECT_EQ(LatticeBlocks(g, c, t, 0, no_progress()).depth, 0);
}

TEST(LatticeBlocks, BranchingRulesAreNotBlocked) {
  const Grammar plant{.axiom = "X", .rules = {{'X', "F[+X]F[-X]+X"}, {'F', "FF"}}, .angle = 20};
  const Compiled c(plant);
  const LatticeTable t(c, c.lattice(), 90);
  EXPECT_EQ(t.n, 18);
  const LatticeBlocks b(plant, c, t, 8, no_progress());
  EXPECT_EQ(b.block['X'], -1);
  EXPECT_GE(b.block['F'], 0);
}

TEST(Turtle, StreamedBlocksMatchTheStringTurtle) {
  const Grammar plant{.axiom = "X", .rules = {{'X', "F[+X]F[-X]+X"}, {'F', "FF"}}, .angle = 20, .start_angles = {90}};
  for (const Grammar& g : {table1::dragon(), table1::terdragon(), table1::gosper(), table1::hilbert(), plant})
    for (int level : {0, 1, 5, 11}) {
      if (predict_counts(g, level).segments > 3e6) continue;
      const Polyline c = turtle2d(g, {.level = level, .normalize = false}, no_progress());
      const std::vector<Vec2> want = reference(g, level);
      ASSERT_EQ(c.points.size(), want.size()) << g.axiom << " " << level;
      const double tol = 1e-9 * std::max(1.0, norm(c.bbox().size()));
      for (std::size_t i = 0; i < want.size(); ++i)
        ASSERT_NEAR(norm(c.points[i] - want[i]), 0, tol) << g.axiom << " level " << level << " point " << i;
    }
}

TEST(Compiled, TurnsAreReducedExactly) {
  // 1e20 is an exact double; 1e20 mod 360 = 280 (0 mod 8 and 10 mod 45).
  const Compiled c(Grammar{.axiom = "F", .angle = 1e20});
  EXPECT_EQ(c.turn['+'], 280);
  EXPECT_EQ(c.turn['-'], -280);
  EXPECT_EQ(c.lattice(), 18);  // 280 = 7 steps of 40 degrees, and | (180) needs an even count
}

TEST(LatticeBlocks, BuildingWorkIsBounded) {
  // 7200 headings times rules of 16000 turns: blocks would cost 10^8 steps to build, so none are made.
  const Grammar g{.axiom = "X", .rules = {{'X', "F" + std::string(16000, '+') + "X"}}, .angle = 0.05};
  const Compiled c(g);
  ASSERT_EQ(c.lattice(), 7200);
  const LatticeTable t(c, c.lattice(), 0);
  EXPECT_EQ(LatticeBlocks(g, c, t, 3, no_progress()).depth, 0);
}
