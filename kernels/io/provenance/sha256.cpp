#include "kernels/io/provenance/sha256.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>

namespace selfsim::io {

namespace {

using u32 = std::uint32_t;

// The first 32 bits of the fractional parts of the square roots (initial hash) and cube roots (round
// constants) of the first primes, as FIPS 180-4 defines them; computed rather than typed out.
struct Constants {
  std::array<u32, 8> h;
  std::array<u32, 64> k;
  Constants() {
    int found = 0;
    for (int n = 2; found < 64; ++n) {
      bool prime = true;
      for (int d = 2; d * d <= n; ++d) prime = prime && n % d != 0;
      if (!prime) continue;
      auto fraction_bits = [](long double x) { return static_cast<u32>((x - std::floor(x)) * 4294967296.0L); };
      if (found < 8) h[static_cast<std::size_t>(found)] = fraction_bits(std::sqrt(static_cast<long double>(n)));
      k[static_cast<std::size_t>(found)] = fraction_bits(std::cbrt(static_cast<long double>(n)));
      ++found;
    }
  }
};

u32 rotr(u32 x, int n) { return (x >> n) | (x << (32 - n)); }

void compress(std::array<u32, 8>& state, const unsigned char* block, const std::array<u32, 64>& k) {
  u32 w[64];
  for (int i = 0; i < 16; ++i)
    w[i] = static_cast<u32>(block[4 * i]) << 24 | static_cast<u32>(block[4 * i + 1]) << 16 |
           static_cast<u32>(block[4 * i + 2]) << 8 | block[4 * i + 3];
  for (int i = 16; i < 64; ++i) {
    const u32 s0 = rotr(w[i - 15], 7) ^ rotr(w[i - 15], 18) ^ (w[i - 15] >> 3);
    const u32 s1 = rotr(w[i - 2], 17) ^ rotr(w[i - 2], 19) ^ (w[i - 2] >> 10);
    w[i] = w[i - 16] + s0 + w[i - 7] + s1;
  }
  u32 a = state[0], b = state[1], c = state[2], d = state[3], e = state[4], f = state[5], g = state[6], h = state[7];
  for (int i = 0; i < 64; ++i) {
    const u32 t1 =
        h + (rotr(e, 6) ^ rotr(e, 11) ^ rotr(e, 25)) + ((e & f) ^ (~e & g)) + k[static_cast<std::size_t>(i)] + w[i];
    const u32 t2 = (rotr(a, 2) ^ rotr(a, 13) ^ rotr(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
    h = g;
    g = f;
    f = e;
    e = d + t1;
    d = c;
    c = b;
    b = a;
    a = t1 + t2;
  }
  const u32 add[8] = {a, b, c, d, e, f, g, h};
  for (int i = 0; i < 8; ++i) state[static_cast<std::size_t>(i)] += add[i];
}

}  // namespace

std::string sha256_hex(std::string_view bytes) {
  static const Constants constants;
  std::array<u32, 8> state = constants.h;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  std::size_t at = 0;
  for (; at + 64 <= bytes.size(); at += 64) compress(state, data + at, constants.k);
  // The tail, a 1 bit, zeros, and the message's length in bits (big-endian) fill the last block or two.
  unsigned char tail[128] = {};
  const std::size_t rest = bytes.size() - at;
  for (std::size_t i = 0; i < rest; ++i) tail[i] = data[at + i];
  tail[rest] = 0x80;
  const std::size_t blocks = rest + 9 <= 64 ? 1 : 2;
  const std::uint64_t bits = static_cast<std::uint64_t>(bytes.size()) * 8;
  for (int i = 0; i < 8; ++i)
    tail[blocks * 64 - 1 - static_cast<std::size_t>(i)] = static_cast<unsigned char>(bits >> (8 * i));
  for (std::size_t b = 0; b < blocks; ++b) compress(state, tail + 64 * b, constants.k);
  std::string hex;
  for (u32 word : state) {
    char buf[9];
    std::snprintf(buf, sizeof buf, "%08x", word);
    hex += buf;
  }
  return hex;
}

}  // namespace selfsim::io
