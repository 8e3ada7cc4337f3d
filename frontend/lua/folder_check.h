// Whether a file stays inside a folder once symbolic links are resolved: require() and load() read only
// from the recipe's own folder (and scripts/), as save() writes only into the output folder.
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace selfsim::interp {

// True when `file` (which exists) resolves to a path inside `folder` (empty means the current folder);
// false when it leads outside, or either cannot be resolved. Never throws.
inline bool resolves_inside(const std::filesystem::path& folder, const std::filesystem::path& file) {
  std::error_code file_ec, dir_ec;
  const auto real = std::filesystem::canonical(file, file_ec);
  const auto home = std::filesystem::canonical(folder.empty() ? std::filesystem::path(".") : folder, dir_ec);
  return !file_ec && !dir_ec && std::mismatch(home.begin(), home.end(), real.begin(), real.end()).first == home.end();
}

// The names of the regular files in `folder` (empty means the current folder) whose extension is one of
// `extensions` (lower case, with the dot; any case in the name), sorted, at most `most` of the folder's
// entries looked at: the candidates of a "did you mean" for a file or module not found. Never throws.
inline std::vector<std::string> files_in(const std::filesystem::path& folder,
                                         const std::vector<std::string>& extensions, std::size_t most = 4096) {
  std::vector<std::string> names;
  try {
    std::error_code ec;
    std::filesystem::directory_iterator it(folder.empty() ? std::filesystem::path(".") : folder, ec), end;
    for (std::size_t seen = 0; !ec && it != end && seen < most; it.increment(ec), ++seen) {
      std::error_code type_ec;
      if (!it->is_regular_file(type_ec)) continue;
      const std::string name = it->path().filename().string();
      std::string ext = it->path().extension().string();
      for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      if (std::find(extensions.begin(), extensions.end(), ext) != extensions.end()) names.push_back(name);
    }
  } catch (...) {  // out of memory, a name the filesystem library rejects: no suggestions, not an error
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace selfsim::interp
