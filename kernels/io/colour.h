// Colours as SVG takes them and every renderer agrees on: the CSS named colours (CSS Color Module Level 4),
// "#rgb" and "#rrggbb". A misspelt name ("purpel") is refused rather than written into a file that then
// renders blank.
#pragma once

#include <string>
#include <vector>

namespace selfsim::io {

// True for a CSS colour name (any case), "#rgb" or "#rrggbb".
bool is_colour(const std::string& text);

// The CSS colour names, lower case, for suggestions.
const std::vector<std::string>& colour_names();

}  // namespace selfsim::io
