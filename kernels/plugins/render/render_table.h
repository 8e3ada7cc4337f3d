// The functions of the rendering plugin (selfsim_render.so, plugin.h): VTK's OpenGL renderer, behind
// preview_png.h.
#pragma once

#include <span>
#include <string>

#include "kernels/io/view/preview_png.h"

namespace selfsim {

struct RenderTable {
  bool (*flat_dataset)(const io::Dataset&);
  io::PreviewSize (*preview_size)(const io::Dataset&);
  // The PNGs' bytes only: the files are written by the command through the one confined writer.
  io::PreviewPictures (*render_preview)(std::span<const io::Dataset>, const std::string&, const io::PreviewOptions&,
                                        Progress&);
};

inline constexpr const char* render_plugin = "selfsim_render.so";
inline constexpr const char* render_table_symbol = "selfsim_render_table";

}  // namespace selfsim
