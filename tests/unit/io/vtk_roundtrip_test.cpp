// .vtp and .vtu written by selfsim's own VTK XML writer, read back twice: with io::read_dataset (what
// `selfsim diff` and load() use) and, independently, with VTK's XML readers in this process (what ParaView
// uses). Points, cells, every field's name, type, component count and values must survive, and curves get
// the derived fields 'arclength' (restarting on each path) and 'path'.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <set>
#include <string>
#include <vector>

#include "io_fixtures.h"
#include "kernels/base/error.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"
#include "kernels/io/read.h"
#include "kernels/io/save.h"

#if __has_include(<vtkXMLPolyDataReader.h>)
#define SELFSIM_TEST_WITH_VTK 1
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPointSet.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>
#endif

using namespace selfsim;
namespace fs = std::filesystem;

namespace {

using Values = std::vector<double>;

// io_fixtures::two_paths() with a per-point float64 colour of 3 components and a per-path int32 'curve'.
const Values curve2_color{0, 0.1, 0.2, 1, 1.1, 1.2, 2, 2.1, 2.2, 3, 3.1, 3.2, 4, 4.1, 4.2};
Polyline curve2() {
  Polyline c = io_fixtures::two_paths();
  c.point_fields.set(real_field("color", curve2_color, 3));
  c.cell_fields.set(int_field("curve", {10, -20}));
  return c;
}
const Values curve2_arclength{0, 1, 2, 0, std::sqrt(1.25)};

// Two 3D paths with z values, a uniform level of 3.
Polyline3 curve3() {
  Polyline3 c;
  c.points = {{0, 0, 0}, {1, 0, 0.5}, {1, 1, 1.5}, {2, 2, -1}, {2, 3, -2}};
  c.path_ends = {3, 5};
  c.point_fields.set(uniform_int("level", 3));
  return c;
}
const Values curve3_arclength{0, std::sqrt(1.25), std::sqrt(1.25) + std::sqrt(2.0), 0, std::sqrt(2.0)};

// The unit corner tetrahedron with a point float field, an int face field and a 2-component point field.
Mesh tetrahedron() {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  m.point_fields.set(real_field("thickness", {0.5, 1.5, 2.5, 3.25}));
  m.face_fields.set(int_field("tile_class", {0, 1, 2, -3}));
  m.point_fields.set(real_field("uv", {0, 0, 1, 0, 0, 1, 0.25, 0.75}, 2));
  return m;
}

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

template <class Map>
std::set<std::string> names(const Map& m) {
  std::set<std::string> s;
  for (const auto& [name, v] : m) s.insert(name);
  return s;
}

// The field `name` of d's point or cell fields has `components` components and exactly `values`.
void expect_field(const std::map<std::string, io::FieldValues>& fields, const std::string& name, int components,
                  const Values& values) {
  auto it = fields.find(name);
  ASSERT_NE(it, fields.end()) << "no field " << name;
  EXPECT_EQ(it->second.components, components) << name;
  ASSERT_EQ(it->second.values.size(), values.size()) << name;
  for (std::size_t i = 0; i < values.size(); ++i)
    EXPECT_NEAR(it->second.values[i], values[i], 1e-15) << name << "[" << i << "]";
}

std::vector<std::array<double, 3>> points3(const PointArray<Vec2>& p) {
  std::vector<std::array<double, 3>> out;
  for (const Vec2& v : p) out.push_back({v.x, v.y, 0});
  return out;
}
template <class Allocator>
std::vector<std::array<double, 3>> points3(const std::vector<Vec3, Allocator>& p) {
  std::vector<std::array<double, 3>> out;
  for (const Vec3& v : p) out.push_back({v.x, v.y, v.z});
  return out;
}

// A curve read back through io::read_dataset: points, polyline cells and fields.
template <class V>
void expect_curve_dataset(const io::Dataset& d, const PolylineT<V>& c, const Values& arclength) {
  EXPECT_EQ(d.shapes, io::CellShapes::lines);
  EXPECT_EQ(d.points, points3(c.points));
  EXPECT_EQ(d.cell_ends, c.path_ends);
  std::vector<std::size_t> ids(c.points.size());
  for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = i;
  EXPECT_EQ(d.cell_points, ids);
  expect_field(d.point_fields, "arclength", 1, arclength);
  Values path;
  for (std::size_t i = 0; i < c.paths(); ++i) path.push_back(static_cast<double>(i));
  expect_field(d.cell_fields, "path", 1, path);
}

const std::vector<std::vector<std::size_t>> tetrahedron_cells{{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};

void expect_tetrahedron_dataset(const io::Dataset& d) {
  EXPECT_EQ(d.shapes, io::CellShapes::polygons);
  EXPECT_EQ(d.points, points3(tetrahedron().points));
  EXPECT_EQ(d.cell_ends, (std::vector<std::size_t>{3, 6, 9, 12}));
  EXPECT_EQ(d.cell_points, (std::vector<std::size_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  EXPECT_EQ(names(d.point_fields), (std::set<std::string>{"thickness", "uv"}));  // no curve fields on a mesh
  EXPECT_EQ(names(d.cell_fields), (std::set<std::string>{"tile_class"}));
  expect_field(d.point_fields, "thickness", 1, {0.5, 1.5, 2.5, 3.25});
  expect_field(d.point_fields, "uv", 2, {0, 0, 1, 0, 0, 1, 0.25, 0.75});
  expect_field(d.cell_fields, "tile_class", 1, {0, 1, 2, -3});
}

// The XML header declares each array with its VTK type.
void expect_declared(const std::string& text, const std::string& type, const std::string& name, int components) {
  const std::string declaration = "<DataArray type=\"" + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" +
                                  std::to_string(components) + "\"";
  EXPECT_NE(text.find(declaration), std::string::npos) << declaration;
}

#ifdef SELFSIM_TEST_WITH_VTK

// The file read by VTK's own XML reader, in this process.
vtkSmartPointer<vtkPointSet> vtk_read(const fs::path& f) {
  // Sequential SMP: read_dataset forks, and a forked child must not inherit a started TBB backend.
  ::setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 1);
  vtkSmartPointer<vtkPointSet> out;
  if (f.extension() == ".vtu") {
    auto r = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    r->SetFileName(f.c_str());
    r->Update();
    EXPECT_EQ(r->GetErrorCode(), 0);
    out = r->GetOutput();
  } else {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(f.c_str());
    r->Update();
    EXPECT_EQ(r->GetErrorCode(), 0);
    out = r->GetOutput();
  }
  return out;
}

void expect_vtk_points(vtkPointSet* d, const std::vector<std::array<double, 3>>& points) {
  ASSERT_EQ(d->GetNumberOfPoints(), static_cast<vtkIdType>(points.size()));
  for (vtkIdType i = 0; i < d->GetNumberOfPoints(); ++i) {
    double p[3];
    d->GetPoint(i, p);
    EXPECT_EQ((std::array<double, 3>{p[0], p[1], p[2]}), points[static_cast<std::size_t>(i)]) << "point " << i;
  }
}

// Cell i has exactly the point ids cells[i] and a type in `types`.
void expect_vtk_cells(vtkPointSet* d, const std::vector<std::vector<std::size_t>>& cells, std::set<int> types) {
  ASSERT_EQ(d->GetNumberOfCells(), static_cast<vtkIdType>(cells.size()));
  auto ids = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType i = 0; i < d->GetNumberOfCells(); ++i) {
    d->GetCellPoints(i, ids);
    std::vector<std::size_t> got;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) got.push_back(static_cast<std::size_t>(ids->GetId(k)));
    EXPECT_EQ(got, cells[static_cast<std::size_t>(i)]) << "cell " << i;
    EXPECT_TRUE(types.contains(d->GetCellType(i))) << "cell " << i << " has VTK type " << d->GetCellType(i);
  }
}

// The array `name` in `data`: VTK type (VTK_INT or VTK_DOUBLE), components and values.
void expect_vtk_array(vtkFieldData* data, const std::string& name, int vtk_type, int components, const Values& values) {
  int count = 0;
  for (int i = 0; i < data->GetNumberOfArrays(); ++i)
    if (data->GetArrayName(i) && name == data->GetArrayName(i)) ++count;
  EXPECT_EQ(count, 1) << "arrays named " << name;
  vtkDataArray* a = data->GetArray(name.c_str());
  ASSERT_NE(a, nullptr) << "no VTK array " << name;
  EXPECT_EQ(a->GetDataType(), vtk_type) << name << " is " << a->GetDataTypeAsString();
  EXPECT_EQ(a->GetNumberOfComponents(), components) << name;
  ASSERT_EQ(a->GetNumberOfTuples() * components, static_cast<vtkIdType>(values.size())) << name;
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int k = 0; k < components; ++k)
      EXPECT_NEAR(a->GetComponent(i, k), values[static_cast<std::size_t>(i * components + k)], 1e-15)
          << name << "[" << i << "][" << k << "]";
}

std::vector<std::vector<std::size_t>> path_cells(const std::vector<std::size_t>& ends) {
  std::vector<std::vector<std::size_t>> cells;
  std::size_t begin = 0;
  for (std::size_t end : ends) {
    cells.emplace_back();
    for (std::size_t i = begin; i < end; ++i) cells.back().push_back(i);
    begin = end;
  }
  return cells;
}

// Curves: polylines (a 2-point line reads as VTK_LINE from PolyData) in .vtp, VTK_POLY_LINE cells in .vtu.
std::set<int> curve_types(const fs::path& f) {
  return f.extension() == ".vtu" ? std::set<int>{VTK_POLY_LINE} : std::set<int>{VTK_LINE, VTK_POLY_LINE};
}

#endif  // SELFSIM_TEST_WITH_VTK

using VtkRoundTrip = io_fixtures::PerFormatTest;

}  // namespace

TEST_P(VtkRoundTrip, CurveWithFieldsThroughReadDataset) {
  const Polyline c = curve2();
  const fs::path f = file("curve");
  EXPECT_EQ(io::save(&c, f, {}, no_progress()), f.string());
  const io::Dataset d = io::read_dataset(f);
  expect_curve_dataset(d, c, curve2_arclength);
  EXPECT_EQ(names(d.point_fields), (std::set<std::string>{"level", "color", "arclength"}));
  EXPECT_EQ(names(d.cell_fields), (std::set<std::string>{"curve", "path"}));
  expect_field(d.point_fields, "level", 1, Values(5, 7));  // the uniform field, once per point
  expect_field(d.point_fields, "color", 3, curve2_color);
  expect_field(d.cell_fields, "curve", 1, {10, -20});
}

TEST_P(VtkRoundTrip, CurveDeclaresInt32AndFloat64Arrays) {
  const Polyline c = curve2();
  const fs::path f = file("curve");
  io::save(&c, f, {}, no_progress());
  const std::string text = slurp(f);
  expect_declared(text, "Int32", "level", 1);
  expect_declared(text, "Float64", "color", 3);
  expect_declared(text, "Float64", "arclength", 1);
  expect_declared(text, "Int32", "curve", 1);
  expect_declared(text, "Int32", "path", 1);
  expect_declared(text, "Float64", "Points", 3);
  EXPECT_NE(text.find(std::string("<VTKFile type=\"") +
                      (std::string(GetParam()) == ".vtu" ? "UnstructuredGrid" : "PolyData") + "\""),
            std::string::npos);
}

TEST_P(VtkRoundTrip, Curve3KeepsZ) {
  const Polyline3 c = curve3();
  const fs::path f = file("helix");
  io::save(&c, f, {}, no_progress());
  const io::Dataset d = io::read_dataset(f);
  expect_curve_dataset(d, c, curve3_arclength);
  EXPECT_EQ(d.points[2], (std::array<double, 3>{1, 1, 1.5}));
  EXPECT_EQ(d.points[4], (std::array<double, 3>{2, 3, -2}));
  expect_field(d.point_fields, "level", 1, Values(5, 3));
}

TEST_P(VtkRoundTrip, MeshWithFieldsThroughReadDataset) {
  const Mesh m = tetrahedron();
  const fs::path f = file("tetra");
  io::save(&m, f, {}, no_progress());
  expect_tetrahedron_dataset(io::read_dataset(f));
  const std::string text = slurp(f);
  expect_declared(text, "Float64", "thickness", 1);
  expect_declared(text, "Float64", "uv", 2);
  expect_declared(text, "Int32", "tile_class", 1);
}

TEST_P(VtkRoundTrip, FieldsAKernelAttachedAreNotReplaced) {
  Polyline c = curve2();
  c.point_fields.set(real_field("arclength", {9, 8, 7, 6, 5}));
  c.cell_fields.set(int_field("path", {4, 4}));
  const fs::path f = file("own");
  io::save(&c, f, {}, no_progress());
  const io::Dataset d = io::read_dataset(f);
  expect_field(d.point_fields, "arclength", 1, {9, 8, 7, 6, 5});
  expect_field(d.cell_fields, "path", 1, {4, 4});
  const std::string text = slurp(f);
  EXPECT_EQ(text.find("Name=\"arclength\""), text.rfind("Name=\"arclength\""));  // declared once
  EXPECT_EQ(text.find("Name=\"path\""), text.rfind("Name=\"path\""));
}

TEST_P(VtkRoundTrip, ArclengthRestartsPerPathAcrossWriterChunks) {
  // Three paths of 50000 unit steps: 150000 points, more than two of the writer's 65536-value chunks, with
  // path starts inside chunks and chunk boundaries inside paths.
  Polyline c;
  const std::size_t n = 50000;
  for (std::size_t p = 0; p < 3; ++p) {
    for (std::size_t i = 0; i < n; ++i) c.points.push_back({static_cast<double>(i), static_cast<double>(p)});
    c.close_path();
  }
  const fs::path f = file("long");
  io::save(&c, f, {}, no_progress());
  const io::Dataset d = io::read_dataset(f);
  const Values& a = d.point_fields.at("arclength").values;
  ASSERT_EQ(a.size(), 3 * n);
  std::size_t wrong = 0;
  for (std::size_t k = 0; k < a.size(); ++k) wrong += a[k] != static_cast<double>(k % n);
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(a[n - 1], n - 1.0);
  EXPECT_EQ(a[n], 0);
  EXPECT_EQ(a[65536], static_cast<double>(65536 - n));
  EXPECT_EQ(d.cell_ends, (std::vector<std::size_t>{n, 2 * n, 3 * n}));
}

// save() refuses a Polyline whose path_ends do not rise to exactly points.size() (only a kernel bug makes
// one: single() and close_path() keep paths consistent). Without the check, no or decreasing ends crashed
// the VTK writer, short ones wrote points of no cell, long ones a file VTK refuses. Each case runs in a
// forked child (a death test, "fast" style) so that a crash fails this test only.
TEST(SaveCurve, InconsistentPathsAreRefused) {
  const std::vector<std::pair<const char*, std::vector<std::size_t>>> cases{{"no path_ends", {}},
                                                                            {"ends short of the points", {3}},
                                                                            {"ends past the points", {3, 7}},
                                                                            {"decreasing ends", {3, 2, 5}}};
  io_fixtures::TempDir dir;
  for (const auto& [what, ends] : cases) {
    Polyline c;
    c.points = {{0, 0}, {1, 0}, {1, 1}, {2, 2}, {3, 3}};
    c.path_ends = ends;
    const fs::path f = dir.path / "c.vtp";
    // Exit code 0: refused with an Error; 1: saved; a signal: crashed.
    EXPECT_EXIT(
        {
          try {
            io::save(&c, f, {}, no_progress());
          } catch (const Error&) {
            std::_Exit(0);
          }
          std::_Exit(1);
        },
        ::testing::ExitedWithCode(0), "")
        << what;
  }
}

#ifdef SELFSIM_TEST_WITH_VTK

TEST_P(VtkRoundTrip, CurveThroughVtkReader) {
  const Polyline c = curve2();
  const fs::path f = file("curve");
  io::save(&c, f, {}, no_progress());
  const vtkSmartPointer<vtkPointSet> d = vtk_read(f);
  ASSERT_NE(d, nullptr);
  expect_vtk_points(d, points3(c.points));
  expect_vtk_cells(d, path_cells(c.path_ends), curve_types(f));
  vtkPointData* pd = d->GetPointData();
  vtkCellData* cd = d->GetCellData();
  EXPECT_EQ(pd->GetNumberOfArrays(), 3);
  EXPECT_EQ(cd->GetNumberOfArrays(), 2);
  expect_vtk_array(pd, "level", VTK_INT, 1, Values(5, 7));
  expect_vtk_array(pd, "color", VTK_DOUBLE, 3, curve2_color);
  expect_vtk_array(pd, "arclength", VTK_DOUBLE, 1, curve2_arclength);
  expect_vtk_array(cd, "curve", VTK_INT, 1, {10, -20});
  expect_vtk_array(cd, "path", VTK_INT, 1, {0, 1});
  ASSERT_NE(pd->GetScalars(), nullptr);  // what ParaView colours by first
  EXPECT_STREQ(pd->GetScalars()->GetName(), "arclength");
}

TEST_P(VtkRoundTrip, Curve3ThroughVtkReader) {
  const Polyline3 c = curve3();
  const fs::path f = file("helix");
  io::save(&c, f, {}, no_progress());
  const vtkSmartPointer<vtkPointSet> d = vtk_read(f);
  ASSERT_NE(d, nullptr);
  expect_vtk_points(d, points3(c.points));
  expect_vtk_cells(d, path_cells(c.path_ends), curve_types(f));
  expect_vtk_array(d->GetPointData(), "level", VTK_INT, 1, Values(5, 3));
  expect_vtk_array(d->GetPointData(), "arclength", VTK_DOUBLE, 1, curve3_arclength);
  expect_vtk_array(d->GetCellData(), "path", VTK_INT, 1, {0, 1});
}

TEST_P(VtkRoundTrip, MeshThroughVtkReader) {
  const Mesh m = tetrahedron();
  const fs::path f = file("tetra");
  io::save(&m, f, {}, no_progress());
  const vtkSmartPointer<vtkPointSet> d = vtk_read(f);
  ASSERT_NE(d, nullptr);
  expect_vtk_points(d, points3(m.points));
  expect_vtk_cells(d, tetrahedron_cells, {VTK_TRIANGLE});
  if (auto* poly = vtkPolyData::SafeDownCast(d)) {
    EXPECT_EQ(poly->GetNumberOfPolys(), 4);
    EXPECT_EQ(poly->GetNumberOfLines(), 0);
  }
  vtkPointData* pd = d->GetPointData();
  EXPECT_EQ(pd->GetNumberOfArrays(), 2);
  EXPECT_EQ(d->GetCellData()->GetNumberOfArrays(), 1);
  expect_vtk_array(pd, "thickness", VTK_DOUBLE, 1, {0.5, 1.5, 2.5, 3.25});
  expect_vtk_array(pd, "uv", VTK_DOUBLE, 2, {0, 0, 1, 0, 0, 1, 0.25, 0.75});
  expect_vtk_array(d->GetCellData(), "tile_class", VTK_INT, 1, {0, 1, 2, -3});
  ASSERT_NE(pd->GetScalars(), nullptr);
  EXPECT_STREQ(pd->GetScalars()->GetName(), "thickness");  // the first point field
}

#else

TEST_P(VtkRoundTrip, VtkReaderChecksNeedVtkHeaders) {
  GTEST_SKIP() << "VTK headers are not on the unit tests' include path: link selfsim_unit_tests with "
                  "VTK::IOXML to check the files with VTK's own readers too";
}

#endif  // SELFSIM_TEST_WITH_VTK

INSTANTIATE_TEST_SUITE_P(Formats, VtkRoundTrip, ::testing::Values(".vtp", ".vtu"),
                         [](const auto& info) { return std::string(info.param).substr(1); });
