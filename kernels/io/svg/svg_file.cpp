// SVG for browsers and vector editors. Path data keeps the curve's own coordinates (a flip of y in a group
// transform makes y point up, as in the papers); the viewBox fits the curve with a small margin, and the
// stroke width is given in pixels of the drawing's width/height, converted to curve units, so a curve of
// any size reads the same. (vector-effect: non-scaling-stroke would say this too, but librsvg and some
// other renderers ignore it.) A turtle's own widths are drawn relative to the drawing, as every picture draws
// them (drawn_width.h, curve_style.h).
#include <algorithm>
#include <cmath>
#include <span>

#include "kernels/base/error.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/svg/curve_style.h"
#include "kernels/io/svg/style_runs.h"
#include "kernels/io/text/put_number.h"
#include "kernels/io/writers.h"

namespace selfsim::io {

void write_svg(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress) {
  const Polyline& c = *std::get<const Polyline*>(v);  // the registry sends only 2D curves here
  const DrawingFrame frame = drawing_frame(c, opt.size);
  const Vec2 lo = frame.lo, extent = frame.extent;
  const double px = frame.scale, big = frame.diameter;
  const CurveStyles styles(c, opt, px);  // turtle widths: curve units to pixels
  const int digits = coordinate_digits(frame);

  std::string s;  // written out every megabyte or so: memory stays flat whatever the curve
  auto flush = [&] {
    out.write(s);
    s.clear();
  };
  // Width and height in the size's unit (pixels, or mm/cm/in for plotters); the stroke width is in that unit too.
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  put_number(s, extent.x * px);
  s += opt.size_unit + "\" height=\"";
  put_number(s, extent.y * px);
  s += opt.size_unit + "\" viewBox=\"";
  for (double v : {lo.x, -(lo.y + extent.y), extent.x, extent.y}) {
    put_number(s, v, digits);
    s += ' ';
  }
  s.back() = '"';
  s += ">\n";
  if (!opt.provenance.empty()) s += "<!-- " + std::string(provenance_key) + " " + opt.provenance + " -->\n";
  s += "<g transform=\"scale(1,-1)\" fill-rule=\"evenodd\" stroke-linejoin=\"round\" stroke-linecap=\"round\">\n";
  const double noise = 1e-12 * big;
  // One <path> element per run of one style (style_runs.h): a group's member, the whole of a plain curve,
  // or the segments of a plant of one width and colour.
  struct Sink {
    std::string& s;
    OutputFile& out;
    double px, noise;
    int digits;
    std::size_t written, total;
    Progress& progress;
    void begin(const PathStyle& style) {
      s += "<path fill=\"" + style.fill + "\" stroke=\"" + style.stroke + "\" stroke-width=\"";
      if (!std::isfinite(style.width / px)) throw Error(drawing_overflow);
      put_number(s, style.width / px);
      s += "\" d=\"";
    }
    void piece(std::span<const Vec2> path, bool closed) {
      char cmd = 'M';
      for (Vec2 p : path) {
        // Rounding noise around zero (-1.36e-19 on a unit curve) is written as the 0 it means.
        p = {std::abs(p.x) < noise ? 0.0 : p.x, std::abs(p.y) < noise ? 0.0 : p.y};
        if (++written % (1u << 20) == 0)
          progress.step(std::min(0.9, 0.9 * static_cast<double>(written) / static_cast<double>(total)));
        s += cmd;
        put_number(s, p.x, digits);
        s += ' ';
        put_number(s, p.y, digits);
        cmd = cmd == 'M' ? 'L' : ' ';
        if (s.size() > (1u << 20)) {
          out.write(s);
          s.clear();
        }
      }
      // A closed path (back at its start) ends with Z, so renderers join its last corner like the others.
      if (closed) s += 'Z';
    }
    void end(const PathStyle&) { s += "\"/>\n"; }
  };
  Sink sink{s, out, px, noise, digits, 0, c.points.size(), progress};
  style_runs(c, styles, sink);  // c has at least one path: save() refuses empty curves
  s += "</g>\n</svg>\n";
  flush();
}

}  // namespace selfsim::io
