// Hints for options that do not exist under the name a user knows from elsewhere (the book, another
// tool): `elasticity = 0.22` on lsystem{} is refused with "the tropism vector's length is its elasticity:
// tropism = { 0, -0.22, 0 }". One table of such names; Options::finish() asks it before any "did you mean".
#pragma once

#include <string>
#include <vector>

namespace selfsim::interp {

// The hint for the unknown option `unknown` when the reader's `known` options hold the option it stands
// for, else empty. `value` is the given value as text (a number's digits, or empty when not a number): a
// hint may show it in place.
std::string option_hint(const std::string& unknown, const std::vector<std::string>& known, const std::string& value);

}  // namespace selfsim::interp
