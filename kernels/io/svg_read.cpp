// Reading SVG path data back (selfsim diff / info): the absolute M/L/Z path data that write_svg produces, one
// polyline cell per subpath, from every <path d="..."> element.
//
// The file is streamed in 64 KiB chunks (a regular file only, read up to its size when opened: see
// regular_file.h), so memory grows with the points read, never with the file's text, and a FIFO or
// /dev/zero is refused at once. A small tokenizer checks as it goes that the XML is well formed, that the
// root is <svg> and that the file is complete: a file cut short is an error, never a dataset with fewer
// points. Path data must be absolute M and L commands with an even number of finite numbers per subpath;
// anything else (relative or curved commands, NaN, infinity, overflow) is an error rather than a guess.
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <vector>

#include "kernels/geom/error.h"
#include "kernels/io/dataset_check.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/regular_file.h"
#include "kernels/io/xml_text.h"

namespace selfsim::io {

namespace {

constexpr std::size_t max_name = 256, max_depth = 256, max_number = 64;

bool space(char c) { return xml_space(c); }
bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == ':' ||
         c == '-' || c == '.' || static_cast<unsigned char>(c) >= 0x80;
}
std::string local(const std::string& name) {
  const std::size_t colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

// The numbers of one d="..." attribute, parsed as they stream past.
class PathData {
 public:
  explicit PathData(Dataset& d) : d_(d) {}

  void start() {
    number_.clear();
    open_ = pending_ = false;
    points_in_subpath_ = 0;
  }

  void put(char c) {
    const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
    if (!word_.empty()) {  // "nan", "inf", "infinity": names of numbers, never commands
      if (letter && word_.size() < 16) return word_.push_back(c);
      end_word();
    }
    if (c == 'n' || c == 'N' || c == 'i' || c == 'I') {
      if (number_ == "-" || number_ == "+") number_.clear();
      end_number();
      word_.assign(1, c);
      return;
    }
    const bool sign = c == '+' || c == '-';
    const bool exponent =
        (c == 'e' || c == 'E') && !number_.empty() && number_.find_first_of("eE") == std::string::npos;
    if ((c >= '0' && c <= '9') || c == '.' || sign || exponent) {
      if (sign && !number_.empty() && number_.back() != 'e' && number_.back() != 'E')
        end_number();  // "1-2" is 1 and -2
      if (number_.size() >= max_number)
        throw Error("a number in the path data is longer than " + std::to_string(max_number) + " characters");
      number_ += c;
      return;
    }
    end_number();
    if (space(c) || c == ',') return;
    if (c == 'M') {
      end_subpath();
      open_ = true;
    } else if (c == 'L') {
      if (!open_) throw Error("the path data does not start with M");
    } else if (c == 'Z' || c == 'z') {  // closes the subpath: back to its first point
      if (!open_) throw Error("the path data does not start with M");
      if (pending_) throw Error("the path data has an odd number of coordinates in a subpath");
      if (points_in_subpath_ == 0) throw Error("the path data closes a subpath without coordinates");
      d_.cell_points.push_back(d_.points.size());
      d_.points.push_back(d_.points[subpath_first_]);
      ++points_in_subpath_;
      end_subpath();
    } else if (letter) {
      throw Error(std::string("unsupported path command '") + c + "' (only absolute M, L and Z are read)");
    } else {
      throw Error("unexpected character '" + one_line(std::string(1, c)) + "' in the path data");
    }
  }

  void finish() {
    if (!word_.empty()) end_word();
    end_number();
    end_subpath();
  }

 private:
  void end_word() {
    std::string w = word_;
    word_.clear();
    for (char& ch : w) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    if (w == "nan" || w == "inf" || w == "infinity")
      throw Error("the path data holds a non-finite number ('" + w + "')");
    if (w.size() == 1) throw Error("unsupported path command '" + w + "' (only absolute M, L and Z are read)");
    throw Error("unexpected text '" + one_line(w) + "' in the path data");
  }

  void end_number() {
    if (number_.empty()) return;
    const char* begin = number_.data() + (number_[0] == '+' ? 1 : 0);
    const char* end = number_.data() + number_.size();
    double v = 0;
    const auto r = std::from_chars(begin, end, v);
    if (r.ec == std::errc::result_out_of_range)
      throw Error("the number '" + number_ + "' in the path data is out of range");
    if (r.ec != std::errc() || r.ptr != end) throw Error("malformed number '" + number_ + "' in the path data");
    if (!std::isfinite(v)) throw Error("the path data holds a non-finite number");
    if (!open_) throw Error("the path data does not start with M");
    number_.clear();
    if (!pending_) {
      x_ = v;
      pending_ = true;
      return;
    }
    pending_ = false;
    if (d_.points.size() >= read_budget_bytes() / 40)
      throw Error("the path data holds more points than the reading limit");
    if (points_in_subpath_ == 0) subpath_first_ = d_.points.size();
    d_.cell_points.push_back(d_.points.size());
    d_.points.push_back({x_, v, 0});
    ++points_in_subpath_;
  }

  void end_subpath() {
    if (!open_) return;
    if (pending_) throw Error("the path data has an odd number of coordinates in a subpath");
    if (points_in_subpath_ == 0) throw Error("the path data has an M command without coordinates");
    d_.cell_ends.push_back(d_.cell_points.size());
    open_ = false;
    points_in_subpath_ = 0;
  }

  Dataset& d_;
  std::string number_, word_;
  bool open_ = false, pending_ = false;  // a subpath started; an x waits for its y
  std::size_t subpath_first_ = 0;        // index of the current subpath's first point
  double x_ = 0;
  std::size_t points_in_subpath_ = 0;
};

// A streaming, checking XML tokenizer that hands path data to PathData.
class SvgParser {
 public:
  explicit SvgParser(Dataset& d) : path_(d) {}

  void feed(std::string_view chunk) {
    for (char c : chunk) {
      if (position_ < 3 && static_cast<unsigned char>(c) == static_cast<unsigned char>("\xEF\xBB\xBF"[position_]) &&
          bom_ == position_) {
        ++bom_;
        ++position_;
        continue;  // a UTF-8 byte order mark
      }
      ++position_;
      byte(c);
    }
  }

  void finish() {
    if (state_ != State::text) throw Error("the file ends inside a tag or comment (truncated?)");
    if (!root_seen_) throw Error("not an SVG file (no <svg> element)");
    if (!stack_.empty()) throw Error("the file ends inside <" + shown(stack_.back()) + "> (truncated?)");
  }

 private:
  enum class State {
    text,
    markup,
    bang,
    comment_dash,
    skip,
    declaration,
    tag_name,
    in_tag,
    self_close,
    attr_name,
    after_attr_name,
    before_value,
    value,
    path_data,
    end_name,
    end_after
  };

  void fail(const char* what) { throw Error(std::string("malformed XML: ") + what); }

  void append(std::string& s, char c) {
    if (s.size() >= max_name) throw Error("an XML name is longer than " + std::to_string(max_name) + " characters");
    s += c;
  }

  void byte(char c) {
    switch (state_) {
      case State::text:
        if (c == '<')
          state_ = State::markup;
        else if (!space(c) && stack_.empty())
          throw Error(root_seen_ ? "text after </svg>" : "not an SVG file");
        return;
      case State::markup:
        if (c == '?')
          skip("?>");
        else if (c == '!')
          state_ = State::bang;
        else if (c == '/')
          name_.clear(), state_ = State::end_name;
        else if (name_char(c))
          name_.assign(1, c), state_ = State::tag_name;
        else
          fail("'<' not followed by a name");
        return;
      case State::bang:
        if (c == '-')
          state_ = State::comment_dash;
        else if (c == '[')
          skip("]]>");  // CDATA
        else
          brackets_ = 0, state_ = State::declaration;
        return;
      case State::comment_dash:
        if (c != '-') fail("'<!-' not followed by '-'");
        skip("-->");
        return;
      case State::skip:
        matched_ = advance_match(skip_end_, matched_, c);
        if (matched_ == skip_end_.size()) state_ = State::text;
        return;
      case State::declaration:  // <!DOCTYPE ...> with an optional [internal subset]
        if (c == '[')
          ++brackets_;
        else if (c == ']')
          --brackets_;
        else if (c == '>' && brackets_ <= 0)
          state_ = State::text;
        return;
      case State::tag_name:
        if (name_char(c)) return append(name_, c);
        is_path_ = local(name_) == "path";
        if (space(c))
          state_ = State::in_tag;
        else if (c == '>')
          open_element(false);
        else if (c == '/')
          state_ = State::self_close;
        else
          fail("bad character in a tag name");
        return;
      case State::in_tag:
        if (space(c)) return;
        if (c == '>')
          open_element(false);
        else if (c == '/')
          state_ = State::self_close;
        else if (name_char(c))
          attr_.assign(1, c), state_ = State::attr_name;
        else
          fail("bad character in a tag");
        return;
      case State::self_close:
        if (c != '>') fail("'/' not followed by '>' in a tag");
        open_element(true);
        return;
      case State::attr_name:
        if (name_char(c)) return append(attr_, c);
        if (space(c))
          state_ = State::after_attr_name;
        else if (c == '=')
          state_ = State::before_value;
        else
          fail("bad character in an attribute name");
        return;
      case State::after_attr_name:
        if (space(c)) return;
        if (c != '=') fail("an attribute without a value");
        state_ = State::before_value;
        return;
      case State::before_value:
        if (space(c)) return;
        if (c != '"' && c != '\'') fail("an attribute value without quotes");
        quote_ = c;
        if (is_path_ && attr_ == "d") {
          path_.start();
          state_ = State::path_data;
        } else {
          state_ = State::value;
        }
        return;
      case State::value:
        if (c == quote_)
          state_ = State::in_tag;
        else if (c == '<')
          fail("'<' in an attribute value");
        return;
      case State::path_data:
        if (c == quote_) {
          path_.finish();
          state_ = State::in_tag;
        } else {
          path_.put(c);
        }
        return;
      case State::end_name:
        if (name_char(c)) return append(name_, c);
        if (space(c))
          state_ = State::end_after;
        else if (c == '>')
          close_element();
        else
          fail("bad character in an end tag");
        return;
      case State::end_after:
        if (space(c)) return;
        if (c != '>') fail("bad character in an end tag");
        close_element();
        return;
    }
  }

  void skip(std::string_view end) {
    skip_end_ = end;
    matched_ = 0;
    state_ = State::skip;
  }

  void open_element(bool self_closing) {
    state_ = State::text;
    if (!root_seen_) {
      if (local(name_) != "svg") throw Error("not an SVG file (the root element is <" + shown(name_) + ">)");
      root_seen_ = true;
    } else if (stack_.empty()) {
      throw Error("an element after </svg>");
    }
    if (self_closing) return;
    if (stack_.size() >= max_depth)
      throw Error("the XML is nested deeper than " + std::to_string(max_depth) + " levels");
    stack_.push_back(name_);
  }

  void close_element() {
    state_ = State::text;
    if (stack_.empty() || stack_.back() != name_)
      throw Error("malformed XML: </" + shown(name_) + "> closes " +
                  (stack_.empty() ? std::string("nothing") : "<" + shown(stack_.back()) + ">"));
    stack_.pop_back();
  }

  PathData path_;
  State state_ = State::text;
  std::string name_, attr_;
  std::vector<std::string> stack_;
  bool root_seen_ = false, is_path_ = false;
  char quote_ = '"';
  std::string_view skip_end_;
  std::size_t matched_ = 0;
  int brackets_ = 0;
  std::uint64_t position_ = 0, bom_ = 0;
};

}  // namespace

Dataset read_svg(const std::filesystem::path& file) {
  try {
    const RegularFile f(file);
    ChunkReader reader(f, std::size_t{1} << 16);
    Dataset d;
    SvgParser parser(d);
    for (std::string_view chunk = reader.next(); !chunk.empty(); chunk = reader.next()) parser.feed(chunk);
    parser.finish();
    check_dataset(d);
    return d;
  } catch (const std::bad_alloc&) {
    throw Error(cannot_read(file, "out of memory"));
  } catch (const std::exception& e) {
    throw Error(cannot_read(file, e.what()));
  }
}

}  // namespace selfsim::io
