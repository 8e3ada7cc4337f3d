// Reading selfsim's own SVG path data back (selfsim diff / info).
#include <charconv>
#include <fstream>
#include <sstream>

#include "kernels/geom/error.h"
#include "kernels/io/read.h"

namespace selfsim::io {

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
