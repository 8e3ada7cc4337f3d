// Evaluating a compiled expression (expression.h): the bytecode interpreter, and the trigonometry in
// degrees it calls.
#include <cmath>
#include <limits>
#include <numbers>

#include "kernels/lsystem/expression.h"
#include "kernels/lsystem/expression_code.h"

namespace selfsim::lsystem {

namespace {

constexpr double kDegreesPerRadian = 180 / std::numbers::pi;

// Angle `degrees` as quadrant * 90 + rest, with rest in radians within +-45 degrees. Reducing in degrees is
// exact, so that multiples of 90 give exact 0 and +-1 below (a turtle that turns by 90 four times comes back
// to the same point) and large angles keep their precision.
struct Reduced {
  int quadrant;
  double rest;
};
Reduced reduce_degrees(double degrees) {
  // exact, within +-180; NaN for inf and NaN. The test skips the slow remainder for the usual small angles.
  const double r = std::fabs(degrees) <= 180 ? degrees : std::remainder(degrees, 360);
  if (std::isnan(r)) return {0, r};  // (casting NaN to int below would be undefined)
  const double quadrant = std::nearbyint(r / 90);
  return {static_cast<int>(quadrant), (r - 90 * quadrant) / kDegreesPerRadian};
}

// sin(rest + quadrant * 90 degrees).
double sin_quadrant(Reduced a) {
  switch (a.quadrant & 3) {  // two's complement: -1 & 3 == 3
    case 0:
      return std::sin(a.rest);
    case 1:
      return std::cos(a.rest);
    case 2:
      return -std::sin(a.rest);
    default:
      return -std::cos(a.rest);
  }
}

double sin_degrees(double degrees) { return sin_quadrant(reduce_degrees(degrees)); }
double cos_degrees(double degrees) {
  Reduced a = reduce_degrees(degrees);
  ++a.quadrant;
  return sin_quadrant(a);
}
// tan at an odd multiple of 90 degrees is a pole: infinite (an error where it is computed), not the +-inf a
// signed zero cosine would give (tan(90) was -inf, so tan(90) < 0 held).
double tan_degrees(double degrees) {
  const Reduced a = reduce_degrees(degrees);
  if ((a.quadrant & 1) != 0 && a.rest == 0) return std::numeric_limits<double>::infinity();
  Reduced c = a;
  ++c.quadrant;
  return sin_quadrant(a) / sin_quadrant(c);
}

}  // namespace

double Expression::run(const Op* pc, const Op* end, const double* args) {
  // The top value stays in a register; `below` holds the values under it. Its first entry is the dummy `top`
  // pushed down by the first value, so that pushing needs no test for an empty stack.
  double top = 0;
  double below[kMaxStack];
  std::size_t n = 0;  // entries used in `below`
  const auto push = [&](double value) {
    below[n++] = top;
    top = value;
  };
  const auto unary = [&](auto f) { top = f(top); };
  const auto binary = [&](auto f) {
    const double a = below[--n];
    top = f(a, top);
  };
  // Many operations turn a value that is not finite into an ordinary number: comparisons and logic (NaN != 0
  // is 1, exp(1000) > 5 is 1), min and max (which drop a NaN, and min(inf, 3) is 3), pow (pow(NaN, 0) is 1),
  // exp(-inf), atan(inf), atan2 and x / inf. eval's check of the result would then miss it, and a condition
  // computed from sqrt(-1) or exp(1000 * x) would silently hold. So every value is checked before any
  // operation reads it or pushes it down: at the head of each step, `top` is the value the previous step
  // made (the first step sees the finite dummy), and every value in `below` was checked as `top` before it
  // went there. Only the last value is left for eval, which reports it as the result.
  const auto check = [](double a) {
    if (!std::isfinite(a)) [[unlikely]]
      throw EvalError(std::isnan(a) ? "a value it computes is not a number" : "a value it computes is infinite");
  };
  for (; pc != end; ++pc) {
    check(top);
    switch (pc->code) {
      case Code::Const:
        push(pc->value);
        break;
      case Code::Param:
        push(args[pc->index]);
        break;
      case Code::Neg:
        unary([](double a) { return -a; });
        break;
      case Code::Not:
        unary([](double a) { return a == 0 ? 1.0 : 0.0; });
        break;
      case Code::Truth:
        unary([](double a) { return a != 0 ? 1.0 : 0.0; });
        break;
      case Code::Sin:
        unary(sin_degrees);
        break;
      case Code::Cos:
        unary(cos_degrees);
        break;
      case Code::Tan:
        unary(tan_degrees);
        break;
      case Code::Asin:
        unary([](double a) { return std::asin(a) * kDegreesPerRadian; });
        break;
      case Code::Acos:
        unary([](double a) { return std::acos(a) * kDegreesPerRadian; });
        break;
      case Code::Atan:
        unary([](double a) { return std::atan(a) * kDegreesPerRadian; });
        break;
      case Code::Sqrt:
        unary([](double a) { return std::sqrt(a); });
        break;
      case Code::Abs:
        unary([](double a) { return std::fabs(a); });
        break;
      case Code::Floor:
        unary([](double a) { return std::floor(a); });
        break;
      case Code::Ceil:
        unary([](double a) { return std::ceil(a); });
        break;
      case Code::Exp:
        unary([](double a) { return std::exp(a); });
        break;
      case Code::Log:
        unary([](double a) { return std::log(a); });
        break;
      case Code::Add:
        binary([](double a, double b) { return a + b; });
        break;
      case Code::Sub:
        binary([](double a, double b) { return a - b; });
        break;
      case Code::Mul:
        binary([](double a, double b) { return a * b; });
        break;
      case Code::Div:
        if (top == 0) [[unlikely]]
          throw EvalError("division by zero");
        binary([](double a, double b) { return a / b; });
        break;
      case Code::Pow:
        binary([](double a, double b) { return std::pow(a, b); });
        break;
      case Code::Eq:
        binary([](double a, double b) { return a == b ? 1.0 : 0.0; });
        break;
      case Code::Ne:
        binary([](double a, double b) { return a != b ? 1.0 : 0.0; });
        break;
      case Code::Lt:
        binary([](double a, double b) { return a < b ? 1.0 : 0.0; });
        break;
      case Code::Le:
        binary([](double a, double b) { return a <= b ? 1.0 : 0.0; });
        break;
      case Code::Gt:
        binary([](double a, double b) { return a > b ? 1.0 : 0.0; });
        break;
      case Code::Ge:
        binary([](double a, double b) { return a >= b ? 1.0 : 0.0; });
        break;
      case Code::Min:
        binary([](double a, double b) { return std::fmin(a, b); });
        break;
      case Code::Max:
        binary([](double a, double b) { return std::fmax(a, b); });
        break;
      case Code::Atan2:
        binary([](double y, double x) { return std::atan2(y, x) * kDegreesPerRadian; });
        break;
      case Code::AndJump:
        if (top == 0) {
          top = 0;  // also turns -0 into 0
          pc += pc->index;
        } else {
          top = below[--n];
        }
        break;
      case Code::OrJump:
        if (top != 0) {
          top = 1;
          pc += pc->index;
        } else {
          top = below[--n];
        }
        break;
    }
  }
  return top;
}

}  // namespace selfsim::lsystem
