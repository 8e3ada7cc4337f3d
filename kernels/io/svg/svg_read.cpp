// Reading SVG back (selfsim diff / info, load): one polyline cell per subpath of every drawn <path d="...">
// element, in selfsim's coordinates (y up), each path's points mapped through its own transform and its
// ancestors', each cell's colour (its path's stroke) in the cell field `color`. What is drawn, namespaces and
// coordinates: svg_element.h; path data: svg_path_data.h.
//
// The file is streamed in 64 KiB chunks (a regular file only, read up to its size when opened: see
// regular_file.h), so memory grows with the points read, never with the file's text, and a FIFO or
// /dev/zero is refused at once. A small tokenizer checks as it goes that the XML is well formed (no
// attribute twice in one tag), that the root is SVG's <svg> and that the file is complete: a file cut short
// is an error, never a dataset with fewer points. Path data streams into the dataset before the rest of its
// tag is known (transform, display or xmlns may follow d), so when the tag ends its points are transformed
// in place, or removed again if the path is not drawn. Errors in the path data of a path that is not drawn
// do not count; a malformed transform of a drawn path or of an element whose content may be drawn does. A
// transformed point that is not finite is an error.
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/io/dataset/dataset_check.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/regular_file.h"
#include "kernels/io/svg/svg_element.h"
#include "kernels/io/svg/svg_path_data.h"
#include "kernels/io/text/xml_text.h"

namespace selfsim::io {

namespace {

constexpr std::size_t max_name = 256, max_depth = 256, max_attributes = 1024;
constexpr std::size_t max_value = std::size_t{1} << 16;  // a transform, style, display, visibility or xmlns value
constexpr std::string_view svg_namespace = "http://www.w3.org/2000/svg";

bool space(char c) { return xml_space(c); }
bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == ':' ||
         c == '-' || c == '.' || static_cast<unsigned char>(c) >= 0x80;
}
std::string local(const std::string& name) {
  const std::size_t colon = name.rfind(':');
  return colon == std::string::npos ? name : name.substr(colon + 1);
}

bool xmlns_attribute(const std::string& attribute) {
  return attribute == "xmlns" || (attribute.size() > 6 && attribute.compare(0, 6, "xmlns:") == 0);
}

// A streaming, checking XML tokenizer that hands path data to PathData and each complete start tag to
// SvgScopes.
class SvgParser {
 public:
  explicit SvgParser(Dataset& d) : d_(d), path_(d) {}
  // The <image> elements met: pictures that a browser draws (a sweep's contact sheet is made of them).
  std::size_t images() const { return images_; }
  // Each cell's colour (red, green, blue in [0, 1], cell after cell): its path's stroke (svg_element.h).
  std::vector<double>& colours() { return colours_; }

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
          begin_tag(c);
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
          begin_attribute();
        else
          fail("bad character in an attribute name");
        return;
      case State::after_attr_name:
        if (space(c)) return;
        if (c != '=') fail("an attribute without a value");
        begin_attribute();
        return;
      case State::before_value:
        if (space(c)) return;
        if (c != '"' && c != '\'') fail("an attribute value without quotes");
        quote_ = c;
        begin_value();
        return;
      case State::value:
        if (c == quote_) return end_value();
        if (c == '<') fail("'<' in an attribute value");
        if (!slot_ && !xmlns_) return;  // a value that does not matter for drawing is not kept
        if (value_.size() >= max_value)
          throw Error("the '" + shown(attr_) + "' attribute is longer than " + std::to_string(max_value) + " bytes");
        value_ += c;
        return;
      case State::path_data:
        if (c == '<') fail("'<' in an attribute value");
        try {
          if (c != quote_) return path_.put(c);
          state_ = State::in_tag;
          path_.finish();
        } catch (const Error& e) {  // counts only if the path is drawn (end_path)
          path_error_ = e.what();
          if (c != quote_) state_ = State::value, slot_ = nullptr, xmlns_ = false;
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

  void begin_tag(char c) {
    name_.assign(1, c);
    state_ = State::tag_name;
    tag_ = SvgTag{};
    attributes_.clear();
    path_read_ = false;
    path_error_.clear();
  }

  void begin_attribute() {
    state_ = State::before_value;
    if (attributes_.size() >= max_attributes)
      throw Error("an element has more than " + std::to_string(max_attributes) + " attributes");
    if (!attributes_.insert(attr_).second)
      throw Error("malformed XML: the attribute '" + shown(attr_) + "' appears twice in <" + shown(name_) + ">");
  }

  // Where an attribute's value goes: path data into the dataset, values that decide drawing into tag_ (only
  // where something may be drawn), the rest nowhere.
  void begin_value() {
    const bool content = scopes_.content_drawn();
    if (content && attr_ == "d" && local(name_) == "path") {
      marks_ = {d_.points.size(), d_.cell_points.size(), d_.cell_ends.size()};
      path_read_ = true;
      path_.start();
      state_ = State::path_data;
      return;
    }
    // The attribute values an element's meaning depends on are kept while its tag is read.
    slot_ = content ? tag_.slot(attr_) : nullptr;
    xmlns_ = content && xmlns_attribute(attr_);
    value_.clear();
    state_ = State::value;
  }

  void end_value() {
    state_ = State::in_tag;
    if (xmlns_) {
      // Illustrator declares namespaces through its DOCTYPE's entities (xmlns="&ns_svg;",
      // xmlns:i="&ns_ai;"), which are not expanded: such a default namespace counts as undeclared (its
      // names as SVG), such a prefix as not SVG.
      std::optional<std::string> uri;
      try {
        uri = xml_unescaped(value_, attr_);
      } catch (const Error&) {
      }
      if (uri || attr_ != "xmlns")
        tag_.namespaces.emplace_back(attr_ == "xmlns" ? "" : attr_.substr(6), uri && *uri == svg_namespace);
      xmlns_ = false;
      return;
    }
    if (slot_) *slot_ = xml_unescaped(value_, attr_);
    slot_ = nullptr;
  }

  void open_element(bool self_closing) {
    state_ = State::text;
    if (root_seen_ && stack_.empty()) throw Error("an element after </svg>");
    const SvgElement e = scopes_.open(name_, tag_);
    if (!root_seen_) {
      if (e.local != "svg") throw Error("not an SVG file (the root element is <" + shown(name_) + ">)");
      if (!e.svg) throw Error("not an SVG file (the root <" + shown(name_) + "> is not in the SVG namespace)");
      root_seen_ = true;
    }
    if (e.svg && e.local == "image") ++images_;
    if (path_read_) end_path(e);
    if (self_closing) return;
    if (stack_.size() >= max_depth)
      throw Error("the XML is nested deeper than " + std::to_string(max_depth) + " levels");
    stack_.push_back(name_);
    scopes_.push(e, tag_);
  }

  // The tag of a path whose data was read is complete: keep its points, transformed, or remove them.
  void end_path(const SvgElement& e) {
    if (!(e.svg && e.local == "path" && e.drawn && e.visible)) {
      d_.points.resize(marks_.points);
      d_.cell_points.resize(marks_.cell_points);
      d_.cell_ends.resize(marks_.cells);
      return;
    }
    if (!path_error_.empty()) throw Error(path_error_);
    for (std::size_t i = marks_.points; i < d_.points.size(); ++i) {
      const Vec2 p = e.to_selfsim.apply({d_.points[i][0], d_.points[i][1]});
      if (!is_finite(p)) throw Error("a point of a path is not finite once transformed");
      d_.points[i] = {p.x, p.y, 0};
    }
    const Rgb colour = e.colour();
    for (std::size_t i = marks_.cells; i < d_.cell_ends.size(); ++i)
      colours_.insert(colours_.end(), colour.begin(), colour.end());
  }

  void close_element() {
    state_ = State::text;
    if (stack_.empty() || stack_.back() != name_)
      throw Error("malformed XML: </" + shown(name_) + "> closes " +
                  (stack_.empty() ? std::string("nothing") : "<" + shown(stack_.back()) + ">"));
    stack_.pop_back();
    scopes_.pop();
  }

  struct Marks {
    std::size_t points = 0, cell_points = 0, cells = 0;
  };

  Dataset& d_;
  std::size_t images_ = 0;
  std::vector<double> colours_;
  PathData path_;
  SvgScopes scopes_;
  State state_ = State::text;
  std::string name_, attr_;
  std::vector<std::string> stack_;
  SvgTag tag_;                                  // the start tag being read
  std::set<std::string> attributes_;            // its attribute names so far
  std::optional<std::string>* slot_ = nullptr;  // where the value being read is kept (SvgTag::slot)
  bool xmlns_ = false;                          // the value being read declares a namespace
  std::string value_;                           // a kept attribute value so far
  bool path_read_ = false;                      // the tag has path data, from marks_ on in the dataset
  Marks marks_;
  std::string path_error_;  // what was wrong with that path data
  bool root_seen_ = false;
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
    if (d.points.empty() && parser.images() > 0)
      throw Error("a contact sheet of " + std::to_string(parser.images()) + " picture" +
                  (parser.images() == 1 ? "" : "s") +
                  " (<image> elements, as a sweep's sheets hold) and no path of its own: open it in a browser");
    // The paths' own colours, as a curve holds them (a per-path `color` of red, green and blue in [0, 1]):
    // a preview draws them, and a loaded drawing saved again keeps them.
    if (!d.cell_ends.empty() && parser.colours().size() == 3 * d.cell_ends.size())
      d.cell_fields["color"] = FieldValues{3, std::move(parser.colours())};
    check_dataset(d);
    return d;
  } catch (const std::bad_alloc&) {
    throw Error(cannot_read(file, "out of memory"));
  } catch (const std::exception& e) {
    throw Error(cannot_read(file, e.what()));
  }
}

}  // namespace selfsim::io
