#include "kernels/io/vtk/vtk_header_check.h"

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/io/dataset/dataset.h"
#include "kernels/io/read_error.h"
#include "kernels/io/text/xml_tags.h"
#include "kernels/io/text/xml_text.h"
#include "kernels/io/vtk/vtk_binary_data.h"

namespace selfsim::io {

namespace {

constexpr std::uint64_t max_count = std::uint64_t{1} << 40;  // any NumberOf*: as --max-points' highest value
constexpr std::uint64_t max_components = 4096;
constexpr std::size_t max_depth = 64;
constexpr std::size_t max_arrays = 100000;

bool space(int c) { return xml_space(c); }

// A plain non-negative decimal ("26", not "-5", "1e15", "0x10" or "+3"); surrounding blanks allowed.
bool plain_count(std::string_view s, std::uint64_t max, std::uint64_t& out) {
  while (!s.empty() && space(s.front())) s.remove_prefix(1);
  while (!s.empty() && space(s.back())) s.remove_suffix(1);
  if (s.empty() || s.size() > 18) return false;
  std::uint64_t v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + static_cast<std::uint64_t>(c - '0');
  }
  out = v;
  return v <= max;
}

// An attribute already checked as a plain count by start_tag, or the fallback when absent.
std::uint64_t count_of(const XmlTag& t, std::string_view key, std::uint64_t fallback) {
  std::uint64_t n = fallback;
  if (const std::string* v = t.find(key); v && !plain_count(*v, max_count, n))
    throw Error("bad attribute " + std::string(key));
  return n;
}

// Bytes in a type's values; 0 for String (variable length), 1 for Bit (counted as bits below).
int type_bytes(const std::string& type) {
  static const std::pair<const char*, int> known[] = {
      {"Int8", 1},    {"UInt8", 1}, {"Char", 1},   {"Int16", 2},   {"UInt16", 2}, {"Int32", 4}, {"UInt32", 4},
      {"Float32", 4}, {"Int64", 8}, {"UInt64", 8}, {"Float64", 8}, {"IdType", 8}, {"Bit", 1},   {"String", 0}};
  for (const auto& [name, bytes] : known)
    if (type == name) return bytes;
  return -1;
}

struct Array {
  std::string label;  // "array 'Points' in <Points>"
  std::string type;
  std::uint64_t components = 1;
  bool tuples_known = false;
  std::uint64_t tuples = 0;
  enum Format { ascii, binary, appended } format = ascii;
  std::uint64_t offset = 0;
  std::uint64_t text_begin = 0, text_end = 0, text_chars = 0;  // inline data: first, one past last non-blank, count
  bool counted_by_piece = false;  // points and cell offsets: in the budget through the piece's counts
};

class Checker {
 public:
  Checker(const RegularFile& f, std::string dataset) : file_(f), xml_(f), dataset_(std::move(dataset)) {}

  VtkDeclared run() {
    XmlTag tag;
    XmlText text;
    for (;;) {
      const bool more = xml_.text(text);
      if (text.chars > 0) on_text(text);
      if (!more) break;
      if (!xml_.tag(tag)) continue;  // a comment
      if (tag.end)
        end_tag(tag.name);
      else if (start_tag(tag))
        break;  // <AppendedData>: the rest is binary
    }
    if (!appended_found_) {
      if (!root_seen_) throw Error("not a VTK XML file (no <VTKFile> element)");
      if (!stack_.empty()) throw Error("the file ends inside <" + shown(stack_.back().name) + "> (truncated?)");
      for (const Array& a : arrays_)
        if (a.format == Array::appended) throw Error(a.label + " is appended, but the file has no <AppendedData>");
    } else {
      check_tail();
      for (const Array& a : arrays_)
        if (a.format == Array::appended) check_array(a);
    }
    return declared_;
  }

 private:
  struct Open {
    std::string name;
    int array = -1;  // index in arrays_ for an inline DataArray
  };

  void on_text(const XmlText& t) {
    if (stack_.empty()) throw Error(root_seen_ ? "text after </VTKFile>" : "not a VTK XML file");
    if (stack_.back().array < 0) return;
    Array& a = arrays_[static_cast<std::size_t>(stack_.back().array)];
    if (a.text_chars == 0) a.text_begin = t.begin;
    a.text_end = t.end;
    a.text_chars += t.chars;
  }

  bool start_tag(const XmlTag& t) {
    if (root_closed_) throw Error("an element after </VTKFile>");
    // Every NumberOf* attribute, on any element, is a plain count within limits.
    for (const auto& [key, value] : t.attributes) {
      if (key.rfind("NumberOf", 0) != 0) continue;
      const bool components = key == "NumberOfComponents";
      std::uint64_t n = 0;
      if (!plain_count(value, components ? max_components : max_count, n) || (components && n == 0))
        throw Error("attribute " + key + "=\"" + shown(value) + "\" of <" + shown(t.name) +
                    "> must be a whole number in [" +
                    (components ? "1, " + std::to_string(max_components) : "0, " + std::to_string(max_count)) + "]");
    }
    if (stack_.empty()) root(t);
    const std::string parent = stack_.empty() ? std::string() : stack_.back().name;
    if (t.name == "AppendedData") {
      appended(t, parent);
      return true;
    }
    Open open{t.name, -1};
    if (t.name == "Piece") piece(t);
    if (t.name == "DataArray" || t.name == "Array") {
      const int index = array(t, parent);
      if (arrays_[static_cast<std::size_t>(index)].format != Array::appended) {  // appended ones: at the end
        if (t.self_closing)
          check_array(arrays_[static_cast<std::size_t>(index)]);
        else
          open.array = index;
      }
    }
    if (!t.self_closing) {
      if (stack_.size() >= max_depth)
        throw Error("the XML is nested deeper than " + std::to_string(max_depth) + " levels");
      stack_.push_back(open);
    } else if (stack_.empty()) {
      root_closed_ = true;
    }
    return false;
  }

  void end_tag(const std::string& name) {
    if (stack_.empty() || stack_.back().name != name)
      throw Error("malformed XML: </" + shown(name) + "> closes " +
                  (stack_.empty() ? std::string("nothing") : "<" + stack_.back().name + ">"));
    if (stack_.back().array >= 0) check_array(arrays_[static_cast<std::size_t>(stack_.back().array)]);
    stack_.pop_back();
    if (stack_.empty()) root_closed_ = true;
  }

  void root(const XmlTag& t) {
    if (t.name != "VTKFile") throw Error("not a VTK XML file (the root element is <" + shown(t.name) + ">)");
    root_seen_ = true;
    const std::string* type = t.find("type");
    if (!type || *type != dataset_)
      throw Error("not a VTK " + dataset_ + " file (type \"" + (type ? shown(*type) : std::string()) + "\")");
    if (const std::string* v = t.find("version")) {
      const std::size_t dot = v->find('.');
      std::uint64_t major = 0, minor = 0;
      if (!plain_count(v->substr(0, dot), 99, major) ||
          (dot != std::string::npos && !plain_count(v->substr(dot + 1), 99, minor)))
        throw Error("unsupported VTK file version \"" + shown(*v) + "\"");
    }
    if (const std::string* v = t.find("byte_order")) {
      if (*v != "LittleEndian" && *v != "BigEndian") throw Error("unknown byte_order \"" + shown(*v) + "\"");
      layout_.big_endian = *v == "BigEndian";
    }
    if (const std::string* v = t.find("header_type")) {
      if (*v != "UInt32" && *v != "UInt64")
        throw Error("unknown header_type \"" + shown(*v) + "\" (expected UInt32 or UInt64)");
      layout_.word_bytes = *v == "UInt64" ? 8 : 4;
    }
    if (const std::string* v = t.find("compressor"); v && !v->empty()) {
      if (*v == "vtkZLibDataCompressor")
        layout_.compressor = VtkCompressor::zlib;
      else if (*v == "vtkLZ4DataCompressor")
        layout_.compressor = VtkCompressor::lz4;
      else if (*v == "vtkLZMADataCompressor")
        layout_.compressor = VtkCompressor::lzma;
      else
        throw Error("unknown compressor \"" + shown(*v) + "\"");
    }
  }

  void add_bytes(std::uint64_t values, std::uint64_t bytes_each) {
    if (values > read_budget_bytes() / bytes_each || (declared_.bytes += values * bytes_each) > read_budget_bytes())
      throw Error("the file declares more data than the reading limit of " + std::to_string(read_budget_bytes() >> 30) +
                  " GiB");
  }

  void piece(const XmlTag& t) {
    points_ = count_of(t, "NumberOfPoints", 0);
    cells_[0] = count_of(t, "NumberOfVerts", 0);
    cells_[1] = count_of(t, "NumberOfLines", 0);
    cells_[2] = count_of(t, "NumberOfStrips", 0);
    cells_[3] = count_of(t, "NumberOfPolys", 0);
    cells_[4] = count_of(t, "NumberOfCells", 0);
    const std::uint64_t cells = cells_[0] + cells_[1] + cells_[2] + cells_[3] + cells_[4];
    declared_.points += points_;
    declared_.cells += cells;
    add_bytes(points_, 24);  // the coordinates
    add_bytes(cells, 8);     // where each cell ends
  }

  int array(const XmlTag& t, const std::string& parent) {
    if (arrays_.size() >= max_arrays) throw Error("the file has more than " + std::to_string(max_arrays) + " arrays");
    Array a;
    const std::string* name = t.find("Name");
    a.label = "array '" + (name ? shown(*name) : std::string()) + "' in <" + shown(parent) + ">";
    const std::string* type = t.find("type");
    if (!type) throw Error(a.label + " has no type");
    if (type_bytes(*type) < 0) throw Error(a.label + " has an unsupported type \"" + shown(*type) + "\"");
    a.type = *type;
    a.components = count_of(t, "NumberOfComponents", 1);
    const std::uint64_t cells = cells_[0] + cells_[1] + cells_[2] + cells_[3] + cells_[4];
    // PolyData's four cell kinds, and an unstructured grid's <Cells>, which also has a `types` array.
    static const char* const cell_kinds[] = {"Verts", "Lines", "Strips", "Polys", "Cells"};
    a.tuples_known = true;
    a.counted_by_piece = parent == "Points" || (name && *name == "offsets");
    if (parent == "Points" || parent == "PointData")
      a.tuples = points_;
    else if (parent == "CellData")
      a.tuples = cells;
    else if (std::find(std::begin(cell_kinds), std::end(cell_kinds), parent) != std::end(cell_kinds) && name &&
             (*name == "offsets" || (parent == "Cells" && *name == "types")))
      a.tuples = cells_[std::find(std::begin(cell_kinds), std::end(cell_kinds), parent) - std::begin(cell_kinds)];
    else if (t.find("NumberOfTuples"))
      a.tuples = count_of(t, "NumberOfTuples", 0);
    else
      a.tuples_known = false;  // connectivity: its length comes from the data
    const std::string* format = t.find("format");
    if (!format || *format == "ascii")
      a.format = Array::ascii;
    else if (*format == "binary")
      a.format = Array::binary;
    else if (*format == "appended")
      a.format = Array::appended;
    else
      throw Error(a.label + " has an unknown format \"" + shown(*format) + "\"");
    if (a.format == Array::appended) {
      const std::string* offset = t.find("offset");
      if (!offset || !plain_count(*offset, file_.size(), a.offset))
        throw Error(a.label + " needs an offset within the file, got \"" + (offset ? shown(*offset) : std::string()) +
                    "\"");
    }
    arrays_.push_back(a);
    return static_cast<int>(arrays_.size() - 1);
  }

  void appended(const XmlTag& t, const std::string& parent) {
    if (parent != "VTKFile") throw Error("<AppendedData> must be inside <VTKFile>, not inside <" + shown(parent) + ">");
    if (t.self_closing) throw Error("<AppendedData/> holds no data");
    const std::string* encoding = t.find("encoding");
    if (encoding && *encoding != "raw" && *encoding != "base64")
      throw Error("unknown AppendedData encoding \"" + shown(*encoding) + "\"");
    appended_base64_ = encoding && *encoding == "base64";
    int c = xml_.get();
    while (space(c)) c = xml_.get();
    if (c != '_')
      throw Error(c < 0 ? "the file ends at <AppendedData> (truncated?)" : "the appended data does not start with '_'");
    appended_begin_ = xml_.position();
    appended_found_ = true;
  }

  // An appended file ends with </AppendedData> and </VTKFile>; their absence means it was cut short.
  void check_tail() {
    std::string buffer(
        static_cast<std::size_t>(std::min<std::uint64_t>(std::uint64_t{1} << 16, file_.size() - appended_begin_)),
        '\0');
    const std::uint64_t start = file_.size() - buffer.size();
    std::string_view tail(buffer.data(), file_.read_at(start, buffer.data(), buffer.size()));
    auto strip = [&](std::string_view end) {
      while (!tail.empty() && space(tail.back())) tail.remove_suffix(1);
      if (tail.size() < end.size() || tail.substr(tail.size() - end.size()) != end) return false;
      tail.remove_suffix(end.size());
      return true;
    };
    if (!strip("</VTKFile>") || !strip("</AppendedData>"))
      throw Error("the file does not end with </AppendedData></VTKFile> (truncated?)");
    appended_end_ = start + tail.size();
  }

  void check_array(const Array& a) {
    const int size = type_bytes(a.type);
    const std::uint64_t values = a.tuples * a.components;  // both bounded: no overflow
    std::uint64_t count = values;                          // values the read dataset will hold
    try {
      if (a.format == Array::ascii) {
        if (a.tuples_known && size > 0 && values > a.text_chars)
          throw Error("it declares " + std::to_string(values) + " values, but its ascii data has only " +
                      std::to_string(a.text_chars) + " characters");
        if (!a.tuples_known) count = a.text_chars;
      } else {
        VtkBinaryLayout l = layout_;
        if (a.format == Array::binary) {
          if (a.text_chars == 0) {
            if (values > 0) throw Error("it has no data");
            return;
          }
          l.base64 = true;
          l.begin = a.text_begin;
          l.end = a.text_end;
        } else {
          l.base64 = appended_base64_;
          l.begin = appended_begin_ + a.offset;
          l.end = appended_end_;
        }
        const std::uint64_t need = !a.tuples_known   ? 0
                                   : a.type == "Bit" ? (values + 7) / 8
                                                     : values * static_cast<std::uint64_t>(size);
        const std::uint64_t held = check_vtk_binary_data(file_, l, need, read_budget_bytes());
        if (!a.tuples_known) count = size > 0 ? held / static_cast<std::uint64_t>(size) : held;
      }
    } catch (const Error& e) {
      throw Error(a.label + ": " + e.what());
    }
    if (!a.counted_by_piece) add_bytes(count, 8);
  }

  const RegularFile& file_;
  XmlTagReader xml_;
  std::string dataset_;  // the VTKFile type expected: "PolyData" or "UnstructuredGrid"

  std::vector<Open> stack_;
  std::vector<Array> arrays_;
  bool root_seen_ = false, root_closed_ = false;
  bool appended_found_ = false, appended_base64_ = false;
  std::uint64_t appended_begin_ = 0, appended_end_ = 0;
  VtkBinaryLayout layout_;
  std::uint64_t points_ = 0, cells_[5] = {0, 0, 0, 0, 0};  // of the current piece
  VtkDeclared declared_;
};

}  // namespace

VtkDeclared check_vtk_header(const RegularFile& file, const std::string& dataset) {
  return Checker(file, dataset).run();
}

}  // namespace selfsim::io
