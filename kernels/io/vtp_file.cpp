// VTK XML PolyData (.vtp): what ParaView opens. Polylines are cells; point fields `level` and `arclength`
// and cell field `path` let a user colour by construction level, by distance along the curve, or by path.
#include <numeric>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include "kernels/geom/error.h"
#include "kernels/io/save.h"

namespace selfsim::io {

namespace {

Field field_of(vtkDataArray* a) {
  Field f;
  f.components = a->GetNumberOfComponents();
  const vtkIdType n = a->GetNumberOfTuples();
  f.values.reserve(static_cast<std::size_t>(n * f.components));
  for (vtkIdType i = 0; i < n; ++i)
    for (int k = 0; k < f.components; ++k) f.values.push_back(a->GetComponent(i, k));
  return f;
}

}  // namespace

void write_vtp(const Polyline& c, const std::filesystem::path& file, const SaveOptions& opt) {
  const vtkIdType n = static_cast<vtkIdType>(c.points.size());
  vtkNew<vtkDoubleArray> xyz;
  xyz->SetNumberOfComponents(3);
  xyz->SetNumberOfTuples(n);
  double* out = xyz->GetPointer(0);
  for (const Vec2& p : c.points) {
    *out++ = p.x;
    *out++ = p.y;
    *out++ = 0;
  }
  vtkNew<vtkPoints> points;
  points->SetData(xyz);

  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(static_cast<vtkIdType>(c.paths()) + 1);
  offsets->SetValue(0, 0);
  for (std::size_t i = 0; i < c.paths(); ++i) offsets->SetValue(static_cast<vtkIdType>(i) + 1, static_cast<vtkIdType>(c.path_ends[i]));
  connectivity->SetNumberOfTuples(n);
  std::iota(connectivity->GetPointer(0), connectivity->GetPointer(0) + n, vtkIdType{0});
  vtkNew<vtkCellArray> lines;
  lines->SetData(offsets, connectivity);

  vtkNew<vtkPolyData> poly;
  poly->SetPoints(points);
  poly->SetLines(lines);

  vtkNew<vtkIntArray> level;
  level->SetName("level");
  level->SetNumberOfTuples(n);
  std::fill(level->GetPointer(0), level->GetPointer(0) + n, c.level);
  poly->GetPointData()->AddArray(level);

  vtkNew<vtkDoubleArray> arc;
  arc->SetName("arclength");
  arc->SetNumberOfTuples(n);
  const std::vector<double> s = arclength(c);
  std::copy(s.begin(), s.end(), arc->GetPointer(0));
  poly->GetPointData()->AddArray(arc);
  poly->GetPointData()->SetActiveScalars("arclength");

  vtkNew<vtkIntArray> path;
  path->SetName("path");
  path->SetNumberOfTuples(static_cast<vtkIdType>(c.paths()));
  std::iota(path->GetPointer(0), path->GetPointer(0) + c.paths(), 0);
  poly->GetCellData()->AddArray(path);

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetFileName(file.c_str());
  writer->SetInputData(poly);
  writer->SetDataModeToAppended();
  writer->EncodeAppendedDataOff();  // raw bytes: several times faster to write and read than base64
  writer->SetHeaderTypeToUInt64();  // arrays over 4 GiB
  if (opt.compress) writer->SetCompressorTypeToZLib();
  else writer->SetCompressorTypeToNone();
  if (writer->Write() != 1) throw Error("cannot write '" + file.string() + "'");
}

Dataset read_vtp(const std::filesystem::path& file) {
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  if (reader->GetErrorCode() != 0 || poly == nullptr) throw Error("cannot read '" + file.string() + "' as VTK PolyData");
  Dataset d;
  d.points.resize(static_cast<std::size_t>(poly->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) poly->GetPoint(i, d.points[static_cast<std::size_t>(i)].data());
  for (vtkCellArray* cells : {poly->GetVerts(), poly->GetLines(), poly->GetPolys(), poly->GetStrips()}) {
    const vtkIdType* ids = nullptr;
    vtkIdType count = 0;
    for (cells->InitTraversal(); cells->GetNextCell(count, ids);) {
      d.cell_points.insert(d.cell_points.end(), ids, ids + count);
      d.cell_ends.push_back(d.cell_points.size());
    }
  }
  for (int i = 0; i < poly->GetPointData()->GetNumberOfArrays(); ++i)
    if (vtkDataArray* a = poly->GetPointData()->GetArray(i)) d.point_fields[a->GetName() ? a->GetName() : "?"] = field_of(a);
  for (int i = 0; i < poly->GetCellData()->GetNumberOfArrays(); ++i)
    if (vtkDataArray* a = poly->GetCellData()->GetArray(i)) d.cell_fields[a->GetName() ? a->GetName() : "?"] = field_of(a);
  return d;
}

}  // namespace selfsim::io
