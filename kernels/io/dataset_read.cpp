#include <algorithm>
#include <cctype>

#include "kernels/geom/error.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/regular_file.h"

namespace selfsim::io {

Dataset read_dataset(const std::filesystem::path& file) {
  try {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (ext == ".vtp") return read_vtp(file);
    if (ext == ".svg") return read_svg(file);
    const RegularFile exists(file);  // a missing or unreadable file says so first
    throw Error(cannot_read(file, "expected a .vtp or .svg file"));
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

}  // namespace selfsim::io
