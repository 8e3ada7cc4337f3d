#include "kernels/lsystem/module_pipe.h"

#include <gtest/gtest.h>

#include "kernels/base/budget.h"
#include "kernels/lsystem/rule_parser.h"
#include "module_grammar.h"

using namespace selfsim;
using namespace selfsim::lsystem;

namespace {

Grammar grammar(const std::string& axiom, const std::vector<std::string>& rules) {
  return test::module_grammar(axiom, rules);
}

// Every module as text, in order.
struct Text : ModuleSink {
  std::string s;
  void module(std::uint8_t c, std::span<const double> a) override { s += module_text(c, a); }
};

}  // namespace

TEST(ModulePipe, GivesTheSinkWhatTheDirectDerivationGives) {
  const Grammar g = grammar("A(1)", {"A(x) -> F(x) [+(30) A(x*0.5)] [-(30) A(x*0.5)]"});
  for (int level : {0, 1, 5, 12}) {
    Text direct, piped;
    rewrite_modules(g, level, direct, {}, no_progress(), true);
    rewrite_modules_piped(g, level, piped, {}, no_progress(), true);
    EXPECT_EQ(piped.s, direct.s) << "level " << level;
  }
}

TEST(ModulePipe, TheDerivationsErrorReachesTheCaller) {
  const Grammar g = grammar("A(3)", {"A(x) -> F A(x - 1) F(1 / x)"});
  Text sink;
  EXPECT_THROW(rewrite_modules_piped(g, 5, sink, {}, no_progress(), true), Error);
}

TEST(ModulePipe, AFailingSinkStopsTheDerivation) {
  struct Fails : ModuleSink {
    std::size_t n = 0;
    void module(std::uint8_t, std::span<const double>) override {
      if (++n > 100000) throw BudgetError("enough");
    }
  } sink;
  // Level 60 of a doubling grammar would never end: the sink's error must stop it.
  const Grammar g = grammar("A", {"A -> AA"});
  EXPECT_THROW(rewrite_modules_piped(g, 60, sink, {}, no_progress(), true), BudgetError);
  struct Stop : Progress {
    bool cancelled() override { return true; }
  } stop;
  Text text;
  EXPECT_THROW(rewrite_modules_piped(g, 60, text, {}, stop, true), Cancelled);
}
