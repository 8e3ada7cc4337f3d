#include "kernels/analysis/dataset_diff.h"

#include <gtest/gtest.h>

#include <limits>

using namespace selfsim;

namespace {

// Two polyline cells over four points, a 2-component point field and a cell field.
io::Dataset base() {
  io::Dataset d;
  d.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}};
  d.cell_ends = {2, 4};
  d.cell_points = {0, 1, 2, 3};
  d.point_fields["color"] = {2, {0, 0.5, 1, 1.5, 2, 2.5, 3, 3.5}};
  d.cell_fields["path"] = {1, {0, 1}};
  return d;
}

}  // namespace

TEST(DatasetDiff, SameDatasetsMatch) {
  EXPECT_TRUE(analysis::dataset_diff(base(), base(), 1e-12).empty());
  io::Dataset a = base(), b = base();
  a.point_fields["x"] = {1, {std::numeric_limits<double>::quiet_NaN(), 0, 0, 0}};
  b.point_fields["x"] = a.point_fields["x"];
  EXPECT_TRUE(analysis::dataset_diff(a, b, 1e-12).empty());  // NaN matches NaN
}

TEST(DatasetDiff, FirstDifferingPointFieldValueNamesFieldAndTuple) {
  io::Dataset b = base();
  b.point_fields["color"].values[3] = 1.75;  // tuple 1, component 1
  b.point_fields["color"].values[6] = 9;     // tuple 3: one summary line per field, tuples counted from 1
  const auto d = analysis::dataset_diff(base(), b, 1e-12);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0],
            "point field 'color' differs at 2 of 4 tuples, the largest difference 6 at tuple 4; the first, tuple 2: "
            "1 vs 1, 1.5 vs 1.75");
}

TEST(DatasetDiff, CellFieldDifference) {
  io::Dataset b = base();
  b.cell_fields["path"].values[1] = 2;
  const auto d = analysis::dataset_diff(base(), b, 1e-12);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "cell field 'path' differs at 1 of 2 tuples; the first, tuple 2: 1 vs 2");
}

TEST(DatasetDiff, ToleranceIsRelativeForLargeValues) {
  io::Dataset a = base(), b = base();
  a.point_fields["color"].values[0] = 1e6;
  b.point_fields["color"].values[0] = 1e6 + 0.5;  // 5e-7 relative
  EXPECT_TRUE(analysis::dataset_diff(a, b, 1e-6).empty());
  EXPECT_EQ(analysis::dataset_diff(a, b, 1e-7).size(), 1u);
}

TEST(DatasetDiff, DifferingCellsAreNamed) {
  io::Dataset b = base();
  b.cell_points = {0, 1, 3, 2};
  const auto d = analysis::dataset_diff(base(), b, 1e-12);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "cell 2 differs: points (2, 3) vs (3, 2)");  // cells from 1; point ids as stored
}

TEST(DatasetDiff, DifferentCellSplitIsACellDifference) {
  io::Dataset b = base();
  b.cell_ends = {3, 4};
  const auto d = analysis::dataset_diff(base(), b, 1e-12);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "cell 1 differs: points (0, 1) vs (0, 1, 2)");
}

TEST(DatasetDiff, DifferentCellKinds) {
  io::Dataset b = base();
  b.shapes = io::CellShapes::polygons;
  const auto d = analysis::dataset_diff(base(), b, 1e-12);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "cell kinds differ (polylines, polygons or mixed)");
}

TEST(DatasetDiff, DifferentCounts) {
  io::Dataset b = base();
  b.points.push_back({5, 5, 5});
  b.cell_ends.push_back(5);
  b.cell_points.push_back(4);
  b.point_fields.erase("color");
  b.cell_fields["path"] = {1, {0, 1, 2}};
  b.cell_fields["extra"] = {1, {0, 0, 0}};
  const auto d = analysis::dataset_diff(base(), b, 1e-12);
  ASSERT_EQ(d.size(), 5u);
  EXPECT_EQ(d[0], "point count differs: 4 vs 5");
  EXPECT_EQ(d[1], "cell count differs: 2 vs 3");
  EXPECT_EQ(d[2], "point field 'color' only in the first file");
  // Each kind's fields of the first file in name order, then those only in the second.
  EXPECT_EQ(d[3], "cell field 'path' has a different size");
  EXPECT_EQ(d[4], "cell field 'extra' only in the second file");
}

TEST(DatasetDiff, ComponentCountMatters) {
  io::Dataset b = base();
  b.point_fields["color"].components = 4;  // same values, other tuples
  const auto d = analysis::dataset_diff(base(), b, 1e-12);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "point field 'color' has a different size");
}

TEST(DatasetDiff, MovedPointPrintsAllDigits) {
  io::Dataset b = base();
  b.points[2][2] = 0.1;
  const auto d = analysis::dataset_diff(base(), b, 1e-12);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0], "points differ at 1 of 4 points; the first, point 3: (1, 1, 0) vs (1, 1, 0.10000000000000001)");
}

TEST(DatasetDiff, AtMostMaxReports) {
  io::Dataset b = base();
  for (auto& p : b.points) p[0] += 1;
  b.point_fields["color"].values[0] = 7;
  b.cell_fields["path"].values[0] = 7;
  // One summary line for the points (not one per point) and one per field.
  const auto all = analysis::dataset_diff(base(), b, 1e-12, 10);
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].rfind("points differ at 4 of 4 points, the largest difference 1 at point 1; the first, point 1", 0),
            0u);
  const auto two = analysis::dataset_diff(base(), b, 1e-12, 2);
  ASSERT_EQ(two.size(), 2u);
  EXPECT_EQ(two[1].rfind("point field 'color' differs", 0), 0u);
}
