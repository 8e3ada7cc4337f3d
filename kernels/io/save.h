// Writing values to files, the writer chosen by the file's extension through the format registry
// (format.h). Every writer writes to an OutputFile, made visible under its name only when complete, so a
// failed, cancelled or killed run leaves no partial file and keeps any older one; and nothing is written
// outside the output folder.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/io/format.h"
#include "kernels/io/output_file.h"

namespace selfsim::io {

struct SaveOptions {
  // .svg style, each one value or a palette cycled over a group's members (curve_style.h); given, they
  // override the style a curve carries in its cell fields.
  std::vector<std::string> stroke{"#1d3557"};  // stroke colours
  std::vector<double> stroke_width{1};         // stroke widths in pixels (or size_unit), whatever the curve's scale
  std::vector<std::string> fill;               // fill colours (or "none") with the even-odd rule; empty for none
  double size = 800;                           // .svg: width or height, whichever is larger, in size_unit
  std::string size_unit;                       // .svg: "" (pixels), "mm", "cm" or "in": a physical size for plotters
  double voxel = 0;                            // .vdb: the voxel size; 0 for 1/128 of the mesh's longest side
  std::string name;                            // .3mf: the object's name; empty for the file's name without extension
  std::string application = "selfsim";         // .3mf: the program that wrote it (the caller adds its version)
  PointBudget budget;                          // the run's, for what a writer builds on the way (a .vdb's grid)
  std::vector<std::string> given;              // the options the caller set, checked against the format's options
  std::string provenance;  // how the value was made, one line of JSON (provenance.h); empty: none recorded

  // Throws Error naming the first bad field.
  void validate() const;
};

// The voxel size a .vdb of m is written at: opt.voxel, or 1/128 of m's longest side.
double vdb_voxel(const Mesh& m, const SaveOptions& opt);

// Writes v to `name` (a relative path) inside the folder `root` and returns the path written; throws Error
// for an unknown extension or one that cannot hold v, an option of another format, an empty value, a value
// whose coordinates, extent, length or fields are not finite, a name leaving the folder, or a failed write.
std::string save(const ValueRef& v, const std::filesystem::path& root, const std::string& name, const SaveOptions& opt,
                 Progress& progress);
// The same for a file given as one path: its folder is the root.
inline std::string save(const ValueRef& v, const std::filesystem::path& file, const SaveOptions& opt,
                        Progress& progress) {
  return save(v, file.parent_path().empty() ? "." : file.parent_path(), file.filename().string(), opt, progress);
}

}  // namespace selfsim::io
