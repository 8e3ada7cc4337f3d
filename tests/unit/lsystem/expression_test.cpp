#include "kernels/lsystem/expression.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

using namespace selfsim;
using namespace selfsim::lsystem;

namespace {

const std::vector<std::string> kXyz = {"x", "y", "z"};

double value(std::string_view text, std::vector<double> args = {0, 0, 0}) {
  return Expression::compile(text, kXyz).eval(args);
}

// "column: message" of the SyntaxError compiling `text` throws, or "compiled".
std::string refusal(std::string_view text, const std::vector<std::string>& names = kXyz) {
  try {
    Expression::compile(text, names);
  } catch (const SyntaxError& e) {
    return std::to_string(e.column) + ": " + e.what();
  }
  return "compiled";
}

// The EvalError message of evaluating `text`, or "evaluated".
std::string eval_error(std::string_view text, std::vector<double> args = {0, 0, 0}) {
  const Expression e = Expression::compile(text, kXyz);
  try {
    e.eval(args);
  } catch (const EvalError& error) {
    return error.what();
  }
  return "evaluated";
}

std::string repeat(std::string_view s, int n) {
  std::string r;
  for (int i = 0; i < n; ++i) r += s;
  return r;
}

TEST(Expression, Numbers) {
  EXPECT_EQ(value("1"), 1);
  EXPECT_EQ(value("1.5"), 1.5);
  EXPECT_EQ(value(".5"), 0.5);
  EXPECT_EQ(value("2."), 2);
  EXPECT_EQ(value("1e-3"), 1e-3);
  EXPECT_EQ(value("2.5E+4"), 25000);
  EXPECT_EQ(value("1E2"), 100);
  EXPECT_EQ(value("007"), 7);
}

// Each case once with constants, which the compiler folds, and once reading parameters, which eval computes: the
// two paths must agree.
TEST(Expression, PrecedenceAndAssociativity) {
  struct Case {
    const char* constant;
    const char* parametric;  // x = 2, y = 3, z = 4
    double expected;
  };
  const Case cases[] = {
      {"2 + 3 * 4", "x + y * z", 14},
      {"(2 + 3) * 4", "(x + y) * z", 20},
      {"2 - 3 - 4", "x - y - z", -5},         // left-associative
      {"2 / 4 / 2", "x / z / x", 0.25},       // left-associative
      {"3 * 2 ^ 4", "y * x ^ z", 48},         // ^ above *
      {"2 ^ 3 ^ 2", "x ^ y ^ x", 512},        // right-associative
      {"2 + 3 < 4", "x + y < z", 0},          // + above <
      {"2 < 3 == 1", "x < y == 1", 1},        // < above ==
      {"4 > 3 > 2", "z > y > x", 0},          // (4 > 3) > 2
      {"1 || 0 && 0", "1 || 0 && 0 * x", 1},  // && above ||
      {"2 == 2 && 3 != 3", "x == 2 && y != 3", 0},
      {"!1 + 1", "!x + 1", 1},  // ! above +
      {"!0 * 3", "!(x - 2) * y", 3},
      {"2 - -3", "x - -y", 5},
      {"+2 - +3", "+x - +y", -1},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(value(c.constant), c.expected) << c.constant;
    EXPECT_EQ(value(c.parametric, {2, 3, 4}), c.expected) << c.parametric;
  }
  EXPECT_EQ(value("5 >= 5"), 1);
  EXPECT_EQ(value("5 <= 4"), 0);
  EXPECT_EQ(value("x <= y", {5, 4, 0}), 0);
  EXPECT_EQ(value("x >= y", {5, 5, 0}), 1);
  EXPECT_EQ(value("min(x, y) + max(x, y) * 10", {2, 3, 0}), 32);
  EXPECT_EQ(value("pow(x, y)", {2, 10, 0}), 1024);
}

TEST(Expression, UnaryMinusAgainstPower) {
  EXPECT_EQ(value("-2^2"), -4);
  EXPECT_EQ(value("-x^2", {3, 0, 0}), -9);
  EXPECT_EQ(value("(-x)^2", {3, 0, 0}), 9);
  EXPECT_EQ(value("2^-1"), 0.5);
  EXPECT_EQ(value("x^-y", {2, 1, 0}), 0.5);
  EXPECT_EQ(value("-x^-y", {2, 2, 0}), -0.25);
  EXPECT_EQ(value("--x", {3, 0, 0}), 3);
  EXPECT_EQ(value("- - 3"), 3);
  EXPECT_EQ(value("!x^2", {0, 0, 0}), 1);  // !(x^2)
}

TEST(Expression, AndOrShortCircuit) {
  // The right side of && is skipped when the left is false: no division by zero.
  const auto guarded = Expression::compile("x != 0 && 1/x > 2", kXyz);
  EXPECT_EQ(guarded.eval(std::vector<double>{0, 0, 0}), 0);
  EXPECT_EQ(guarded.eval(std::vector<double>{0.25, 0, 0}), 1);
  EXPECT_EQ(guarded.eval(std::vector<double>{1, 0, 0}), 0);
  EXPECT_EQ(value("x == 0 || 1/x > 2", {0, 0, 0}), 1);
  EXPECT_EQ(value("x == 0 || 1/x > 2", {1, 0, 0}), 0);
  EXPECT_EQ(value("0 && 1/0"), 0);
  EXPECT_EQ(value("1 || 1/0"), 1);
  EXPECT_EQ(value("x && 1/y", {0, 0, 0}), 0);
  EXPECT_EQ(value("x || 1/y", {-3, 0, 0}), 1);
  EXPECT_EQ(eval_error("x || 1/y", {0, 0, 0}), "division by zero");

  // The result is always 1 or 0.
  EXPECT_EQ(value("x && y", {2, -5, 0}), 1);
  EXPECT_EQ(value("x && y", {2, 0, 0}), 0);
  EXPECT_EQ(value("x || y", {0, 7, 0}), 1);
  EXPECT_EQ(value("x || y", {0, 0, 0}), 0);
  EXPECT_EQ(value("1 && x", {5, 0, 0}), 1);  // a constant left side that does not decide
  EXPECT_EQ(value("0 || x", {5, 0, 0}), 1);
  EXPECT_EQ(value("0 || x", {0, 0, 0}), 0);
  EXPECT_EQ(value("3 && 4"), 1);
  EXPECT_EQ(value("(x && y) + (y || z) * 10 + (x && y || z) * 100", {1, 0, 2}), 110);
}

TEST(Expression, DivisionByZeroThrows) {
  EXPECT_EQ(eval_error("1 / x"), "division by zero");
  EXPECT_EQ(eval_error("0 / 0"), "division by zero");
  EXPECT_EQ(eval_error("1 / 0"), "division by zero");
  EXPECT_EQ(eval_error("x / (y - 1)", {1, 1, 0}), "division by zero");
  EXPECT_EQ(value("1 / x", {4, 0, 0}), 0.25);
  // It is an EvalError, and so a selfsim::Error.
  EXPECT_THROW(value("1 / x"), Error);
}

TEST(Expression, NotFiniteResultThrows) {
  EXPECT_EQ(eval_error("sqrt(-1)"), "result is not a number");
  EXPECT_EQ(eval_error("sqrt(x)", {-1, 0, 0}), "result is not a number");
  EXPECT_EQ(eval_error("log(x)", {-1, 0, 0}), "result is not a number");
  EXPECT_EQ(eval_error("exp(1000)"), "result is infinite");
  EXPECT_EQ(eval_error("-exp(x)", {1000, 0, 0}), "a value it computes is infinite");  // not the result itself
  EXPECT_EQ(eval_error("log(0)"), "result is infinite");
  EXPECT_EQ(eval_error("tan(90)"), "result is infinite");
  EXPECT_EQ(value("sqrt(x)", {2.25, 0, 0}), 1.5);
}

// tan at an odd multiple of 90 degrees (reduced exactly, so the pole is met exactly) is infinite and so an
// error, in every quadrant and both signs, constant or computed; just beside it, tan is large and finite with
// the sign of its side.
TEST(Expression, TanAtItsPolesThrows) {
  for (double pole : {90.0, -90.0, 270.0, -270.0, 450.0, 90.0 * 1000001, 90.0 + 360.0 * 1e12}) {
    EXPECT_EQ(eval_error("tan(x)", {pole, 0, 0}), "result is infinite") << pole;
    EXPECT_EQ(eval_error("tan(x) < 0", {pole, 0, 0}), "a value it computes is infinite") << pole;
    EXPECT_EQ(eval_error("tan(x) > 0", {pole, 0, 0}), "a value it computes is infinite") << pole;
  }
  EXPECT_EQ(eval_error("tan(90) < 0"), "a value it computes is infinite");
  EXPECT_EQ(eval_error("tan(x * 3) < 0", {30, 0, 0}), "a value it computes is infinite");
  EXPECT_GT(value("tan(x)", {89.9999999, 0, 0}), 5e8);
  EXPECT_LT(value("tan(x)", {90.0000001, 0, 0}), -5e8);
  EXPECT_EQ(value("tan(x)", {180, 0, 0}), 0);
  EXPECT_EQ(value("tan(x)", {-180, 0, 0}), 0);
}

// A NaN met on the way is an error even where the operation would hide it in an ordinary number: a
// comparison or logic (NaN != 0 is true), min and max (which drop it), pow (pow(NaN, 0) is 1).
TEST(Expression, NaNOnTheWayThrows) {
  const std::string nan = "a value it computes is not a number";
  EXPECT_EQ(eval_error("sqrt(x) != 0", {-1, 0, 0}), nan);
  EXPECT_EQ(eval_error("sqrt(x) > 1", {-1, 0, 0}), nan);
  EXPECT_EQ(eval_error("!sqrt(x)", {-1, 0, 0}), nan);
  EXPECT_EQ(eval_error("sqrt(x) && 1", {-1, 0, 0}), nan);
  EXPECT_EQ(eval_error("0 || sqrt(x)", {-1, 0, 0}), nan);
  EXPECT_EQ(eval_error("min(sqrt(x), 1)", {-1, 0, 0}), nan);
  EXPECT_EQ(eval_error("pow(sqrt(x), 0)", {-1, 0, 0}), nan);
  // Constant expressions too, which are folded when compiled (a constant left side of && or || decides).
  EXPECT_EQ(eval_error("sqrt(-1) || 0"), nan);
  EXPECT_EQ(eval_error("sqrt(-1) && 1"), nan);
  EXPECT_EQ(eval_error("min(sqrt(-1), 1)"), nan);
  // What a NaN would not have decided is not evaluated: || and && skip their right side as before.
  EXPECT_EQ(value("1 || sqrt(x)", {-1, 0, 0}), 1);
  EXPECT_EQ(value("0 && sqrt(x) > 1", {-1, 0, 0}), 0);
}

// An infinite value met on the way is an error like a NaN, wherever an operation would turn it into an
// ordinary number: every operator and function is tried with an infinite operand (exp(x) with x = 1000), in
// constant expressions (folded when compiled) as with parameters.
TEST(Expression, InfiniteOnTheWayThrows) {
  const std::string inf = "a value it computes is infinite";
  for (const std::string big : {"exp(x)", "exp(1000)", "(x * 1e306)"}) {
    for (const std::string text : {"B > 5",
                                   "B >= 5",
                                   "B < 5",
                                   "B <= 5",
                                   "B == B",
                                   "B != 0",
                                   "!B",
                                   "B && 1",
                                   "0 || B",
                                   "-B < 0",
                                   "min(B, 3)",
                                   "max(-B, 3)",
                                   "pow(B, 0)",
                                   "pow(2, -B)",
                                   "pow(1, B)",
                                   "exp(-B)",
                                   "atan(B)",
                                   "atan2(1, B)",
                                   "atan2(B, B)",
                                   "1 / B",
                                   "1 / (B + 1)",
                                   "sin(B) * 0",
                                   "floor(B) - ceil(B)",
                                   "abs(B) > sqrt(B)",
                                   "log(B) < 0",
                                   "acos(B) != 1",
                                   "asin(B) != 1",
                                   "tan(B) == 1",
                                   "cos(B) > 2"}) {
      std::string e = text;
      for (std::size_t at; (at = e.find('B')) != std::string::npos;) e.replace(at, 1, big);
      EXPECT_EQ(eval_error(e, {1000, 0, 0}), inf) << e;
    }
  }
  // 1 / 0 names its own cause; log(0) is -inf, and exp of it 0.
  EXPECT_EQ(eval_error("exp(log(x))", {0, 0, 0}), inf);
  EXPECT_EQ(eval_error("min(exp(x), 3) == 3", {1000, 0, 0}), inf);
  // Large but finite values on the way are ordinary numbers.
  EXPECT_EQ(value("min(exp(x), 3)", {700, 0, 0}), 3);
  EXPECT_EQ(value("1 / (x * 1e300)", {1e8, 0, 0}), 1 / (1e8 * 1e300));
}

TEST(Expression, AnglesAreDegrees) {
  EXPECT_NEAR(value("sin(30)"), 0.5, 1e-15);
  EXPECT_NEAR(value("cos(x)", {60, 0, 0}), 0.5, 1e-15);
  EXPECT_NEAR(value("tan(45)"), 1, 1e-15);
  EXPECT_NEAR(value("sin(x)", {750, 0, 0}), 0.5, 1e-15);
  EXPECT_NEAR(value("asin(1)"), 90, 1e-13);
  EXPECT_NEAR(value("acos(0.5)"), 60, 1e-13);
  EXPECT_NEAR(value("atan(1)"), 45, 1e-13);
  EXPECT_NEAR(value("atan2(1, 1)"), 45, 1e-13);
  EXPECT_NEAR(value("atan2(x, y)", {1, -1, 0}), 135, 1e-13);
  EXPECT_NEAR(value("atan2(x, y)", {-2, 0, 0}), -90, 1e-13);
  // Multiples of 90 degrees are exact, however large.
  EXPECT_EQ(value("sin(90)"), 1);
  EXPECT_EQ(value("cos(x)", {90, 0, 0}), 0);
  EXPECT_EQ(value("cos(x)", {180, 0, 0}), -1);
  EXPECT_EQ(value("sin(x)", {-90, 0, 0}), -1);
  EXPECT_EQ(value("sin(x)", {360 * 1e6 + 270, 0, 0}), -1);
  EXPECT_EQ(value("cos(x)", {-360 * 1e6 - 90, 0, 0}), 0);
  EXPECT_EQ(value("sin(x) + cos(x)", {1e300, 0, 0}), value("sin(1e300) + cos(1e300)"));  // folding agrees
}

TEST(Expression, ParameterSlotsAndPi) {
  const std::vector<std::string> names = {"x", "len", "pi"};
  const auto e = Expression::compile("len * 10 + x - pi", names);
  EXPECT_EQ(e.eval(std::vector<double>{1, 2, 3}), 18);  // the parameter pi hides the constant
  EXPECT_FALSE(e.constant());
  EXPECT_EQ(value("pi"), std::numbers::pi);
  EXPECT_EQ(value("2 * pi + x", {1, 0, 0}), 2 * std::numbers::pi + 1);

  // Name i reads args[i]; arguments beyond the names compiled are ignored.
  const std::vector<std::string> ab = {"a", "b"};
  EXPECT_EQ(Expression::compile("b - a", ab).eval(std::vector<double>{1, 5, 100}), 4);
  // Only the arguments up to the last parameter read are required.
  EXPECT_EQ(Expression::compile("a * 2", ab).eval(std::vector<double>{4}), 8);
  EXPECT_THROW(Expression::compile("b * 2", ab).eval(std::vector<double>{4}), Error);
  // Names may contain digits and underscores, and a parameter may be called like a function.
  const std::vector<std::string> odd = {"_a1", "sin"};
  EXPECT_EQ(Expression::compile("_a1 + sin(sin)", odd).eval(std::vector<double>{1, 90}), 2);
}

TEST(Expression, ConstantExpressionsFoldToOneValue) {
  const auto folded = Expression::compile("2 * pi / 4 + sin(90) - max(1, 2) ^ 2", kXyz);
  EXPECT_TRUE(folded.constant());
  EXPECT_EQ(folded.code_size(), 1u);
  EXPECT_EQ(folded.eval({}), 2 * std::numbers::pi / 4 + 1 - 4);  // no arguments needed

  const auto parametric = Expression::compile("x + 2 * 3", kXyz);
  EXPECT_FALSE(parametric.constant());
  EXPECT_EQ(parametric.code_size(), 3u);  // x, 6, +
  EXPECT_EQ(parametric.eval(std::vector<double>{1, 0, 0}), 7);

  // A decided && drops its right side, parameters and all.
  const auto decided = Expression::compile("0 && x > 1", kXyz);
  EXPECT_TRUE(decided.constant());
  EXPECT_EQ(decided.code_size(), 1u);
  EXPECT_FALSE(Expression::compile("1 && x > 1", kXyz).constant());

  // A division by zero is not folded away: eval reports it, each time.
  const auto broken = Expression::compile("1 + 1 / 0", kXyz);
  EXPECT_TRUE(broken.constant());
  EXPECT_THROW(broken.eval({}), EvalError);

  const Expression none;
  EXPECT_TRUE(none.empty());
  EXPECT_THROW(none.eval({}), Error);
  EXPECT_FALSE(folded.empty());
}

TEST(Expression, SyntaxErrorsPointAtTheProblem) {
  EXPECT_EQ(refusal(""), "0: expected an expression");
  EXPECT_EQ(refusal(" \t "), "0: expected an expression");
  EXPECT_EQ(refusal("1 +"), "3: expected a number, a name or '(' at the end of the expression");
  EXPECT_EQ(refusal("1 + * 2"), "4: expected a number, a name or '(' at '*'");
  EXPECT_EQ(refusal("()"), "1: expected a number, a name or '(' at ')'");
  EXPECT_EQ(refusal("(1 + 2"), "6: missing ')' to close the '(' at column 0");
  EXPECT_EQ(refusal("2 * (1 + 2 3"), "11: missing ')' to close the '(' at column 4");
  EXPECT_EQ(refusal("(1 + 2))"), "7: unexpected ')'");
  EXPECT_EQ(refusal("x y"), "2: unexpected 'y' after the expression");
  EXPECT_EQ(refusal("x 12"), "2: unexpected '12' after the expression");
  EXPECT_EQ(refusal("x = 1"), "2: unexpected '=': did you mean '=='?");
  EXPECT_EQ(refusal("x & y"), "2: unexpected '&': did you mean '&&'?");
  EXPECT_EQ(refusal("x |y"), "2: unexpected '|': did you mean '||'?");
  EXPECT_EQ(refusal("1 # 2"), "2: unexpected character '#'");
  EXPECT_EQ(refusal("1 +\n2"), "3: unexpected byte 0x0a");
  EXPECT_EQ(refusal("x + yy", {"x", "len"}), "4: unknown parameter name 'yy' (parameters: x, len)");
  EXPECT_EQ(refusal("2 * y", {}), "4: unknown parameter name 'y' (no parameters)");
  EXPECT_EQ(refusal("1 + min(1)"), "4: min takes 2 arguments, got 1");
  EXPECT_EQ(refusal("max(1, 2, 3)"), "0: max takes 2 arguments, got 3");
  EXPECT_EQ(refusal("sqrt(1, 2)"), "0: sqrt takes 1 argument, got 2");
  EXPECT_EQ(refusal("x + sin()"), "4: sin takes 1 argument, got 0");
  EXPECT_EQ(refusal("2 * foo(1)"), "4: unknown function 'foo'");
  EXPECT_EQ(refusal("min(1 2)"), "6: expected ',' or ')' after an argument of min, found '2'");
  EXPECT_EQ(refusal("max(1, 2"), "8: missing ')' to close the '(' at column 3");
  EXPECT_EQ(refusal("2 + 1e"), "4: number '1e' has no exponent digits");
  EXPECT_EQ(refusal("1e+ 2"), "0: number '1e+' has no exponent digits");
  EXPECT_EQ(refusal("x * 1e999"), "4: number '1e999' is out of range");
  EXPECT_EQ(refusal("1 < = 2"), "4: unexpected '=': did you mean '=='?");
}

TEST(Expression, LengthIsLimited) {
  const std::string longest = "1" + repeat("+1", 4999);  // 9999 bytes
  EXPECT_EQ(Expression::compile(longest, kXyz).eval({}), 5000);
  EXPECT_EQ(refusal(longest + "+1"), "10000: expression is longer than 10000 bytes");
}

// Hostile nesting is refused before it can exhaust the C++ stack: this would crash if recursion were unbounded.
TEST(Expression, DeepNestingIsRefusedWithoutCrashing) {
  const std::string nests = "100: expression nests too deeply (more than 100 levels)";
  EXPECT_EQ(refusal(std::string(9999, '(')), nests);
  EXPECT_EQ(refusal(std::string(4999, '(') + "1" + std::string(4999, ')')), nests);
  EXPECT_EQ(refusal(std::string(9999, '-') + "1"), nests);
  EXPECT_EQ(refusal(std::string(9999, '!') + "x"), nests);
  EXPECT_EQ(refusal(repeat("-(", 4999) + "1"), nests);
  EXPECT_EQ(refusal(repeat("abs(", 2499)), "403: expression nests too deeply (more than 100 levels)");
  EXPECT_EQ(refusal(repeat("2^", 4999) + "2"), "201: expression nests too deeply (more than 100 levels)");
  // Longer text is refused before it is read at all.
  const std::string too_long = "10000: expression is longer than 10000 bytes";
  EXPECT_EQ(refusal(std::string(100000, '(') + "1" + std::string(100000, ')')), too_long);
  EXPECT_EQ(refusal(std::string(100000, '-') + "1"), too_long);

  // 100 levels are allowed.
  EXPECT_EQ(value(std::string(100, '(') + "x" + std::string(100, ')'), {7, 0, 0}), 7);
  EXPECT_EQ(value(std::string(100, '-') + "x", {7, 0, 0}), 7);
  EXPECT_EQ(refusal(std::string(101, '(') + "x" + std::string(101, ')')), nests);
}

TEST(Expression, StackHasSixtyFourSlots) {
  // x^x^...^x keeps every x on the stack until the last one arrives.
  const std::string fits = "x" + repeat("^x", 63);
  EXPECT_EQ(value(fits, {1, 0, 0}), 1);
  EXPECT_EQ(refusal(fits + "^x"),
            "128: expression needs more than 64 values at once: split it or add fewer nested operands");
  // So does x+(x+(x+...)).
  const std::string sum = repeat("x+(", 63) + "x" + std::string(63, ')');
  EXPECT_EQ(value(sum, {1, 0, 0}), 64);
  EXPECT_EQ(refusal(repeat("x+(", 64) + "x" + std::string(64, ')')),
            "192: expression needs more than 64 values at once: split it or add fewer nested operands");
  // Constants fold as they are read, so the same shape with numbers needs one slot.
  EXPECT_EQ(value(repeat("1+(", 90) + "1" + std::string(90, ')')), 91);
}

TEST(Expression, WhitespaceBetweenTokens) {
  EXPECT_EQ(value(" \t1\t+  x *\t2 ", {3, 0, 0}), 7);
  EXPECT_EQ(value("sin ( 90 )"), 1);
  EXPECT_EQ(value("min(\tx ,y )", {3, 2, 0}), 2);
  EXPECT_EQ(value("x\t<=\t1 &&\ty  !=  0", {1, 2, 0}), 1);
  EXPECT_EQ(value("- 2 ^ - 1"), -0.5);
  EXPECT_EQ(value("x||y", {0, 1, 0}), 1);
}

// eval keeps its stack on the C++ stack: threads sharing one Expression do not disturb one another.
TEST(Expression, EvaluatesConcurrently) {
  const auto e = Expression::compile("x * x - y * 2 + (x > y && y != 0)", kXyz);
  std::vector<int> wrong(4, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&, t] {
      for (int i = 0; i < 20000; ++i) {
        const double x = t * 100000 + i, y = i % 7;
        if (e.eval(std::vector<double>{x, y, 0}) != x * x - y * 2 + (x > y && y != 0)) ++wrong[t];
      }
    });
  }
  for (auto& thread : threads) thread.join();
  EXPECT_EQ(wrong, std::vector<int>(4, 0));
}

}  // namespace
