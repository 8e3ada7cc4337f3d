#include "kernels/io/view/result_plot.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "kernels/base/error.h"
#include "kernels/io/text/colour.h"
#include "kernels/io/text/json_text.h"
#include "kernels/io/text/palette.h"
#include "kernels/io/text/put_number.h"
#include "kernels/io/text/xml_text.h"

namespace selfsim::io {

namespace {

constexpr double width = 640, height = 420;
constexpr double right = 24, top = 58, bottom = 62;  // margins around the plot area (the left one fits the labels)

// (v - lo) / (hi - lo) computed in halves, so that a range as wide as the doubles themselves cannot overflow.
double fraction(double v, double lo, double hi) { return (v * 0.5 - lo * 0.5) / (hi * 0.5 - lo * 0.5); }

// lo (side -1) or hi (side 1) moved out by 3% of the range, so that no point sits on the frame when a tick
// falls on it; kept within the doubles.
double padded(double lo, double hi, int side) {
  const double pad = (hi * 0.5 - lo * 0.5) * 0.06;
  return std::clamp(side < 0 ? lo - pad : hi + pad, -DBL_MAX, DBL_MAX);
}

std::string num(double v) {
  std::string s;
  put_number(s, v, 7);
  return s;
}

// A tick's label: enough significant digits to tell ticks `step` apart at the axis' magnitude.
std::string tick_label(double t, double step, double magnitude) {
  if (t == 0) t = 0;  // never "-0"
  const int digits = std::clamp(static_cast<int>(std::ceil(std::log10(magnitude / step))) + 1, 1, 17);
  std::string s;
  put_number(s, t, digits);
  return s;
}

std::string text(const std::string& t) { return xml_escaped(xml_shown(t)); }

}  // namespace

std::vector<double> legend_ticks(double lo, double hi) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi)) return {};
  std::vector<double> inside;
  const double slack = 1e-9 * (hi - lo);  // a tick computed as k * step a rounding away from an end
  for (double t : plot_ticks(lo, hi))
    if (t >= lo - slack && t <= hi + slack) inside.push_back(t);
  if (inside.size() < 2) inside.clear();
  return inside;
}

std::vector<double> plot_ticks(double lo, double hi) {
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo <= hi)) throw Error("plot_ticks: a range of finite numbers");
  if (lo == hi) {  // one value: a range around it
    const double d = lo == 0 ? 1 : std::abs(lo) * 0.1;
    lo = std::max(lo - d, -DBL_MAX), hi = std::min(hi + d, DBL_MAX);
  }
  const double raw = (hi * 0.5 - lo * 0.5) * 0.4;  // a fifth of the range
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  const double m = raw / power;
  const double step = (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * power;
  const double first = std::floor(lo / step), last = std::ceil(hi / step);
  std::vector<double> ticks;
  // The tick numbers counted as whole numbers a double holds exactly: a range a few units in the last place
  // wide (x = 1 and the next double) has first near 2^54, where ++k is k again and the loop never ended.
  if (std::isfinite(step) && step > 0 && std::isfinite(first * step) && std::isfinite(last * step) &&
      last - first <= 20 && std::abs(first) < 0x1p52 && std::abs(last) < 0x1p52)
    for (int k = 0; k <= static_cast<int>(last - first); ++k) ticks.push_back((first + k) * step);
  if (ticks.size() < 2) ticks = {lo, hi};  // a range at the edge of the doubles: its own ends
  return ticks;
}

std::string result_plot_svg(const PlotLabels& labels, std::vector<PlotPoint> points) {
  if (points.empty()) throw Error("a plot needs at least one point");
  for (const PlotPoint& p : points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw Error("a plot's points must be finite numbers");
  std::stable_sort(points.begin(), points.end(), [](const PlotPoint& a, const PlotPoint& b) { return a.x < b.x; });
  double ylo = points[0].y, yhi = points[0].y;
  for (const PlotPoint& p : points) ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
  const std::vector<double> xt = plot_ticks(padded(points.front().x, points.back().x, -1),
                                            padded(points.front().x, points.back().x, 1)),
                            yt = plot_ticks(padded(ylo, yhi, -1), padded(ylo, yhi, 1));
  const double x0 = xt.front(), x1 = xt.back(), y0 = yt.front(), y1 = yt.back();
  const double xmag = std::max(std::abs(x0), std::abs(x1)), ymag = std::max(std::abs(y0), std::abs(y1));
  const double xstep = (x1 * 0.5 - x0 * 0.5) * 2 / static_cast<double>(xt.size() - 1);
  const double ystep = (y1 * 0.5 - y0 * 0.5) * 2 / static_cast<double>(yt.size() - 1);
  // The y ticks' labels decide the left margin: about 7 units a character at 12, and room for the axis' name.
  std::vector<std::string> ylabels;
  std::size_t longest = 0;
  for (double t : yt) longest = std::max(longest, ylabels.emplace_back(tick_label(t, ystep, ymag)).size());
  const double left = std::clamp(44 + 7.0 * static_cast<double>(longest), 84.0, 240.0);
  const double w = width - left - right, h = height - top - bottom;
  auto sx = [&](double v) { return left + fraction(v, x0, x1) * w; };
  auto sy = [&](double v) { return top + h - fraction(v, y0, y1) * h; };
  const std::string colour = colour_hex(class_colour(0));

  std::string s =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"640\" "
      "height=\"420\" viewBox=\"0 0 640 420\" font-family=\"sans-serif\" font-size=\"12\">\n"
      "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text class=\"title\" x=\"" +
      num(left) + "\" y=\"24\" font-size=\"16\">" + text(labels.title) + "</text>\n";
  if (!labels.note.empty())
    s += "<text class=\"note\" x=\"" + num(left) + "\" y=\"42\" fill=\"#555\">" + text(labels.note) + "</text>\n";
  // The grid and the ticks' labels.
  for (double t : xt) {
    const std::string x = num(sx(t));
    s += "<line x1=\"" + x + "\" y1=\"" + num(top) + "\" x2=\"" + x + "\" y2=\"" + num(top + h + 5) +
         "\" stroke=\"#e4e4e4\"/>\n<text class=\"xtick\" x=\"" + x + "\" y=\"" + num(top + h + 19) +
         "\" text-anchor=\"middle\">" + tick_label(t, xstep, xmag) + "</text>\n";
  }
  for (std::size_t i = 0; i < yt.size(); ++i) {
    const double t = yt[i];
    const std::string y = num(sy(t));
    s += "<line x1=\"" + num(left - 5) + "\" y1=\"" + y + "\" x2=\"" + num(left + w) + "\" y2=\"" + y +
         "\" stroke=\"#e4e4e4\"/>\n<text class=\"ytick\" x=\"" + num(left - 8) + "\" y=\"" + num(sy(t) + 4) +
         "\" text-anchor=\"end\">" + ylabels[i] + "</text>\n";
  }
  // The axes, their names, then the line and the points over them.
  s += "<rect x=\"" + num(left) + "\" y=\"" + num(top) + "\" width=\"" + num(w) + "\" height=\"" + num(h) +
       "\" fill=\"none\" stroke=\"#333\"/>\n";
  s += "<text class=\"xlabel\" x=\"" + num(left + w / 2) + "\" y=\"" + num(height - 16) +
       "\" text-anchor=\"middle\" font-size=\"14\">" + text(labels.x) + "</text>\n";
  s += "<text class=\"ylabel\" transform=\"translate(" + num(left - 24 - 7.0 * static_cast<double>(longest)) + " " +
       num(top + h / 2) + ") rotate(-90)\" text-anchor=\"middle\" font-size=\"14\">" + text(labels.y) + "</text>\n";
  if (points.size() > 1) {
    s += "<polyline fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2\" points=\"";
    for (std::size_t i = 0; i < points.size(); ++i)
      s += (i ? " " : "") + num(sx(points[i].x)) + "," + num(sy(points[i].y));
    s += "\"/>\n";
  }
  for (const PlotPoint& p : points) {
    const std::string x = json_number(p.x), y = json_number(p.y);
    s += "<circle cx=\"" + num(sx(p.x)) + "\" cy=\"" + num(sy(p.y)) + "\" r=\"4\" fill=\"" + colour + "\" data-x=\"" +
         x + "\" data-y=\"" + y + "\"><title>" + text(labels.x) + " = " + x + ": " + text(labels.y) + " = " + y +
         "</title></circle>\n";
  }
  return s + "</svg>\n";
}

}  // namespace selfsim::io
