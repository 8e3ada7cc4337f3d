#include "kernels/io/vtk/vtk_binary_data.h"

#include <string>

#include "kernels/base/error.h"

namespace selfsim::io {

namespace {

// The most a compressor can shrink data, with room to spare: deflate stays under 1032:1, LZ4 under 255:1;
// xz reaches about 7000:1 on a gigabyte of zeros.
std::uint64_t max_ratio(VtkCompressor c) {
  switch (c) {
    case VtkCompressor::zlib:
      return 1100;
    case VtkCompressor::lz4:
      return 300;
    case VtkCompressor::lzma:
      return 10000;
    case VtkCompressor::none:
      break;
  }
  return 1;
}

int base64_value(unsigned char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+') return 62;
  if (c == '/') return 63;
  return -1;
}

bool space(unsigned char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Sequential bytes of the data between begin and end, decoded from base64 where the layout says so.
class DataCursor {
 public:
  DataCursor(const RegularFile& f, const VtkBinaryLayout& l)
      : file_(f), pos_(l.begin), end_(l.end), base64_(l.base64) {}

  // Reads n decoded bytes; false when the data ends first.
  bool read(unsigned char* out, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i)
      if (!next(out[i])) return false;
    return true;
  }
  std::uint64_t position() const { return pos_; }

 private:
  bool raw(unsigned char& c) {
    if (pos_ >= end_) return false;
    if (pos_ < buffer_pos_ || pos_ >= buffer_pos_ + buffer_len_) {
      buffer_pos_ = pos_;
      buffer_len_ =
          file_.read_at(pos_, buffer_, static_cast<std::size_t>(std::min<std::uint64_t>(sizeof buffer_, end_ - pos_)));
      if (buffer_len_ == 0) return false;
    }
    c = buffer_[pos_ - buffer_pos_];
    ++pos_;
    return true;
  }
  bool next(unsigned char& c) {
    if (!base64_) return raw(c);
    if (pending_at_ == pending_n_) {
      int v[4], got = 0;
      while (got < 4) {
        unsigned char ch = 0;
        if (!raw(ch)) return false;
        if (space(ch)) continue;
        if (ch == '=') {
          v[got++] = -2;
          continue;
        }
        v[got] = base64_value(ch);
        if (v[got] < 0) throw Error("the base64 data holds a character that is not base64");
        ++got;
      }
      if (v[0] < 0 || v[1] < 0 || (v[2] == -2 && v[3] != -2)) throw Error("the base64 data is malformed");
      const unsigned bits = (static_cast<unsigned>(v[0]) << 18) | (static_cast<unsigned>(v[1]) << 12) |
                            (static_cast<unsigned>(v[2] < 0 ? 0 : v[2]) << 6) |
                            static_cast<unsigned>(v[3] < 0 ? 0 : v[3]);
      pending_[0] = static_cast<unsigned char>(bits >> 16);
      pending_[1] = static_cast<unsigned char>(bits >> 8);
      pending_[2] = static_cast<unsigned char>(bits);
      pending_n_ = v[2] == -2 ? 1 : v[3] == -2 ? 2 : 3;
      pending_at_ = 0;
    }
    c = pending_[pending_at_++];
    return true;
  }

  const RegularFile& file_;
  std::uint64_t pos_, end_;
  bool base64_;
  unsigned char buffer_[4096];
  std::uint64_t buffer_pos_ = 0;
  std::size_t buffer_len_ = 0;
  unsigned char pending_[3]{};
  int pending_n_ = 0, pending_at_ = 0;
};

// Characters of one base64 unit encoding n bytes.
std::uint64_t base64_chars(std::uint64_t n) { return (n + 2) / 3 * 4; }

std::string bytes_text(std::uint64_t n) { return std::to_string(n) + " bytes"; }

}  // namespace

std::uint64_t check_vtk_binary_data(const RegularFile& file, const VtkBinaryLayout& l, std::uint64_t need_bytes,
                                    std::uint64_t max_bytes) {
  if (l.begin > l.end) throw Error("its data starts past the end of the file");
  DataCursor cursor(file, l);
  const int w = l.word_bytes;
  auto word = [&](const char* what) {
    unsigned char b[8];
    if (!cursor.read(b, static_cast<std::size_t>(w)))
      throw Error(std::string("the file ends inside its data header (") + what + ")");
    std::uint64_t v = 0;
    for (int i = 0; i < w; ++i) v |= static_cast<std::uint64_t>(b[l.big_endian ? w - 1 - i : i]) << (8 * i);
    return v;
  };
  const std::uint64_t room = l.end - l.begin;  // bytes or base64 characters
  const std::uint64_t room_bytes = l.base64 ? room / 4 * 3 : room;

  if (l.compressor == VtkCompressor::none) {
    const std::uint64_t n = word("byte count");
    if (n < need_bytes)
      throw Error("its data holds " + bytes_text(n) + ", fewer than the " + bytes_text(need_bytes) +
                  " its declared size needs");
    if (n > max_bytes)
      throw Error("its data declares " + bytes_text(n) + ", over the reading limit of " + bytes_text(max_bytes));
    const std::uint64_t span =
        l.base64 ? base64_chars(static_cast<std::uint64_t>(w) + n) : static_cast<std::uint64_t>(w) + n;
    if (span > room) throw Error("its data declares " + bytes_text(n) + ", more than the file holds (truncated?)");
    return n;
  }

  const std::uint64_t blocks = word("block count"), block_size = word("block size"),
                      last_size = word("last block size");
  if (blocks > room_bytes / static_cast<std::uint64_t>(w))
    throw Error("its compression header declares " + std::to_string(blocks) +
                " blocks, more than the file could hold (truncated?)");
  if (blocks > 0 && (block_size == 0 || last_size > block_size))
    throw Error("its compression header declares blocks of " + bytes_text(block_size) + " with a last block of " +
                bytes_text(last_size));
  if (block_size > max_bytes)
    throw Error("its compression header declares blocks of " + bytes_text(block_size) + ", over the reading limit");
  const std::uint64_t ratio = max_ratio(l.compressor);
  std::uint64_t compressed = 0, total = 0;
  for (std::uint64_t i = 0; i < blocks; ++i) {
    const std::uint64_t c = word("compressed block size");
    const std::uint64_t u = (i + 1 == blocks && last_size != 0) ? last_size : block_size;
    if (c > room_bytes)
      throw Error("its compression header declares a block of " + bytes_text(c) +
                  ", more than the file holds (truncated?)");
    if (u / ratio > c + 64)
      throw Error("its compression header declares a block of " + bytes_text(c) + " compressed and " + bytes_text(u) +
                  " uncompressed, which no " + "compressor makes");
    compressed += c;
    total += u;
    if (compressed > room_bytes || total > max_bytes)
      throw Error(total > max_bytes
                      ? "its compressed data declares more than the reading limit of " + bytes_text(max_bytes)
                      : "its compressed data is larger than the file (truncated?)");
  }
  if (total < need_bytes)
    throw Error("its data holds " + bytes_text(total) + ", fewer than the " + bytes_text(need_bytes) +
                " its declared size needs");
  const std::uint64_t header = static_cast<std::uint64_t>(w) * (3 + blocks);
  const std::uint64_t span = l.base64 ? base64_chars(header) + base64_chars(compressed) : header + compressed;
  if (span > room) throw Error("its compressed data runs past the end of the file (truncated?)");
  return total;
}

}  // namespace selfsim::io
