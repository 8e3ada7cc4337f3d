#include "kernels/io/dataset/dataset_values.h"

#include <string>

#include "kernels/base/error.h"
#include "kernels/geom/polygon_triangles.h"

namespace selfsim::io {

namespace {

Field as_field(const std::string& name, const FieldValues& v) { return real_field(name, v.values, v.components); }

// The cell field values of each cell repeated `copies[i]` times.
Field repeated(const std::string& name, const FieldValues& v, const std::vector<std::size_t>& copies) {
  std::vector<double> out;
  const std::size_t k = static_cast<std::size_t>(v.components);
  for (std::size_t c = 0; c < copies.size(); ++c)
    for (std::size_t j = 0; j < copies[c]; ++j)
      out.insert(out.end(), v.values.begin() + c * k, v.values.begin() + (c + 1) * k);
  return real_field(name, std::move(out), v.components);
}

template <class V>
PolylineT<V> curve(const Dataset& d, V (*point)(const std::array<double, 3>&)) {
  PolylineT<V> c;
  c.points.reserve(d.cell_points.size());
  for (std::size_t id : d.cell_points) c.points.push_back(point(d.points[id]));
  c.path_ends = d.cell_ends;
  // Point fields follow the points: a cell that reuses a point (a closed loop) repeats its values.
  for (const auto& [name, v] : d.point_fields) {
    std::vector<double> out;
    const std::size_t k = static_cast<std::size_t>(v.components);
    for (std::size_t id : d.cell_points)
      out.insert(out.end(), v.values.begin() + id * k, v.values.begin() + (id + 1) * k);
    c.point_fields.set(real_field(name, std::move(out), v.components));
  }
  for (const auto& [name, v] : d.cell_fields) c.cell_fields.set(as_field(name, v));
  return c;
}

}  // namespace

Mesh dataset_mesh(const Dataset& d, Progress& progress) {
  Mesh m;
  m.points.reserve(d.points.size());
  for (const auto& p : d.points) m.points.push_back({p[0], p[1], p[2]});
  std::vector<std::size_t> triangles_of(d.cell_ends.size());
  std::vector<Vec3> corners;
  std::vector<std::array<std::size_t, 3>> cut;
  std::size_t begin = 0;
  for (std::size_t c = 0; c < d.cell_ends.size(); ++c) {
    const std::size_t end = d.cell_ends[c];
    if (end - begin < 3) throw Error("polygon " + std::to_string(c + 1) + " has fewer than 3 points");
    if (end - begin > 3 && progress.cancelled()) throw Cancelled();  // a concave face's cutting is quadratic
    corners.clear();
    for (std::size_t k = begin; k < end; ++k) corners.push_back(m.points[d.cell_points[k]]);
    cut.clear();
    try {
      polygon_triangles(corners, cut);  // a concave polygon is cut into ears, never fanned outside itself
    } catch (const Error& e) {
      throw Error("polygon " + std::to_string(c + 1) + ": " + e.what());
    }
    for (const auto& t : cut)
      m.triangles.push_back({static_cast<std::uint32_t>(d.cell_points[begin + t[0]]),
                             static_cast<std::uint32_t>(d.cell_points[begin + t[1]]),
                             static_cast<std::uint32_t>(d.cell_points[begin + t[2]])});
    triangles_of[c] = end - begin - 2;
    begin = end;
  }
  for (const auto& [name, v] : d.point_fields) m.point_fields.set(as_field(name, v));
  for (const auto& [name, v] : d.cell_fields) m.face_fields.set(repeated(name, v, triangles_of));
  m.validate();
  return m;
}

std::variant<Polyline, Polyline3, Mesh> dataset_value(const Dataset& d, Progress& progress) {
  if (d.shapes == CellShapes::mixed)
    throw Error("it holds cells other than polylines or polygons (vertices, strips, volumes, or both kinds)");
  if (d.cell_ends.empty()) throw Error("it holds no cells (no polylines or polygons)");
  if (d.shapes == CellShapes::polygons) return dataset_mesh(d, progress);
  bool flat = true;
  for (const auto& p : d.points) flat &= p[2] == 0;
  if (flat) return curve<Vec2>(d, [](const std::array<double, 3>& p) { return Vec2{p[0], p[1]}; });
  return curve<Vec3>(d, [](const std::array<double, 3>& p) { return Vec3{p[0], p[1], p[2]}; });
}

}  // namespace selfsim::io
