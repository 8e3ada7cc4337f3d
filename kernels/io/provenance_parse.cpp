// Reading a provenance record back (parse_provenance). The record is only text in a file, so anyone may
// have written it: strings are read strictly, as JSON defines them, and a string that JSON would refuse
// (a bad \u escape, a lone surrogate, a raw control character) or that holds a NUL is an Error naming the
// field. A NUL matters most: a path holding one would be cut there when it reaches the system (rerun ran
// the recipe path cut at the NUL), and a key holding one is not the key the record seems to hold.
#include <cstdint>
#include <map>
#include <string>

#include "kernels/geom/error.h"
#include "kernels/io/hex_digit.h"
#include "kernels/io/provenance.h"
#include "kernels/io/read_error.h"

namespace selfsim::io {

namespace {

void put_utf8(std::string& out, std::uint32_t c) {
  if (c < 0x800) {
    out += static_cast<char>(0xc0 | (c >> 6));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xe0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
  } else {
    out += static_cast<char>(0xf0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3f));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3f));
  }
  out += static_cast<char>(0x80 | (c & 0x3f));
}

// A reader for exactly the JSON provenance_json writes: an object of strings, one object of strings and
// one whole number. A shape it does not know gives nullopt (not a record); a malformed string, a field given
// twice or a seed out of range throws Error naming the field.
class Parser {
 public:
  explicit Parser(const std::string& text) : t_(text) {}

  std::optional<Provenance> provenance() {
    Provenance p;
    std::map<std::string, bool> seen;
    if (!eat('{')) return std::nullopt;
    do {
      std::string key;
      if (!string(key, "a key of the record") || !eat(':')) return std::nullopt;
      if (seen[key]) throw Error("the field \"" + shown(key) + "\" is given twice");
      seen[key] = true;
      if (key == "set") {
        if (!eat('{')) return std::nullopt;
        if (!eat('}')) {
          do {
            std::string k, v;
            if (!string(k, "a key of \"set\"") || !eat(':')) return std::nullopt;
            if (!string(v, "the \"set\" value of '" + shown(k) + "'")) return std::nullopt;
            if (p.sets.count(k) != 0) throw Error("the \"set\" key '" + shown(k) + "' is given twice");
            p.sets[k] = v;
          } while (eat(','));
          if (!eat('}')) return std::nullopt;
        }
      } else if (key == "seed") {
        if (!seed(p.seed)) return std::nullopt;
      } else {
        std::string value;
        if (!string(value, "the field \"" + shown(key) + "\"")) return std::nullopt;
        if (key == "selfsim")
          p.version = value;
        else if (key == "recipe")
          p.recipe = value;
        else if (key == "sha256")
          p.sha256 = value;
        else if (key == "name")
          p.name = value;
      }
    } while (eat(','));
    if (!eat('}') || p.recipe.empty()) return std::nullopt;
    return p;
  }

 private:
  void skip() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\n' || t_[i_] == '\t' || t_[i_] == '\r')) ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < t_.size() && t_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }

  // A whole number: an optional '-' and digits, within long long (JSON's grammar, no fraction or exponent).
  bool seed(long long& out) {
    skip();
    const std::size_t start = i_;
    const bool negative = i_ < t_.size() && t_[i_] == '-';
    std::size_t end = negative ? i_ + 1 : i_;
    while (end < t_.size() && t_[end] >= '0' && t_[end] <= '9') ++end;
    if (end == start + (negative ? 1 : 0)) return false;
    const unsigned long long limit = negative ? 9223372036854775808ull : 9223372036854775807ull;
    unsigned long long magnitude = 0;
    for (i_ = negative ? start + 1 : start; i_ < end; ++i_) {
      const unsigned d = static_cast<unsigned>(t_[i_] - '0');
      if (magnitude > (limit - d) / 10)
        throw Error("the field \"seed\" holds " + shown(t_.substr(start, end - start)) +
                    ", beyond a 64-bit whole number");
      magnitude = magnitude * 10 + d;
    }
    out = negative ? static_cast<long long>(0 - magnitude) : static_cast<long long>(magnitude);
    return true;
  }

  // Four hex digits after "\u" (at i_, which is left on the last digit); throws naming `field`.
  std::uint32_t code_unit(const std::string& field) {
    std::uint32_t c = 0;
    for (int k = 1; k <= 4; ++k) {
      const std::size_t at = i_ + static_cast<std::size_t>(k);
      const int d = at < t_.size() ? hex_digit(t_[at]) : -1;
      if (d < 0)
        throw Error(field + " holds a bad escape '\\u" + shown(t_.substr(i_ + 1, 4)) + "' (\\u takes 4 hex digits)");
      c = c * 16 + static_cast<std::uint32_t>(d);
    }
    i_ += 4;
    return c;
  }

  // A JSON string into `out`; false when there is none here (not a record), an Error naming `field` when it
  // is malformed.
  bool string(std::string& out, const std::string& field) {
    if (!eat('"')) return false;
    for (; i_ < t_.size(); ++i_) {
      const auto c = static_cast<unsigned char>(t_[i_]);
      if (c == '"') {
        ++i_;
        if (out.find('\0') != std::string::npos) throw Error(field + " holds a NUL character");
        return true;
      }
      if (c < 0x20)
        throw Error(field + " holds a raw control character (byte " + std::to_string(c) +
                    "); JSON writes it as an escape");
      if (c != '\\') {
        out += static_cast<char>(c);
        continue;
      }
      if (++i_ >= t_.size()) break;
      switch (t_[i_]) {
        case '"':
          out += '"';
          break;
        case '\\':
          out += '\\';
          break;
        case '/':
          out += '/';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        case 'u':
          unicode(out, field);
          break;
        default:
          throw Error(field + " holds an unknown escape '\\" + shown(t_.substr(i_, 1)) + "'");
      }
    }
    throw Error(field + " has no closing quote");
  }

  // The character of a \u escape. json_escaped writes a byte of text that is not UTF-8 as \u0080 to \u00ff:
  // those stand for that byte, so a non-UTF-8 path reads back as it was. Above, UTF-8, from a pair for a
  // character beyond U+FFFF.
  void unicode(std::string& out, const std::string& field) {
    std::uint32_t c = code_unit(field);
    if (c < 0x100) {
      out += static_cast<char>(c);
      return;
    }
    if (c >= 0xdc00 && c <= 0xdfff) throw Error(field + " holds a lone surrogate '\\u" + hex4(c) + "'");
    if (c >= 0xd800 && c <= 0xdbff) {
      if (i_ + 2 >= t_.size() || t_[i_ + 1] != '\\' || t_[i_ + 2] != 'u')
        throw Error(field + " holds a lone surrogate '\\u" + hex4(c) + "'");
      i_ += 2;
      const std::uint32_t low = code_unit(field);
      if (low < 0xdc00 || low > 0xdfff)
        throw Error(field + " holds a lone surrogate '\\u" + hex4(c) + "' (followed by '\\u" + hex4(low) + "')");
      c = 0x10000 + ((c - 0xd800) << 10) + (low - 0xdc00);
    }
    put_utf8(out, c);
  }

  static std::string hex4(std::uint32_t c) {
    const char* digits = "0123456789abcdef";
    return {digits[(c >> 12) & 15], digits[(c >> 8) & 15], digits[(c >> 4) & 15], digits[c & 15]};
  }

  const std::string& t_;
  std::size_t i_ = 0;
};

}  // namespace

std::optional<Provenance> parse_provenance(const std::string& json) { return Parser(json).provenance(); }

}  // namespace selfsim::io
