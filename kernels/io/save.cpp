#include "kernels/io/save.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>

#include "kernels/geom/error.h"

namespace selfsim::io {

const std::vector<std::string>& curve_extensions() {
  static const std::vector<std::string> ext{".svg", ".vtp"};
  return ext;
}

namespace {

// A CSS colour ("#1d3557", "steelblue", "rgb(10, 20, 30)"): nothing that could end the SVG attribute.
bool colour_like(const std::string& c) {
  return !c.empty() && c.size() < 64 && std::all_of(c.begin(), c.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) ||
           std::string_view("#(),.% ").find(ch) != std::string_view::npos;
  });
}

}  // namespace

void SaveOptions::validate() const {
  if (!colour_like(stroke))
    throw Error("option 'stroke' must be a colour such as '#1d3557' or 'black', got '" + stroke + "'");
  if (!fill.empty() && !colour_like(fill))
    throw Error("option 'fill' must be a colour such as '#a8dadc' or 'none', got '" + fill + "'");
  if (!(stroke_width > 0 && stroke_width < 1e6))
    throw Error("option 'stroke_width' must be a positive number of pixels");
  if (!(size >= 16 && size <= 100000)) throw Error("option 'size' must be in [16, 100000] pixels");
}

std::string save_curve(const Polyline& c, const std::filesystem::path& root, const std::string& name,
                       const SaveOptions& opt, Progress& progress) {
  opt.validate();
  const std::string file = std::filesystem::path(name).filename().string();
  const std::string ext = std::filesystem::path(name).extension().string();
  const auto& known = curve_extensions();
  if (std::find(known.begin(), known.end(), ext) == known.end())
    throw Error("cannot save a curve as '" + ext + "' (file '" + file + "'), expected one of: " + quoted_list(known));
  if (c.points.empty()) throw Error("cannot save an empty curve to '" + file + "'");
  if (!c.finite()) throw Error("cannot save '" + file + "': the curve has non-finite coordinates");
  // Finite points can still overflow what a file derives from them: the extent (SVG viewBox, with its
  // margin) and the arclength field. Scale such a curve down before saving it.
  const Vec2 extent = c.bbox().size() * 1.05;
  if (!is_finite(extent) || !std::isfinite(c.length()))
    throw Error("cannot save '" + file + "': the curve's extent or length overflows (scale it down with c:transform)");
  OutputFile out(root, name);
  const std::string task = "writing " + file;
  progress.start(task.c_str());
  if (ext == ".vtp")
    write_vtp(c, out, opt, progress);
  else
    write_svg(c, out, opt, progress);
  if (progress.cancelled()) throw Cancelled();
  out.commit();
  return out.path();
}
}  // namespace selfsim::io
