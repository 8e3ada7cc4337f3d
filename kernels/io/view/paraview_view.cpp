#include "kernels/io/view/paraview_view.h"

#include <cmath>
#include <cstdio>

#include "kernels/base/utf8.h"
#include "kernels/io/output_file.h"

namespace selfsim::io {

namespace {

// The fixed part of every view: kernels/io/view/paraview_view_body.py, embedded by CMake.
constexpr const char* view_body =
#include "paraview_view_body.inc"
    ;

// A Python string literal of UTF-8 text.
std::string python_string(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (ch == '"' || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (c < 0x20 || c == 0x7f) {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02x", c);
      out += buffer;
    } else {
      out += ch;
    }
  }
  return out + "\"";
}

std::string python_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

const char* role_name(ViewRole r) {
  return r == ViewRole::curve ? "curve" : r == ViewRole::surface ? "surface" : "region";
}

std::string dataset_text(const ViewDataset& d) {
  const Colouring& c = d.colouring;
  std::string s =
      "        {\"file\": " + python_string(d.file) + ", \"name\": " + python_string(d.name) + ", \"role\": \"" +
      role_name(d.role) + "\", \"series\": " + (d.series ? "True" : "False") +
      ", \"flat\": " + (d.flat ? "True" : "False") + ", \"up\": " + std::to_string(d.up >= 0 && d.up <= 2 ? d.up : 1) +
      ",\n         \"field\": " + (c.field.empty() ? "None" : python_string(c.field)) + ", \"association\": \"" +
      (c.on_points ? "POINTS" : "CELLS") + "\", \"categorical\": " + (c.categorical ? "True" : "False") +
      ", \"range\": " +
      (std::isfinite(c.min) && std::isfinite(c.max) ? "[" + python_number(c.min) + ", " + python_number(c.max) + "]"
                                                    : std::string("None")) +
      ",\n         \"categories\": [";
  for (std::size_t i = 0; i < c.categories.size(); ++i) s += (i > 0 ? ", " : "") + std::to_string(c.categories[i]);
  return s + "]},\n";
}

}  // namespace

bool view_can_name(const ViewDataset& d) {
  return valid_utf8(d.file) && valid_utf8(d.name) && valid_utf8(d.colouring.field);
}

std::string paraview_view_text(std::span<const ViewDataset> datasets, const std::filesystem::path& folder) {
  std::string list;
  for (const ViewDataset& d : datasets)
    if (view_can_name(d)) list += dataset_text(d);
  const std::string where = valid_utf8(folder.string()) ? folder.string() : ".";
  return "# ParaView view written by selfsim. Open it with:  paraview --script=view.py\n"
         "# or render it without a window:                   pvbatch view.py --png view.png\n"
         "SELFSIM_VIEW = {\n    \"folder\": " +
         python_string(where) + ",\n    \"datasets\": [\n" + list + "    ],\n}\n" + view_body;
}

std::string write_paraview_view(std::span<const ViewDataset> datasets, const std::filesystem::path& root,
                                const std::string& name, const std::filesystem::path& named) {
  std::error_code ec;
  const std::filesystem::path& shown = named.empty() ? root : named;
  const std::filesystem::path folder = std::filesystem::absolute(shown, ec);
  OutputFile out(root, name);
  out.write(paraview_view_text(datasets, ec ? shown : folder.lexically_normal()));
  out.commit();
  return out.path();
}

}  // namespace selfsim::io
