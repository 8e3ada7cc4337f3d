// Whether a file stays inside a folder once symbolic links are resolved: require() and load() read only
// from the recipe's own folder (and scripts/), as save() writes only into the output folder.
#pragma once

#include <algorithm>
#include <filesystem>

namespace selfsim::interp {

// True when `file` (which exists) resolves to a path inside `folder` (empty means the current folder);
// false when it leads outside, or either cannot be resolved. Never throws.
inline bool resolves_inside(const std::filesystem::path& folder, const std::filesystem::path& file) {
  std::error_code file_ec, dir_ec;
  const auto real = std::filesystem::canonical(file, file_ec);
  const auto home = std::filesystem::canonical(folder.empty() ? std::filesystem::path(".") : folder, dir_ec);
  return !file_ec && !dir_ec && std::mismatch(home.begin(), home.end(), real.begin(), real.end()).first == home.end();
}

}  // namespace selfsim::interp
