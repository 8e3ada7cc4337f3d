#include "kernels/io/vtk/vtk_pieces.h"

#include <memory>

namespace selfsim::io {

namespace {

// VTK cell type numbers (vtkCellType.h).
constexpr std::uint8_t vtk_poly_line = 4, vtk_triangle = 5;

double z_of(Vec2) { return 0; }
double z_of(Vec3 p) { return p.z; }

template <class Points>
VtkArray coordinates(const Points& points) {
  return {"Points", "Float64", 3, points.size(), [&points](std::size_t begin, std::size_t end, void* out) {
            double* o = static_cast<double*>(out);
            for (std::size_t i = begin; i < end; ++i) {
              *o++ = points[i].x;
              *o++ = points[i].y;
              *o++ = z_of(points[i]);
            }
          }};
}

// Distance along each path, restarting at 0 on every path. The writer fills chunks in order, so a running
// state carries the sum from one chunk to the next.
template <class V>
VtkArray arclength(const PolylineT<V>& c) {
  struct Run {
    std::size_t path = 0;
    double length = 0;
  };
  auto run = std::make_shared<Run>();
  return {"arclength", "Float64", 1, c.points.size(), [&c, run](std::size_t begin, std::size_t end, void* out) {
            double* o = static_cast<double*>(out);
            for (std::size_t i = begin; i < end; ++i) {
              if (i == c.path_begin(run->path))
                run->length = 0;
              else
                run->length += norm(c.points[i] - c.points[i - 1]);
              *o++ = run->length;
              if (i + 1 == c.path_ends[run->path]) ++run->path;
            }
          }};
}

void add_fields(const Fields& fields, std::size_t count, std::vector<VtkArray>& arrays) {
  for (const Field& f : fields.list) arrays.push_back(field_array(f, count));
}

}  // namespace

template <class V>
VtkPiece curve_piece(const PolylineT<V>& c, VtkDataset dataset) {
  VtkPiece p;
  p.dataset = dataset;
  p.points = c.points.size();
  p.cells = c.paths();
  add_fields(c.point_fields, p.points, p.point_data);
  if (!c.point_fields.find("arclength")) p.point_data.push_back(arclength(c));
  p.active_scalars = "arclength";
  add_fields(c.cell_fields, p.cells, p.cell_data);
  if (!c.cell_fields.find("path"))
    p.cell_data.push_back(computed_array<std::int32_t>("path", p.cells, [](std::size_t i) { return i; }));
  p.coordinates = coordinates(c.points);
  p.topology.push_back(computed_array<std::int64_t>("connectivity", p.points, [](std::size_t i) { return i; }));
  p.topology.push_back(
      computed_array<std::int64_t>("offsets", p.cells, [&c](std::size_t i) { return c.path_ends[i]; }));
  if (dataset == VtkDataset::UnstructuredGrid)
    p.topology.push_back(computed_array<std::uint8_t>("types", p.cells, [](std::size_t) { return vtk_poly_line; }));
  return p;
}

template VtkPiece curve_piece(const Polyline&, VtkDataset);
template VtkPiece curve_piece(const Polyline3&, VtkDataset);

VtkPiece mesh_piece(const Mesh& m, VtkDataset dataset) {
  VtkPiece p;
  p.dataset = dataset;
  p.points = m.points.size();
  p.cells = m.faces();
  add_fields(m.point_fields, p.points, p.point_data);
  if (!m.point_fields.empty()) p.active_scalars = m.point_fields.list.front().name;
  add_fields(m.face_fields, p.cells, p.cell_data);
  p.coordinates = coordinates(m.points);
  p.topology.push_back(computed_array<std::int64_t>("connectivity", 3 * p.cells,
                                                    [&m](std::size_t i) { return m.triangles[i / 3][i % 3]; }));
  p.topology.push_back(computed_array<std::int64_t>("offsets", p.cells, [](std::size_t i) { return 3 * (i + 1); }));
  if (dataset == VtkDataset::UnstructuredGrid)
    p.topology.push_back(computed_array<std::uint8_t>("types", p.cells, [](std::size_t) { return vtk_triangle; }));
  return p;
}

}  // namespace selfsim::io
