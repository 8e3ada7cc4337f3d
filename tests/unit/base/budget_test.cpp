#include "kernels/base/budget.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace selfsim {
namespace {

std::string refusal(double predicted, PointBudget b) {
  try {
    check_budget(predicted, b, "it");
  } catch (const BudgetError& e) {
    return e.what();
  }
  return "";
}

// The one budget message: raising --max-points is suggested only where it could help (issue 21: a request
// past the flag's own highest value, or one whose size overflows to inf or NaN, said "raise it" and "about
// -nan points").
TEST(Budget, RefusalsSayWhetherTheLimitCanBeRaised) {
  PointBudget b;
  b.limit = 1000;
  EXPECT_EQ(refusal(1000, b), "");
  EXPECT_EQ(refusal(1001, b), "it would make 1001 points, over the limit of 1000 (raise it with --max-points)");
  EXPECT_EQ(refusal(2e12, b),
            "it would make 2000000000000 points, more than --max-points can allow on any machine (1099511627776): "
            "lower the request");
  for (const double overflowing : {HUGE_VAL, std::nan(""), 1e301}) {
    const std::string m = refusal(overflowing, b);
    EXPECT_NE(m.find("more points than can be counted"), std::string::npos) << m;
    EXPECT_EQ(m.find("nan"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace selfsim
