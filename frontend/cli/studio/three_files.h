// The three.js files the studio's page draws its 3D views with: Debian's libjs-three, served from where the
// package installs it (never from the network, never a copy in this repository). Only a fixed list of
// paths is answered, each naming one installed file: no other path below the folder, and no '..', can be
// asked for. Without the package the page says so and shows the preview PNGs instead.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace selfsim::interp {

// Where libjs-three is installed: /usr/share/javascript/three, or $SELFSIM_THREE (a packager's other
// layout; the tests point it at an empty folder to see the page without three.js).
std::filesystem::path three_folder();

// The installed file an address such as "/three/three.min.js" stands for; nullopt for any address not on
// the list (the caller answers 404).
std::optional<std::filesystem::path> three_file(const std::string& path);

// What to say when the package is missing.
inline constexpr const char* three_missing = "three.js is not installed (apt-get install libjs-three)\n";

}  // namespace selfsim::interp
