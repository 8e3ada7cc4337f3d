// Writing values to files, the writer chosen by the file's extension. Every writer writes to a temporary
// name beside the target and renames it at the end, so a failed or cancelled run leaves no partial file
// and keeps any older one.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "kernels/geom/polyline.h"
#include "kernels/geom/progress.h"

namespace selfsim::io {

struct SaveOptions {
  std::string stroke = "#1d3557"; // .svg: stroke colour
  double stroke_width = 1;        // .svg: stroke width in screen pixels, whatever the curve's scale
  std::string fill;               // .svg: fill colour with the even-odd rule; empty for no fill
  double size = 800;              // .svg: width or height in pixels, whichever is larger

  // Throws Error naming the first bad field.
  void validate() const;
};

// Extensions a Polyline can be saved as, with the dot (".svg", ".vtp").
const std::vector<std::string>& curve_extensions();

// Writes c to `file`; throws Error for an unknown extension or a failed write.
void save_curve(const Polyline& c, const std::filesystem::path& file, const SaveOptions& opt, Progress& progress);

// Format-specific writers; `file` is the temporary name save_curve renames.
void write_vtp(const Polyline& c, const std::filesystem::path& file, const SaveOptions& opt, Progress& progress);
void write_svg(const Polyline& c, const std::filesystem::path& file, const SaveOptions& opt, Progress& progress);

}  // namespace selfsim::io
