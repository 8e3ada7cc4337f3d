// The run's point budget (--max-points), checked in one place before any kernel allocates. The budget is
// per run: points held by values the recipe still has count against it, so sixty curves of a million
// points each are refused under a limit of a million and one, as one such curve is.
#pragma once

#include <string>

#include "kernels/base/count_text.h"
#include "kernels/base/error.h"

namespace selfsim {

// The default --max-points: 2^28 points of 16 bytes, 4 GiB of vertices, well inside a 24 GiB machine.
inline constexpr double default_max_points = 1 << 28;
// The highest --max-points accepted: 2^40 points would be 16 TiB, far past any machine.
inline constexpr double highest_max_points = 1099511627776.0;

struct PointBudget {
  double limit = default_max_points;  // --max-points
  double held = 0;                    // points already held by live values of the run

  double left() const { return limit - held; }
};

// Thrown when a request is over the budget; a caller holding garbage may collect it and try again.
struct BudgetError : Error {
  using Error::Error;
};

// Throws BudgetError when `predicted` more points do not fit: "<what> would make N points, over the limit
// of L (raise it with --max-points)".
// A size that overflows, or more than the flag's own highest value could ever allow, cannot be raised to:
// the message says so instead of pointing at the flag.
inline void check_budget(double predicted, const PointBudget& b, const std::string& what) {
  if (predicted <= b.left()) return;
  if (!(predicted < 1e300))
    throw BudgetError(what + " would make more points than can be counted (its size overflows): lower the request");
  if (predicted > highest_max_points)
    throw BudgetError(what + " would make " + count_text(predicted) + " points, more than --max-points can allow on " +
                      "any machine (" + count_text(highest_max_points) + "): lower the request");
  throw BudgetError(
      what + " would make " + count_text(predicted) + " points, over the limit of " + count_text(b.limit) +
      (b.held > 0 ? " with " + count_text(b.held) + " held by the recipe's other values" : std::string()) +
      " (raise it with --max-points)");
}

}  // namespace selfsim
