// A streaming reader of an XML file's tags, for checking a file before a third-party parser reads it
// (vtk_header_check.cpp). Memory stays small whatever the file: a tag may be at most 64 KiB, character data
// is only measured, comments and processing instructions are skipped, and DOCTYPE declarations (entity
// expansion) and CDATA sections are refused. Throws Error with the reason.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kernels/io/regular_file.h"

namespace selfsim::io {

struct XmlTag {
  std::string name;                                             // without the '/' of an end tag
  std::vector<std::pair<std::string, std::string>> attributes;  // as written, entities not expanded
  bool end = false;                                             // </name>
  bool self_closing = false;                                    // <name/>

  const std::string* find(std::string_view key) const;
};

// Non-blank character data before a tag: positions of its first and one past its last non-blank byte.
struct XmlText {
  std::uint64_t begin = 0, end = 0, chars = 0;  // chars: non-blank bytes
};

class XmlTagReader {
 public:
  explicit XmlTagReader(const RegularFile& file);  // skips a UTF-8 byte order mark

  // Character data up to the next '<'; false when the file ends first.
  bool text(XmlText& text);
  // The markup after that '<': true with a tag, false for a comment or processing instruction (skipped).
  bool tag(XmlTag& tag);
  // The next byte (-1 at the end), and the file position of the byte get() returns next: for reading on
  // after a tag, past the XML.
  int get();
  std::uint64_t position() const { return chunk_position_ + at_; }

 private:
  void skip_past(std::string_view end, const char* what);
  void parse(const std::string& raw, XmlTag& tag) const;

  ChunkReader reader_;
  std::string_view chunk_;
  std::size_t at_ = 0;
  std::uint64_t chunk_position_ = 0;
};

}  // namespace selfsim::io
