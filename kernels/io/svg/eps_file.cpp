// Encapsulated PostScript, as seed 000's tool exported its curves (§3.2): for print workflows, LaTeX and
// illustration programs. The layout and styles are the SVG writer's (curve_style.h): the bounding box is the
// curve's with a 2% margin, its longer side `size` points (or a physical size), y up as PostScript has it.
// Coordinates are written relative to the box's corner, so they stay small whatever the curve's position.
// Each run of paths of one style is one PostScript path: filled with the even-odd rule where a fill is
// given, then stroked. A turtle's widths and colours are drawn segment by segment, as in SVG.
#include <algorithm>
#include <cmath>
#include <span>

#include "kernels/base/error.h"
#include "kernels/io/svg/curve_style.h"
#include "kernels/io/svg/style_runs.h"
#include "kernels/io/text/colour.h"
#include "kernels/io/text/put_number.h"
#include "kernels/io/writers.h"

namespace selfsim::io {

namespace {

// Points (1/72 inch) per unit of the size option.
double points_per_unit(const std::string& unit) {
  if (unit == "mm") return 72 / 25.4;
  if (unit == "cm") return 72 / 2.54;
  if (unit == "in") return 72;
  return 1;  // a plain number is points, as SVG's is pixels
}

void put_colour(std::string& s, const std::string& colour) {
  const Rgb c = *colour_rgb(colour);  // styles hold only colours SaveOptions or the fields checked
  for (double v : c) {
    put_number(s, std::round(v * 255) / 255, 4);
    s += ' ';
  }
  s += "setrgbcolor\n";
}

}  // namespace

void write_eps(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress) {
  const Polyline& c = *std::get<const Polyline*>(v);  // the registry sends only 2D curves here
  const double unit = points_per_unit(opt.size_unit);
  const DrawingFrame frame = drawing_frame(c, opt.size * unit);
  const CurveStyles styles(c, opt, frame.scale / unit);  // turtle widths: curve units to the size's unit
  const double w = frame.extent.x * frame.scale, h = frame.extent.y * frame.scale;

  std::string s;
  auto flush = [&] {
    out.write(s);
    s.clear();
  };
  s += "%!PS-Adobe-3.0 EPSF-3.0\n%%BoundingBox: 0 0 " + std::to_string(static_cast<long long>(std::ceil(w))) + " " +
       std::to_string(static_cast<long long>(std::ceil(h))) + "\n%%HiResBoundingBox: 0 0 ";
  put_number(s, w);
  s += ' ';
  put_number(s, h);
  s += "\n%%Creator: selfsim\n%%LanguageLevel: 2\n%%Pages: 1\n%%EndComments\n"
       "save\n/m { moveto } bind def\n/l { lineto } bind def\n1 setlinejoin 1 setlinecap\n";
  // Each run of one style (style_runs.h) is one PostScript path, filled where a fill is given, then stroked.
  struct Sink {
    std::string& s;
    OutputFile& out;
    const DrawingFrame& frame;
    double unit;
    std::size_t written, total;
    Progress& progress;
    void begin(const PathStyle&) { s += "newpath\n"; }
    void piece(std::span<const Vec2> path, bool closed) {
      const char* op = " m\n";
      for (Vec2 p : path) {
        const Vec2 q = frame.scale * (p - frame.lo);
        put_number(s, q.x, 8);
        s += ' ';
        put_number(s, q.y, 8);
        s += op;
        op = " l\n";
        if (++written % (1u << 20) == 0)
          progress.step(std::min(0.9, 0.9 * static_cast<double>(written) / static_cast<double>(total)));
        if (s.size() > (1u << 20)) {
          out.write(s);
          s.clear();
        }
      }
      if (closed) s += "closepath\n";
    }
    void end(const PathStyle& style) {
      if (style.fill != "none") {
        s += "gsave\n";
        put_colour(s, style.fill);
        s += "eofill\ngrestore\n";
      }
      const double width = style.width * unit;
      if (!std::isfinite(width)) throw Error(drawing_overflow);
      if (style.stroke == "none") {
        s += "newpath\n";  // filled only (or nothing): the path is dropped unstroked
      } else {
        put_colour(s, style.stroke);
        put_number(s, width);
        s += " setlinewidth\nstroke\n";
      }
    }
  };
  Sink sink{s, out, frame, unit, 0, c.points.size(), progress};
  style_runs(c, styles, sink);
  s += "restore\nshowpage\n%%EOF\n";
  flush();
}

}  // namespace selfsim::io
