// Reading .vtp files back (selfsim diff / info) with VTK's own reader, the one ParaView uses, so that every
// flavour of the format (ascii, inline base64, appended raw or base64, zlib / LZ4 / LZMA compression,
// either header type and byte order) reads as ParaView reads it. VTK's reader trusts the file, so a
// hostile or broken file goes through three guards:
//   1. check_vtk_header (vtk_header_check.h) streams the XML part and checks every declared size against
//      the file and a memory budget, so the crashes, std::bad_alloc aborts and hangs that crafted headers
//      cause in VTK never start. This alone handles every crafted file we know of.
//   2. VTK then reads in a forked child process (child_process.h) with an address-space limit and a time
//      limit. Whatever the checks did not foresee (a crash, an allocation failure, a loop deep inside VTK)
//      ends the child, not us, and becomes one line: "the VTK reader crashed (Segmentation fault)". The
//      child's stdout and stderr go to /dev/null and VTK's messages go to an output window that keeps the
//      first error, which comes back as the reason; nothing VTK says reaches the terminal. The Dataset
//      comes back over a pipe. The cost is a fork per file, nothing next to reading it.
//   3. The Dataset is checked (dataset_check.h) and must hold the points and cells the header declared.
// Simpler alternatives fall short: catching exceptions cannot catch a segfault, and checks alone cannot
// prove that a third-party reader never misbehaves.
#include <unistd.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cstdlib>

#include "kernels/base/error.h"
#include "kernels/io/child_process.h"
#include "kernels/io/dataset/dataset_check.h"
#include "kernels/io/dataset/dataset_pipe.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/regular_file.h"
#include "kernels/io/vtk/vtk_error_text.h"
#include "kernels/io/vtk/vtk_header_check.h"

namespace selfsim::io {

namespace {

// Keeps VTK's first error message and drops everything else VTK would print.
class FirstErrorWindow : public vtkOutputWindow {
 public:
  static FirstErrorWindow* New();
  vtkTypeMacro(FirstErrorWindow, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override {
    if (first_error.empty() && text) first_error = text;
  }
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  std::string first_error;
};
vtkStandardNewMacro(FirstErrorWindow);

// "ERROR: In .../vtkXMLReader.cxx, line 42\nvtkXMLPolyDataReader (0x55d0): Error parsing ...\n\n" -> the message.
std::string vtk_reason(const std::string& text, const std::string& vtk_name, const std::string& shown_name) {
  std::string reason = vtk_error_line(text);
  for (std::size_t at; (at = reason.find("  ")) != std::string::npos;) reason.erase(at, 1);
  for (std::size_t at; !vtk_name.empty() && (at = reason.find(vtk_name)) != std::string::npos;)
    reason.replace(at, vtk_name.size(), shown_name);
  if (reason.size() > 300) reason = reason.substr(0, 300) + "...";
  return reason.empty() ? "VTK could not read it" : "VTK: " + reason;
}

// Sends the values of a's tuples as doubles (the count goes first, from the caller): straight from
// memory when they already are doubles, in chunks otherwise.
void send_values(PipeOut& out, vtkDataArray* a, int components) {
  const vtkIdType n = a->GetNumberOfTuples();
  if (auto* doubles = vtkDoubleArray::FastDownCast(a); doubles && n > 0) {
    out.write(doubles->GetPointer(0),
              static_cast<std::size_t>(n) * static_cast<std::size_t>(components) * sizeof(double));
    return;
  }
  std::vector<double> chunk;
  for (vtkIdType begin = 0; begin < n; begin += 8192) {
    const vtkIdType end = std::min<vtkIdType>(n, begin + 8192);
    chunk.clear();
    for (vtkIdType i = begin; i < end; ++i)
      for (int k = 0; k < components; ++k) chunk.push_back(a->GetComponent(i, k));
    out.write(chunk.data(), chunk.size() * sizeof(double));
  }
}

void send_fields(PipeOut& out, vtkFieldData* data) {
  std::vector<vtkDataArray*> arrays;  // numeric arrays only: string arrays have no geometry to compare
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
    if (vtkDataArray* a = data->GetArray(i)) arrays.push_back(a);
  put_count(out, arrays.size());
  for (vtkDataArray* a : arrays) {
    put_name(out, a->GetName() ? a->GetName() : "?");
    put_count(out, static_cast<std::uint64_t>(a->GetNumberOfComponents()));
    put_count(out, static_cast<std::uint64_t>(a->GetNumberOfTuples()) *
                       static_cast<std::uint64_t>(a->GetNumberOfComponents()));
    send_values(out, a, a->GetNumberOfComponents());
  }
}

// A polydata or unstructured grid in dataset_pipe.h's format. Cells in VTK's cell order, which cell data
// follows: verts, lines, polys, strips for polydata; the one cell array of a grid.
void send_dataset(PipeOut& out, vtkPointSet* data, const std::vector<vtkCellArray*>& kinds, CellShapes shapes) {
  put_count(out, static_cast<std::uint64_t>(shapes));
  vtkPoints* points = data->GetPoints();
  if (points && points->GetData()) {
    if (points->GetData()->GetNumberOfComponents() != 3) throw Error("points without 3 components");  // VTK ensures 3
    put_count(out, static_cast<std::uint64_t>(points->GetNumberOfPoints()));
    send_values(out, points->GetData(), 3);
  } else {
    put_count(out, 0);
  }
  std::uint64_t cells = 0, ids = 0;
  for (vtkCellArray* c : kinds)
    if (c)
      cells += static_cast<std::uint64_t>(c->GetNumberOfCells()),
          ids += static_cast<std::uint64_t>(c->GetNumberOfConnectivityIds());
  std::vector<std::uint64_t> chunk;
  auto flush = [&](bool force) {
    if (chunk.size() >= 8192 || (force && !chunk.empty())) {
      out.write(chunk.data(), chunk.size() * sizeof(std::uint64_t));
      chunk.clear();
    }
  };
  for (int pass = 0; pass < 2; ++pass) {  // cell ends, then their point ids
    put_count(out, pass == 0 ? cells : ids);
    std::uint64_t end = 0;
    for (vtkCellArray* c : kinds) {
      if (!c) continue;
      const vtkIdType* cell = nullptr;
      vtkIdType count = 0;
      for (c->InitTraversal(); c->GetNextCell(count, cell);) {
        end += static_cast<std::uint64_t>(count);
        if (pass == 0)
          chunk.push_back(end);
        else
          for (vtkIdType k = 0; k < count; ++k)
            chunk.push_back(static_cast<std::uint64_t>(cell[k]));  // a negative id fails the range check
        flush(false);
      }
    }
    flush(true);
  }
  send_fields(out, data->GetPointData());
  send_fields(out, data->GetCellData());
  // How the file was made (provenance.h), a FieldData string, or nothing.
  vtkAbstractArray* made = data->GetFieldData() ? data->GetFieldData()->GetAbstractArray(provenance_key) : nullptr;
  auto* text = vtkStringArray::SafeDownCast(made);
  put_name(out, text && text->GetNumberOfValues() > 0 ? text->GetValue(0).substr(0, 1u << 16) : std::string());
}

// Polylines, polygons or both, from a grid's cell types.
CellShapes grid_shapes(vtkUnstructuredGrid* grid) {
  bool lines = false, polys = false, other = false;
  for (vtkIdType i = 0; i < grid->GetNumberOfCells(); ++i) {
    const int type = grid->GetCellType(i);
    lines |= type == VTK_LINE || type == VTK_POLY_LINE;
    polys |= type == VTK_TRIANGLE || type == VTK_QUAD || type == VTK_POLYGON;
    other |=
        !(type == VTK_LINE || type == VTK_POLY_LINE || type == VTK_TRIANGLE || type == VTK_QUAD || type == VTK_POLYGON);
  }
  return other || (lines && polys) ? CellShapes::mixed : polys ? CellShapes::polygons : CellShapes::lines;
}

// In the child: read with VTK, answer 'D' and the Dataset, or 'E' and the reason.
int read_in_child(PipeOut& out, const std::string& vtk_name, const std::string& shown_name, bool unstructured) {
  // No TBB threads in a forked child (TBB's state does not survive fork). vtkSMPTools.h itself does not
  // compile as C++20, so the backend is chosen through the variable VTK reads at its first SMP use.
  ::setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 1);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkNew<FirstErrorWindow> window;
  vtkOutputWindow::SetInstance(window);
  const vtkSmartPointer<vtkXMLReader> reader =
      unstructured ? vtkSmartPointer<vtkXMLReader>::Take(vtkXMLUnstructuredGridReader::New())
                   : vtkSmartPointer<vtkXMLReader>::Take(vtkXMLPolyDataReader::New());
  reader->SetFileName(vtk_name.c_str());
  reader->Update();
  vtkPolyData* poly = vtkPolyData::SafeDownCast(reader->GetOutputAsDataSet());
  vtkUnstructuredGrid* grid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutputAsDataSet());
  std::string error;
  if (!window->first_error.empty())
    error = vtk_reason(window->first_error, vtk_name, shown_name);
  else if (reader->GetErrorCode() != 0 || (poly == nullptr && grid == nullptr))
    error = "VTK could not read it";
  if (!error.empty()) {
    send_failure(out, error);
    return 0;
  }
  send_success(out);
  if (poly) {
    const bool lines = poly->GetNumberOfLines() > 0, polys = poly->GetNumberOfPolys() > 0,
               other = poly->GetNumberOfVerts() > 0 || poly->GetNumberOfStrips() > 0;
    const CellShapes shapes = other || (lines && polys) ? CellShapes::mixed
                              : polys                   ? CellShapes::polygons
                                                        : CellShapes::lines;
    send_dataset(out, poly, {poly->GetVerts(), poly->GetLines(), poly->GetPolys(), poly->GetStrips()}, shapes);
  } else {
    send_dataset(out, grid, {grid->GetCells()}, grid_shapes(grid));
  }
  return 0;
}

Dataset read_checked(const std::filesystem::path& file, bool unstructured) {
  const RegularFile f(file);
  const VtkDeclared declared = check_vtk_header(f, unstructured ? "UnstructuredGrid" : "PolyData");
  const std::string vtk_name = f.reopen_name(file);
  ChildLimits limits;
  limits.what = "the VTK reader";
  limits.memory_bytes =
      std::min((std::uint64_t{1} << 30) + 3 * declared.bytes, 3 * read_budget_bytes());  // half the machine
  limits.seconds = 30 + static_cast<double>(f.size() + declared.bytes) / (8 << 20);
  Dataset d;
  run_in_child(
      limits, [&](PipeOut& out) { return read_in_child(out, vtk_name, one_line(file.string()), unstructured); },
      [&](PipeIn& in) { d = receive_answer(in, limits.what, read_budget_bytes() / 8); });
  check_dataset(d);
  if (d.points.size() != declared.points || d.cell_ends.size() != declared.cells)
    throw Error("VTK read " + std::to_string(d.points.size()) + " points and " + std::to_string(d.cell_ends.size()) +
                " cells, but the file declares " + std::to_string(declared.points) + " and " +
                std::to_string(declared.cells));
  return d;
}

}  // namespace

Dataset read_vtk(const std::filesystem::path& file, bool unstructured) {
  try {
    return read_checked(file, unstructured);
  } catch (const std::bad_alloc&) {
    throw Error(cannot_read(file, "out of memory"));
  } catch (const std::exception& e) {
    throw Error(cannot_read(file, e.what()));
  }
}

}  // namespace selfsim::io
