#include "kernels/io/dataset/dataset_values.h"

#include <gtest/gtest.h>

#include <string>

#include "kernels/base/error.h"

using namespace selfsim;

namespace {

// Two polyline cells: (0,0,z) (1,0,z) (1,1,z), then (2,2,z) (3,2,z); point field 'w', cell field 'curve'.
io::Dataset lines(double z = 0) {
  io::Dataset d;
  d.shapes = io::CellShapes::lines;
  d.points = {{0, 0, z}, {1, 0, z}, {1, 1, z}, {2, 2, z}, {3, 2, z}};
  d.cell_ends = {3, 5};
  d.cell_points = {0, 1, 2, 3, 4};
  d.point_fields["w"] = {1, {10, 11, 12, 13, 14}};
  d.cell_fields["curve"] = {1, {7, 8}};
  return d;
}

// A quad and a triangle: points 0-3 the unit square, point 4 above it.
io::Dataset polygons() {
  io::Dataset d;
  d.shapes = io::CellShapes::polygons;
  d.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
  d.cell_ends = {4, 7};
  d.cell_points = {0, 1, 2, 3, 0, 1, 4};
  d.point_fields["thickness"] = {1, {0.5, 1.5, 2.5, 3.5, 4.5}};
  d.cell_fields["tile_class"] = {2, {1, -1, 2, -2}};
  return d;
}

std::string value_error(const io::Dataset& d) {
  try {
    io::dataset_value(d);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST(DatasetValue, FlatLinesAreAPolyline) {
  const auto v = io::dataset_value(lines());
  ASSERT_TRUE(std::holds_alternative<Polyline>(v));
  const Polyline& c = std::get<Polyline>(v);
  EXPECT_EQ(c.points, (PointArray<Vec2>{{0, 0}, {1, 0}, {1, 1}, {2, 2}, {3, 2}}));
  EXPECT_EQ(c.path_ends, (std::vector<std::size_t>{3, 5}));
  const Field* w = c.point_fields.find("w");
  ASSERT_NE(w, nullptr);
  EXPECT_EQ(w->scalar(), Scalar::Float64);  // a file's integer types are not kept
  EXPECT_EQ(std::vector<double>(w->reals().begin(), w->reals().end()), (std::vector<double>{10, 11, 12, 13, 14}));
  const Field* curve = c.cell_fields.find("curve");
  ASSERT_NE(curve, nullptr);
  EXPECT_EQ(std::vector<double>(curve->reals().begin(), curve->reals().end()), (std::vector<double>{7, 8}));
  EXPECT_NO_THROW(c.point_fields.check(c.points.size(), "point"));
  EXPECT_NO_THROW(c.cell_fields.check(c.paths(), "cell"));
}

TEST(DatasetValue, LinesWithZAreAPolyline3) {
  const auto v = io::dataset_value(lines(0.5));
  ASSERT_TRUE(std::holds_alternative<Polyline3>(v));
  const Polyline3& c = std::get<Polyline3>(v);
  ASSERT_EQ(c.points.size(), 5u);
  EXPECT_EQ(c.points[4], (Vec3{3, 2, 0.5}));
  EXPECT_EQ(c.path_ends, (std::vector<std::size_t>{3, 5}));
  EXPECT_NE(c.point_fields.find("w"), nullptr);
}

TEST(DatasetValue, OneNonZeroZMakesAPolyline3) {
  io::Dataset d = lines();
  d.points[2][2] = -1e-300;
  const auto v = io::dataset_value(d);
  ASSERT_TRUE(std::holds_alternative<Polyline3>(v));
  EXPECT_EQ(std::get<Polyline3>(v).points[2].z, -1e-300);
  EXPECT_EQ(std::get<Polyline3>(v).points[1].z, 0);
}

TEST(DatasetValue, ClosedLoopRepeatsItsFirstPointAndItsValues) {
  io::Dataset d;
  d.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  d.cell_ends = {4};
  d.cell_points = {0, 1, 2, 0};
  d.point_fields["color"] = {2, {0, 1, 10, 11, 20, 21}};
  const Polyline c = std::get<Polyline>(io::dataset_value(d));
  EXPECT_EQ(c.points, (PointArray<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 0}}));
  const Field* color = c.point_fields.find("color");
  ASSERT_NE(color, nullptr);
  EXPECT_EQ(color->components, 2);
  EXPECT_EQ(std::vector<double>(color->reals().begin(), color->reals().end()),
            (std::vector<double>{0, 1, 10, 11, 20, 21, 0, 1}));
}

TEST(DatasetValue, PolygonsAreAMeshOfFans) {
  const auto v = io::dataset_value(polygons());
  ASSERT_TRUE(std::holds_alternative<Mesh>(v));
  const Mesh& m = std::get<Mesh>(v);
  EXPECT_EQ(m.points.size(), 5u);
  EXPECT_EQ(m.points[4], (Vec3{0.5, 0.5, 1}));
  // The quad as the fan (0,1,2) (0,2,3), then the triangle.
  EXPECT_EQ(m.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {0, 1, 4}}));
  const Field* thickness = m.point_fields.find("thickness");
  ASSERT_NE(thickness, nullptr);
  EXPECT_EQ(thickness->stored(), 5u);
  // The quad's face values on both its triangles.
  const Field* tile = m.face_fields.find("tile_class");
  ASSERT_NE(tile, nullptr);
  EXPECT_EQ(tile->components, 2);
  EXPECT_EQ(std::vector<double>(tile->reals().begin(), tile->reals().end()),
            (std::vector<double>{1, -1, 1, -1, 2, -2}));
  EXPECT_NO_THROW(m.validate());
}

TEST(DatasetValue, APentagonIsThreeTriangles) {
  io::Dataset d;
  d.shapes = io::CellShapes::polygons;
  d.points = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}};
  d.cell_ends = {5};
  d.cell_points = {0, 1, 2, 3, 4};
  d.cell_fields["id"] = {1, {42}};
  const Mesh m = io::dataset_mesh(d);
  EXPECT_EQ(m.triangles, (std::vector<Triangle>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
  const Field* id = m.face_fields.find("id");
  ASSERT_NE(id, nullptr);
  EXPECT_EQ(std::vector<double>(id->reals().begin(), id->reals().end()), (std::vector<double>{42, 42, 42}));
}

TEST(DatasetValue, MixedCellsAreAnError) {
  io::Dataset d = polygons();
  d.shapes = io::CellShapes::mixed;
  EXPECT_EQ(value_error(d),
            "it holds cells other than polylines or polygons (vertices, strips, volumes, or both kinds)");
}

TEST(DatasetValue, NoCellsIsAnError) {
  io::Dataset d = polygons();
  d.shapes = io::CellShapes::lines;
  d.cell_ends.clear();
  d.cell_points.clear();
  EXPECT_EQ(value_error(d), "it holds no cells (no polylines or polygons)");
}

TEST(DatasetValue, PolygonOfTwoPointsIsAnError) {
  io::Dataset d = polygons();
  d.cell_ends = {4, 6};
  d.cell_points = {0, 1, 2, 3, 0, 1};
  d.cell_fields.clear();
  EXPECT_EQ(value_error(d), "polygon 2 has fewer than 3 points");
}

TEST(DatasetValue, PolygonUsingAPointTwiceIsAnError) {
  io::Dataset d = polygons();
  d.cell_points = {0, 1, 2, 3, 0, 4, 4};
  EXPECT_EQ(value_error(d), "triangle 3 uses one point twice");
}
