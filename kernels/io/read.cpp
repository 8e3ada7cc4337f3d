#include "kernels/io/read.h"

#include <unistd.h>

#include <algorithm>
#include <cctype>

#include "kernels/base/error.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/read_error.h"
#include "kernels/io/regular_file.h"

namespace selfsim::io {

std::uint64_t read_budget_bytes() {
  const double memory = static_cast<double>(::sysconf(_SC_PHYS_PAGES)) * static_cast<double>(::sysconf(_SC_PAGESIZE));
  return static_cast<std::uint64_t>(std::min(memory / 6, 16.0 * (std::uint64_t{1} << 30)));
}

namespace {

Dataset read_by_extension(const std::filesystem::path& file, std::string ext) {
  try {
    ext = lower_case(std::move(ext));
    const bool vtk = ext == ".vtp" || ext == ".vtu",
               mesh = ext == ".stl" || ext == ".obj" || ext == ".ply" || ext == ".3mf";
    if (vtk || mesh || ext == ".svg") {
      // selfsim never writes an empty file, and two broken files must never compare as "same".
      Dataset d = vtk ? read_vtk(file, ext == ".vtu") : mesh ? read_mesh_file(file, ext) : read_svg(file);
      if (d.points.empty()) throw Error("it holds no points");
      return d;
    }
    const RegularFile exists(file);  // a missing or unreadable file says so first
    throw Error(cannot_read(file, "expected a .vtp, .vtu, .svg, .stl, .3mf, .obj or .ply file"));
  } catch (const Error& e) {
    const std::string message = e.what();
    if (message.rfind("cannot read '", 0) == 0) throw;
    throw Error(cannot_read(file, message));
  } catch (const std::bad_alloc&) {
    throw Error(cannot_read(file, "out of memory"));
  } catch (const std::exception& e) {
    throw Error(cannot_read(file, e.what()));
  }
}

}  // namespace

Dataset read_dataset(const std::filesystem::path& file) { return read_dataset(file, file); }

Dataset read_dataset(const std::filesystem::path& file, const std::filesystem::path& shown) {
  try {
    return read_by_extension(file, shown.extension().string());
  } catch (const Error& e) {
    // Messages name the file as the user knows it, not the /proc name it was opened by.
    std::string message = e.what();
    const std::string opened = one_line(file.string()), known = one_line(shown.string());
    if (opened != known)
      for (std::size_t at = 0; (at = message.find(opened, at)) != std::string::npos; at += known.size())
        message.replace(at, opened.size(), known);
    throw Error(message);
  }
}

}  // namespace selfsim::io
