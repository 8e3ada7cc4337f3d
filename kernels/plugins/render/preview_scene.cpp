#include "kernels/plugins/render/preview_scene.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkVariant.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace selfsim::io {

// A perceptually even blue-green-yellow ramp (after matplotlib's viridis), 256 entries.
void continuous_table(vtkLookupTable* lut, double lo, double hi) {
  static const double stops[][3] = {{0.267, 0.005, 0.329},
                                    {0.231, 0.322, 0.545},
                                    {0.129, 0.569, 0.549},
                                    {0.369, 0.788, 0.384},
                                    {0.992, 0.906, 0.145}};
  lut->SetNumberOfTableValues(256);
  for (int i = 0; i < 256; ++i) {
    const double t = i / 255.0 * 4;
    const int k = std::min(3, static_cast<int>(t));
    const double f = t - k;
    double c[3];
    for (int j = 0; j < 3; ++j) c[j] = stops[k][j] * (1 - f) + stops[k + 1][j] * f;
    lut->SetTableValue(i, c[0], c[1], c[2], 1);
  }
  lut->SetTableRange(lo, hi > lo ? hi : lo + 1);
}

namespace {

// One channel of a colour given as hue, lightness and saturation (the standard HLS model).
double hls_channel(double m1, double m2, double h) {
  h -= std::floor(h);
  if (h < 1.0 / 6) return m1 + (m2 - m1) * h * 6;
  if (h < 0.5) return m2;
  if (h < 2.0 / 3) return m1 + (m2 - m1) * (2.0 / 3 - h) * 6;
  return m1;
}

}  // namespace

// Distinct colours for classes, the same as a ParaView view's (paraview_view_body.py, category_colours):
// hues a golden angle apart from a blue, three lightness and saturation steps out of phase with them, so
// that neighbouring class numbers never look alike and 256 classes still separate.
void category_table(vtkLookupTable* lut, const std::vector<int>& categories) {
  const auto n = static_cast<vtkIdType>(categories.size());
  lut->IndexedLookupOn();
  lut->SetNumberOfTableValues(std::max<vtkIdType>(n, 1));
  const double golden = (3 - std::sqrt(5.0)) / 2;  // the golden angle, in turns
  static const double lightness[3] = {0.50, 0.68, 0.36}, saturation[3] = {0.75, 0.55, 0.90};
  for (vtkIdType i = 0; i < n; ++i) {
    const double hue = std::fmod(0.58 + static_cast<double>(i) * golden, 1.0);
    const double l = lightness[i % 3], sat = saturation[(i / 3) % 3];
    const double m2 = l <= 0.5 ? l * (1 + sat) : l + sat - l * sat, m1 = 2 * l - m2;
    lut->SetTableValue(i, hls_channel(m1, m2, hue + 1.0 / 3), hls_channel(m1, m2, hue),
                       hls_channel(m1, m2, hue - 1.0 / 3), 1);
    lut->SetAnnotation(vtkVariant(static_cast<double>(categories[static_cast<std::size_t>(i)])),
                       std::to_string(categories[static_cast<std::size_t>(i)]));
  }
}

namespace {

vtkSmartPointer<vtkDoubleArray> field_array(const std::string& name, const FieldValues& f) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name.c_str());
  a->SetNumberOfComponents(f.components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(f.values.size() / static_cast<std::size_t>(f.components)));
  std::copy(f.values.begin(), f.values.end(), a->GetPointer(0));
  return a;
}

}  // namespace

// Points, cells and the colouring field as VTK polydata. Polylines become lines, polygons polys; in a
// mixed dataset cells of one or two points are drawn as lines and longer ones as polygons. Points without
// any cell are drawn as vertices.
vtkSmartPointer<vtkPolyData> poly_data(const Dataset& d, const Colouring& c) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(d.points.size()));
  for (std::size_t i = 0; i < d.points.size(); ++i) points->SetPoint(static_cast<vtkIdType>(i), d.points[i].data());
  poly->SetPoints(points);
  vtkNew<vtkCellArray> lines, polys, verts;
  std::vector<vtkIdType> ids;
  for (std::size_t i = 0, begin = 0; i < d.cell_ends.size(); begin = d.cell_ends[i++]) {
    ids.assign(d.cell_points.begin() + static_cast<std::ptrdiff_t>(begin),
               d.cell_points.begin() + static_cast<std::ptrdiff_t>(d.cell_ends[i]));
    const bool polygon = d.shapes == CellShapes::polygons || (d.shapes == CellShapes::mixed && ids.size() >= 3);
    (polygon ? polys : lines)->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  if (d.cell_ends.empty())
    for (vtkIdType i = 0; i < static_cast<vtkIdType>(d.points.size()); ++i) verts->InsertNextCell(1, &i);
  // Cell data follows VTK's order of cells: verts, lines, polys. Only a mixed dataset reorders its cells;
  // its cell field is then left out (the picture is uncoloured) rather than shown on the wrong cells.
  const bool reordered =
      d.shapes == CellShapes::mixed && lines->GetNumberOfCells() > 0 && polys->GetNumberOfCells() > 0;
  poly->SetVerts(verts);
  poly->SetLines(lines);
  poly->SetPolys(polys);
  if (!c.field.empty()) {
    if (c.on_points) {
      if (auto f = d.point_fields.find(c.field); f != d.point_fields.end())
        poly->GetPointData()->SetScalars(field_array(c.field, f->second));
    } else if (!reordered) {
      if (auto f = d.cell_fields.find(c.field); f != d.cell_fields.end())
        poly->GetCellData()->SetScalars(field_array(c.field, f->second));
    }
  }
  return poly;
}

}  // namespace selfsim::io
