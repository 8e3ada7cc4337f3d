// Where the print check measures: the spacing ladder (plan_samples) stops at the finest rung that fits the
// budget, though it passes over the rungs a lower bound already rules out without counting them.
#include "kernels/print/print_samples.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "kernels/base/progress.h"

using namespace selfsim;
using namespace selfsim::print;

namespace {

// A flat n x n sheet of `cell` mm squares (two triangles each, smaller than any spacing below: one point
// each, which makes the lower bound tight), and beside it one large triangle `big` mm on a side (halved
// many times).
Mesh sheet_and_triangle(int n, double cell, double big) {
  Mesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.points.push_back({i * cell, j * cell, 0});
  const auto at = [n](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  const auto first = static_cast<std::uint32_t>(m.points.size());
  m.points.push_back({0, 0, 5});
  m.points.push_back({big, 0, 5});
  m.points.push_back({0.5 * big, 0.8 * big, 5});
  m.triangles.push_back({first, first + 1, first + 2});
  return m;
}

double area_of(const Mesh& m) {
  double a = 0;
  for (const Triangle& t : m.triangles)
    a += 0.5 * norm(cross(m.points[t[1]] - m.points[t[0]], m.points[t[2]] - m.points[t[0]]));
  return a;
}

// How many points sampling down to `spacing` makes, exactly (no budget).
std::size_t points_at(const Mesh& m, double spacing, double area) {
  return plan_samples(m, spacing, area, std::numeric_limits<double>::max(), no_progress()).count();
}

}  // namespace

TEST(PlanSamples, TheLadderStopsAtTheFinestRungThatFits) {
  const Mesh m = sheet_and_triangle(40, 0.45, 30);
  const double area = area_of(m), finest = 0.4;
  const std::size_t all = points_at(m, finest, area);
  ASSERT_GT(all, 5 * m.faces());
  // Budgets of at least one point a triangle (what the check asks for at least), and budgets just as large
  // as a rung's count: there the lower bound must not rule the rung out (the sheet's triangles give two
  // points each from 0.45 to 0.64 mm: a bound of two is exact there).
  const double faces = static_cast<double>(m.faces());
  std::vector<double> budgets{0.9 * all, 0.5 * all, 0.3 * all, 2 * faces, 1.3 * faces, 1.05 * faces};
  for (double rung = finest; rung < 2; rung *= 1.25) budgets.push_back(static_cast<double>(points_at(m, rung, area)));
  for (double most : budgets) {
    const SamplePlan plan = plan_samples(m, finest, area, most, no_progress());
    // The rungs as the ladder makes them: from the area's bound (or `finest`) up by 1.25, the first that fits.
    double rung = std::max(finest, std::sqrt(area / (0.433 * most)));
    while (static_cast<double>(points_at(m, rung, area)) > most) rung *= 1.25;
    EXPECT_EQ(plan.spacing, rung) << "budget " << most;
    EXPECT_LE(static_cast<double>(plan.count()), most) << "budget " << most;
    EXPECT_EQ(plan.count(), points_at(m, plan.spacing, area)) << "budget " << most;
    EXPECT_EQ(samples_of(m, false, plan).points.size(), plan.count()) << "budget " << most;
  }
}
