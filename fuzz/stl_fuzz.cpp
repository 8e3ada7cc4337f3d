// Fuzz target: selfsim's own .stl reader (kernels/io/mesh/stl_read.cpp), as `selfsim info FILE.stl`, `selfsim diff` and
// load() reach it. See read_fuzz.h.
#include "fuzz/read_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return selfsim::fuzz::read_one(data, size, ".stl");
}
