// Fuzz target: selfsim's own .ply reader (kernels/io/mesh/ply_read.cpp), as `selfsim info FILE.ply`, `selfsim diff` and
// load() reach it. See read_fuzz.h.
#include "fuzz/read_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return selfsim::fuzz::read_one(data, size, ".ply");
}
