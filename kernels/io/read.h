// Reading geometry files back, for `selfsim diff` and `selfsim info`: the reader is chosen by extension.
// Every failure (a missing, empty, truncated, garbage or crafted file, a directory, FIFO or device, a file
// over the reading limit) throws Error with one line, "cannot read 'FILE': REASON"; nothing else escapes,
// and nothing is printed.
#pragma once

#include <filesystem>
#include <string>

#include "kernels/io/dataset/dataset.h"

namespace selfsim::io {

// Reads a file written by selfsim (or any .vtp, .vtu, .svg, .stl, .obj or .ply file) for comparison and
// inspection.
Dataset read_dataset(const std::filesystem::path& file);
// The same for a file opened under another name (FileBeneath::name()): the format comes from `shown`, and
// messages name `shown`.
Dataset read_dataset(const std::filesystem::path& file, const std::filesystem::path& shown);

// Format-specific readers.
// .vtp (PolyData) or .vtu (unstructured grid) through VTK (a plugin, plugin.h); see
// kernels/plugins/vtk/vtk_read.cpp for how hostile files are handled.
Dataset read_vtk(const std::filesystem::path& file, bool unstructured);
// .stl, .obj or .ply (ext, lower case with the dot) through selfsim's own strict readers (mesh_readers.h).
Dataset read_mesh_file(const std::filesystem::path& file, const std::string& ext);
Dataset read_svg(const std::filesystem::path& file);  // absolute M/L path data, streamed

}  // namespace selfsim::io
