#include "kernels/lsystem/module_count.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernels/base/error.h"
#include "kernels/lsystem/module_rewrite.h"
#include "kernels/lsystem/rule_parser.h"
#include "kernels/lsystem/turtle/module_turtle.h"
#include "module_grammar.h"

using namespace selfsim;
using namespace selfsim::lsystem;
using test::draws_f;
using test::rules_of;

namespace {

struct Counter : ModuleSink {
  double modules = 0, steps = 0;
  void module(std::uint8_t s, std::span<const double>) override {
    ++modules;
    steps += s == 'F';
  }
};

// What the derivation feeds the turtle, counted module by module.
Counter derived(const Grammar& g, int level) {
  Counter c;
  ModuleLimits limits;
  limits.steps = draws_f();
  rewrite_modules(g, level, c, limits, no_progress(), true);
  return c;
}

Grammar grammar(const std::string& axiom, const std::vector<std::string>& rules,
                const std::vector<std::string>& decomposition, const std::vector<std::string>& interpretation,
                int max_depth) {
  Grammar g = test::module_grammar(axiom, rules);
  g.decomposition = rules_of(decomposition);
  g.interpretation = rules_of(interpretation);
  g.max_depth = max_depth;
  return g;
}

struct CancelAtOnce : Progress {
  bool cancelled() override { return true; }
};

}  // namespace

// Predicted exactly what the derivation writes: productions, decompositions (to max_depth, on the axiom
// too) and interpretations, parameters, empty successors, depth limits.
TEST(ModuleCount, EqualsWhatTheDerivationWrites) {
  const std::vector<Grammar> grammars = {
      grammar("A", {"A -> A A"}, {}, {"A -> F"}, 64),
      grammar("A", {"A -> A A"}, {"B -> F C"}, {"A -> F"}, 64),
      grammar("A B", {"A -> A B", "B -> A"}, {"B -> F C F"}, {"C -> F F", "A -> F [ + F ]"}, 3),
      grammar("A(1)", {"A(x) -> A(x) B(x / 2) A(x)"}, {"B(x) -> F G(x) B(x)"}, {"A(x) -> F G(x)"}, 2),
      grammar("A", {"A -> A X"}, {"X -> X X"}, {"X -> F X", "A -> "}, 5),
      grammar("T", {"T -> T T"}, {}, {"T -> U U", "U -> V V", "V -> F F"}, 2),  // stops at depth 2: V stays
  };
  for (std::size_t k = 0; k < grammars.size(); ++k)
    for (int level : {0, 1, 4, 7}) {
      const std::optional<ModuleCounts> n = predict_module_counts(grammars[k], level, draws_f(), true, no_progress());
      ASSERT_TRUE(n.has_value()) << k;
      const Counter c = derived(grammars[k], level);
      EXPECT_EQ(n->modules, c.modules) << "grammar " << k << " level " << level;
      EXPECT_EQ(n->steps, c.steps) << "grammar " << k << " level " << level;
    }
}

TEST(ModuleCount, HugeLevelsAtOnce) {
  const Grammar g = grammar("A", {"A -> A A"}, {"B -> F C"}, {"A -> F"}, 64);
  const std::optional<ModuleCounts> n = predict_module_counts(g, 200, draws_f(), true, no_progress());
  ASSERT_TRUE(n.has_value());
  EXPECT_EQ(n->steps, std::ldexp(1.0, 200));
}

TEST(ModuleCount, ConditionsContextsChoicesAndCutsAreNotPredicted) {
  EXPECT_FALSE(predict_module_counts(grammar("A(1)", {"A(x) : x > 0 -> A(x) A(x)"}, {}, {}, 4), 3, draws_f(), true,
                                     no_progress()));
  EXPECT_FALSE(predict_module_counts(grammar("B A", {"B < A -> A A"}, {}, {}, 4), 3, draws_f(), true, no_progress()));
  Grammar chooses = grammar("A", {"A -> A"}, {}, {"A -> F A"}, 4);
  chooses.interpretation[0].options.push_back(chooses.interpretation[0].options[0]);
  EXPECT_FALSE(predict_module_counts(chooses, 3, draws_f(), true, no_progress()));
  EXPECT_FALSE(predict_module_counts(grammar("A", {"A -> A [ % A ]"}, {}, {}, 4), 3, draws_f(), true, no_progress()));
  EXPECT_FALSE(predict_module_counts(grammar("A", {"A -> A"}, {"A -> F %"}, {}, 4), 3, draws_f(), true, no_progress()));
}

TEST(ModuleCount, PollsForAStop) {
  CancelAtOnce stop;
  EXPECT_THROW(predict_module_counts(grammar("A", {"A -> A A"}, {}, {"A -> F"}, 8), 3, draws_f(), true, stop),
               Cancelled);
}

// The turtle and the count refuse or count a predicted level at once, without deriving it.
TEST(ModuleCount, CurveRefusedAndCountedAtOnce) {
  const Grammar g = grammar("A", {"A -> A A"}, {}, {"A -> F"}, 64);
  TurtleOptions opt;
  opt.level = 40;
  opt.budget = PointBudget{1000, 0};
  EXPECT_THROW(module_turtle2d(g, opt, no_progress()), BudgetError);
  EXPECT_EQ(module_segments(g, 40, 1000, no_progress()), std::ldexp(1.0, 40));
}
