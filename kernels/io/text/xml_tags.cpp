#include "kernels/io/text/xml_tags.h"

#include "kernels/base/error.h"
#include "kernels/io/read_error.h"
#include "kernels/io/text/xml_text.h"

namespace selfsim::io {

namespace {

constexpr std::size_t max_tag_bytes = std::size_t{1} << 16;

}  // namespace

const std::string* XmlTag::find(std::string_view key) const {
  for (const auto& [k, v] : attributes)
    if (k == key) return &v;
  return nullptr;
}

XmlTagReader::XmlTagReader(const RegularFile& file) : reader_(file) {
  chunk_ = reader_.next();
  if (chunk_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;
}

int XmlTagReader::get() {
  if (at_ >= chunk_.size()) {
    chunk_position_ += chunk_.size();
    chunk_ = reader_.next();
    at_ = 0;
    if (chunk_.empty()) return -1;
  }
  return static_cast<unsigned char>(chunk_[at_++]);
}

void XmlTagReader::skip_past(std::string_view end, const char* what) {
  std::size_t matched = 0;
  // Bounded like tags: VTK's parser takes time quadratic in a comment's length (20 MB: over 30 s).
  for (std::size_t skipped = 0;; ++skipped) {
    if (skipped > max_tag_bytes) throw Error(std::string(what) + " is longer than 64 KiB");
    const int c = get();
    if (c < 0) throw Error(std::string("the file ends inside ") + what + " (truncated?)");
    matched = advance_match(end, matched, static_cast<char>(c));
    if (matched == end.size()) return;
  }
}

bool XmlTagReader::text(XmlText& text) {
  text = {};
  for (;;) {
    const int c = get();
    if (c < 0) return false;
    if (c == '<') return true;
    if (!xml_space(c)) {
      if (text.chars++ == 0) text.begin = position() - 1;
      text.end = position();
    }
  }
}

bool XmlTagReader::tag(XmlTag& tag) {
  int c = get();
  if (c == '?') {
    skip_past("?>", "a processing instruction");
    return false;
  }
  if (c == '!') {
    if (get() != '-' || get() != '-') throw Error("DOCTYPE declarations and CDATA sections are not supported");
    skip_past("-->", "a comment");
    return false;
  }
  std::string raw;
  char quote = 0;
  for (;;) {
    if (c < 0) throw Error("the file ends inside a tag (truncated?)");
    if (quote) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = static_cast<char>(c);
    } else if (c == '>') {
      break;
    } else if (c == '<') {
      throw Error("malformed XML: '<' inside a tag");
    }
    raw += static_cast<char>(c);
    if (raw.size() > max_tag_bytes) throw Error("an XML tag is longer than 64 KiB");
    c = get();
  }
  parse(raw, tag);
  return true;
}

void XmlTagReader::parse(const std::string& raw, XmlTag& t) const {
  t = {};
  std::size_t i = 0;
  if (!raw.empty() && raw[0] == '/') {
    t.end = true;
    ++i;
  }
  auto name_char = [](char c) { return !xml_space(c) && c != '=' && c != '/' && c != '"' && c != '\''; };
  while (i < raw.size() && name_char(raw[i])) t.name += raw[i++];
  if (t.name.empty()) throw Error("malformed XML: a tag without a name");
  for (;;) {
    while (i < raw.size() && xml_space(raw[i])) ++i;
    if (i == raw.size()) break;
    if (t.end) throw Error("malformed XML: an end tag with attributes");
    if (raw[i] == '/' && i + 1 == raw.size()) {
      t.self_closing = true;
      break;
    }
    std::string key;
    while (i < raw.size() && name_char(raw[i])) key += raw[i++];
    while (i < raw.size() && xml_space(raw[i])) ++i;
    if (key.empty() || i == raw.size() || raw[i] != '=')
      throw Error("malformed XML attribute in <" + shown(t.name) + ">");
    ++i;
    while (i < raw.size() && xml_space(raw[i])) ++i;
    if (i == raw.size() || (raw[i] != '"' && raw[i] != '\''))
      throw Error("malformed XML attribute in <" + shown(t.name) + ">");
    const char quote = raw[i++];
    const std::size_t end = raw.find(quote, i);
    if (end == std::string::npos) throw Error("malformed XML attribute in <" + shown(t.name) + ">");
    if (t.find(key)) throw Error("attribute " + shown(key) + " given twice in <" + shown(t.name) + ">");
    t.attributes.emplace_back(key, raw.substr(i, end - i));
    i = end + 1;
  }
}

}  // namespace selfsim::io
