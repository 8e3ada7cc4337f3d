// The chunk layout follows the APNG specification: the signature, IHDR (and PLTE/tRNS) of the first frame,
// acTL (frame and play counts), then per frame an fcTL (its region, delay, dispose and blend) and its data
// (IDAT for the first, fdAT with a sequence number for the rest), IEND. fcTL and fdAT share one sequence.
#include "kernels/io/view/apng.h"

#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <string_view>

#include "kernels/base/error.h"

namespace selfsim::io {

namespace {

constexpr std::string_view signature("\x89PNG\r\n\x1a\n", 8);

struct Chunk {
  std::string type;
  std::string_view data;
};

std::uint32_t big_endian(std::string_view s, std::size_t at) {
  return (std::uint32_t(static_cast<unsigned char>(s[at])) << 24) |
         (std::uint32_t(static_cast<unsigned char>(s[at + 1])) << 16) |
         (std::uint32_t(static_cast<unsigned char>(s[at + 2])) << 8) |
         std::uint32_t(static_cast<unsigned char>(s[at + 3]));
}

void put32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>((v >> shift) & 0xff);
}
void put16(std::string& out, std::uint16_t v) {
  out += static_cast<char>(v >> 8);
  out += static_cast<char>(v & 0xff);
}

void put_chunk(std::string& out, std::string_view type, std::string_view data) {
  put32(out, static_cast<std::uint32_t>(data.size()));
  std::string body(type);
  body += data;
  out += body;
  put32(out, static_cast<std::uint32_t>(
                 crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
}

// The chunks of one PNG file, checked for a signature, whole chunks and an IHDR first.
std::vector<Chunk> chunks(std::string_view png, const std::string& which) {
  if (png.substr(0, signature.size()) != signature) throw Error(which + " is not a PNG file");
  std::vector<Chunk> out;
  for (std::size_t at = signature.size(); at < png.size();) {
    if (png.size() - at < 12) throw Error(which + " ends inside a chunk");
    const std::uint32_t n = big_endian(png, at);
    if (n > png.size() - at - 12) throw Error(which + " ends inside a chunk");
    out.push_back({std::string(png.substr(at + 4, 4)), png.substr(at + 8, n)});
    at += 12 + n;
    if (out.back().type == "IEND") break;
  }
  if (out.empty() || out.front().type != "IHDR" || out.front().data.size() != 13)
    throw Error(which + " does not start with an image header");
  return out;
}

// The delay as a fraction the format holds (16-bit numerator and denominator).
void put_delay(std::string& out, double seconds, const std::string& which) {
  if (!(seconds > 0) || seconds > 655.35) throw Error(which + "'s delay must be in (0, 655.35] seconds");
  put16(out, static_cast<std::uint16_t>(std::lround(seconds * 100)));
  put16(out, 100);
}

}  // namespace

std::string animated_png(const std::vector<ApngFrame>& frames, int plays) {
  if (frames.empty()) throw Error("an animation needs at least one frame");
  if (plays < 0) throw Error("an animation's play count must be 0 (forever) or more");
  const std::vector<Chunk> first = chunks(frames.front().png, "frame 1");
  const std::string_view header = first.front().data;
  std::string out(signature);
  put_chunk(out, "IHDR", header);
  for (const Chunk& c : first)
    if (c.type == "PLTE" || c.type == "tRNS") put_chunk(out, c.type, c.data);
  std::string actl;
  put32(actl, static_cast<std::uint32_t>(frames.size()));
  put32(actl, static_cast<std::uint32_t>(plays));
  put_chunk(out, "acTL", actl);

  std::uint32_t sequence = 0;
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::string which = "frame " + std::to_string(i + 1);
    const std::vector<Chunk> own = i == 0 ? first : chunks(frames[i].png, which);
    // Size, bit depth, colour type and interlacing must be the first frame's (the header's 13 bytes, less
    // nothing: compression and filter methods are fixed by the format).
    if (own.front().data != header) throw Error(which + " differs from frame 1 in size or pixel format");
    std::string fctl;
    put32(fctl, sequence++);
    fctl += header.substr(0, 8);  // width and height
    put32(fctl, 0);               // x offset
    put32(fctl, 0);               // y offset
    put_delay(fctl, frames[i].seconds, which);
    fctl += '\0';  // dispose: none (the next frame covers the whole picture)
    fctl += '\0';  // blend: source (replace, not composite)
    put_chunk(out, "fcTL", fctl);
    bool any = false;
    for (const Chunk& c : own) {
      if (c.type != "IDAT") continue;
      any = true;
      if (i == 0) {
        put_chunk(out, "IDAT", c.data);
      } else {
        std::string fdat;
        put32(fdat, sequence++);
        fdat += c.data;
        put_chunk(out, "fdAT", fdat);
      }
    }
    if (!any) throw Error(which + " holds no image data");
  }
  put_chunk(out, "IEND", {});
  return out;
}

}  // namespace selfsim::io
