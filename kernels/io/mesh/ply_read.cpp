// Reading PLY (ASCII and binary, either byte order) for load(), info and diff: the x, y, z properties of
// `vertex` and the vertex_indices (or vertex_index) list of `face`; every other element and property is
// read past. Coordinates keep the file's precision (double properties stay doubles). Strict: the header
// must be complete and well formed within 64 KiB, every declared count must fit the file, and every value
// must be a finite number or an index of an existing vertex.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/io/dataset/dataset.h"
#include "kernels/io/file_stream.h"
#include "kernels/io/mesh/mesh_readers.h"
#include "kernels/io/read_error.h"

namespace selfsim::io {

static_assert(std::endian::native == std::endian::little, "the byte order conversion assumes a little-endian host");

namespace {

enum class Format { ascii, little, big };

struct Type {
  int bytes = 0;
  bool real = false, is_signed = false;
};

Type type_of(std::string_view name, const std::string& at) {
  if (name == "char" || name == "int8") return {1, false, true};
  if (name == "uchar" || name == "uint8") return {1, false, false};
  if (name == "short" || name == "int16") return {2, false, true};
  if (name == "ushort" || name == "uint16") return {2, false, false};
  if (name == "int" || name == "int32") return {4, false, true};
  if (name == "uint" || name == "uint32") return {4, false, false};
  if (name == "float" || name == "float32") return {4, true, true};
  if (name == "double" || name == "float64") return {8, true, true};
  throw Error(at + ": unknown property type '" + shown(name) + "'");
}

struct Property {
  std::string name;
  Type type;
  bool list = false;
  Type count;  // of a list
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

// Values of one element instance, in property order, from a line (ASCII) or the bytes (binary).
double lowest(const Type& t) { return t.is_signed ? -std::ldexp(1.0, 8 * t.bytes - 1) : 0; }
double highest(const Type& t) { return std::ldexp(1.0, 8 * t.bytes - (t.is_signed ? 1 : 0)) - 1; }

// The fewest bytes an instance of e can take: binary, its scalars and list counts; ASCII, a character and
// a separator per value.
std::uint64_t min_bytes(const Element& e, Format format) {
  std::uint64_t n = 0;
  for (const Property& p : e.properties)
    n += format == Format::ascii ? 2 : static_cast<std::uint64_t>(p.list ? p.count.bytes : p.type.bytes);
  return n;
}

class ValueReader {
 public:
  ValueReader(FileStream& in, Format format) : in_(in), format_(format) {}

  // Starts an instance (ASCII: reads its line).
  void begin(const std::string& element) {
    if (format_ != Format::ascii) return;
    std::string_view line;
    do {
      if (!in_.line(line)) throw Error("the file ends inside the " + element + " data (truncated?)");
      words_ = words(line);
    } while (words_.empty());
    next_ = 0;
  }
  // `what` names the value in an error, built only then: `what()` returns it.
  template <class What>
  double value(const Type& t, What what) {
    if (format_ == Format::ascii) {
      if (next_ >= words_.size()) throw Error("line " + std::to_string(in_.line_number()) + ": too few values");
      auto at = [&] { return "line " + std::to_string(in_.line_number()) + ": " + what(); };
      double v = 0;
      try {
        v = number_word(words_[next_++], "");  // the message is built only for an error
      } catch (const Error& e) {
        throw Error(at() + e.what());
      }
      if (!t.real && (v != std::floor(v) || v < lowest(t) || v > highest(t)))
        throw Error(at() + " must be a whole number in [" + number_text(lowest(t)) + ", " + number_text(highest(t)) +
                    "]");
      return v;
    }
    unsigned char b[8];
    in_.bytes(b, static_cast<std::size_t>(t.bytes));
    if (format_ == Format::big) std::reverse(b, b + t.bytes);
    std::uint64_t u = 0;
    std::memcpy(&u, b, static_cast<std::size_t>(t.bytes));  // little-endian machine
    double v = 0;
    if (t.real)
      v = t.bytes == 4 ? std::bit_cast<float>(static_cast<std::uint32_t>(u)) : std::bit_cast<double>(u);
    else if (t.is_signed)
      v = static_cast<double>(static_cast<std::int64_t>(u << (64 - 8 * t.bytes)) >> (64 - 8 * t.bytes));
    else
      v = static_cast<double>(u);
    if (!std::isfinite(v)) throw Error(what() + " must be a finite number");
    return v;
  }
  void end() {
    if (format_ == Format::ascii && next_ != words_.size())
      throw Error("line " + std::to_string(in_.line_number()) + ": more values than the header declares");
  }
  // After the last element: nothing but blank lines may follow.
  void finish() {
    if (format_ == Format::ascii) {
      std::string_view line;
      while (in_.line(line))
        if (!words(line).empty())
          throw Error("line " + std::to_string(in_.line_number()) + ": data after the last element");
    } else if (!in_.at_end()) {
      throw Error("data after the last element");
    }
  }

 private:
  FileStream& in_;
  Format format_;
  std::vector<std::string_view> words_;
  std::size_t next_ = 0;
};

}  // namespace

Dataset read_ply(const RegularFile& f) {
  FileStream in(f);
  std::string_view line;
  if (!in.line(line) || line != "ply") throw Error("not a PLY file (no 'ply' on the first line)");
  Format format = Format::ascii;
  bool has_format = false;
  std::vector<Element> elements;
  std::uint64_t header_bytes = 4;
  for (;;) {
    if (!in.line(line)) throw Error("the header has no 'end_header'");
    header_bytes += line.size() + 1;
    if (header_bytes > (1u << 16)) throw Error("the header is longer than 64 KiB");
    const std::string at = "line " + std::to_string(in.line_number());
    const auto w = words(line);
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
    if (w[0] == "end_header") break;
    if (w[0] == "format") {
      if (w.size() != 3 || w[2] != "1.0") throw Error(at + ": expected 'format <kind> 1.0'");
      if (has_format) throw Error(at + ": a second 'format' line");
      if (w[1] == "ascii")
        format = Format::ascii;
      else if (w[1] == "binary_little_endian")
        format = Format::little;
      else if (w[1] == "binary_big_endian")
        format = Format::big;
      else
        throw Error(at + ": unknown format '" + shown(w[1]) + "'");
      has_format = true;
    } else if (w[0] == "element") {
      if (w.size() != 3) throw Error(at + ": expected 'element <name> <count>'");
      // Every element takes at least a byte: a count past the file's size is a lie.
      const auto count = integer_word(w[2], 0, static_cast<long long>(f.size()), at + ": element count");
      elements.push_back({std::string(w[1]), static_cast<std::uint64_t>(count), {}});
    } else if (w[0] == "property") {
      if (elements.empty()) throw Error(at + ": a property before any element");
      Property p;
      if (w.size() == 5 && w[1] == "list")
        p = {std::string(w[4]), type_of(w[3], at), true, type_of(w[2], at)};
      else if (w.size() == 3)
        p = {std::string(w[2]), type_of(w[1], at), false, {}};
      else
        throw Error(at + ": expected 'property <type> <name>' or 'property list <type> <type> <name>'");
      if (p.list && p.count.real) throw Error(at + ": a list count must be an integer type");
      for (const Property& q : elements.back().properties)
        if (q.name == p.name) throw Error(at + ": a second property '" + shown(p.name) + "'");
      elements.back().properties.push_back(p);
    } else {
      throw Error(at + ": unknown header line '" + shown(w[0]) + "'");
    }
  }
  if (!has_format) throw Error("the header has no 'format' line");
  // What the header declares must fit the rest of the file, so no file makes us allocate or loop for
  // more than it holds; and the vertices must say where they are.
  double need = 0;
  for (const Element& e : elements) {
    if (e.properties.empty() && e.count > 0) throw Error("element '" + shown(e.name) + "' has no properties");
    need += static_cast<double>(e.count) * static_cast<double>(min_bytes(e, format));
    if (e.name == "vertex")
      for (const char* axis : {"x", "y", "z"})
        if (std::none_of(e.properties.begin(), e.properties.end(),
                         [&](const Property& p) { return p.name == axis && !p.list; }))
          throw Error(std::string("the vertex element has no '") + axis + "' property");
  }
  const std::uint64_t data = f.size() - std::min<std::uint64_t>(f.size(), header_bytes);
  if (need > static_cast<double>(data))
    throw Error("the header declares at least " + number_text(need) + " bytes of data, but the file holds " +
                std::to_string(data));

  Dataset d;
  d.shapes = CellShapes::polygons;
  ValueReader values(in, format);
  for (const Element& e : elements) {
    const bool vertex = e.name == "vertex", face = e.name == "face";
    if (vertex) d.points.reserve(static_cast<std::size_t>(e.count));
    for (std::uint64_t i = 0; i < e.count; ++i) {
      values.begin(e.name);
      std::array<double, 3> p{};
      for (const Property& prop : e.properties) {
        const auto what = [&] { return e.name + " " + std::to_string(i + 1) + " " + prop.name; };
        if (!prop.list) {
          const double v = values.value(prop.type, what);
          if (vertex && (prop.name == "x" || prop.name == "y" || prop.name == "z"))
            p[static_cast<std::size_t>(prop.name[0] - 'x')] = v;
          continue;
        }
        const double n = values.value(prop.count, [&] { return what() + " count"; });
        if (n < 0 || n > 65535) throw Error(what() + " count must be in [0, 65535], got " + number_text(n));
        const bool corners = face && (prop.name == "vertex_indices" || prop.name == "vertex_index");
        if (corners && n < 3) throw Error(what() + ": a face has at least three corners");
        for (int k = 0; k < static_cast<int>(n); ++k) {
          const double id = values.value(prop.type, what);
          if (!corners) continue;
          if (!(id >= 0 && id == std::floor(id) && id < 4294967296.0))
            throw Error(what() + " must hold vertex numbers from 0, got " + number_text(id));
          d.cell_points.push_back(static_cast<std::size_t>(id));
        }
        if (corners) d.cell_ends.push_back(d.cell_points.size());
      }
      values.end();
      if (vertex) d.points.push_back(p);
    }
  }
  values.finish();
  for (std::size_t id : d.cell_points)
    if (id >= d.points.size())
      throw Error("a face uses vertex " + std::to_string(id) + ", but there are " + std::to_string(d.points.size()));
  return d;
}

}  // namespace selfsim::io
