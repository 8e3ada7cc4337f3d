// The SVG style options `stroke`, `stroke_width` and `fill`, read the same way for save() (where each may be
// a palette: a list cycled over a group's members) and for a member of group{} (one value each). Colours
// are checked here so a misspelt name gets a suggestion ("did you mean 'purple'?").
#pragma once

#include <string>
#include <vector>

#include "frontend/lua/options_reader.h"

namespace selfsim::interp {

struct StyleOptions {
  std::vector<std::string> stroke;  // empty when not given
  std::vector<double> stroke_width;
  std::vector<std::string> fill;  // colours or "none"
};

// Reads the three keys that `o` holds (absent ones stay empty); with palette = false each must be one value.
StyleOptions read_style(lua_State* L, Options& o, bool palette);

}  // namespace selfsim::interp
