// Reading a provenance record back (parse_provenance). The record is only text in a file, so anyone may
// have written it: strings are read strictly, as JSON defines them, and a string that JSON would refuse
// (a bad \u escape, a lone surrogate, a raw control character, raw bytes that are not UTF-8) or that holds
// a NUL is an Error naming the field. A NUL matters most: a path holding one would be cut there when it
// reaches the system (rerun ran the recipe path cut at the NUL), and a key holding one is not the key the
// record seems to hold. Every other departure from what provenance_json writes (a number in "set", a seed
// of 1.0 or -1) is an Error too, naming the field and what was expected: "records no recipe" for a record
// that is there sent the reader looking for the wrong fault.
#include <algorithm>
#include <cstdint>
#include <map>
#include <string>

#include "kernels/base/error.h"
#include "kernels/base/utf8.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/read_error.h"
#include "kernels/io/text/hex_digit.h"

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
// one seed. Text that does not begin with '{' is no record (nullopt); once it does, the record is there,
// and anything in it other than what selfsim writes throws Error naming the field and what was expected,
// the values a run would refuse included (a seed outside [0, 2^63): rerun would pass it to --seed).
class Parser {
 public:
  explicit Parser(const std::string& text) : t_(text) {}

  std::optional<Provenance> provenance() {
    if (t_.compare(0, 3, "\xef\xbb\xbf") == 0)
      throw Error("expected '{' at the start of the record, found a UTF-8 byte order mark (bytes EF BB BF)");
    if (!eat('{')) return std::nullopt;
    Provenance p;
    std::map<std::string, bool> seen;
    std::string last;  // the field before a missing ',' or '}'
    do {
      std::string key;
      need_string(key, "a key of the record");
      const std::string field = "the field \"" + shown(key) + "\"";
      need(':', "':' after the key \"" + shown(key) + "\"");
      if (seen[key]) throw Error(field + " is given twice");
      seen[key] = true;
      if (key == "set") {
        if (!eat('{')) throw Error(field + " is " + found() + ", not an object of strings");
        if (!eat('}')) {
          do {
            std::string k, v;
            need_string(k, "a key of \"set\"");
            need(':', "':' after the \"set\" key '" + shown(k) + "'");
            need_string(v, "the \"set\" value of '" + shown(k) + "'");
            if (p.sets.count(k) != 0) throw Error("the \"set\" key '" + shown(k) + "' is given twice");
            p.sets[k] = v;
          } while (eat(','));
          need('}', "',' or '}' after the last \"set\" value");
        }
      } else if (key == "seed") {
        p.seed = seed();
      } else {
        std::string value;
        need_string(value, field);
        if (key == "selfsim")
          p.version = value;
        else if (key == "recipe")
          p.recipe = value;
        else if (key == "sha256")
          p.sha256 = value;
        else if (key == "name")
          p.name = value;
      }
      last = field;
    } while (eat(','));
    need('}', "',' or '}' after " + last);
    if (p.recipe.empty())
      throw Error(seen["recipe"] ? "the field \"recipe\" is empty" : "the record has no field \"recipe\"");
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

  // What stands at i_, for a message: the next JSON token as written, or "the end of the record".
  std::string found() {
    skip();
    if (i_ >= t_.size()) return "the end of the record";
    std::size_t end = i_ + 1;
    if (t_[i_] == '"') {
      while (end < t_.size() && t_[end] != '"') end += t_[end] == '\\' ? 2 : 1;
      end = std::min(end + 1, t_.size());
    } else if (std::string("{}[],:").find(t_[i_]) == std::string::npos) {
      while (end < t_.size() && std::string("{}[],:\" \n\r\t").find(t_[end]) == std::string::npos) ++end;
    }
    return shown(t_.substr(i_, end - i_));
  }

  // `c`, or an Error saying what was `expected` and what is there instead.
  void need(char c, const std::string& expected) {
    if (!eat(c)) throw Error("expected " + expected + ", found " + found());
  }

  void need_string(std::string& out, const std::string& field) {
    if (!string(out, field)) throw Error(field + " is " + found() + ", not a string");
  }

  // The seed: digits alone (JSON's grammar, no sign, fraction or exponent), below 2^63, as --seed takes it.
  long long seed() {
    skip();
    const std::size_t start = i_;
    std::size_t end = i_;
    while (end < t_.size() && t_[end] >= '0' && t_[end] <= '9') ++end;
    const std::string refused =
        "the field \"seed\" holds " + found() + ", not a whole number in [0, 2^63) (what --seed takes)";
    if (end == start || (end < t_.size() && std::string(",} \n\r\t").find(t_[end]) == std::string::npos))
      throw Error(refused);
    unsigned long long magnitude = 0;
    for (std::size_t k = start; k < end; ++k) {
      const unsigned d = static_cast<unsigned>(t_[k] - '0');
      if (magnitude > (9223372036854775807ull - d) / 10) throw Error(refused + ": it is 2^63 or more");
      magnitude = magnitude * 10 + d;
    }
    i_ = end;
    return static_cast<long long>(magnitude);
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
      if (c >= 0x80) {  // raw, it must be UTF-8: selfsim writes a byte of text that is not as \u0080-\u00ff
        const std::size_t n = utf8_length(t_, i_);
        if (n == 0)
          throw Error(field + " holds a byte that is not UTF-8 (0x" + hex4(c).substr(2) +
                      "); a record is UTF-8 and writes such a byte as an escape, \\u00" + hex4(c).substr(2));
        out.append(t_, i_, n);
        i_ += n - 1;
        continue;
      }
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
