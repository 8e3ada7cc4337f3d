// The rendering plugin's one exported function: its table (render_table.h).
#include "kernels/plugins/render/render_table.h"

namespace {

const selfsim::RenderTable table{selfsim::io::flat_dataset, selfsim::io::preview_size, selfsim::io::render_preview};

}  // namespace

extern "C" __attribute__((visibility("default"))) const void* selfsim_render_table() { return &table; }
