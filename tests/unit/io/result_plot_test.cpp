// A sweep's plot of a result: round ticks that cover the data, and an SVG whose points carry their exact
// values, sorted by x, inside the plot area, with the line through them; refusals for what cannot be drawn.
#include "kernels/io/view/result_plot.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <regex>
#include <string>

#include "kernels/base/error.h"

using namespace selfsim;

namespace {

void expect_round_ticks(double lo, double hi) {
  const std::vector<double> t = io::plot_ticks(lo, hi);
  ASSERT_GE(t.size(), 2u) << lo << " " << hi;
  EXPECT_LE(t.size(), 12u) << lo << " " << hi;
  EXPECT_LE(t.front(), lo);
  EXPECT_GE(t.back(), hi);
  const double step = t[1] - t[0];
  for (std::size_t i = 1; i < t.size(); ++i) EXPECT_NEAR(t[i] - t[i - 1], step, std::abs(step) * 1e-9);
  const double mantissa = step / std::pow(10.0, std::floor(std::log10(step)));
  // (the difference of two ticks near 1e6 carries their rounding: round to 1e-6)
  EXPECT_TRUE(std::abs(mantissa - 1) < 1e-6 || std::abs(mantissa - 2) < 1e-6 || std::abs(mantissa - 5) < 1e-6) << step;
}

TEST(ResultPlot, TicksAreRoundAndCover) {
  const std::vector<double> t = io::plot_ticks(0.3, 0.9);
  ASSERT_FALSE(t.empty());
  EXPECT_NEAR(t.front(), 0.2, 1e-12);
  EXPECT_NEAR(t.back(), 1.0, 1e-12);
  expect_round_ticks(2, 4.25);
  expect_round_ticks(-7, 1e6);
  expect_round_ticks(1000000.1, 1000000.2);
  expect_round_ticks(1e-300, 3e-300);
  expect_round_ticks(5, 5);  // one value: widened around it
  expect_round_ticks(0, 0);
  const std::vector<double> wide = io::plot_ticks(-DBL_MAX, DBL_MAX);  // the whole range: finite ticks
  for (double v : wide) EXPECT_TRUE(std::isfinite(v));
  EXPECT_LE(wide.front(), -DBL_MAX);
  EXPECT_GE(wide.back(), DBL_MAX);
}

// A colour bar's labels: round numbers inside its range, not its fifths (0.6982, 0.8655, ...).
TEST(ResultPlot, LegendTicksAreRoundAndInside) {
  const std::vector<double> wall = io::legend_ticks(0.6982, 1.033);
  ASSERT_EQ(wall.size(), 4u);
  EXPECT_NEAR(wall.front(), 0.7, 1e-12);
  EXPECT_NEAR(wall.back(), 1.0, 1e-12);
  EXPECT_EQ(io::legend_ticks(0, 11), (std::vector<double>{0, 5, 10}));  // not 2.75, 5.5, 8.25
  const std::vector<double> ends = io::legend_ticks(0, 1);              // ticks on both ends are kept
  EXPECT_EQ(ends.front(), 0);
  EXPECT_NEAR(ends.back(), 1, 1e-12);
  EXPECT_TRUE(io::legend_ticks(3, 3).empty());
  EXPECT_TRUE(io::legend_ticks(0, std::nan("")).empty());
}

TEST(ResultPlot, PointsCarryTheirValuesInOrderOfX) {
  io::PlotLabels labels{"dimension against factor", "b.lua: 3 of 3 runs", "factor", "dimension"};
  const std::string svg = io::result_plot_svg(labels, {{0.9, 1.5}, {0.3, 1.1}, {0.6, 0.1 + 0.2}});
  const std::regex circle("<circle cx=\"([^\"]+)\" cy=\"([^\"]+)\"[^>]* data-x=\"([^\"]+)\" data-y=\"([^\"]+)\"");
  std::vector<std::array<double, 4>> got;
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), circle); it != std::sregex_iterator(); ++it)
    got.push_back({std::stod((*it)[1]), std::stod((*it)[2]), std::stod((*it)[3]), std::stod((*it)[4])});
  ASSERT_EQ(got.size(), 3u) << svg;
  EXPECT_EQ(got[0][2], 0.3);
  EXPECT_EQ(got[1][2], 0.6);
  EXPECT_EQ(got[1][3], 0.1 + 0.2);  // written as 0.30000000000000004
  EXPECT_EQ(got[2][2], 0.9);
  for (const auto& p : got) {  // inside the plot area (84..616 by 58..358)
    EXPECT_GE(p[0], 84);
    EXPECT_LE(p[0], 616);
    EXPECT_GE(p[1], 58);
    EXPECT_LE(p[1], 358);
  }
  EXPECT_LT(got[0][0], got[1][0]);
  EXPECT_LT(got[2][1], got[0][1]);  // the larger y drawn higher
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_NE(svg.find(">dimension against factor</text>"), std::string::npos);
  EXPECT_NE(svg.find("class=\"ylabel\""), std::string::npos);
}

// A range a few units in the last place wide (a sweep over x = 1 and the next double): the tick count ran
// forever at 2^54, where k + 1 == k, until memory ran out. Ticks now, covering it, increasing.
TEST(ResultPlot, ARangeOfAFewUlps) {
  for (const double lo : {1.0, 1.5, -3.0, 1e15, 4503599627370496.0}) {
    const double hi = std::nextafter(std::nextafter(lo, INFINITY), INFINITY);
    const std::vector<double> t = io::plot_ticks(lo, hi);
    ASSERT_GE(t.size(), 2u) << lo;
    EXPECT_LE(t.size(), 22u) << lo;
    EXPECT_LE(t.front(), lo);
    EXPECT_GE(t.back(), hi);
    for (std::size_t i = 1; i < t.size(); ++i) EXPECT_LT(t[i - 1], t[i]) << lo;
  }
  const std::string svg = io::result_plot_svg({"t", "", "x", "y"}, {{1, 1}, {std::nextafter(1.0, 2.0), 2}});
  EXPECT_NE(svg.find("data-x=\"1.0000000000000002\""), std::string::npos) << svg;
}

TEST(ResultPlot, OnePointAndRefusals) {
  const std::string one = io::result_plot_svg({"t", "", "x", "y"}, {{2, 3}});
  EXPECT_EQ(one.find("<polyline"), std::string::npos);  // nothing to join
  EXPECT_NE(one.find("data-x=\"2\" data-y=\"3\""), std::string::npos);
  EXPECT_THROW(io::result_plot_svg({"t", "", "x", "y"}, {}), Error);
  EXPECT_THROW(io::result_plot_svg({"t", "", "x", "y"}, {{1, NAN}}), Error);
  EXPECT_THROW(io::plot_ticks(2, 1), Error);
  // Labels are XML text: markup in a name is escaped.
  EXPECT_NE(io::result_plot_svg({"a<b & c", "", "x", "y"}, {{1, 1}}).find("a&lt;b &amp; c"), std::string::npos);
}

}  // namespace
