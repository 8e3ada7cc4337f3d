// Fuzz target: the .vdb reader (kernels/plugins/openvdb/vdb_read.cpp), as `selfsim info FILE.vdb`, `selfsim preview`,
// load() and volume.vdb() reach it: the grids' metadata, then the surface of the first level set. OpenVDB
// trusts its files, so the reader checks what a file declares before reading and runs OpenVDB in a limited
// child process; a selfsim::Error is a proper refusal, a crash, hang or other exception here is a finding,
// as is a surface whose polygons name points that are not there.
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "fuzz/fuzz_support.h"
#include "kernels/base/error.h"
#include "kernels/io/vdb/vdb_read.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace selfsim;
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("selfsim-fuzz-" + std::to_string(::getpid()) + ".vdb");
  static const struct Remove {
    ~Remove() { std::filesystem::remove(file); }
  } remove_at_exit;
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (f == nullptr) fuzz::finding("cannot write " + file.string());
  if (size > 0 && std::fwrite(data, 1, size, f) != size) fuzz::finding("cannot write " + file.string());
  std::fclose(f);
  static const bool verbose = fuzz::env_flag("SELFSIM_FUZZ_VERBOSE");
  try {
    const auto grids = io::read_vdb_info(file);
    if (verbose) std::fprintf(stderr, "info: %zu grids\n", grids.size());
  } catch (const Error& e) {
    if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
    return 0;
  } catch (...) {
    fuzz::unexpected_exception("io::read_vdb_info");
  }
  try {
    // With the voxels, as volume.vdb reads them: a tile's expanded into the count announced (the seeds
    // tiles*.vdb hold active tiles at each level of the tree), under a budget small enough that a crafted
    // tile is refused before it is voxelised.
    const io::VdbSurface s = io::read_vdb_surface(file, {.budget = {.limit = 1 << 24}, .samples = true});
    std::size_t begin = 0;
    for (std::size_t end : s.mesh.cell_ends) {
      fuzz::require(end >= begin + 3, "a polygon with fewer than 3 points");
      begin = end;
    }
    fuzz::require(begin == s.mesh.cell_points.size(), "cell_ends does not end at cell_points.size()");
    for (std::size_t p : s.mesh.cell_points) fuzz::require(p < s.mesh.points.size(), "a polygon names no point");
    fuzz::require(s.samples.index.size() == s.samples.value.size(), "voxel indices and values differ in number");
  } catch (const Error& e) {
    if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
  } catch (...) {
    fuzz::unexpected_exception("io::read_vdb_surface");
  }
  return 0;
}
