// Decimation by VTK's vtkQuadricDecimation (decimate.h).
#include "kernels/print/decimate.h"

#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkQuadricDecimation.h>

#include <string>

#include "kernels/base/check.h"
#include "kernels/base/count_text.h"
#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"

namespace selfsim::print {

namespace {

// VTK's progress events ask our Progress whether to stop; the filter then aborts (AbortExecute).
class StopWhenCancelled : public vtkCommand {
 public:
  static StopWhenCancelled* New() { return new StopWhenCancelled; }
  Progress* progress = nullptr;
  bool stopped = false;
  void Execute(vtkObject* caller, unsigned long, void*) override {
    if (progress != nullptr && progress->cancelled()) {
      stopped = true;
      static_cast<vtkAlgorithm*>(caller)->AbortExecuteOn();
    }
  }
};

}  // namespace

Mesh decimate(const Mesh& m, double triangles, Progress& progress) {
  m.validate();
  const double n = static_cast<double>(m.faces());
  if (!(triangles >= 4) || !std::isfinite(triangles))
    throw Error("option 'triangles' must be at least 4, got " + number_text(triangles));
  if (!(triangles < n))
    throw Error("option 'triangles' is " + count_text(triangles) + ", but the mesh has only " + count_text(n) +
                ": decimation makes fewer");
  progress.start("decimating");
  const bool closed = mesh_topology(m, progress).closed();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(m.points.size()));
  for (std::size_t i = 0; i < m.points.size(); ++i)
    points->SetPoint(static_cast<vtkIdType>(i), m.points[i].x, m.points[i].y, m.points[i].z);
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(static_cast<vtkIdType>(m.faces()), static_cast<vtkIdType>(3 * m.faces()));
  for (const Triangle& t : m.triangles) {
    const vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  input->SetPolys(polys);
  vtkNew<vtkQuadricDecimation> filter;
  filter->SetInputData(input);
  filter->SetTargetReduction(1 - triangles / n);
  vtkNew<StopWhenCancelled> stop;
  stop->progress = &progress;
  filter->AddObserver(vtkCommand::ProgressEvent, stop);
  filter->Update();
  if (stop->stopped || progress.cancelled()) throw Cancelled();
  vtkPolyData* out = filter->GetOutput();
  Mesh r;
  r.points.resize(static_cast<std::size_t>(out->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i) {
    double p[3];
    out->GetPoint(i, p);
    r.points[static_cast<std::size_t>(i)] = {p[0], p[1], p[2]};
  }
  vtkCellArray* cells = out->GetPolys();
  vtkNew<vtkIdList> ids;
  for (cells->InitTraversal(); cells->GetNextCell(ids);)
    if (ids->GetNumberOfIds() == 3)
      r.triangles.push_back({static_cast<std::uint32_t>(ids->GetId(0)), static_cast<std::uint32_t>(ids->GetId(1)),
                             static_cast<std::uint32_t>(ids->GetId(2))});
  if (r.triangles.empty()) throw Error("VTK's decimation left no triangles");
  if (closed) {
    const std::string open = first_open_edge(r);
    if (!open.empty()) throw Error("VTK's decimation opened the closed mesh (" + open + "): ask for more triangles");
  }
  if (!r.finite()) throw Error("VTK's decimation gave non-finite points");
  return r;
}

}  // namespace selfsim::print
