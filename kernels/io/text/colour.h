// Colours as SVG takes them and every renderer agrees on: the CSS named colours (CSS Color Module Level 4),
// "#rgb" and "#rrggbb". A misspelt name ("purpel") is refused rather than written into a file that then
// renders blank. Colours are also values: a curve's per-path `color` field holds them as RGB in [0, 1].
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace selfsim::io {

using Rgb = std::array<double, 3>;  // red, green, blue in [0, 1]

// The colour a CSS colour name (any case), "#rgb" or "#rrggbb" stands for, or nothing for other text.
std::optional<Rgb> colour_rgb(const std::string& text);
// True for a CSS colour name (any case), "#rgb" or "#rrggbb".
inline bool is_colour(const std::string& text) { return colour_rgb(text).has_value(); }
// "#rrggbb" for c, each component rounded to the nearest of 256 levels (and clamped to [0, 1]).
std::string colour_hex(const Rgb& c);

// The CSS colour names, lower case, for suggestions.
const std::vector<std::string>& colour_names();

}  // namespace selfsim::io
