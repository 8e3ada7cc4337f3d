#include "kernels/io/file_stream.h"

#include <cmath>
#include <cstring>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/io/read_error.h"

namespace selfsim::io {

namespace {

constexpr std::size_t buffer_bytes = std::size_t{1} << 20;
constexpr std::size_t max_line = std::size_t{1} << 16;

}  // namespace

// A small file gets a small buffer: zero-filling a megabyte for a 300-byte file costs more than reading it.
FileStream::FileStream(const RegularFile& file, std::uint64_t start)
    : file_(file),
      pos_(start),
      buffer_(static_cast<std::size_t>(std::min<std::uint64_t>(buffer_bytes, file.size() + 1))) {}

bool FileStream::fill() {
  if (begin_ > 0) {  // keep the unread tail at the front
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  const std::size_t n = file_.read_at(pos_, buffer_.data() + end_, buffer_.size() - end_);
  pos_ += n;
  end_ += n;
  return n > 0;
}

bool FileStream::line(std::string_view& out) {
  std::size_t scanned = 0;  // bytes after begin_ known to hold no newline (fill() keeps them at the front)
  for (;;) {
    const char* start = buffer_.data() + begin_;
    const auto* nl = static_cast<const char*>(std::memchr(start + scanned, '\n', end_ - begin_ - scanned));
    std::size_t n = 0, skip = 0;
    if (nl != nullptr) {
      n = static_cast<std::size_t>(nl - start);
      skip = 1;
    } else {
      scanned = end_ - begin_;
      if (scanned > max_line) throw Error("line " + std::to_string(lines_ + 1) + " is longer than 64 KiB");
      if (fill()) continue;
      if (begin_ == end_) return false;
      n = end_ - begin_;  // the last line, without a newline
      start = buffer_.data() + begin_;
    }
    if (n > max_line) throw Error("line " + std::to_string(lines_ + 1) + " is longer than 64 KiB");
    out = std::string_view(start, n);
    if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
    if (lines_ == 0 && out.substr(0, 3) == "\xEF\xBB\xBF") out.remove_prefix(3);  // a UTF-8 byte order mark
    begin_ += n + skip;
    ++lines_;
    return true;
  }
}

void FileStream::bytes(void* out, std::size_t n) {
  char* o = static_cast<char*>(out);
  while (n > 0) {
    if (begin_ == end_ && !fill()) throw Error("the file ends early (truncated?)");
    const std::size_t k = std::min(n, end_ - begin_);
    std::memcpy(o, buffer_.data() + begin_, k);
    begin_ += k;
    o += k;
    n -= k;
  }
}

bool FileStream::at_end() { return begin_ == end_ && !fill(); }

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == '\f')) ++i;
    const std::size_t start = i;
    while (i < line.size() && !(line[i] == ' ' || line[i] == '\t' || line[i] == '\r' || line[i] == '\f')) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

double number_word(std::string_view word, const std::string& what) {
  if (word.size() > 1 && word.front() == '+' && word[1] != '-' && word[1] != '+') word.remove_prefix(1);
  double v = 0;
  const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
  if (r.ec == std::errc::result_out_of_range && r.ptr == word.data() + word.size())
    throw Error(what + " is out of the range of a double: '" + shown(word) + "'");
  if (r.ec != std::errc() || r.ptr != word.data() + word.size())
    throw Error(what + " is not a number: '" + shown(word) + "'");
  if (!std::isfinite(v)) throw Error(what + " must be a finite number, got " + number_text(v));
  return v;
}

long long integer_word(std::string_view word, long long lo, long long hi, const std::string& what) {
  if (word.size() > 1 && word.front() == '+' && word[1] != '-' && word[1] != '+') word.remove_prefix(1);
  long long v = 0;
  const auto r = std::from_chars(word.data(), word.data() + word.size(), v);
  if (r.ec != std::errc() || r.ptr != word.data() + word.size())
    throw Error(what + " is not a whole number: '" + shown(word) + "'");
  if (v < lo || v > hi) throw Error(what + " must be in " + range_text(lo, hi) + ", got " + std::to_string(v));
  return v;
}

}  // namespace selfsim::io
