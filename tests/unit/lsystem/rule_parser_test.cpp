#include "kernels/lsystem/rule_parser.h"

#include <gtest/gtest.h>

using namespace selfsim;
using namespace selfsim::lsystem;

namespace {

std::string symbols(const std::vector<Call>& calls) {
  std::string s;
  for (const Call& c : calls) s += static_cast<char>(c.symbol);
  return s;
}

// The column a malformed rule is reported at, or npos if it parses.
std::size_t error_column(const std::string& text) {
  try {
    parse_rule(text, "rule 1");
  } catch (const RuleError& e) {
    return e.column;
  }
  return std::string::npos;
}

}  // namespace

TEST(RuleParser, ParametricRuleWithCondition) {
  const Production p = parse_rule("A(x) : x > 1 -> F(x) [+(30) A(x*0.6)]", "rule 1");
  EXPECT_EQ(p.pred.symbol, 'A');
  ASSERT_EQ(p.pred.params, std::vector<std::string>{"x"});
  ASSERT_FALSE(p.condition.empty());
  const double two[] = {2}, half[] = {0.5};
  EXPECT_EQ(p.condition.eval(two), 1);
  EXPECT_EQ(p.condition.eval(half), 0);
  ASSERT_EQ(p.options.size(), 1u);
  const std::vector<Call>& m = p.options[0].modules;
  EXPECT_EQ(symbols(m), "F[+A]");
  ASSERT_EQ(m[3].args.size(), 1u);
  EXPECT_DOUBLE_EQ(m[3].args[0].eval(two), 1.2);
  EXPECT_DOUBLE_EQ(m[2].args[0].eval(two), 30);
  EXPECT_TRUE(m[1].args.empty());
  EXPECT_EQ(p.slots, 1);
  EXPECT_FALSE(p.context());
}

TEST(RuleParser, ContextsBindParametersLeftPredecessorRight) {
  const Production p = parse_rule("B(a) < A(x) > C(c) D : a < c -> X(a + x * 10 + c * 100)", "rule 1");
  ASSERT_EQ(p.left.size(), 1u);
  EXPECT_EQ(p.left[0].symbol, 'B');
  ASSERT_EQ(p.right.size(), 2u);
  EXPECT_EQ(p.right[1].symbol, 'D');
  EXPECT_EQ(p.slots, 3);
  const double scope[] = {1, 2, 3};  // a, x, c
  EXPECT_DOUBLE_EQ(p.options[0].modules[0].args[0].eval(scope), 321);
  EXPECT_TRUE(p.context());
}

TEST(RuleParser, RightContextMayHoldBranches) {
  const Production p = parse_rule("S > G[H]M -> X", "rule 1");
  std::string right;
  for (const Pattern& m : p.right) right += static_cast<char>(m.symbol);
  EXPECT_EQ(right, "G[H]M");
}

TEST(RuleParser, TrailingWeightIsStochastic) {
  const Production p = parse_rule("F -> F[+F]F : 0.3", "rule 1");
  EXPECT_DOUBLE_EQ(p.options[0].weight, 0.3);
  EXPECT_EQ(symbols(p.options[0].modules), "F[+F]F");
  EXPECT_TRUE(rule_weight_given("F -> F[+F]F : 0.3"));
  EXPECT_FALSE(rule_weight_given("A(x) : x > 1 -> F"));
}

TEST(RuleParser, SaltsCountEachSymbolInItsText) {
  const Production p = parse_rule("A -> B A B", "rule 1");
  const std::vector<Call>& m = p.options[0].modules;
  EXPECT_EQ(m[0].salt, (std::uint64_t{'B'} << 32) | 0);
  EXPECT_EQ(m[1].salt, (std::uint64_t{'A'} << 32) | 0);
  EXPECT_EQ(m[2].salt, (std::uint64_t{'B'} << 32) | 1);
}

TEST(RuleParser, ErrorsPointAtTheirColumn) {
  EXPECT_EQ(error_column("A(x) -> F(y)"), 10u);     // unknown parameter name
  EXPECT_EQ(error_column("A(x) -> F(x"), 9u);       // the '(' never closed
  EXPECT_EQ(error_column("A B -> C"), 0u);          // two modules as predecessor
  EXPECT_EQ(error_column("A -> ]F"), 5u);           // ']' without '['
  EXPECT_EQ(error_column("A -> [F"), 7u);           // '[' never closed: at the end
  EXPECT_EQ(error_column("A -> F}"), 6u);           // '}' with no polygon open
  EXPECT_EQ(error_column("A -> {{F}"), 9u);         // a nested '{' never closed: at the end
  EXPECT_EQ(error_column("A(x, x) -> F"), 5u);      // a name twice
  EXPECT_EQ(error_column("A -> B : -1"), 9u);       // negative weight
  EXPECT_EQ(error_column("A(x) : x > -> F"), 11u);  // condition ends early: at its end
  EXPECT_EQ(error_column("A F"), 3u);               // no arrow: at the end
  EXPECT_EQ(error_column("A(1) -> F"), 2u);         // a left side names parameters
  EXPECT_EQ(error_column("[ -> F"), 0u);            // brackets have no rules
  EXPECT_EQ(error_column("A -> F()"), 7u);          // empty parameter
  EXPECT_EQ(error_column("A(x) -> F(x,)"), 12u);    // empty parameter after a comma
  EXPECT_EQ(error_column("A(x) -> F(x) : 1"), std::string::npos);
}

TEST(RuleParser, AbopStarMeansAny) {
  const Production p = parse_rule("* < + > * : * -> -", "rule 1");
  EXPECT_FALSE(p.context());
  EXPECT_TRUE(p.condition.empty());
  EXPECT_EQ(parse_rule("A(l) : * -> F(l)", "rule 1").pred.params.size(), 1u);
  EXPECT_EQ(error_column("B(l) : (l > 0.05 -> F"), 7u);  // the '(' never closed, not a missing '->'
}

TEST(RuleParser, CaretSitsUnderTheColumn) {
  EXPECT_EQ(caret_lines("A(x) -> F(y)", 10), "  A(x) -> F(y)\n            ^");
  const std::string long_text = std::string(300, 'F') + "(";
  const std::string lines = caret_lines(long_text, 300);
  const std::size_t newline = lines.find('\n');
  ASSERT_NE(newline, std::string::npos);
  EXPECT_LE(newline, 110u);  // the line is cut around the column
  EXPECT_EQ(lines[lines.size() - 1], '^');
  EXPECT_EQ(lines[lines.size() - 1 - newline - 1], '(');  // the caret under the '('
}

TEST(RuleParser, CaretCountsCharactersNotBytes) {
  // «» take 4 bytes but show as 2 characters: the caret sits under the 'y' (byte 15, character 13).
  EXPECT_EQ(caret_lines("A(x) -> «» F(y)", 15), "  A(x) -> «» F(y)\n               ^");
  EXPECT_EQ(shown_column("A(x) -> «» F(y)", 15), 13u);
  // A control byte shows escaped, as the message's lines print it: 4 columns.
  EXPECT_EQ(caret_lines("A -> \x01 F(y)", 9), "  A -> \\x01 F(y)\n              ^");
  // A byte that is not UTF-8 shows as one replacement character; a caret past the end follows the last.
  EXPECT_EQ(caret_lines("\xff F(", 4), "  \xff F(\n      ^");
  EXPECT_EQ(shown_column("\xff F(", 4), 4u);
}

// The caret is placed by the columns a terminal gives each character, not by characters: a wide one takes
// 2 (the caret sat 3 columns left of the '(' after 日本語), a combining mark and none (it sat one right after
// e + U+0301). Characters that a terminal acts on or hides show escaped, as Lua writes them, in the columns of
// the escape: U+200B (which shifted the caret by 1), U+202E (printed raw, it reversed what followed).
TEST(RuleParser, CaretCountsDisplayColumns) {
  EXPECT_EQ(caret_lines("A -> \u65e5\u672c\u8a9eF(", 15), "  A -> \u65e5\u672c\u8a9eF(\n" + std::string(14, ' ') + "^");
  EXPECT_EQ(caret_lines("A -> \uff26(", 8), "  A -> \uff26(\n" + std::string(9, ' ') + "^");              // fullwidth F
  EXPECT_EQ(caret_lines("A -> \U0001f333F(", 10), "  A -> \U0001f333F(\n" + std::string(10, ' ') + "^");  // emoji
  EXPECT_EQ(caret_lines("A -> e\u0301F(", 9), "  A -> e\u0301F(\n" + std::string(9, ' ') + "^");
  EXPECT_EQ(caret_lines("A -> \u200bF(", 9), "  A -> \\u{200b}F(\n" + std::string(16, ' ') + "^");
  EXPECT_EQ(caret_lines("A -> \u202eabF(", 10), "  A -> \\u{202e}abF(\n" + std::string(17, ' ') + "^");
  EXPECT_EQ(caret_lines("A -> \u2067F(", 9), "  A -> \\u{2067}F(\n" + std::string(16, ' ') + "^");
  EXPECT_EQ(caret_lines("A -> \u0085F(", 8), "  A -> \\u{85}F(\n" + std::string(14, ' ') + "^");  // a C1 control
}

// DEL and other bytes a module may be are named in the message as the rule line shows them: "\x7f" in both
// (the message said "\127").
TEST(RuleParser, ControlBytesAreNamedAsTheCaretLineShowsThem) {
  try {
    parse_rule("A -> \x7f(", "rule 1");
    FAIL() << "parsed";
  } catch (const RuleError& e) {
    EXPECT_EQ(std::string(e.what()), "missing ')' for the parameters of \\x7f");
    EXPECT_EQ(caret_lines("A -> \x7f(", e.column), "  A -> \\x7f(\n" + std::string(11, ' ') + "^");
  }
}
