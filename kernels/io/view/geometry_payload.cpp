#include "kernels/io/view/geometry_payload.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <unordered_map>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/io/drawn_width.h"
#include "kernels/io/text/json_text.h"
#include "kernels/io/text/palette.h"
#include "kernels/io/view/tube_rings.h"

namespace selfsim::io {

namespace {

constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

std::array<std::uint8_t, 3> bytes_of(const Rgb& c) {
  std::array<std::uint8_t, 3> b{};
  for (int j = 0; j < 3; ++j) b[j] = static_cast<std::uint8_t>(std::lround(std::clamp(c[j], 0.0, 1.0) * 255));
  return b;
}

std::string hex_list(const std::vector<Rgb>& colours) {
  std::string s;
  for (const Rgb& c : colours) s += std::string(s.empty() ? "" : ", ") + "\"" + colour_hex(c) + "\"";
  return "[" + s + "]";
}

template <class T>
void append(std::string& out, const T* data, std::size_t count) {
  const std::size_t at = out.size();
  out.resize(at + count * sizeof(T));
  if (count > 0) std::memcpy(out.data() + at, data, count * sizeof(T));  // little-endian hosts only (x86, arm)
}

// The colour of each cell or point, as an index into `palette` (the distinct colours used), so that vertices
// split per colour compare one number.
struct Painted {
  std::vector<std::array<std::uint8_t, 3>> palette;
  std::vector<std::uint32_t> index;  // per point or per cell; empty: everything palette[0]
  bool on_cells = false;
};

Painted paint(const Dataset& d, const Colouring& c, Progress& progress) {
  Painted p;
  const bool own = c.field.empty() && has_own_colours(d);
  const std::size_t count = c.on_points && !own ? d.points.size() : d.cell_ends.size();
  const auto& fields = c.on_points && !own ? d.point_fields : d.cell_fields;
  const auto f = own ? fields.find("color") : c.field.empty() ? fields.end() : fields.find(c.field);
  if (!own && (f == fields.end() || f->second.components != 1 || f->second.values.size() != count)) {
    p.palette.push_back(value_colour(Colouring{}, 0));
    return p;
  }
  p.on_cells = own || !c.on_points;
  p.index.resize(count);
  // Distinct colours by their packed RGB: a class field has a few, a ramp at most 2^24, a curve's own colours
  // one a cell (a hash map: a sorted list took a quadratic time of inserts, 6 s for 200,000 cells).
  std::unordered_map<std::uint32_t, std::uint32_t> seen;  // rgb -> palette index
  for (std::size_t i = 0; i < count; ++i) {
    if ((i & 0xfffff) == 0xfffff && progress.cancelled()) throw Cancelled();
    const std::vector<double>& v = f->second.values;
    const auto rgb = own ? bytes_of({v[3 * i], v[3 * i + 1], v[3 * i + 2]}) : value_colour(c, v[i]);
    const std::uint32_t key = (std::uint32_t{rgb[0]} << 16) | (std::uint32_t{rgb[1]} << 8) | rgb[2];
    const auto [at, first] = seen.try_emplace(key, static_cast<std::uint32_t>(p.palette.size()));
    if (first) p.palette.push_back(rgb);
    p.index[i] = at->second;
  }
  return p;
}

}  // namespace

bool has_own_colours(const Dataset& d) {
  if (d.shapes != CellShapes::lines) return false;
  const auto f = d.cell_fields.find("color");
  return f != d.cell_fields.end() && f->second.components == 3 && f->second.values.size() == 3 * d.cell_ends.size();
}

std::string colouring_json(const Colouring& c, bool own) {
  std::vector<Rgb> ramp, classes;
  for (int i = 0; i <= 8; ++i) ramp.push_back(ramp_colour(i / 8.0));
  std::string values;
  if (c.categorical)
    for (std::size_t i = 0; i < c.categories.size(); ++i) {
      classes.push_back(category_colour(c.categories[i], i, coloured_by_value(c.field)));
      values += (i ? ", " : "") + std::to_string(c.categories[i]);
    }
  const auto number = [](double v) { return std::isfinite(v) ? json_number(v) : std::string("0"); };
  return "{\"field\": " + json_string(c.field) + ", \"own\": " + (own ? "true" : "false") + ", \"on\": \"" +
         (c.on_points ? "points" : "cells") + "\", \"categorical\": " + (c.categorical ? "true" : "false") +
         ", \"min\": " + number(c.min) + ", \"max\": " + number(c.max) + ", \"ramp\": " + hex_list(ramp) +
         ", \"classes\": [" + values + "], \"colours\": " + hex_list(classes) + "}";
}

std::array<std::uint8_t, 3> value_colour(const Colouring& c, double v) {
  if (c.field.empty()) return bytes_of({0.45, 0.58, 0.78});  // the preview's colour for an uncoloured value
  const Rgb grey{0.5, 0.5, 0.5};
  if (!std::isfinite(v)) return bytes_of(grey);
  if (c.categorical) {
    const auto at = std::lower_bound(c.categories.begin(), c.categories.end(), v);
    if (at == c.categories.end() || *at != v) return bytes_of(grey);
    return bytes_of(
        category_colour(*at, static_cast<std::size_t>(at - c.categories.begin()), coloured_by_value(c.field)));
  }
  const double span = c.max > c.min ? c.max - c.min : 1;
  return bytes_of(ramp_colour((v - c.min) / span));
}

namespace {

// The tubes of d's polylines (tube_rings.h), coloured as their points or cells are: their ring points'
// positions relative to origin, their palette indices, and their triangles. Returns the triangle count.
std::uint64_t tubes(const Dataset& d, const Painted& painted, const TubeWidths& widths,
                    const std::array<double, 3>& origin, std::vector<float>& positions,
                    std::vector<std::uint32_t>& colour, std::vector<std::uint32_t>& indices,
                    const std::function<void(std::uint64_t)>& too_large, Progress& progress) {
  const std::vector<double>& width = d.point_fields.at("width").values;
  std::vector<std::array<double, 3>> line, rings;
  std::vector<double> radii;
  std::uint64_t triangles = 0;
  for (std::size_t i = 0, begin = 0; i < d.cell_ends.size(); begin = d.cell_ends[i++]) {
    if ((i & 0xffff) == 0xffff && progress.cancelled()) throw Cancelled();
    line.clear();
    radii.clear();
    for (std::size_t k = begin; k < d.cell_ends[i]; ++k) {
      const std::size_t p = d.cell_points[k];
      if (p >= d.points.size()) throw Error("a cell names point " + std::to_string(p) + ", past its points");
      line.push_back(d.points[p]);
      radii.push_back(drawn_radius(width[p], widths.max_width, widths.diagonal));
    }
    rings.clear();
    const std::size_t before = indices.size();
    const std::size_t made =
        tube_rings(line, radii, tube_sides, static_cast<std::uint32_t>(colour.size()), rings, indices);
    triangles += (indices.size() - before) / 3;
    too_large(colour.size() + made);
    for (std::size_t r = 0; r < made; ++r) {
      const std::size_t k = begin + r / tube_sides;
      colour.push_back(painted.index.empty() ? 0 : painted.index[painted.on_cells ? i : d.cell_points[k]]);
      for (int j = 0; j < 3; ++j) positions.push_back(static_cast<float>(rings[r][j] - origin[j]));
    }
  }
  return triangles;
}

}  // namespace

std::size_t line_segments(const Dataset& d) {
  std::size_t segments = 0;
  for (std::size_t i = 0, begin = 0; i < d.cell_ends.size(); begin = d.cell_ends[i++])
    segments += d.cell_ends[i] - begin > 0 ? d.cell_ends[i] - begin - 1 : 0;
  return segments;
}

bool drawn_as_tubes(const Dataset& d, const TubeWidths& widths) {
  if (d.shapes != CellShapes::lines || !(widths.diagonal > 0) || !(widths.max_width > 0)) return false;
  const auto w = d.point_fields.find("width");
  if (w == d.point_fields.end() || w->second.components != 1 || w->second.values.size() != d.points.size())
    return false;
  return line_segments(d) <= max_tube_segments;
}

std::string geometry_payload(const Dataset& d, const Colouring& c, std::uint64_t max_bytes, const TubeWidths& widths,
                             Progress& progress) {
  if (d.points.empty()) throw Error("it holds no points");
  std::array<double, 6> bounds{};
  for (int j = 0; j < 3; ++j) {
    bounds[2 * j] = std::numeric_limits<double>::infinity();
    bounds[2 * j + 1] = -std::numeric_limits<double>::infinity();
  }
  for (const auto& p : d.points)
    for (int j = 0; j < 3; ++j) {
      if (!std::isfinite(p[j])) throw Error("it holds a point that is not finite");
      bounds[2 * j] = std::min(bounds[2 * j], p[j]);
      bounds[2 * j + 1] = std::max(bounds[2 * j + 1], p[j]);
    }
  // Halves first: (lo + hi) / 2 overflows for points near the largest double. Positions go to the page as
  // float32 relative to the origin, so half the extent must fit one, or a vertex would arrive infinite.
  const std::array<double, 3> origin{bounds[0] / 2 + bounds[1] / 2, bounds[2] / 2 + bounds[3] / 2,
                                     bounds[4] / 2 + bounds[5] / 2};
  for (int j = 0; j < 3; ++j)
    if (!(bounds[2 * j + 1] / 2 - bounds[2 * j] / 2 < 0.5 * std::numeric_limits<float>::max()))
      throw Error("it is too large for a 3D view (an extent of " + number_text(bounds[2 * j + 1] - bounds[2 * j]) +
                  "; a browser draws in 32-bit floats)");

  // What the cells become: a polygon of n points n - 2 triangles, a polyline of n points n - 1 segments.
  std::uint64_t triangles = 0, segments = 0;
  for (std::size_t i = 0, begin = 0; i < d.cell_ends.size(); begin = d.cell_ends[i++]) {
    const std::size_t n = d.cell_ends[i] - begin;
    const bool polygon = d.shapes == CellShapes::polygons || (d.shapes == CellShapes::mixed && n >= 3);
    if (polygon)
      triangles += n >= 3 ? n - 2 : 0;
    else
      segments += n >= 2 ? n - 1 : 0;
  }
  const auto size_for = [&](std::uint64_t vertices) {
    return 1024 + 15 * vertices + 4 * (3 * triangles + 2 * segments);  // header, positions and colours, indices
  };
  const auto too_large = [&](std::uint64_t vertices) {
    if (size_for(vertices) <= max_bytes && vertices < none) return;
    throw Error("its 3D view would take " + std::to_string(size_for(vertices) >> 20) + " MiB, over the " +
                std::to_string(max_bytes >> 20) + " MiB a view may take");
  };
  too_large(d.points.size());

  const Painted painted = paint(d, c, progress);
  std::vector<float> positions;       // each vertex's, relative to origin
  std::vector<std::uint32_t> colour;  // each vertex's palette index
  std::vector<std::uint32_t> indices;
  if (drawn_as_tubes(d, widths)) {
    triangles = 2 * tube_sides * segments;  // at most: a line of coincident points makes none
    segments = 0;
    too_large(0);
    triangles = tubes(d, painted, widths, origin, positions, colour, indices, too_large, progress);
  } else {
    // Vertices: one per point, or with a cell field one per point and colour (a chain of copies per point).
    std::vector<std::uint32_t> source;  // each vertex's point
    std::vector<std::uint32_t> head(painted.on_cells ? d.points.size() : 0, none), next;
    if (!painted.on_cells) {
      source.resize(d.points.size());
      for (std::size_t i = 0; i < source.size(); ++i) source[i] = static_cast<std::uint32_t>(i);
      colour.assign(d.points.size(), 0);
      if (!painted.index.empty()) colour = painted.index;
    }
    const auto vertex = [&](std::size_t point, std::size_t cell) -> std::uint32_t {
      if (!painted.on_cells) return static_cast<std::uint32_t>(point);
      const std::uint32_t want = painted.index[cell];
      for (std::uint32_t k = head[point]; k != none; k = next[k])
        if (colour[k] == want) return k;
      if (source.size() + 1 >= none) too_large(source.size() + 1);
      source.push_back(static_cast<std::uint32_t>(point));
      colour.push_back(want);
      next.push_back(head[point]);
      head[point] = static_cast<std::uint32_t>(source.size() - 1);
      return head[point];
    };

    indices.reserve(static_cast<std::size_t>(3 * triangles + 2 * segments));
    for (int pass = 0; pass < 2; ++pass)  // triangles first, then segments
      for (std::size_t i = 0, begin = 0; i < d.cell_ends.size(); begin = d.cell_ends[i++]) {
        if ((i & 0xfffff) == 0xfffff && progress.cancelled()) throw Cancelled();
        const std::size_t n = d.cell_ends[i] - begin;
        const bool polygon = d.shapes == CellShapes::polygons || (d.shapes == CellShapes::mixed && n >= 3);
        const auto id = [&](std::size_t k) {
          const std::size_t point = d.cell_points[begin + k];
          if (point >= d.points.size())
            throw Error("a cell names point " + std::to_string(point) + ", past its points");
          return vertex(point, i);
        };
        if (pass == 0 && polygon && n >= 3) {
          const std::uint32_t first = id(0);
          for (std::size_t k = 1; k + 1 < n; ++k) indices.insert(indices.end(), {first, id(k), id(k + 1)});
        } else if (pass == 1 && !polygon) {
          for (std::size_t k = 0; k + 1 < n; ++k) indices.insert(indices.end(), {id(k), id(k + 1)});
        }
      }
    too_large(source.size());
    positions.resize(3 * source.size());
    for (std::size_t v = 0; v < source.size(); ++v)
      for (int j = 0; j < 3; ++j) positions[3 * v + j] = static_cast<float>(d.points[source[v]][j] - origin[j]);
  }

  std::string header = "{\"vertices\": " + std::to_string(colour.size()) +
                       ", \"triangles\": " + std::to_string(triangles) + ", \"segments\": " + std::to_string(segments) +
                       ", \"origin\": [" + json_number(origin[0]) + ", " + json_number(origin[1]) + ", " +
                       json_number(origin[2]) + "], \"bounds\": [";
  for (int j = 0; j < 6; ++j) header += (j ? ", " : "") + json_number(bounds[j]);
  header += "], \"legend\": " + colouring_json(c, c.field.empty() && has_own_colours(d)) + "}";
  header.append((4 - header.size() % 4) % 4, ' ');

  std::string out;
  out.reserve(static_cast<std::size_t>(size_for(colour.size())));
  out += "SSG1";
  const auto header_bytes = static_cast<std::uint32_t>(header.size());
  append(out, &header_bytes, 1);
  out += header;
  append(out, positions.data(), positions.size());
  append(out, indices.data(), indices.size());
  std::vector<std::uint8_t> rgb(3 * colour.size());
  for (std::size_t v = 0; v < colour.size(); ++v) std::memcpy(&rgb[3 * v], painted.palette[colour[v]].data(), 3);
  append(out, rgb.data(), rgb.size());
  out.append((4 - out.size() % 4) % 4, '\0');
  if (progress.cancelled()) throw Cancelled();
  return out;
}

}  // namespace selfsim::io
