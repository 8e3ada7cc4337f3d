// Writing values to files, the writer chosen by the file's extension. Every writer writes to an
// OutputFile, made visible under its name only when complete, so a failed, cancelled or killed run leaves
// no partial file and keeps any older one; and nothing is written outside the output folder.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "kernels/geom/polyline.h"
#include "kernels/geom/progress.h"
#include "kernels/io/output_file.h"

namespace selfsim::io {

struct SaveOptions {
  std::string stroke = "#1d3557";  // .svg: stroke colour
  double stroke_width = 1;         // .svg: stroke width in screen pixels, whatever the curve's scale
  std::string fill;                // .svg: fill colour with the even-odd rule; empty for no fill
  double size = 800;               // .svg: width or height in pixels, whichever is larger

  // Throws Error naming the first bad field.
  void validate() const;
};

// Extensions a Polyline can be saved as, with the dot (".svg", ".vtp").
const std::vector<std::string>& curve_extensions();

// Writes c to `name` (a relative path) inside the folder `root` and returns the path written; throws Error
// for an unknown extension, a curve whose extent or length is not finite, a name leaving the folder, or a
// failed write.
std::string save_curve(const Polyline& c, const std::filesystem::path& root, const std::string& name,
                       const SaveOptions& opt, Progress& progress);
// The same for a file given as one path: its folder is the root.
inline std::string save_curve(const Polyline& c, const std::filesystem::path& file, const SaveOptions& opt,
                              Progress& progress) {
  return save_curve(c, file.parent_path().empty() ? "." : file.parent_path(), file.filename().string(), opt, progress);
}

// Format-specific writers, into the file save_curve then commits.
void write_vtp(const Polyline& c, OutputFile& out, const SaveOptions& opt, Progress& progress);
void write_svg(const Polyline& c, OutputFile& out, const SaveOptions& opt, Progress& progress);

}  // namespace selfsim::io
