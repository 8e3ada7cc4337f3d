// Fuzz target: the .svg reader (kernels/io/svg/svg_read.cpp), as `selfsim info FILE.svg` and `selfsim diff`
// reach it. See read_fuzz.h.
#include "fuzz/read_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return selfsim::fuzz::read_one(data, size, ".svg");
}
