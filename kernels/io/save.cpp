#include "kernels/io/save.h"

#include <algorithm>
#include <cctype>
#include <string_view>
#include <unistd.h>

#include "kernels/geom/error.h"

namespace selfsim::io {

namespace {

// Removes the temporary file unless the write got as far as renaming it.
struct TemporaryFile {
  std::filesystem::path path;
  bool kept = false;
  ~TemporaryFile() {
    if (!kept) {
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
    }
  }
};

}  // namespace

const std::vector<std::string>& curve_extensions() {
  static const std::vector<std::string> ext{".svg", ".vtp"};
  return ext;
}

namespace {

// A CSS colour ("#1d3557", "steelblue", "rgb(10, 20, 30)"): nothing that could end the SVG attribute.
bool colour_like(const std::string& c) {
  return !c.empty() && c.size() < 64 && std::all_of(c.begin(), c.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) || std::string_view("#(),.% ").find(ch) != std::string_view::npos;
  });
}

}  // namespace

void SaveOptions::validate() const {
  if (!colour_like(stroke)) throw Error("option 'stroke' must be a colour such as '#1d3557' or 'black', got '" + stroke + "'");
  if (!fill.empty() && !colour_like(fill))
    throw Error("option 'fill' must be a colour such as '#a8dadc' or 'none', got '" + fill + "'");
  if (!(stroke_width > 0 && stroke_width < 1e6)) throw Error("option 'stroke_width' must be a positive number of pixels");
  if (!(size >= 16 && size <= 100000)) throw Error("option 'size' must be in [16, 100000] pixels");
}

void save_curve(const Polyline& c, const std::filesystem::path& file, const SaveOptions& opt, Progress& progress) {
  opt.validate();
  const std::string ext = file.extension().string();
  const auto& known = curve_extensions();
  if (std::find(known.begin(), known.end(), ext) == known.end())
    throw Error("cannot save a curve as '" + ext + "' (file '" + file.filename().string() + "'), expected one of: " + quoted_list(known));
  if (c.points.empty()) throw Error("cannot save an empty curve to '" + file.filename().string() + "'");
  if (!c.finite()) throw Error("cannot save '" + file.filename().string() + "': the curve has non-finite coordinates");
  const std::string task = "writing " + file.filename().string();
  progress.start(task.c_str());
  TemporaryFile tmp{file.string() + ".part-" + std::to_string(::getpid())};
  if (ext == ".vtp") write_vtp(c, tmp.path, opt, progress);
  else write_svg(c, tmp.path, opt, progress);
  if (progress.cancelled()) throw Cancelled();
  std::error_code ec;
  std::filesystem::rename(tmp.path, file, ec);
  if (ec) throw Error("cannot write '" + file.string() + "': " + ec.message());
  tmp.kept = true;
}

}  // namespace selfsim::io
