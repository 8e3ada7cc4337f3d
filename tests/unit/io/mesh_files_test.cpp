// .stl, .obj and .ply meshes written through OpenMesh, read back twice: with io::read_dataset (OpenMesh's
// readers in a child process) and, independently, with VTK's vtkSTLReader, vtkOBJReader and vtkPLYReader.
// STL repeats corners (readers merge them) and STL and PLY hold float32 coordinates, so points compare as
// sets within 1e-6 and triangles by the original points they use, in order up to rotation (orientation
// is kept).
#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "io_fixtures.h"
#include "kernels/base/error.h"
#include "kernels/geom/mesh.h"
#include "kernels/io/read.h"
#include "kernels/io/save.h"

#if __has_include(<vtkSTLReader.h>) && __has_include(<vtkPLYReader.h>) && __has_include(<vtkOBJReader.h>)
#define SELFSIM_TEST_WITH_VTK_MESH_READERS 1
#include <vtkCellArray.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#endif

using namespace selfsim;
namespace fs = std::filesystem;

namespace {

using Point = std::array<double, 3>;
using Corners = std::array<std::size_t, 3>;

// A tetrahedron, faces outward, at coordinates float32 cannot hold exactly.
Mesh tetrahedron() {
  Mesh m;
  m.points = {{0.1, 0.2, 0.3}, {1.1, 0.2, 0.3}, {0.1, 1.2, 0.3}, {0.1, 0.2, 1.3}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// An open square of two triangles, tilted out of z = 0.
Mesh square() {
  Mesh m;
  m.points = {{0, 0, 0.1}, {1, 0, 0.2}, {1, 1, 0.3}, {0, 1, 0.2}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// Three triangles on the edge (0, 1): OpenMesh, and so STL, OBJ and PLY, cannot hold it.
Mesh three_on_one_edge() {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  return m;
}

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::size_t files_in(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

// The index of the point of m within 1e-6 of p on every axis; m.points.size() when none or several are.
std::size_t original_index(const Mesh& m, const Point& p) {
  std::size_t found = m.points.size(), matches = 0;
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    const Vec3 q = m.points[i];
    if (std::abs(q.x - p[0]) <= 1e-6 && std::abs(q.y - p[1]) <= 1e-6 && std::abs(q.z - p[2]) <= 1e-6)
      found = i, ++matches;
  }
  return matches == 1 ? found : m.points.size();
}

// The triangle rotated to start at its smallest index (same orientation).
Corners canonical(Corners t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

std::vector<Corners> canonical_triangles(const Mesh& m) {
  std::vector<Corners> out;
  for (const Triangle& t : m.triangles) out.push_back(canonical({t[0], t[1], t[2]}));
  std::sort(out.begin(), out.end());
  return out;
}

// `points` (distinct) and `triangles` (point ids, one per corner) are m's points and triangles, in any
// order, within 1e-6, with every triangle's orientation kept.
void expect_same_mesh(const Mesh& m, const std::vector<Point>& points, const std::vector<Corners>& triangles) {
  ASSERT_EQ(points.size(), m.points.size());
  std::vector<std::size_t> to_original;
  std::vector<int> hits(m.points.size() + 1, 0);
  for (const Point& p : points) {
    to_original.push_back(original_index(m, p));
    ++hits[to_original.back()];
  }
  for (std::size_t i = 0; i < m.points.size(); ++i) EXPECT_EQ(hits[i], 1) << "original point " << i;
  ASSERT_EQ(hits.back(), 0) << "points that match no original point";
  ASSERT_EQ(triangles.size(), m.faces());
  std::vector<Corners> got;
  for (const Corners& t : triangles) {
    for (std::size_t id : t) ASSERT_LT(id, to_original.size());
    got.push_back(canonical({to_original[t[0]], to_original[t[1]], to_original[t[2]]}));
  }
  std::sort(got.begin(), got.end());
  EXPECT_EQ(got, canonical_triangles(m));
}

void expect_same_mesh(const Mesh& m, const io::Dataset& d) {
  EXPECT_EQ(d.shapes, io::CellShapes::polygons);
  std::vector<Corners> triangles;
  std::size_t begin = 0;
  for (std::size_t end : d.cell_ends) {
    ASSERT_EQ(end - begin, 3u) << "a cell that is not a triangle";
    triangles.push_back({d.cell_points[begin], d.cell_points[begin + 1], d.cell_points[begin + 2]});
    begin = end;
  }
  expect_same_mesh(m, d.points, triangles);
}

#ifdef SELFSIM_TEST_WITH_VTK_MESH_READERS

// The mesh file read by VTK's own reader for its extension, in this process.
vtkSmartPointer<vtkPolyData> vtk_read(const fs::path& f) {
  ::setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 1);  // read_dataset forks: no started TBB backend
  vtkSmartPointer<vtkPolyDataAlgorithm> r;
  const std::string ext = f.extension().string();
  if (ext == ".stl") {
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->SetFileName(f.c_str());
    r = stl;
  } else if (ext == ".ply") {
    auto ply = vtkSmartPointer<vtkPLYReader>::New();
    ply->SetFileName(f.c_str());
    r = ply;
  } else {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(f.c_str());
    r = obj;
  }
  r->Update();
  EXPECT_EQ(r->GetErrorCode(), 0) << f;
  return r->GetOutput();
}

// VTK's points, merged within 1e-9 (an STL reader may keep every corner), and its triangles on them.
void expect_same_mesh(const Mesh& m, vtkPolyData* d) {
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->GetNumberOfLines(), 0);
  EXPECT_EQ(d->GetNumberOfPolys(), static_cast<vtkIdType>(m.faces()));
  std::vector<Point> points;
  std::vector<std::size_t> merged;  // VTK point id -> index into points
  for (vtkIdType i = 0; i < d->GetNumberOfPoints(); ++i) {
    Point p;
    d->GetPoint(i, p.data());
    auto same = std::find_if(points.begin(), points.end(), [&](const Point& q) {
      return std::abs(p[0] - q[0]) <= 1e-9 && std::abs(p[1] - q[1]) <= 1e-9 && std::abs(p[2] - q[2]) <= 1e-9;
    });
    merged.push_back(static_cast<std::size_t>(same - points.begin()));
    if (same == points.end()) points.push_back(p);
  }
  std::vector<Corners> triangles;
  vtkCellArray* polys = d->GetPolys();
  const vtkIdType* ids = nullptr;
  vtkIdType n = 0;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);) {
    ASSERT_EQ(n, 3) << "a polygon that is not a triangle";
    triangles.push_back({merged[static_cast<std::size_t>(ids[0])], merged[static_cast<std::size_t>(ids[1])],
                         merged[static_cast<std::size_t>(ids[2])]});
  }
  expect_same_mesh(m, points, triangles);
}

#endif  // SELFSIM_TEST_WITH_VTK_MESH_READERS

using MeshFiles = io_fixtures::PerFormatTest;

}  // namespace

TEST_P(MeshFiles, TetrahedronThroughReadDataset) {
  const Mesh m = tetrahedron();
  const fs::path f = file("tetra");
  EXPECT_EQ(io::save(&m, f, {}, no_progress()), f.string());
  const io::Dataset d = io::read_dataset(f);
  expect_same_mesh(m, d);
  EXPECT_TRUE(d.point_fields.empty());  // these formats hold no fields
  EXPECT_TRUE(d.cell_fields.empty());
}

// OpenMesh's own reader, independent of selfsim's, reads what selfsim writes: same counts, same closedness.
TEST_P(MeshFiles, TetrahedronThroughOpenMeshReader) {
  const Mesh m = tetrahedron();
  const fs::path f = file("tetra_om");
  io::save(&m, f, {}, no_progress());
  OpenMesh::TriMesh_ArrayKernelT<> om;
  OpenMesh::IO::Options opt;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(om, f.string(), opt));
  EXPECT_EQ(om.n_vertices(), 4u);
  EXPECT_EQ(om.n_faces(), 4u);
  for (const auto& e : om.edges()) EXPECT_FALSE(om.is_boundary(e));
}

TEST_P(MeshFiles, OpenSquareThroughReadDataset) {
  const Mesh m = square();
  const fs::path f = file("square");
  io::save(&m, f, {}, no_progress());
  expect_same_mesh(m, io::read_dataset(f));
}

TEST_P(MeshFiles, FieldsAreDroppedNotRefused) {
  Mesh m = tetrahedron();
  m.point_fields.set(real_field("thickness", {1, 2, 3, 4}));
  m.face_fields.set(int_field("tile_class", {0, 1, 0, 1}));
  const fs::path f = file("tetra");
  io::save(&m, f, {}, no_progress());
  expect_same_mesh(m, io::read_dataset(f));
}

TEST_P(MeshFiles, NonManifoldMeshIsRefusedAndLeavesNoFile) {
  const Mesh m = three_on_one_edge();
  try {
    io::save(&m, file("bad"), {}, no_progress());
    FAIL() << "a non-manifold mesh was saved";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("non-manifold"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("triangle 3"), std::string::npos) << e.what();
  }
  EXPECT_EQ(files_in(dir), 0u);
}

TEST_P(MeshFiles, FlippedFaceIsRefused) {
  Mesh m = tetrahedron();
  m.triangles[3] = {1, 3, 2};
  try {
    io::save(&m, file("flipped"), {}, no_progress());
    FAIL() << "a mesh with a flipped face was saved";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("non-manifold"), std::string::npos) << e.what();
  }
  EXPECT_EQ(files_in(dir), 0u);
}

TEST_P(MeshFiles, CancelledWriteLeavesNoFile) {
  struct StopAtOnce : Progress {
    bool cancelled() override { return true; }
  } stop;
  const Mesh m = tetrahedron();
  EXPECT_THROW(io::save(&m, file("tetra"), {}, stop), Cancelled);
  EXPECT_EQ(files_in(dir), 0u);
}

TEST_P(MeshFiles, CancelledWriteKeepsTheOldFile) {
  struct StopAtOnce : Progress {
    bool cancelled() override { return true; }
  } stop;
  const fs::path f = file("tetra");
  { std::ofstream(f) << "old"; }
  const Mesh m = tetrahedron();
  EXPECT_THROW(io::save(&m, f, {}, stop), Cancelled);
  EXPECT_EQ(slurp(f), "old");
  EXPECT_EQ(files_in(dir), 1u);
}

#ifdef SELFSIM_TEST_WITH_VTK_MESH_READERS

TEST_P(MeshFiles, TetrahedronThroughVtkReader) {
  const Mesh m = tetrahedron();
  const fs::path f = file("tetra");
  io::save(&m, f, {}, no_progress());
  expect_same_mesh(m, vtk_read(f));
}

TEST_P(MeshFiles, OpenSquareThroughVtkReader) {
  const Mesh m = square();
  const fs::path f = file("square");
  io::save(&m, f, {}, no_progress());
  expect_same_mesh(m, vtk_read(f));
}

#else

TEST_P(MeshFiles, VtkReaderChecksNeedVtkHeaders) {
  GTEST_SKIP() << "VTK headers are not on the unit tests' include path: link selfsim_unit_tests with "
                  "VTK::IOGeometry and VTK::IOPLY to check the files with VTK's own readers too";
}

#endif  // SELFSIM_TEST_WITH_VTK_MESH_READERS

INSTANTIATE_TEST_SUITE_P(Formats, MeshFiles, ::testing::Values(".stl", ".obj", ".ply"),
                         [](const auto& info) { return std::string(info.param).substr(1); });

TEST(MeshFilesStl, IsBinaryWith50BytesATriangle) {
  io_fixtures::TempDir dir;
  for (const Mesh& m : {tetrahedron(), square()}) {
    const fs::path f = dir.path / "m.stl";
    io::save(&m, f, {}, no_progress());
    const std::string bytes = slurp(f);
    ASSERT_EQ(bytes.size(), 84 + 50 * m.faces());
    std::uint32_t count = 0;
    std::memcpy(&count, bytes.data() + 80, 4);
    EXPECT_EQ(count, m.faces());
    EXPECT_NE(bytes.rfind("solid", 0), 0u) << "an ASCII STL header";
  }
}

TEST(MeshFilesStl, NormalsPointOutward) {
  // Each 50-byte record starts with the face normal (3 float32); for the unit corner tetrahedron around
  // its centroid the normal points away from it.
  io_fixtures::TempDir dir;
  const Mesh m = tetrahedron();
  const fs::path f = dir.path / "m.stl";
  io::save(&m, f, {}, no_progress());
  const std::string bytes = slurp(f);
  ASSERT_EQ(bytes.size(), 84 + 50 * m.faces());
  const Vec3 centre = (m.points[0] + m.points[1] + m.points[2] + m.points[3]) / 4;
  for (std::size_t k = 0; k < m.faces(); ++k) {
    float r[12];
    std::memcpy(r, bytes.data() + 84 + 50 * k, sizeof r);
    const Vec3 normal{r[0], r[1], r[2]};
    const Vec3 corner_centre = Vec3{r[3] + r[6] + r[9], r[4] + r[7] + r[10], r[5] + r[8] + r[11]} / 3;
    EXPECT_NEAR(norm(normal), 1, 1e-6) << "triangle " << k;
    EXPECT_GT(dot(normal, corner_centre - centre), 0) << "triangle " << k;
  }
}

TEST(MeshFilesObj, IsTextWithAVertexLineAPointAndAFaceLineATriangle) {
  io_fixtures::TempDir dir;
  const Mesh m = tetrahedron();
  const fs::path f = dir.path / "m.obj";
  io::save(&m, f, {}, no_progress());
  std::ifstream in(f);
  std::size_t v = 0, faces = 0;
  for (std::string line; std::getline(in, line);) {
    v += line.rfind("v ", 0) == 0;
    faces += line.rfind("f ", 0) == 0;
  }
  EXPECT_EQ(v, m.points.size());
  EXPECT_EQ(faces, m.faces());
}

// OpenMesh 9's writers take every point through a Vec3f, so .obj (like .stl and .ply) holds single precision:
// written with 9 digits (all a float32 needs), each coordinate reads back as the same float32.
TEST(MeshFilesObj, HoldsSinglePrecisionExactly) {
  io_fixtures::TempDir dir;
  Mesh m = tetrahedron();
  m.points[3] = {0.1, 0.2, 1.0 / 3};
  const fs::path f = dir.path / "m.obj";
  io::save(&m, f, {}, no_progress());
  const io::Dataset d = io::read_dataset(f);
  ASSERT_EQ(d.points.size(), 4u);
  bool found = false;
  for (const Point& p : d.points) found |= float(p[0]) == 0.1f && float(p[1]) == 0.2f && float(p[2]) == 1.0f / 3;
  EXPECT_TRUE(found) << "no point (0.1, 0.2, 1/3) as float32";
  EXPECT_EQ(slurp(f).find("0.10000000149011612"), std::string::npos) << "17 digits of a float are noise";
}

TEST(MeshFilesPly, IsBinaryLittleEndian) {
  io_fixtures::TempDir dir;
  const Mesh m = tetrahedron();
  const fs::path f = dir.path / "m.ply";
  io::save(&m, f, {}, no_progress());
  const std::string bytes = slurp(f);
  EXPECT_EQ(bytes.rfind("ply\n", 0), 0u);
  EXPECT_NE(bytes.find("format binary_little_endian 1.0"), std::string::npos);
  EXPECT_NE(bytes.find("element vertex 4"), std::string::npos);
  EXPECT_NE(bytes.find("element face 4"), std::string::npos);
}

TEST(MeshFilesSave, CurvesAreNotMeshFormats) {
  io_fixtures::TempDir dir;
  for (const char* name : {"c.stl", "c.obj", "c.ply"}) {
    EXPECT_THROW(io::save(&io_fixtures::two_paths_value, dir.path / name, {}, no_progress()), Error) << name;
  }
  EXPECT_EQ(files_in(dir.path), 0u);
}

TEST(MeshFilesSave, EmptyMeshIsRefused) {
  io_fixtures::TempDir dir;
  const Mesh m;
  try {
    io::save(&m, dir.path / "m.stl", {}, no_progress());
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot save a mesh without triangles to 'm.stl'");
  }
  EXPECT_EQ(files_in(dir.path), 0u);
}
