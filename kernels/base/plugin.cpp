#include "kernels/base/plugin.h"

#include <dlfcn.h>
#include <unistd.h>

#include <filesystem>
#include <map>
#include <mutex>
#include <string>

#include "kernels/base/error.h"

namespace selfsim {

namespace {

// The folder of the running executable: plugins installed beside it win over the build folder's.
std::filesystem::path executable_folder() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe.parent_path();
}

}  // namespace

const void* plugin_table(const char* library, const char* symbol) {
  static std::mutex lock;
  static std::map<std::string, const void*> tables;
  const std::lock_guard<std::mutex> hold(lock);
  const std::string key = std::string(library) + ":" + symbol;
  if (const auto it = tables.find(key); it != tables.end()) return it->second;
  std::string why;
  for (const std::filesystem::path& folder : {executable_folder(), std::filesystem::path(SELFSIM_PLUGIN_DIR)}) {
    if (folder.empty()) continue;
    const std::filesystem::path file = folder / library;
    std::error_code ec;
    if (!std::filesystem::exists(file, ec)) continue;
    // Never closed: the tables and the objects the plugin makes (shared grids) live to the end.
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      why = dlerror();
      continue;
    }
    const auto get = reinterpret_cast<const void* (*)()>(dlsym(handle, symbol));
    if (get == nullptr) {
      why = file.string() + " has no " + symbol;
      continue;
    }
    return tables[key] = get();
  }
  throw Error(std::string("cannot load ") + library + ", which selfsim builds beside its binary (" +
              (why.empty() ? "not found in " + executable_folder().string() + " or " SELFSIM_PLUGIN_DIR : why) +
              "): rebuild with make");
}

}  // namespace selfsim
