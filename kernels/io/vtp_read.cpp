// Reading .vtp files back (selfsim diff / info) with VTK's own reader, the one ParaView uses.
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include "kernels/geom/error.h"
#include "kernels/io/read.h"

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
