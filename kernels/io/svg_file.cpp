// SVG for browsers and vector editors. Path data keeps the curve's own coordinates (a flip of y in a group
// transform makes y point up, as in the papers); the viewBox fits the curve with a small margin, and the
// stroke width is given in pixels of the drawing's width/height, converted to curve units, so a curve of
// any size reads the same. (vector-effect: non-scaling-stroke would say this too, but librsvg and some
// other renderers ignore it.)
#include <charconv>
#include <fstream>
#include <sstream>

#include "kernels/geom/error.h"
#include "kernels/io/save.h"

namespace selfsim::io {

namespace {

// Nine significant digits: well below a pixel at any sensible zoom, and far smaller files than 17.
void put(std::string& s, double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 9);
  s.append(buf, r.ptr);
}

}  // namespace

void write_svg(const Polyline& c, const std::filesystem::path& file, const SaveOptions& opt, Progress& progress) {
  const BBox2 b = c.bbox();
  Vec2 extent = b.size();
  const double big = std::max({extent.x, extent.y, 1e-300});
  const double margin = 0.02 * big;
  const Vec2 lo = b.min - Vec2{margin, margin};
  extent = extent + Vec2{2 * margin, 2 * margin};
  const double px = opt.size / std::max(extent.x, extent.y);

  std::ofstream out(file, std::ios::binary);
  std::string s;  // written out every megabyte or so: memory stays flat whatever the curve
  auto flush = [&] {
    out.write(s.data(), static_cast<std::streamsize>(s.size()));
    s.clear();
  };
  s += "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"";
  put(s, extent.x * px);
  s += "\" height=\"";
  put(s, extent.y * px);
  s += "\" viewBox=\"";
  for (double v : {lo.x, -(lo.y + extent.y), extent.x, extent.y}) {
    put(s, v);
    s += ' ';
  }
  s.back() = '"';
  s += ">\n<g transform=\"scale(1,-1)\">\n<path fill=\"" + (opt.fill.empty() ? std::string("none") : opt.fill) +
       "\" fill-rule=\"evenodd\" stroke=\"" + opt.stroke + "\" stroke-width=\"";
  put(s, opt.stroke_width / px);
  s += "\" stroke-linejoin=\"round\" stroke-linecap=\"round\" d=\"";
  std::size_t written = 0;
  for (std::size_t i = 0; i < c.paths(); ++i) {
    char cmd = 'M';
    for (Vec2 p : c.path(i)) {
      if (++written % (1u << 20) == 0) progress.step(0.9 * static_cast<double>(written) / static_cast<double>(c.points.size()));
      s += cmd;
      put(s, p.x);
      s += ' ';
      put(s, p.y);
      cmd = cmd == 'M' ? 'L' : ' ';
      if (s.size() > (1u << 20)) flush();
    }
  }
  s += "\"/>\n</g>\n</svg>\n";
  flush();
  if (!out.flush()) throw Error("cannot write '" + file.string() + "' (disk full?)");
}

Dataset read_svg(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  Dataset d;
  // Reads the absolute M/L path data that write_svg produces, one polyline cell per subpath.
  for (std::size_t at = text.find(" d=\""); at != std::string::npos; at = text.find(" d=\"", at)) {
    at += 4;
    const std::size_t end = text.find('"', at);
    if (end == std::string::npos) break;
    const char* p = text.data() + at;
    const char* stop = text.data() + end;
    std::vector<double> xy;
    auto flush = [&] {
      for (std::size_t k = 0; k + 1 < xy.size(); k += 2) {
        d.cell_points.push_back(d.points.size());
        d.points.push_back({xy[k], xy[k + 1], 0});
      }
      if (!xy.empty()) d.cell_ends.push_back(d.cell_points.size());
      xy.clear();
    };
    while (p < stop) {
      if (*p == 'M') flush();
      if (*p == 'M' || *p == 'L' || *p == ' ' || *p == ',' || *p == '\n') {
        ++p;
        continue;
      }
      double v = 0;
      auto r = std::from_chars(p, stop, v);
      if (r.ec != std::errc()) throw Error("cannot read path data in '" + file.string() + "'");
      xy.push_back(v);
      p = r.ptr;
    }
    flush();
    at = end;
  }
  return d;
}

}  // namespace selfsim::io
