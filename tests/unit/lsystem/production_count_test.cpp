#include "kernels/lsystem/production_count.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "kernels/lsystem/rewrite.h"
#include "kernels/lsystem/turtle/turtle2d.h"
#include "table1.h"

using namespace selfsim::lsystem;

namespace {
double pow_(double b, int n) { return std::pow(b, n); }
}  // namespace

TEST(ProductionCount, ClosedFormsOfTable1) {
  for (int n = 0; n <= 18; ++n) {  // 7^18 is the last Gosper count below 2^53, where doubles are exact
    EXPECT_EQ(predict_counts(table1::dragon(), n).segments, pow_(2, n)) << n;
    EXPECT_EQ(predict_counts(table1::terdragon(), n).segments, pow_(3, n)) << n;
    EXPECT_EQ(predict_counts(table1::arrowhead(), n).segments, pow_(3, n)) << n;
    EXPECT_EQ(predict_counts(table1::koch(), n).segments, pow_(4, n)) << n;
    EXPECT_EQ(predict_counts(table1::koch_snowflake(), n).segments, 3 * pow_(4, n)) << n;
    EXPECT_EQ(predict_counts(table1::gosper(), n).segments, pow_(7, n)) << n;
    // Table 1's Hilbert axiom is the classic level 1, so level n lives on the 2^(n+1) grid.
    EXPECT_EQ(predict_counts(table1::hilbert(), n).segments, pow_(4, n + 1) - 1) << n;
  }
}

TEST(ProductionCount, PredictionEqualsExpansion) {
  for (auto g : {table1::dragon(), table1::terdragon(), table1::hilbert(), table1::arrowhead(),
                 table1::koch_snowflake(), table1::gosper()})
    for (int n = 0; n <= 6; ++n) {
      const LevelCounts c = predict_counts(g, n);
      EXPECT_EQ(c.symbols, static_cast<double>(expand_string(g, n, 1e9).size()));
      EXPECT_EQ(c.segments, static_cast<double>(turtle2d(g, {.level = n}, selfsim::no_progress()).segments()));
    }
}

TEST(ProductionCount, BranchesCountAsPathBreaks) {
  Grammar plant{.axiom = "X", .rules = {{'X', "F[+X][-X]FX"}, {'F', "FF"}}, .angle = 25};
  for (int n = 0; n <= 5; ++n) {
    const std::string s = expand_string(plant, n, 1e9);
    EXPECT_EQ(predict_counts(plant, n).breaks, static_cast<double>(std::count(s.begin(), s.end(), ']')));
  }
}

TEST(ProductionCount, HugeLevelsStayOrdered) {
  // 2^200 is far past exact integers but must still compare as enormous, not wrap around.
  EXPECT_GT(predict_counts(table1::dragon(), 200).segments, 1e59);
}

// The deepest '[' nesting of a string, by reading it.
double nesting(const std::string& s) {
  double depth = 0, deepest = 0;
  for (char c : s) {
    depth += c == '[' ? 1 : c == ']' ? -1 : 0;
    deepest = std::max(deepest, depth);
  }
  return deepest;
}

TEST(ProductionCount, BranchDepthEqualsExpansion) {
  const std::vector<Grammar> grammars{{.axiom = "X", .rules = {{'X', "F+[[X]-X]-F[-FX]+X"}, {'F', "FF"}}},
                                      {.axiom = "X", .rules = {{'X', "[X[X]]"}}},
                                      {.axiom = "[F]X[]", .rules = {{'X', "F[X]X[[F]]"}, {'F', "F[F]"}}},
                                      table1::dragon()};
  for (const Grammar& g : grammars)
    for (int level = 0; level <= 6; ++level)
      EXPECT_EQ(predict_counts(g, level).max_depth, nesting(expand_string(g, level, 1e7)))
          << g.axiom << " level " << level;
  // X -> [X[X]]: 2 x level open at once (a '[' never closed is refused: Grammar::validate).
  EXPECT_EQ(predict_counts(grammars[1], 24).max_depth, 48);
}
