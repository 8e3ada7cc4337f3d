#include "kernels/io/view/apng.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <string>
#include <vector>

#include "kernels/base/error.h"

using selfsim::io::animated_png;
using selfsim::io::ApngFrame;

namespace {

void put32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((v >> shift) & 0xff);
}
std::uint32_t get32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (int i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(s[at + i]);
  return v;
}
void chunk(std::string& out, const std::string& type, const std::string& data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  const std::string body = type + data;
  out += body;
  put32(out, static_cast<std::uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(body.data()), body.size())));
}

// A w x h RGB PNG filled with one colour, made with zlib directly.
std::string solid_png(int w, int h, unsigned char shade) {
  std::string raw;
  for (int y = 0; y < h; ++y) {
    raw += '\0';  // filter: none
    raw += std::string(static_cast<std::size_t>(w) * 3, static_cast<char>(shade));
  }
  std::string z(compressBound(raw.size()), '\0');
  uLongf n = z.size();
  compress(reinterpret_cast<Bytef*>(z.data()), &n, reinterpret_cast<const Bytef*>(raw.data()), raw.size());
  z.resize(n);
  std::string ihdr;
  put32(ihdr, static_cast<std::uint32_t>(w));
  put32(ihdr, static_cast<std::uint32_t>(h));
  ihdr += std::string("\x08\x02\x00\x00\x00", 5);
  std::string png("\x89PNG\r\n\x1a\n", 8);
  chunk(png, "IHDR", ihdr);
  chunk(png, "IDAT", z);
  chunk(png, "IEND", "");
  return png;
}

struct Read {
  std::string type, data;
};
// Every chunk of a PNG, each CRC checked.
std::vector<Read> read_chunks(const std::string& png) {
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  std::vector<Read> out;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::uint32_t n = get32(png, at);
    const std::string body = png.substr(at + 4, 4 + n);
    EXPECT_EQ(get32(png, at + 8 + n), crc32(0, reinterpret_cast<const Bytef*>(body.data()), body.size()));
    out.push_back({body.substr(0, 4), body.substr(4)});
    at += 12 + n;
  }
  return out;
}

std::string inflated(const std::string& z, std::size_t size) {
  std::string raw(size, '\0');
  uLongf n = size;
  EXPECT_EQ(uncompress(reinterpret_cast<Bytef*>(raw.data()), &n, reinterpret_cast<const Bytef*>(z.data()), z.size()),
            Z_OK);
  raw.resize(n);
  return raw;
}

}  // namespace

TEST(AnimatedPng, ChunksInOrderWithOneSequenceAndEachFramesPixels) {
  const std::vector<ApngFrame> frames = {
      {solid_png(4, 3, 10), 0.5}, {solid_png(4, 3, 20), 0.25}, {solid_png(4, 3, 30), 2}};
  const std::vector<Read> c = read_chunks(animated_png(frames));
  std::vector<std::string> types;
  for (const Read& r : c) types.push_back(r.type);
  EXPECT_EQ(types, (std::vector<std::string>{"IHDR", "acTL", "fcTL", "IDAT", "fcTL", "fdAT", "fcTL", "fdAT", "IEND"}));
  EXPECT_EQ(get32(c[1].data, 0), 3u);  // frames
  EXPECT_EQ(get32(c[1].data, 4), 0u);  // plays forever
  // fcTL and fdAT share one sequence from 0; each fcTL covers the whole picture with its own delay.
  const std::size_t seq_at[] = {2, 4, 5, 6, 7};
  for (std::uint32_t k = 0; k < 5; ++k) EXPECT_EQ(get32(c[seq_at[k]].data, 0), k);
  EXPECT_EQ(get32(c[4].data, 4), 4u);
  EXPECT_EQ(get32(c[4].data, 8), 3u);
  EXPECT_EQ(static_cast<unsigned char>(c[4].data[20]) * 256 + static_cast<unsigned char>(c[4].data[21]), 25);
  EXPECT_EQ(static_cast<unsigned char>(c[4].data[22]) * 256 + static_cast<unsigned char>(c[4].data[23]), 100);
  // Each frame's pixels are its own: the third frame's data inflates to rows of 30.
  const std::string raw = inflated(c[7].data.substr(4), 3 * (1 + 12));
  ASSERT_EQ(raw.size(), 39u);
  EXPECT_EQ(raw[1], 30);
  EXPECT_EQ(inflated(c[3].data, 39)[1], 10);
}

TEST(AnimatedPng, RefusesFramesThatDoNotMatch) {
  EXPECT_THROW(animated_png({}), selfsim::Error);
  EXPECT_THROW(animated_png({{solid_png(4, 3, 1), 1}, {solid_png(5, 3, 1), 1}}), selfsim::Error);
  EXPECT_THROW(animated_png({{solid_png(4, 3, 1), 1}, {"GIF89a", 1}}), selfsim::Error);
  EXPECT_THROW(animated_png({{solid_png(4, 3, 1), 0}}), selfsim::Error);
  EXPECT_THROW(animated_png({{solid_png(4, 3, 1).substr(0, 30), 1}}), selfsim::Error);
  try {
    animated_png({{solid_png(4, 3, 1), 1}, {solid_png(4, 4, 1), 1}});
  } catch (const selfsim::Error& e) {
    EXPECT_NE(std::string(e.what()).find("frame 2"), std::string::npos) << e.what();
  }
}
