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

#include "kernels/io/view/palette.h"

namespace selfsim::io {

// The shared ramp (palette.h), 256 entries.
void continuous_table(vtkLookupTable* lut, double lo, double hi) {
  lut->SetNumberOfTableValues(256);
  for (int i = 0; i < 256; ++i) {
    const Rgb c = ramp_colour(i / 255.0);
    lut->SetTableValue(i, c[0], c[1], c[2], 1);
  }
  lut->SetTableRange(lo, hi > lo ? hi : lo + 1);
}

// The shared class colours (palette.h), each annotated with its value.
void category_table(vtkLookupTable* lut, const std::vector<int>& categories) {
  const auto n = static_cast<vtkIdType>(categories.size());
  lut->IndexedLookupOn();
  lut->SetNumberOfTableValues(std::max<vtkIdType>(n, 1));
  for (vtkIdType i = 0; i < n; ++i) {
    const Rgb c = class_colour(static_cast<std::size_t>(i));
    lut->SetTableValue(i, c[0], c[1], c[2], 1);
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
