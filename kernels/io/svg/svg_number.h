// SVG's number grammar, shared by the path data and transform readers: sign? (digits? "." digits | digits
// "."?) (("e" | "E") sign? digits)?, read greedily: a number ends at the first character that cannot continue
// it, so ".5.5" is 0.5 then 0.5, "1.5.5" is 1.5 then 0.5, "1e-2.5" is 0.01 then 0.5 and "1-2" is 1 then -2,
// as SVG's path data grammar says. A token that is not a whole number ("1e", "-", ".") is an error.
#pragma once

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <system_error>

#include "kernels/base/error.h"

namespace selfsim::io {

constexpr std::size_t max_svg_number = 64;  // characters in one number

inline bool svg_digit(char c) { return c >= '0' && c <= '9'; }
inline bool svg_number_start(char c) { return svg_digit(c) || c == '.' || c == '+' || c == '-'; }

// One number being read, a character at a time.
class SvgNumberToken {
 public:
  bool empty() const { return size_ == 0; }
  std::string_view text() const { return {text_, size_}; }
  void clear() { size_ = 0, dot_ = exponent_ = digit_ = false; }

  // Whether c continues the number (not empty) read so far.
  bool continues(char c) const {
    if (svg_digit(c)) return true;
    if (c == '.') return !dot_ && !exponent_;
    if (c == 'e' || c == 'E') return !exponent_ && digit_;
    if (c == '+' || c == '-') return text_[size_ - 1] == 'e' || text_[size_ - 1] == 'E';
    return false;
  }
  // Appends c; throws Error, naming `where`, past max_svg_number characters.
  void add(char c, const char* where) {
    if (size_ == max_svg_number)
      throw Error("a number " + std::string(where) + " is longer than " + std::to_string(max_svg_number) +
                  " characters");
    text_[size_++] = c;
    dot_ = dot_ || c == '.';
    exponent_ = exponent_ || c == 'e' || c == 'E';
    digit_ = digit_ || svg_digit(c);
  }

 private:
  char text_[max_svg_number];
  std::size_t size_ = 0;
  bool dot_ = false, exponent_ = false, digit_ = false;
};

// The value of one whole number token: std::errc{} when it is one, invalid_argument when it is not a whole
// number ("1e", "-", "."), result_out_of_range when it overflows (or underflows) a double. The tokens hold
// only digits, '.', 'e', 'E' and signs, never "inf" or "nan", so a value read is finite.
inline std::errc svg_number_parse(std::string_view number, double& v) {
  const char* begin = number.data() + (!number.empty() && number[0] == '+' ? 1 : 0);
  const char* end = number.data() + number.size();
  const auto r = std::from_chars(begin, end, v);
  if (r.ec == std::errc::result_out_of_range) return r.ec;
  if (begin == end || r.ec != std::errc() || r.ptr != end || !std::isfinite(v)) return std::errc::invalid_argument;
  return {};
}

// The same, throwing Error for a token that is not a number; `where` ends the message ("in the path data").
inline double svg_number_value(std::string_view number, const std::string& where) {
  double v = 0;
  const std::errc e = svg_number_parse(number, v);
  if (e == std::errc::result_out_of_range)
    throw Error("the number '" + std::string(number) + "' " + where + " is out of range");
  if (e != std::errc()) throw Error("malformed number '" + std::string(number) + "' " + where);
  return v;
}

}  // namespace selfsim::io
