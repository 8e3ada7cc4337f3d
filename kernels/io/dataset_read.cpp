#include "kernels/geom/error.h"
#include "kernels/io/read.h"

namespace selfsim::io {

Dataset read_dataset(const std::filesystem::path& file) {
  if (!std::filesystem::exists(file)) throw Error("no such file: '" + file.string() + "'");
  const std::string ext = file.extension().string();
  if (ext == ".vtp") return read_vtp(file);
  if (ext == ".svg") return read_svg(file);
  throw Error("cannot read '" + file.string() + "': expected a .vtp or .svg file");
}

}  // namespace selfsim::io
