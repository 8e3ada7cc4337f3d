#include "kernels/lsystem/turtle/turtle_split.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <atomic>
#include <cstring>

#include "../table1.h"
#include "kernels/lsystem/production_count.h"
#include "kernels/lsystem/rewrite.h"
#include "kernels/lsystem/turtle/turtle2d.h"

using namespace selfsim;
using namespace selfsim::lsystem;

namespace {

Polyline with_threads(const Grammar& g, int level, int threads) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  return turtle2d(g, {.level = level}, no_progress());
}

std::optional<TurtleSplit> split_of(const Grammar& g, int level) {
  const Compiled c(g);
  if (c.lattice() == 0) return std::nullopt;
  const LatticeTable t(c, c.lattice(), g.start_angle(level));
  return split_level(g, c, t, level, no_progress());
}

// The plain string turtle in unit steps, the reference for where every point must be.
std::vector<Vec2> string_turtle(const Grammar& g, int level) {
  const std::string s = expand_string(g, level, 1e9);
  std::vector<Vec2> pts{{0, 0}};
  Vec2 pos{};
  double degrees = g.start_angle(level);
  for (char x : s) {
    if (g.draws(x)) {
      pos += polar(degrees * std::numbers::pi / 180);
      pts.push_back(pos);
    } else {
      degrees += g.turn_of(x);
    }
  }
  return pts;
}

}  // namespace

TEST(TurtleSplit, ByteIdenticalForAnyThreadCount) {
  for (const auto& [g, level] : std::vector<std::pair<Grammar, int>>{{table1::dragon(), 18},
                                                                     {table1::terdragon(), 11},
                                                                     {table1::koch_snowflake(), 8},
                                                                     {table1::hilbert(), 9},
                                                                     {table1::gosper(), 6},
                                                                     {table1::arrowhead(), 11}}) {
    ASSERT_TRUE(split_of(g, level).has_value()) << g.axiom << " level " << level << " should be split";
    const Polyline one = with_threads(g, level, 1);
    for (int threads : {2, 7}) {
      const Polyline many = with_threads(g, level, threads);
      ASSERT_EQ(many.points.size(), one.points.size());
      EXPECT_EQ(std::memcmp(many.points.data(), one.points.data(), one.points.size() * sizeof(Vec2)), 0)
          << g.axiom << " level " << level << " differs between 1 and " << threads << " threads";
      EXPECT_EQ(many.path_ends, one.path_ends);
    }
  }
}

TEST(TurtleSplit, MatchesTheStringTurtle) {
  for (const auto& [g, level] : std::vector<std::pair<Grammar, int>>{
           {table1::dragon(), 17}, {table1::terdragon(), 11}, {table1::koch_snowflake(), 8}, {table1::gosper(), 6}}) {
    const Polyline c = turtle2d(g, {.level = level, .normalize = false}, no_progress());
    const std::vector<Vec2> want = string_turtle(g, level);
    ASSERT_EQ(c.points.size(), want.size());
    const double step = std::pow(g.shrink, level), tol = 1e-9 * step * static_cast<double>(want.size());
    for (std::size_t i = 0; i < want.size(); i += 97)
      ASSERT_NEAR(norm(c.points[i] - step * want[i]), 0, tol) << g.axiom << " level " << level << " point " << i;
    EXPECT_NEAR(norm(c.points.back() - step * want.back()), 0, tol);
  }
}

TEST(TurtleSplit, ChunksCoverTheLevelInOrder) {
  const auto split = split_of(table1::dragon(), 20);
  ASSERT_TRUE(split.has_value());
  EXPECT_EQ(split->points, (std::size_t{1} << 20) + 1);
  std::size_t symbol = 0, point = 1;
  for (const TurtleChunk& k : split->chunks) {
    EXPECT_EQ(k.begin, symbol);
    EXPECT_EQ(k.first_point, point);
    EXPECT_GT(k.end, k.begin);
    symbol = k.end;
    point += k.points;
  }
  EXPECT_EQ(symbol, split->symbols.size());
  EXPECT_EQ(point, split->points);
  // The split string is the level-depth string, and the turtle ends where the dragon does: at (-2^10, 0)
  // rotated by the start heading, 2^10 unit steps away for level 20.
  EXPECT_EQ(split->symbols, expand_string(table1::dragon(), split->depth, 1e6));
  EXPECT_NEAR(norm(split->end), 1024, 1e-6);
}

TEST(TurtleSplit, OnlyWhereItIsExact) {
  const Grammar plant{.axiom = "X", .rules = {{'X', "F[+X]F[-X]+X"}, {'F', "FF"}}, .angle = 20};
  EXPECT_FALSE(split_of(plant, 9).has_value()) << "branches are drawn by one thread";
  const Grammar moves{.axiom = "F", .rules = {{'F', "F+f-FF"}}, .angle = 90};
  EXPECT_FALSE(split_of(moves, 9).has_value()) << "moves are drawn by one thread";
  EXPECT_FALSE(split_of(table1::dragon(), 10).has_value()) << "small levels are drawn by one thread";
  const Grammar irrational{.axiom = "F", .rules = {{'F', "F+F-F"}}, .angle = 1};
  EXPECT_EQ(Compiled(Grammar{.axiom = "F", .angle = std::sqrt(2.0)}).lattice(), 0);
  EXPECT_TRUE(split_of(irrational, 11).has_value()) << "1 degree is a lattice of 360";
}

TEST(TurtleSplit, CancelledFromWorkerThreads) {
  struct StopLater : Progress {
    std::atomic<int> calls{0};
    bool cancelled() override { return ++calls > 40; }
  } stop;
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
  EXPECT_THROW(turtle2d(table1::dragon(), {.level = 24}, stop), Cancelled);
}

TEST(TurtleSplit, AnAxiomLongerThanTheSplitLimitIsSplitAsItIs) {
  const Grammar g{.axiom = std::string(70000, 'F'), .rules = {{'F', "F+F-F"}}, .angle = 90};
  const auto split = split_of(g, 1);
  ASSERT_TRUE(split.has_value());
  EXPECT_EQ(split->depth, 0);
  EXPECT_EQ(with_threads(g, 1, 1).points.size(), 210001u);
  EXPECT_EQ(with_threads(g, 0, 2).points.size(), 70001u);
}
