// Fuzz target: selfsim's own .obj reader (kernels/io/mesh/obj_read.cpp), as `selfsim info FILE.obj`, `selfsim diff` and
// load() reach it. See read_fuzz.h.
#include "fuzz/read_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return selfsim::fuzz::read_one(data, size, ".obj");
}
