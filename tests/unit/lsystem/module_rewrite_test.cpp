#include "kernels/lsystem/module_rewrite.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernels/base/budget.h"
#include "kernels/lsystem/rewrite.h"
#include "kernels/lsystem/rule_parser.h"

using namespace selfsim;
using namespace selfsim::lsystem;

namespace {

// A module grammar from ABOP rule strings; rules whose text ends in ": w" and share a predecessor become
// the weighted choices of one rule, as the recipe reader groups them.
Grammar grammar(const std::string& axiom, const std::vector<std::string>& rules, std::uint64_t seed = 0) {
  Grammar g;
  g.axiom = axiom;
  g.start = parse_calls(axiom, {});
  for (const std::string& r : rules) {
    Production p = parse_rule(r, "rule " + std::to_string(g.productions.size() + 1));
    if (rule_weight_given(r) && !g.productions.empty() && g.productions.back().pred.symbol == p.pred.symbol)
      g.productions.back().options.push_back(std::move(p.options[0]));
    else
      g.productions.push_back(std::move(p));
  }
  g.seed = seed;
  return g;
}

std::string text(const Grammar& g, int level) { return module_string_text(g, level, 1e8, no_progress()); }

}  // namespace

TEST(ModuleRewrite, PlainRulesMatchTheByteKernel) {
  Grammar plain;
  plain.axiom = "F++F++F";
  plain.rules['F'] = "F-F++F-F";
  const Grammar modules = grammar("F++F++F", {"F -> F-F++F-F"});
  for (int n = 0; n <= 5; ++n) EXPECT_EQ(text(modules, n), expand_string(plain, n, 1e8)) << "level " << n;
}

TEST(ModuleRewrite, ParametersAreEvaluatedPerApplication) {
  const Grammar g = grammar("A(1)", {"A(x) -> F(x) [+(30) A(x*0.5)] [-(30) A(x*0.5)]"});
  EXPECT_EQ(text(g, 0), "A(1)");
  EXPECT_EQ(text(g, 1), "F(1)[+(30)A(0.5)][-(30)A(0.5)]");
  EXPECT_EQ(text(g, 2), "F(1)[+(30)F(0.5)[+(30)A(0.25)][-(30)A(0.25)]][-(30)F(0.5)[+(30)A(0.25)][-(30)A(0.25)]]");
}

TEST(ModuleRewrite, ConditionsChooseTheFirstRuleThatHolds) {
  const Grammar g = grammar("A(0)", {"A(x) : x < 3 -> A(x + 1) B", "A(x) : x >= 3 -> C(x)"});
  EXPECT_EQ(text(g, 3), "A(3)BBB");
  EXPECT_EQ(text(g, 4), "C(3)BBB");
  EXPECT_EQ(text(g, 9), "C(3)BBB");  // no rule for C: it stays
}

TEST(ModuleRewrite, ContextSignalTravelsAlongTheString) {
  // ABOP 1.8: a signal b moves right one module per step.
  const Grammar g = grammar("baaaa", {"b < a -> b", "b -> a"});
  EXPECT_EQ(text(g, 1), "abaaa");
  EXPECT_EQ(text(g, 3), "aaaba");
  EXPECT_EQ(text(g, 4), "aaaab");
}

TEST(ModuleRewrite, LeftContextSkipsCompletedBranchesAndItsOwnBracket) {
  EXPECT_EQ(text(grammar("A[B]C", {"A < C -> X"}), 1), "A[B]X");
  EXPECT_EQ(text(grammar("A[B]", {"A < B -> X"}), 1), "A[X]");
  EXPECT_EQ(text(grammar("A[B]", {"B < A -> X"}), 1), "A[B]");
}

TEST(ModuleRewrite, RightContextSkipsBranchesItDoesNotEnterAndStopsAtItsBranchEnd) {
  EXPECT_EQ(text(grammar("A[B]C", {"A > C -> X"}), 1), "X[B]C");
  EXPECT_EQ(text(grammar("A[B]C", {"A > [B]C -> X"}), 1), "X[B]C");
  EXPECT_EQ(text(grammar("A[B]C", {"A > [C] -> X"}), 1), "A[B]C");
  EXPECT_EQ(text(grammar("[A]B", {"A > B -> X"}), 1), "[A]B");
  // ABOP's G[H]M: a ']' in the context skips the rest of the branch entered.
  EXPECT_EQ(text(grammar("SG[HI]M", {"S > G[H]M -> X"}), 1), "XG[HI]M");
}

TEST(ModuleRewrite, ContextsSkipIgnoredSymbols) {
  Grammar g = grammar("A+B", {"A < B -> X"});
  EXPECT_EQ(text(g, 1), "A+X");
  g.ignore = "";
  EXPECT_EQ(text(g, 1), "A+B");
}

TEST(ModuleRewrite, ContextParametersBind) {
  const Grammar g = grammar("A(1)B(2)C(3)", {"A(a) < B(b) > C(c) -> B(a + b * 10 + c * 100)"});
  EXPECT_EQ(text(g, 1), "A(1)B(321)C(3)");
}

TEST(ModuleRewrite, ContextRulesComeBeforeContextFree) {
  const Grammar g = grammar("AB", {"B -> Y", "A < B -> X"});
  EXPECT_EQ(text(g, 1), "AX");
}

TEST(ModuleRewrite, CutDropsTheRestOfItsBranch) {
  EXPECT_EQ(text(grammar("A[B%C[D]E]F", {"Z -> Z"}), 0), "A[B]F");
  const Grammar g = grammar("A", {"A -> F[B]A", "B -> F%F"});
  EXPECT_EQ(text(g, 2), "F[F]F[B]A");
  // The same cut where a context rule makes every level be held in memory.
  const Grammar c = grammar("A", {"A -> F[B]A", "B -> F%F", "Q < Q -> Q"});
  EXPECT_EQ(text(c, 2), "F[F]F[B]A");
}

TEST(ModuleRewrite, EvaluationErrorsNameTheRuleAndLevel) {
  const Grammar g = grammar("A(2)", {"A(x) -> A(x - 1) F(1 / x)"});
  EXPECT_NO_THROW(text(g, 2));
  try {
    text(g, 3);
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("rule 1"), std::string::npos) << m;
    EXPECT_NE(m.find("level 3"), std::string::npos) << m;
    EXPECT_NE(m.find("division by zero"), std::string::npos) << m;
  }
}

TEST(ModuleRewrite, WorkBeyondTheLimitIsRefused) {
  const Grammar g = grammar("A", {"A -> AA"});
  struct Null : ModuleSink {
    void module(std::uint8_t, std::span<const double>) override {}
  } sink;
  EXPECT_THROW(rewrite_modules(g, 30, sink, {.work = 1e6, .held = 1e6}, no_progress()), BudgetError);
  const Grammar c = grammar("A", {"A -> AA", "Q < Q -> Q"});
  EXPECT_THROW(rewrite_modules(c, 30, sink, {.work = 1e12, .held = 1e5}, no_progress()), BudgetError);
}

TEST(ModuleRewrite, CancelledMidLevel) {
  struct Stop : Progress {
    bool cancelled() override { return true; }
  } stop;
  struct Null : ModuleSink {
    void module(std::uint8_t, std::span<const double>) override {}
  } sink;
  EXPECT_THROW(rewrite_modules(grammar("A", {"A -> AA"}), 22, sink, {}, stop), Cancelled);
}

TEST(ModuleRewrite, ChoiceFollowsTheWeights) {
  const Successor options[] = {{1, {}}, {0, {}}, {3, {}}};
  EXPECT_EQ(choose_option(options, 0.0), 0u);
  EXPECT_EQ(choose_option(options, 0.2499), 0u);
  EXPECT_EQ(choose_option(options, 0.25), 2u);
  EXPECT_EQ(choose_option(options, 0.999999), 2u);
  const Successor trailing_zero[] = {{1, {}}, {0, {}}};
  EXPECT_EQ(choose_option(trailing_zero, 0.9999999999), 0u);
}

TEST(ModuleRewrite, StochasticChoiceIsReproducibleAndFollowsTheWeights) {
  std::string fifty;
  for (int i = 0; i < 50; ++i) fifty += "[S]";
  const Grammar g = grammar("A", {"A -> " + fifty + "A", "S -> B : 1", "S -> C : 3"}, 7);
  const std::string s = text(g, 201);
  EXPECT_EQ(s, text(g, 201));  // same seed, same string
  double b = 0, c = 0;
  for (char ch : s) {
    b += ch == 'B';
    c += ch == 'C';
  }
  ASSERT_EQ(b + c, 10000);
  // C has probability 3/4: within 5 standard deviations of a binomial.
  const double n = b + c, sigma = std::sqrt(n * 0.75 * 0.25);
  EXPECT_NEAR(c, 0.75 * n, 5 * sigma);
  Grammar other = g;
  other.seed = 8;
  EXPECT_NE(text(other, 201), s);
}

TEST(ModuleRewrite, StochasticLevelsGrowFromTheLevelBefore) {
  // Each step writes B or C before the A: a choice once made stays, whatever level is asked for.
  const Grammar g = grammar("A", {"A -> BA : 1", "A -> CA : 1"}, 3);
  std::string before = text(g, 0);
  for (int k = 1; k <= 60; ++k) {
    const std::string after = text(g, k);
    ASSERT_EQ(after.size(), before.size() + 1);
    EXPECT_EQ(after.substr(0, before.size() - 1), before.substr(0, before.size() - 1)) << "level " << k;
    before = after;
  }
  EXPECT_NE(before.find('B'), std::string::npos);
  EXPECT_NE(before.find('C'), std::string::npos);
}

TEST(ModuleRewrite, EditingOneRuleKeepsTheChoicesBelowTheOthers) {
  // Y's subtree is drawn the same whatever X's rule writes.
  const Grammar a = grammar("X[Y]", {"X -> XX", "Y -> Y[P]Y : 1", "Y -> YQ : 1", "P -> PP : 1", "P -> R : 1"}, 5);
  const Grammar b = grammar("X[Y]", {"X -> XXXF", "Y -> Y[P]Y : 1", "Y -> YQ : 1", "P -> PP : 1", "P -> R : 1"}, 5);
  auto branch = [](const std::string& s) { return s.substr(s.find('[')); };
  for (int k = 1; k <= 6; ++k) EXPECT_EQ(branch(text(a, k)), branch(text(b, k))) << "level " << k;
}

TEST(ModuleRewrite, ConstantsAreReadByEveryExpression) {
  Grammar g;
  g.constants = {{"r", 0.5}, {"a", 30}};
  const std::vector<std::string> names{"r", "a"};
  g.axiom = "A(a)";
  g.start = parse_calls(g.axiom, names);
  g.productions.push_back(parse_rule("A(x) : x > a / 4 -> B(x) A(x * r)", "rule 1", names));
  EXPECT_EQ(text(g, 2), "B(30)B(15)A(7.5)");  // 7.5 > 30 / 4 fails: A(7.5) stays
  EXPECT_EQ(text(g, 5), "B(30)B(15)A(7.5)");
  try {
    parse_rule("A(r) -> B", "rule 1", names);
    FAIL() << "no error";
  } catch (const RuleError& e) {
    EXPECT_NE(std::string(e.what()).find("also a constant"), std::string::npos) << e.what();
  }
}

namespace {

std::vector<Production> rules_of(const std::vector<std::string>& texts) {
  std::vector<Production> out;
  for (const std::string& t : texts) out.push_back(parse_rule(t, "rule " + std::to_string(out.size() + 1)));
  return out;
}

}  // namespace

TEST(ModuleRewrite, DecompositionRewritesWhatEachStepWrites) {
  Grammar g = grammar("B", {"A -> AB"});
  g.decomposition = rules_of({"B -> CD"});
  EXPECT_EQ(text(g, 0), "CD");  // the axiom too
  g = grammar("A", {"A -> AB"});
  g.decomposition = rules_of({"B -> CD"});
  EXPECT_EQ(text(g, 1), "ACD");
  EXPECT_EQ(text(g, 2), "ACDCD");
  // Recursive, to max_depth levels.
  Grammar r = grammar("X", {"Z -> Z"});
  r.decomposition = rules_of({"X -> XY"});
  r.max_depth = 3;
  EXPECT_EQ(text(r, 0), "XYYY");
  // With parameters and in a context-sensitive grammar.
  Grammar c = grammar("A(1)", {"A(x) -> A(x + 1) B(x)", "Q < Q -> Q"});
  c.decomposition = rules_of({"B(x) -> C(x * 10) D"});
  EXPECT_EQ(text(c, 2), "A(3)C(20)DC(10)D");
}

TEST(ModuleRewrite, InterpretationOnlyWhenDrawing) {
  Grammar g = grammar("A", {"A -> AA"});
  g.interpretation = rules_of({"A -> F+F"});
  EXPECT_EQ(text(g, 2), "AAAA");  // the string is the derivation's
  struct Collect : ModuleSink {
    std::string s;
    void module(std::uint8_t c, std::span<const double>) override { s += static_cast<char>(c); }
  } drawn;
  rewrite_modules(g, 1, drawn, {}, no_progress(), true);
  EXPECT_EQ(drawn.s, "F+FF+F");
}

TEST(ModuleRewrite, RunawayDecompositionAndInterpretationAreStopped) {
  struct Null : ModuleSink {
    void module(std::uint8_t, std::span<const double>) override {}
  } sink;
  Grammar g = grammar("A", {"Z -> Z"});
  g.interpretation = rules_of({"A -> AA"});
  g.max_depth = 64;
  EXPECT_THROW(rewrite_modules(g, 0, sink, {.work = 1e6, .held = 1e6}, no_progress(), true), BudgetError);
  Grammar d = grammar("A", {"Z -> Z"});
  d.decomposition = rules_of({"A -> AA"});
  d.max_depth = 64;
  EXPECT_THROW(rewrite_modules(d, 0, sink, {.work = 1e12, .held = 1e5}, no_progress()), BudgetError);
}

TEST(ModuleRewrite, ExtremeWeightsKeepTheirRatio) {
  // Relative to the largest: neither 1e308 + 1e308 overflowing nor subnormal weights losing their ratio.
  for (double w : {1e308, 4.9e-324, 1.0}) {
    const Successor options[] = {{w, {}}, {w, {}}};
    EXPECT_EQ(choose_option(options, 0.49), 0u) << w;
    EXPECT_EQ(choose_option(options, 0.51), 1u) << w;
  }
}
