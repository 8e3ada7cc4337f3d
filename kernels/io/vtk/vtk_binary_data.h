// Checking the header in front of one VTK XML data array's binary data against the file, before VTK's
// reader trusts it. Uncompressed data starts with one header word, its byte count; compressed data with
// [number of blocks, block size, size of the last block, compressed size of each block]. Words are UInt32 or
// UInt64 in the file's byte order; base64 data (inline format="binary", or appended encoding="base64")
// encodes them too, the compressed header as its own base64 unit.
#pragma once

#include <cstdint>

#include "kernels/io/regular_file.h"

namespace selfsim::io {

enum class VtkCompressor { none, zlib, lz4, lzma };

struct VtkBinaryLayout {
  bool base64 = false;
  std::uint64_t begin = 0;  // file position of the header's first byte (raw) or character (base64)
  std::uint64_t end = 0;    // one past the last position the data may occupy
  int word_bytes = 4;       // header_type UInt32 or UInt64
  bool big_endian = false;
  VtkCompressor compressor = VtkCompressor::none;
};

// Checks that the data the header announces lies between begin and end, that it holds at least
// need_bytes bytes, that no block claims to expand more than its compressor ever could, and that it is at
// most max_bytes uncompressed. Returns its uncompressed size in bytes. Throws Error with the reason.
std::uint64_t check_vtk_binary_data(const RegularFile& file, const VtkBinaryLayout& layout, std::uint64_t need_bytes,
                                    std::uint64_t max_bytes);

}  // namespace selfsim::io
