// A sweep's plot of one result against the one number that varies (plot_NAME.svg beside results.csv): the
// points joined by a line in order of x, axes with ticks at round numbers and their labels, the result's
// name as the title. Pure: text in, SVG text out; the sweep writes it through the confined writer.
#pragma once

#include <string>
#include <vector>

namespace selfsim::io {

struct PlotPoint {
  double x = 0, y = 0;
};

struct PlotLabels {
  std::string title;  // "dimension against factor"
  std::string note;   // under the title: "bowyer.lua, 7 of 9 runs"
  std::string x, y;   // the axes' names: the swept key, the result
};

// The plot as a whole SVG document, 640 x 420, its axes running from a round tick below the data (less 3% of
// its range) to one above. Each point is a circle carrying its exact values as
// data-x and data-y (the shortest text that reads back the same double), for tools and tests; the points
// are drawn in order of x whatever their order given. Throws Error for no point or a value that is not
// finite.
std::string result_plot_svg(const PlotLabels& labels, std::vector<PlotPoint> points);

// Round tick values covering [lo, hi] (lo <= hi, both finite): a step of 1, 2 or 5 times a power of ten
// giving 4 to 10 ticks, the first at or below lo and the last at or above hi. A range of one value is
// widened around it first. Exposed for the unit test.
std::vector<double> plot_ticks(double lo, double hi);
// The same round ticks, only those inside [lo, hi] (a colour bar's labels, which cannot reach past its ends);
// empty when fewer than two fall inside or the range is not finite.
std::vector<double> legend_ticks(double lo, double hi);

}  // namespace selfsim::io
