// Reading STL (binary and ASCII) for load(), info and diff. STL stores each triangle's three corners
// apart; corners with the same coordinates become one shared point (first seen, first numbered), so a
// closed surface reads back closed. Strict: a binary file's size must match its triangle count, an ASCII
// facet holds exactly three vertices, and every coordinate is a finite number, with the line or triangle
// named otherwise.
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "kernels/geom/error.h"
#include "kernels/io/dataset.h"
#include "kernels/io/file_stream.h"
#include "kernels/io/mesh_readers.h"

namespace selfsim::io {

namespace {

// Shared points: the first corner at a position gets the next index.
class PointMerger {
 public:
  explicit PointMerger(Dataset& d) : d_(d) {}
  std::size_t index(const std::array<double, 3>& p) {
    const auto [it, added] = ids_.try_emplace(key(p), d_.points.size());
    if (added) d_.points.push_back(p);
    return it->second;
  }

 private:
  struct Key {
    std::uint64_t x, y, z;
    bool operator==(const Key&) const = default;
  };
  struct Hash {
    std::size_t operator()(const Key& k) const {
      return k.x * 0x9E3779B97F4A7C15ull ^ k.y * 0xC2B2AE3D27D4EB4Full ^ k.z;
    }
  };
  // -0 and +0 are one position.
  static std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v == 0 ? 0.0 : v); }
  static Key key(const std::array<double, 3>& p) { return {bits(p[0]), bits(p[1]), bits(p[2])}; }

  Dataset& d_;
  std::unordered_map<Key, std::size_t, Hash> ids_;
};

void add_triangle(Dataset& d, PointMerger& points, const std::array<std::array<double, 3>, 3>& corners) {
  for (const auto& c : corners) d.cell_points.push_back(points.index(c));
  d.cell_ends.push_back(d.cell_points.size());
}

Dataset read_binary(const RegularFile& f, std::uint32_t n) {
  Dataset d;
  d.shapes = CellShapes::polygons;
  PointMerger points(d);
  FileStream in(f, 84);
  for (std::uint32_t t = 0; t < n; ++t) {
    unsigned char record[50];
    in.bytes(record, sizeof record);
    std::array<std::array<double, 3>, 3> corners{};
    for (int k = 0; k < 9; ++k) {
      std::uint32_t word = 0;
      std::memcpy(&word, record + 12 + 4 * k, 4);  // after the normal; little-endian, as on this machine
      const float v = std::bit_cast<float>(word);
      if (!std::isfinite(v)) throw Error("triangle " + std::to_string(t + 1) + " has a non-finite coordinate");
      corners[static_cast<std::size_t>(k / 3)][static_cast<std::size_t>(k % 3)] = v;
    }
    add_triangle(d, points, corners);
  }
  return d;
}

Dataset read_ascii(const RegularFile& f) {
  Dataset d;
  d.shapes = CellShapes::polygons;
  PointMerger points(d);
  FileStream in(f);
  std::string_view line;
  std::array<std::array<double, 3>, 3> corners{};
  int corner = -1;  // -1 outside a facet, else vertices read in it
  bool ended = false;
  while (in.line(line)) {
    const auto w = words(line);
    if (w.empty()) continue;
    const std::string at = "line " + std::to_string(in.line_number());
    if (ended) throw Error(at + ": text after 'endsolid'");
    if (w[0] == "solid" || w[0] == "outer" || w[0] == "endloop") continue;
    if (w[0] == "facet") {
      if (corner >= 0) throw Error(at + ": 'facet' inside a facet");
      corner = 0;
    } else if (w[0] == "vertex") {
      if (corner < 0) throw Error(at + ": 'vertex' outside a facet");
      if (corner == 3) throw Error(at + ": a facet holds exactly three vertices, this one more");
      if (w.size() != 4) throw Error(at + ": 'vertex' takes three coordinates");
      for (std::size_t k = 0; k < 3; ++k)
        corners[static_cast<std::size_t>(corner)][k] = number_word(w[k + 1], at + ": vertex coordinate");
      ++corner;
    } else if (w[0] == "endfacet") {
      if (corner != 3)
        throw Error(at + ": a facet holds exactly three vertices, this one " + std::to_string(std::max(corner, 0)));
      add_triangle(d, points, corners);
      corner = -1;
    } else if (w[0] == "endsolid") {
      ended = true;
    } else {
      throw Error(at + ": unexpected '" + std::string(w[0].substr(0, 20)) + "' in an ASCII STL");
    }
  }
  if (corner >= 0) throw Error("the file ends inside a facet (truncated?)");
  return d;
}

}  // namespace

Dataset read_stl(const RegularFile& f) {
  std::uint32_t n = 0;
  const bool sized = f.size() >= 84 && f.read_at(80, &n, 4) == 4;
  if (sized && f.size() == 84 + 50 * std::uint64_t{n}) return read_binary(f, n);
  char head[6] = {};
  f.read_at(0, head, 5);
  if (std::string_view(head, 5) == "solid") return read_ascii(f);
  if (!sized) throw Error("not an STL file (too short for a binary STL, and no 'solid' for an ASCII one)");
  throw Error("a binary STL of " + std::to_string(n) + " triangles has " + std::to_string(84 + 50 * std::uint64_t{n}) +
              " bytes, this file " + std::to_string(f.size()) + " (truncated, or not an STL file)");
}

}  // namespace selfsim::io
