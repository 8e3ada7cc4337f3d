// SHA-256 (FIPS 180-4) of a byte string, as 64 lowercase hex digits: the recipe's fingerprint in an
// output's provenance, so `selfsim rerun` can tell whether the recipe changed since.
#pragma once

#include <string>
#include <string_view>

namespace selfsim::io {

std::string sha256_hex(std::string_view bytes);

}  // namespace selfsim::io
