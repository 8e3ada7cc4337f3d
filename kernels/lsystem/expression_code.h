// The bytecode of a compiled expression (expression.h), shared by its compiler (expression.cpp) and its
// evaluator (expression_run.cpp). Internal to kernels/lsystem.
#pragma once

#include <cstdint>

#include "kernels/lsystem/expression.h"

namespace selfsim::lsystem {

// Grouped by how many values each operation leaves on the stack, which stack_effect relies on.
enum class Expression::Code : std::uint8_t {
  // push one value
  Const,
  Param,
  // replace the top value
  Neg,
  Not,
  Truth,  // 1 if nonzero, else 0: the result of && and || is always 1 or 0
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Sqrt,
  Abs,
  Floor,
  Ceil,
  Exp,
  Log,
  // replace the two top values by one
  Add,
  Sub,
  Mul,
  Div,
  Pow,
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,
  Min,
  Max,
  Atan2,
  // Short circuit: if the top value decides the result (0 for &&, nonzero for ||), it becomes that result (0 or
  // 1) and the right operand is skipped; otherwise it is popped and the right operand follows.
  AndJump,
  OrJump,
};

}  // namespace selfsim::lsystem
