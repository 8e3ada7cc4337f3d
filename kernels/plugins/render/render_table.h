// The functions of the rendering plugin (selfsim_render.so, plugin.h): VTK's OpenGL renderer, behind
// preview_png.h.
#pragma once

#include <filesystem>
#include <string>

#include "kernels/io/view/preview_png.h"

namespace selfsim {

struct RenderTable {
  bool (*flat_dataset)(const io::Dataset&);
  io::PreviewSize (*preview_size)(const io::Dataset&);
  // The PNG's bytes only: the file is written by the interpreter's one confined writer (preview_plugin.cpp).
  std::string (*render_preview_png)(const io::Dataset&, const std::string&, Progress&);
};

inline constexpr const char* render_plugin = "selfsim_render.so";
inline constexpr const char* render_table_symbol = "selfsim_render_table";

}  // namespace selfsim
