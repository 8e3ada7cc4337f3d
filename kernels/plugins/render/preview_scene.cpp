#include "kernels/plugins/render/preview_scene.h"

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkTubeFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVariant.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "kernels/io/drawn_width.h"
#include "kernels/io/text/palette.h"
#include "kernels/io/view/geometry_payload.h"

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
void category_table(vtkLookupTable* lut, const std::vector<int>& categories, bool by_value) {
  const auto n = static_cast<vtkIdType>(categories.size());
  lut->IndexedLookupOn();
  lut->SetNumberOfTableValues(std::max<vtkIdType>(n, 1));
  for (vtkIdType i = 0; i < n; ++i) {
    const int value = categories[static_cast<std::size_t>(i)];
    const Rgb c = category_colour(value, static_cast<std::size_t>(i), by_value);
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

// An SVG's stroke colours as bytes, which the mapper draws as they are.
vtkSmartPointer<vtkUnsignedCharArray> colour_bytes(const FieldValues& f) {
  auto a = vtkSmartPointer<vtkUnsignedCharArray>::New();
  a->SetName(direct_colour_field);
  a->SetNumberOfComponents(3);
  a->SetNumberOfTuples(static_cast<vtkIdType>(f.values.size() / 3));
  for (std::size_t i = 0; i < f.values.size(); ++i)
    a->SetValue(static_cast<vtkIdType>(i),
                static_cast<unsigned char>(std::lround(255 * std::clamp(f.values[i], 0.0, 1.0))));
  return a;
}

// A class field's values as their classes' colours (palette.h), so that the mapper draws them as they are:
// VTK's indexed lookup goes through a variant per value, a large part of a million-face preview.
vtkSmartPointer<vtkUnsignedCharArray> class_bytes(const std::string& name, const FieldValues& f,
                                                  const std::vector<int>& categories) {
  const bool by_value = coloured_by_value(name);
  auto a = vtkSmartPointer<vtkUnsignedCharArray>::New();
  a->SetName(name.c_str());
  a->SetNumberOfComponents(3);
  const std::size_t n = f.values.size() / static_cast<std::size_t>(f.components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(n));
  unsigned char* out = a->GetPointer(0);
  for (std::size_t i = 0; i < n; ++i) {
    const double v = f.values[i * static_cast<std::size_t>(f.components)];
    const auto at = std::lower_bound(categories.begin(), categories.end(), static_cast<int>(v));
    const bool known = at != categories.end() && *at == v;
    const Rgb c =
        known ? category_colour(*at, static_cast<std::size_t>(at - categories.begin()), by_value) : Rgb{0.6, 0.6, 0.6};
    for (int k = 0; k < 3; ++k)
      out[3 * i + static_cast<std::size_t>(k)] = static_cast<unsigned char>(std::lround(255 * c[k]));
  }
  return a;
}

// Tube geometry (8 sides per segment) is built up to this many segments; past it lines are drawn as tubes
// by the line shader, which costs nothing per segment but cannot vary the width.
constexpr std::size_t preview_tube_segments = 200000;
// Past this many faces normals are computed without splitting at sharp edges or reorienting: both cost
// more than the rest of a preview of a million-triangle mesh.
constexpr vtkIdType max_careful_normals = 300000;

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
  auto array = [&](const FieldValues& f) -> vtkSmartPointer<vtkDataArray> {
    if (c.categorical) return class_bytes(c.field, f, c.categories);
    return field_array(c.field, f);
  };
  if (!c.field.empty()) {
    if (c.on_points) {
      if (auto f = d.point_fields.find(c.field); f != d.point_fields.end())
        poly->GetPointData()->AddArray(array(f->second));
    } else if (!reordered) {
      if (auto f = d.cell_fields.find(c.field); f != d.cell_fields.end())
        poly->GetCellData()->AddArray(array(f->second));
    }
  }
  return poly;
}

bool has_direct_colours(const Dataset& d) {
  const auto f = d.cell_fields.find(direct_colour_field);
  return f != d.cell_fields.end() && f->second.components == 3 && f->second.values.size() == 3 * d.cell_ends.size();
}

SceneStyle scene_style(std::span<const Dataset> steps, const Colouring& colouring, bool direct) {
  SceneStyle s;
  s.colouring = colouring;
  s.direct = direct;
  s.flat = true;
  const double inf = std::numeric_limits<double>::infinity();
  double lo[3] = {inf, inf, inf}, hi[3] = {-inf, -inf, -inf};
  for (const Dataset& d : steps) {
    for (const auto& p : d.points) {
      if (p[2] != 0) s.flat = false;
      for (int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], p[a]);
        hi[a] = std::max(hi[a], p[a]);
      }
    }
    if (auto w = d.point_fields.find("width"); w != d.point_fields.end() && w->second.components == 1)
      for (double v : w->second.values)
        if (std::isfinite(v)) s.max_width = std::max(s.max_width, std::abs(v));
  }
  // Tubes for every step or for none: a growth that turned from tubes to lines halfway would not read as one.
  for (const Dataset& d : steps)
    if (line_segments(d) > preview_tube_segments) s.max_width = 0;
  double diagonal = 0;
  for (int a = 0; a < 3; ++a) diagonal += hi[a] > lo[a] ? (hi[a] - lo[a]) * (hi[a] - lo[a]) : 0;
  s.size = diagonal > 0 ? std::sqrt(diagonal) : 1;
  return s;
}

StepDrawing step_drawing(const Dataset& d, const SceneStyle& style) {
  StepDrawing out;
  vtkSmartPointer<vtkPolyData> poly = poly_data(d, style.colouring);
  out.mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  out.surface = poly->GetNumberOfPolys() > 0;
  const std::size_t n = line_segments(d);
  out.line_width = n < 4000 ? 2.5f : n < 40000 ? 1.5f : 1.0f;
  const auto width = d.point_fields.find("width");
  const bool widths = !out.surface && poly->GetNumberOfLines() > 0 && style.max_width > 0 &&
                      width != d.point_fields.end() && width->second.components == 1;
  const bool direct = style.direct && has_direct_colours(d) && poly->GetNumberOfPolys() == 0;
  if (direct) poly->GetCellData()->AddArray(colour_bytes(d.cell_fields.at(direct_colour_field)));
  if (widths) {
    // Every picture's rule (drawn_width.h): relative to the drawing's size and the widest width.
    auto radius = vtkSmartPointer<vtkDoubleArray>::New();
    radius->SetName("selfsim_radius");
    radius->SetNumberOfTuples(poly->GetNumberOfPoints());
    for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) {
      const auto at = static_cast<std::size_t>(i);
      const double w = at < width->second.values.size() ? width->second.values[at] : 0;
      radius->SetValue(i, drawn_radius(w, style.max_width, style.size));
    }
    poly->GetPointData()->SetScalars(radius);
    vtkNew<vtkTubeFilter> tubes;
    tubes->SetInputData(poly);
    tubes->SetNumberOfSides(8);
    tubes->SetVaryRadiusToVaryRadiusByAbsoluteScalar();
    tubes->CappingOn();
    tubes->Update();
    out.mapper->SetInputData(tubes->GetOutput());
    out.surface = true;
    out.tubes = true;
  } else if (out.surface && !style.flat) {
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputData(poly);
    const bool careful = poly->GetNumberOfPolys() <= max_careful_normals;
    normals->SetFeatureAngle(60);
    normals->SetSplitting(careful);
    normals->SetConsistency(careful);
    normals->ComputeCellNormalsOff();
    normals->Update();
    out.mapper->SetInputData(normals->GetOutput());
  } else {
    out.mapper->SetInputData(poly);
    // A 3D curve's lines are shaded as tubes by the line shader, so that depth reads.
    out.lit_lines = !out.surface && !style.flat && poly->GetNumberOfLines() > 0;
    out.tubes = out.lit_lines;
  }
  vtkPolyDataMapper* m = out.mapper;
  if (direct) {
    m->SetColorModeToDirectScalars();
    m->SetScalarModeToUseCellFieldData();
    m->SelectColorArray(direct_colour_field);
    m->ScalarVisibilityOn();
  } else if (!style.colouring.field.empty() && style.colouring.categorical) {
    m->SetColorModeToDirectScalars();  // the classes' colours, made by class_bytes
    m->SetScalarModeToUsePointFieldData();
    if (!style.colouring.on_points) m->SetScalarModeToUseCellFieldData();
    m->SelectColorArray(style.colouring.field.c_str());
    m->ScalarVisibilityOn();
  } else if (!style.colouring.field.empty() && style.lut != nullptr) {
    m->SetLookupTable(style.lut);
    m->UseLookupTableScalarRangeOn();
    m->SetColorModeToMapScalars();
    m->SetScalarModeToUsePointFieldData();
    if (!style.colouring.on_points) m->SetScalarModeToUseCellFieldData();
    m->SelectColorArray(style.colouring.field.c_str());
    m->ScalarVisibilityOn();
  } else {
    m->ScalarVisibilityOff();
  }
  return out;
}

void show_step(vtkActor* actor, const StepDrawing& drawing, const SceneStyle& style) {
  actor->SetMapper(drawing.mapper);
  vtkProperty* p = actor->GetProperty();
  p->SetColor(0.45, 0.58, 0.78);  // also where a step lacks the field the others are coloured by
  p->LightingOn();
  if (drawing.surface) {
    p->SetAmbient(0.15);
    p->SetDiffuse(0.8);
    p->SetSpecular(style.flat && !drawing.tubes ? 0 : 0.15);
    p->SetSpecularPower(25);
  } else if (drawing.lit_lines) {
    p->SetRenderLinesAsTubes(true);
    p->SetAmbient(0.25);
    p->SetDiffuse(0.75);
    p->SetSpecular(0.1);
    p->SetRenderPointsAsSpheres(true);
  } else {
    p->LightingOff();  // flat lines and points in their own colour, not shaded
  }
  p->SetLineWidth(drawing.lit_lines ? drawing.line_width + 1.5f : drawing.line_width);
  p->SetPointSize(3);
}

}  // namespace selfsim::io
