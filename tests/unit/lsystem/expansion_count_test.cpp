#include "kernels/lsystem/expansion_count.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "kernels/base/budget.h"
#include "kernels/lsystem/module_rewrite.h"
#include "kernels/lsystem/rule_parser.h"
#include "module_grammar.h"

using namespace selfsim;
using namespace selfsim::lsystem;
using test::draws_f;
using test::rules_of;

namespace {

constexpr double unlimited = std::numeric_limits<double>::infinity();

// The size of one module's expansion by `rules` to max_depth.
ExpansionSize size_of(const Grammar& g, const std::vector<Production>& rules, std::uint8_t symbol,
                      std::vector<double> args = {}, double max_modules = unlimited, double max_steps = unlimited,
                      Progress& progress = no_progress()) {
  const RuleIndex index(rules);
  RuleScope scope(g);
  ExpansionCount count(index, g.max_depth, scope, draws_f(), progress);
  return count.count(symbol, args, 0, 0, max_modules, max_steps);
}

struct Counter : ModuleSink {
  double modules = 0, steps = 0;
  void module(std::uint8_t s, std::span<const double>) override {
    ++modules;
    steps += s == 'F';
  }
};

}  // namespace

TEST(ExpansionCount, DoublingRuleIsCountedExactlyAndAtOnce) {
  Grammar g = test::module_grammar("A", {});
  const std::vector<Production> rules = rules_of({"A -> F A A"});
  // D levels deep: 2^D - 1 F and 2^D A left as they are.
  g.max_depth = 10;
  ExpansionSize s = size_of(g, rules, 'A');
  EXPECT_EQ(s.modules, 2047);
  EXPECT_EQ(s.steps, 1023);
  EXPECT_FALSE(s.over);
  ASSERT_NE(s.rule, nullptr);
  EXPECT_EQ(s.rule->text, "A -> F A A");
  // Memoised per depth: 2^65 - 1 modules counted in 64 steps (as a double).
  g.max_depth = 64;
  s = size_of(g, rules, 'A');
  EXPECT_EQ(s.modules, std::ldexp(1.0, 65));
  EXPECT_FALSE(s.over);
  // A symbol without a rule, or max_depth 0: the module itself.
  EXPECT_EQ(size_of(g, rules, 'F').modules, 1);
  g.max_depth = 0;
  EXPECT_EQ(size_of(g, rules, 'A').modules, 1);
}

TEST(ExpansionCount, EqualsWhatTheDerivationWrites) {
  // Parameters and a condition: the count follows them as the derivation does.
  Grammar g = test::module_grammar("A(1)", {});
  g.interpretation = rules_of({"A(x) : x > 0.01 -> F(x) [+ A(x * 0.5)] A(x * 0.7)"});
  g.max_depth = 12;
  Counter drawn;
  rewrite_modules(g, 0, drawn, {}, no_progress(), true);
  const ExpansionSize s = size_of(g, g.interpretation, 'A', {1});
  EXPECT_EQ(s.modules, drawn.modules);
  EXPECT_EQ(s.steps, drawn.steps);
  EXPECT_GT(s.modules, 1000);
}

TEST(ExpansionCount, StopsPastItsCaps) {
  Grammar g = test::module_grammar("A", {});
  g.max_depth = 40;
  // Choices make every module's expansion its own (no memo helps): counting stops just past the cap.
  const std::vector<Production> choices = rules_of({"A -> F A A : 1", "A -> F A A A : 1"});
  std::vector<Production> one = {choices[0]};
  one[0].options.push_back(choices[1].options[0]);
  const ExpansionSize s = size_of(g, one, 'A', {}, unlimited, 1000);
  EXPECT_TRUE(s.over);
  EXPECT_GT(s.steps, 1000);
  EXPECT_LT(s.steps, 1100);
  EXPECT_TRUE(size_of(g, one, 'A', {}, 5000, unlimited).over);
}

TEST(ExpansionCount, PollsForAStop) {
  struct Stop : Progress {
    bool cancelled() override { return true; }
  } stop;
  Grammar g = test::module_grammar("A", {});
  g.max_depth = 40;
  EXPECT_THROW(size_of(g, rules_of({"A -> F A A"}), 'A', {}, unlimited, unlimited, stop), Cancelled);
}

// The derivation counts an interpretation or decomposition before any of it reaches the sink: refused with
// nothing drawn, not after drawing up to the budget.
TEST(ExpansionCount, DerivationRefusesBeforeWriting) {
  Grammar g = test::module_grammar("A", {"Z -> Z"});
  g.interpretation = rules_of({"A -> F A A"});
  g.max_depth = 40;
  Counter drawn;
  ModuleLimits limits{.work = 1e12, .held = 1e6};
  limits.points = PointBudget{1e5};
  limits.steps = draws_f();
  try {
    rewrite_modules(g, 0, drawn, limits, no_progress(), true);
    FAIL() << "not refused";
  } catch (const BudgetError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("level 0 through entry 1 (A -> F A A) would make more than 100000 points"), std::string::npos)
        << m;
  }
  EXPECT_EQ(drawn.modules, 0);
  // The modules written, for g:count (no point budget).
  EXPECT_THROW(rewrite_modules(g, 0, drawn, {.work = 1e6, .held = 1e6}, no_progress(), true), BudgetError);
  EXPECT_EQ(drawn.modules, 0);
  // Decomposition: counted before it is held.
  Grammar d = test::module_grammar("A", {"Z -> Z"});
  d.decomposition = rules_of({"A -> F A A"});
  d.max_depth = 40;
  EXPECT_THROW(rewrite_modules(d, 0, drawn, {.work = 1e12, .held = 1e5}, no_progress()), BudgetError);
  EXPECT_EQ(drawn.modules, 0);
  // Within the budget, drawn as before.
  g.max_depth = 10;
  rewrite_modules(g, 0, drawn, limits, no_progress(), true);
  EXPECT_EQ(drawn.modules, 2047);
}
