// Tiny meshes built by hand, whose topology is known: closed solids, a disk, an annulus, and the three
// ways a mesh fails to be manifold (a flipped face, an edge of three faces, a bowtie vertex).
#include "kernels/geom/mesh_check.h"

#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "kernels/base/error.h"

using namespace selfsim;

namespace {

// The unit corner tetrahedron, every face counter-clockwise seen from outside.
Mesh tetrahedron() {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

// The regular octahedron: points ±x, ±y, ±z.
Mesh octahedron() {
  Mesh m;
  m.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// The unit square in z = 0 as two triangles, facing +z.
Mesh square() {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// A square ring in z = 0: inner square (points 0-3, half-width 1) and outer square (points 4-7, half-width
// 2), joined by 8 triangles, all facing +z.
Mesh annulus() {
  Mesh m;
  const double c[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};  // counter-clockwise
  for (const auto& p : c) m.points.push_back({p[0], p[1], 0});
  for (const auto& p : c) m.points.push_back({2 * p[0], 2 * p[1], 0});
  for (std::uint32_t i = 0; i < 4; ++i) {
    const std::uint32_t j = (i + 1) % 4;
    m.triangles.push_back({i, 4 + i, 4 + j});
    m.triangles.push_back({i, 4 + j, j});
  }
  return m;
}

// Every face of a convex mesh around the origin has its area normal pointing away from the origin.
void expect_outward(const Mesh& m) {
  for (const Triangle& t : m.triangles) {
    const Vec3 centre = (m.points[t[0]] + m.points[t[1]] + m.points[t[2]]) / 3;
    EXPECT_GT(dot(area_normal(m, t), centre), 0) << t[0] << " " << t[1] << " " << t[2];
  }
}

std::string validate_error(const Mesh& m) {
  try {
    m.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

TEST(MeshTopology, ClosedTetrahedron) {
  const Mesh m = tetrahedron();
  const MeshTopology t = mesh_topology(m);
  EXPECT_EQ(t.vertices, 4u);
  EXPECT_EQ(t.edges, 6u);
  EXPECT_EQ(t.faces, 4u);
  EXPECT_EQ(t.euler(), 2);
  EXPECT_EQ(t.boundary_edges, 0u);
  EXPECT_EQ(t.boundary_loops, 0u);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.nonmanifold_edges, 0u);
  EXPECT_EQ(t.misoriented_edges, 0u);
  EXPECT_EQ(t.nonmanifold_vertices, 0u);
  EXPECT_TRUE(t.manifold());
  EXPECT_TRUE(t.closed());
  EXPECT_EQ(t.first_problem, "");
}

TEST(MeshTopology, TetrahedronFacesOutward) {
  Mesh m = tetrahedron();
  for (Vec3& p : m.points) p -= Vec3::all(0.25);  // centroid at the origin
  expect_outward(m);
  // Twice the area of the slanted face (side sqrt 2) times its unit normal (1, 1, 1)/sqrt 3.
  EXPECT_EQ(area_normal(m, m.triangles[3]), (Vec3{1, 1, 1}));
  EXPECT_EQ(area_normal(m, {0, 1, 2}), -area_normal(m, {0, 2, 1}));
}

TEST(MeshTopology, ClosedOctahedron) {
  const Mesh m = octahedron();
  expect_outward(m);
  const MeshTopology t = mesh_topology(m);
  EXPECT_EQ(t.vertices, 6u);
  EXPECT_EQ(t.edges, 12u);
  EXPECT_EQ(t.faces, 8u);
  EXPECT_EQ(t.euler(), 2);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.boundary_loops, 0u);
  EXPECT_TRUE(t.closed());
  EXPECT_EQ(t.first_problem, "");
}

TEST(MeshTopology, SquareIsAnOpenDisk) {
  const MeshTopology t = mesh_topology(square());
  EXPECT_EQ(t.vertices, 4u);
  EXPECT_EQ(t.edges, 5u);
  EXPECT_EQ(t.faces, 2u);
  EXPECT_EQ(t.euler(), 1);
  EXPECT_EQ(t.boundary_edges, 4u);
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_EQ(t.components, 1u);
  EXPECT_TRUE(t.manifold());
  EXPECT_FALSE(t.closed());
  EXPECT_EQ(t.first_problem, "");
}

TEST(MeshTopology, AnnulusHasTwoBoundaryLoops) {
  const MeshTopology t = mesh_topology(annulus());
  EXPECT_EQ(t.vertices, 8u);
  EXPECT_EQ(t.edges, 16u);
  EXPECT_EQ(t.faces, 8u);
  EXPECT_EQ(t.euler(), 0);
  EXPECT_EQ(t.boundary_edges, 8u);
  EXPECT_EQ(t.boundary_loops, 2u);
  EXPECT_EQ(t.components, 1u);
  EXPECT_TRUE(t.manifold());
  EXPECT_FALSE(t.closed());
}

TEST(MeshTopology, TwoDisjointTriangles) {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  const MeshTopology t = mesh_topology(m);
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.boundary_loops, 2u);
  EXPECT_EQ(t.boundary_edges, 6u);
  EXPECT_EQ(t.euler(), 2);  // two disks
  EXPECT_TRUE(t.manifold());
  EXPECT_FALSE(t.closed());
}

TEST(MeshTopology, UnusedPointsAreNotVertices) {
  Mesh m = tetrahedron();
  m.points.push_back({9, 9, 9});
  const MeshTopology t = mesh_topology(m);
  EXPECT_EQ(t.vertices, 4u);
  EXPECT_EQ(t.euler(), 2);
  EXPECT_TRUE(t.closed());
}

TEST(MeshTopology, EmptyMeshIsNotClosed) {
  const MeshTopology t = mesh_topology(Mesh{});
  EXPECT_EQ(t.faces, 0u);
  EXPECT_EQ(t.components, 0u);
  EXPECT_TRUE(t.manifold());
  EXPECT_FALSE(t.closed());
}

TEST(MeshTopology, FlippedTriangleIsMisoriented) {
  Mesh m = tetrahedron();
  m.triangles[3] = {1, 3, 2};  // the slanted face turned inward
  const MeshTopology t = mesh_topology(m);
  EXPECT_EQ(t.misoriented_edges, 3u);  // each of its edges meets a neighbour going the same way
  EXPECT_EQ(t.nonmanifold_edges, 0u);
  EXPECT_EQ(t.boundary_edges, 0u);
  EXPECT_EQ(t.euler(), 2);
  EXPECT_FALSE(t.manifold());
  EXPECT_FALSE(t.closed());
  EXPECT_TRUE(contains(t.first_problem, "orientation")) << t.first_problem;
  EXPECT_TRUE(contains(t.first_problem, "and 4 ")) << t.first_problem;  // face 3 counted from 1
}

TEST(MeshTopology, EdgeOfThreeFaces) {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0}, {0.5, 0, 1}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const MeshTopology t = mesh_topology(m);
  EXPECT_EQ(t.nonmanifold_edges, 1u);
  EXPECT_EQ(t.edges, 7u);
  EXPECT_EQ(t.components, 1u);
  EXPECT_FALSE(t.manifold());
  EXPECT_FALSE(t.closed());
  EXPECT_EQ(t.first_problem, "edge (1, 2) is shared by 3 faces");  // counted from 1
  EXPECT_TRUE(contains(t.first_problem, "shared by 3 faces"));
}

TEST(MeshTopology, BowtieVertex) {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  const MeshTopology t = mesh_topology(m);
  EXPECT_EQ(t.nonmanifold_vertices, 1u);
  EXPECT_EQ(t.nonmanifold_edges, 0u);
  EXPECT_EQ(t.misoriented_edges, 0u);
  EXPECT_EQ(t.components, 2u);  // faces joined only through a point are separate pieces
  EXPECT_FALSE(t.manifold());
  EXPECT_TRUE(contains(t.first_problem, "bowtie")) << t.first_problem;
  EXPECT_TRUE(contains(t.first_problem, "vertex 1 ")) << t.first_problem;
}

TEST(MeshValidate, AcceptsAGoodMesh) {
  Mesh m = tetrahedron();
  m.point_fields.set(real_field("thickness", {1, 2, 3, 4}));
  m.face_fields.set(int_field("tile_class", {0, 1, 0, 1}));
  EXPECT_EQ(validate_error(m), "");
}

TEST(MeshValidate, IndexOutOfRange) {
  Mesh m = tetrahedron();
  m.triangles[1] = {0, 1, 4};
  EXPECT_EQ(validate_error(m), "triangle 2 uses point 5, but there are 4 points");
}

TEST(MeshValidate, RepeatedIndex) {
  for (const Triangle& bad : {Triangle{1, 1, 2}, Triangle{1, 2, 2}, Triangle{2, 1, 2}}) {
    Mesh m = tetrahedron();
    m.triangles[2] = bad;
    EXPECT_EQ(validate_error(m), "triangle 3 uses one point twice");
  }
}

TEST(MeshValidate, NonFinitePoint) {
  Mesh m = tetrahedron();
  m.points[2].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validate_error(m), "point 3 has non-finite coordinates");
  EXPECT_FALSE(m.finite());
  m.points[2].y = std::numeric_limits<double>::infinity();
  EXPECT_EQ(validate_error(m), "point 3 has non-finite coordinates");
  EXPECT_TRUE(tetrahedron().finite());
}

TEST(MeshValidate, FieldOfTheWrongSize) {
  Mesh m = tetrahedron();
  m.face_fields.set(int_field("tile_class", {0, 1, 0}));
  EXPECT_EQ(validate_error(m), "face field 'tile_class' has 3 values, expected 4 × 1");
  m = tetrahedron();
  m.point_fields.set(real_field("thickness", {1, 2, 3, 4, 5}));
  EXPECT_EQ(validate_error(m), "point field 'thickness' has 5 values, expected 4 × 1");
}

TEST(Mesh, FacesBBoxAndBytes) {
  const Mesh m = octahedron();
  EXPECT_EQ(m.faces(), 8u);
  EXPECT_EQ(m.bbox().min, (Vec3{-1, -1, -1}));
  EXPECT_EQ(m.bbox().max, (Vec3{1, 1, 1}));
  EXPECT_GE(m.bytes(), 6 * sizeof(Vec3) + 8 * sizeof(Triangle));
}
