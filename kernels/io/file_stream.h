// Reading a RegularFile front to back, for the mesh readers: lines of text (bounded in length) and raw
// bytes, through one buffer. Memory stays small whatever the file; nothing is read past the size the file
// had when it was opened.
#pragma once

#include <charconv>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "kernels/io/regular_file.h"

namespace selfsim::io {

class FileStream {
 public:
  explicit FileStream(const RegularFile& file, std::uint64_t start = 0);

  // The next line without its end ("\n" or "\r\n") into `out`; false at the end of the file. Throws Error
  // for a line over 64 KiB (no text mesh format has one).
  bool line(std::string_view& out);
  // Lines read so far: the number of the line `line` returned last.
  std::size_t line_number() const { return lines_; }
  // Exactly n bytes into out; throws Error when the file ends first.
  void bytes(void* out, std::size_t n);
  bool at_end();

 private:
  bool fill();  // more bytes into the buffer; false at the end of the file

  const RegularFile& file_;
  std::uint64_t pos_;  // file position of buffer_[end_]
  std::vector<char> buffer_;
  std::size_t begin_ = 0, end_ = 0, lines_ = 0;
};

// The whitespace-separated words of a line.
std::vector<std::string_view> words(std::string_view line);

// A word as a finite number, or an Error naming `what` ("line 12: vertex x").
double number_word(std::string_view word, const std::string& what);
// A word as a whole number in [lo, hi].
long long integer_word(std::string_view word, long long lo, long long hi, const std::string& what);

}  // namespace selfsim::io
