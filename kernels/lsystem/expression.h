// Arithmetic expressions of parametric L-system rules (ABOP notation): the conditions and actual parameters in
// productions such as `A(x, len) : x > 1 -> F(len * 0.5) +(x * 30) A(x - 1, len)`. An expression is compiled
// once to a flat bytecode and then evaluated for every symbol of every level, millions of times, so evaluation
// allocates nothing, takes no lock and shares no scratch space between threads.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernels/base/error.h"

namespace selfsim::lsystem {

// Thrown by Expression::compile. `column` is the 0-based byte offset in the compiled text of the problem (the
// caller prints a caret under it).
struct SyntaxError : Error {
  std::size_t column;
  SyntaxError(const std::string& message, std::size_t column) : Error(message), column(column) {}
};

// Thrown by Expression::eval: a division by zero, or a result that is not finite.
struct EvalError : Error {
  using Error::Error;
};

// Numbers (`1.5`, `.5`, `1e-3`), parameter names, the constant `pi`, the functions sin cos tan asin acos atan
// atan2 (all in degrees, like the turtle's angles), sqrt abs floor ceil exp log min max pow, and the operators
// || && == != < <= > >= + - * / unary - + ! and right-associative ^, lowest precedence first. Comparisons and
// logic give 1 or 0, any nonzero value is true, and && || evaluate their right side only when needed.
class Expression {
 public:
  static constexpr std::size_t kMaxLength = 10000;  // bytes of text
  static constexpr int kMaxNesting = 100;           // parentheses, unary operators and ^ inside one another
  static constexpr std::size_t kMaxStack = 64;      // values held at once while evaluating

  Expression() = default;  // empty(): no code

  // Compiles `text` once; `names` are the parameters in scope, name i reads args[i] at evaluation (the first
  // of repeated names wins). A parameter named `pi` hides the constant. Constant subexpressions are folded.
  static Expression compile(std::string_view text, std::span<const std::string> names);

  // Evaluates with args.size() >= the number of names given to compile (only those up to the last parameter
  // the text reads are required). Thread-safe (const, no shared scratch). Throws EvalError, or Error when
  // the expression is empty or args is too short.
  double eval(std::span<const double> args) const;

  bool empty() const { return code_.empty(); }
  bool constant() const { return constant_; }             // reads no parameter (so a caller may evaluate it once)
  std::size_t code_size() const { return code_.size(); }  // bytecode operations, after constant folding

 private:
  enum class Code : std::uint8_t;
  struct Op {
    Code code;
    std::uint32_t index = 0;  // parameter slot, or how many operations a jump skips
    double value = 0;         // the constant pushed
  };
  class Compiler;

  // Runs the operations [pc, end) and returns the value left on the stack.
  static double run(const Op* pc, const Op* end, const double* args);

  std::vector<Op> code_;
  std::size_t arity_ = 0;  // highest parameter slot read + 1: the arguments eval needs
  bool constant_ = true;
};

}  // namespace selfsim::lsystem
