#include "frontend/cli/studio/three_files.h"

#include <cstdlib>

namespace selfsim::interp {

std::filesystem::path three_folder() {
  const char* folder = std::getenv("SELFSIM_THREE");
  return folder && *folder ? std::filesystem::path(folder) : std::filesystem::path("/usr/share/javascript/three");
}

std::optional<std::filesystem::path> three_file(const std::string& path) {
  // The page's two scripts: three.js itself, and its orbit controls (examples/js: the version that adds
  // THREE.OrbitControls to the global THREE, as the page loads scripts without modules).
  static const std::pair<const char*, const char*> served[] = {
      {"/three/three.min.js", "build/three.min.js"},
      {"/three/OrbitControls.js", "examples/js/controls/OrbitControls.js"},
  };
  for (const auto& [address, file] : served)
    if (path == address) return three_folder() / file;
  return std::nullopt;
}

}  // namespace selfsim::interp
