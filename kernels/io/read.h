// Reading geometry files back, for `selfsim diff` and `selfsim info`: the reader is chosen by extension.
#pragma once

#include <filesystem>

#include "kernels/io/dataset.h"

namespace selfsim::io {

// Reads a file written by selfsim (or any .vtp / .svg polyline file) for comparison and inspection.
Dataset read_dataset(const std::filesystem::path& file);

// Format-specific readers.
Dataset read_vtp(const std::filesystem::path& file);
Dataset read_svg(const std::filesystem::path& file);

}  // namespace selfsim::io
