// ASCII lower case, for the names selfsim compares without regard to case: file extensions, colour names.
#pragma once

#include <cctype>
#include <string>

namespace selfsim {

inline std::string lower_case(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

}  // namespace selfsim
