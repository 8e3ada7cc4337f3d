// preview_png.h forwarded to the rendering plugin (plugin.h), loaded on first use.
#include "kernels/base/plugin.h"
#include "kernels/io/output_file.h"
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

std::string render_preview_png(const Dataset& d, const std::string& title, Progress& progress) {
  return render().render_preview_png(d, title, progress);
}

std::string write_preview_png(const Dataset& d, const std::string& title, const std::filesystem::path& root,
                              const std::string& name, Progress& progress) {
  const std::string png = render().render_preview_png(d, title, progress);
  OutputFile file(root, name);  // every folder of `name` opened below root, never through a link
  file.write(png);
  file.commit();
  return file.path();
}

}  // namespace selfsim::io
