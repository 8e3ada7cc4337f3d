// preview_png.h forwarded to the rendering plugin (plugin.h), loaded on first use.
#include "kernels/base/plugin.h"
#include "kernels/plugins/render/render_table.h"

namespace selfsim::io {

namespace {

// Loaded once (a failed load is tried again on the next call).
const RenderTable& render() {
  static const RenderTable& table = *static_cast<const RenderTable*>(plugin_table(render_plugin, render_table_symbol));
  return table;
}

}  // namespace

bool flat_dataset(const Dataset& d) { return render().flat_dataset(d); }

PreviewSize preview_size(const Dataset& d) { return render().preview_size(d); }

PreviewPictures render_preview(std::span<const Dataset> steps, const std::string& title, const PreviewOptions& options,
                               Progress& progress) {
  return render().render_preview(steps, title, options, progress);
}

}  // namespace selfsim::io
