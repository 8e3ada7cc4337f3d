// Reading STL (binary and ASCII) for load(), info and diff. STL stores each triangle's three corners
// apart; corners with the same coordinates become one shared point (first seen, first numbered), so a
// closed surface reads back closed. Strict: a binary file's size must match its triangle count, an ASCII
// facet holds exactly three vertices, and every coordinate is a finite number, with the line or triangle
// named otherwise.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/io/dataset/dataset.h"
#include "kernels/io/file_stream.h"
#include "kernels/io/mesh/mesh_readers.h"

namespace selfsim::io {

static_assert(std::endian::native == std::endian::little, "binary STL is little-endian: add byte swaps");

namespace {

using Corner = std::array<double, 3>;

// Every triangle's corners, then shared points: corners at the same position become one point, numbered
// in the order first seen. Found by sorting, not hashing, so no crafted file can make it quadratic.
Dataset merged(const std::vector<Corner>& corners) {
  Dataset d;
  d.shapes = CellShapes::polygons;
  std::vector<std::size_t> order(corners.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return corners[a] != corners[b] ? corners[a] < corners[b] : a < b;  // -0 == +0: one position
  });
  std::vector<std::size_t> first(corners.size());  // the first corner at each corner's position
  for (std::size_t k = 0; k < order.size(); ++k)
    first[order[k]] = k > 0 && corners[order[k]] == corners[order[k - 1]] ? first[order[k - 1]] : order[k];
  std::vector<std::size_t> id(corners.size());
  d.cell_points.reserve(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (first[i] == i) {
      id[i] = d.points.size();
      d.points.push_back(corners[i]);
    }
    d.cell_points.push_back(id[first[i]]);
    if (i % 3 == 2) d.cell_ends.push_back(i + 1);
  }
  return d;
}

Dataset read_binary(const RegularFile& f, std::uint32_t n) {
  std::vector<Corner> corners;
  corners.reserve(3 * std::size_t{n});  // the file's size matches n: checked by the caller
  FileStream in(f, 84);
  for (std::uint32_t t = 0; t < n; ++t) {
    unsigned char record[50];
    in.bytes(record, sizeof record);
    for (int k = 0; k < 3; ++k) {
      Corner c{};
      for (int j = 0; j < 3; ++j) {
        std::uint32_t word = 0;
        std::memcpy(&word, record + 12 + 12 * k + 4 * j, 4);  // after the normal; little-endian, as here
        const float v = std::bit_cast<float>(word);
        if (!std::isfinite(v)) throw Error("triangle " + std::to_string(t + 1) + " has a non-finite coordinate");
        c[static_cast<std::size_t>(j)] = v;
      }
      corners.push_back(c);
    }
  }
  return merged(corners);
}

Dataset read_ascii(const RegularFile& f) {
  std::vector<Corner> corners;
  FileStream in(f);
  std::string_view line;
  Corner c{};
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
      for (std::size_t k = 0; k < 3; ++k) c[k] = number_word(w[k + 1], at + ": vertex coordinate");
      corners.push_back(c);
      ++corner;
    } else if (w[0] == "endfacet") {
      if (corner != 3)
        throw Error(at + ": a facet holds exactly three vertices, this one " + std::to_string(std::max(corner, 0)));
      corner = -1;
    } else if (w[0] == "endsolid") {
      ended = true;
    } else {
      throw Error(at + ": unexpected '" + std::string(w[0].substr(0, 20)) + "' in an ASCII STL");
    }
  }
  if (corner >= 0) throw Error("the file ends inside a facet (truncated?)");
  return merged(corners);
}

}  // namespace

Dataset read_stl(const RegularFile& f) {
  std::uint32_t n = 0;
  const bool sized = f.size() >= 84 && f.read_at(80, &n, 4) == 4;
  if (sized && f.size() == 84 + 50 * std::uint64_t{n}) return read_binary(f, n);
  char head[6] = {};
  f.read_at(0, head, 5);
  if (std::string_view(head, 5) == "solid") {
    try {
      return read_ascii(f);
    } catch (const Error&) {
      // Binary STLs may begin "solid" too: one with NUL bytes near the start was meant to be binary.
      char start[512] = {};
      const std::size_t n = f.read_at(0, start, sizeof start);
      if (!sized || std::memchr(start, '\0', n) == nullptr) throw;
    }
  }
  if (!sized) throw Error("not an STL file (too short for a binary STL, and no 'solid' for an ASCII one)");
  throw Error("a binary STL of " + std::to_string(n) + " triangles has " + std::to_string(84 + 50 * std::uint64_t{n}) +
              " bytes, this file " + std::to_string(f.size()) + " (truncated, or not an STL file)");
}

}  // namespace selfsim::io
