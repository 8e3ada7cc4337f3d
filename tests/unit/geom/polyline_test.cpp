#include "kernels/geom/polyline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace selfsim;

namespace {

// Two 3D paths: a 3-4-5 step (length 5 + 12) and a unit segment along z (length 1).
Polyline3 two_paths3() {
  Polyline3 c;
  c.points = {{0, 0, 0}, {3, 4, 0}, {3, 4, 12}, {-1, 0, 2}, {-1, 0, 3}};
  c.path_ends = {3, 5};
  return c;
}

}  // namespace

TEST(Polyline3, SegmentsAndLength) {
  const Polyline3 c = two_paths3();
  EXPECT_EQ(c.paths(), 2u);
  EXPECT_EQ(c.segments(), 3u);
  EXPECT_DOUBLE_EQ(c.length(), 5 + 12 + 1);
  EXPECT_EQ(c.path_begin(0), 0u);
  EXPECT_EQ(c.path_begin(1), 3u);
  ASSERT_EQ(c.path(1).size(), 2u);
  EXPECT_EQ(c.path(1)[0], (Vec3{-1, 0, 2}));
}

TEST(Polyline3, NoSegmentCrossesPaths) {
  // The jump from the end of path 0 to the start of path 1 is not a segment.
  Polyline3 c;
  c.points = {{0, 0, 0}, {1, 0, 0}, {100, 0, 0}, {101, 0, 0}};
  c.path_ends = {2, 4};
  EXPECT_EQ(c.segments(), 2u);
  EXPECT_DOUBLE_EQ(c.length(), 2);
}

TEST(Polyline3, BBox) {
  const BBox3 b = two_paths3().bbox();
  EXPECT_EQ(b.min, (Vec3{-1, 0, 0}));
  EXPECT_EQ(b.max, (Vec3{3, 4, 12}));
}

TEST(Polyline3, FiniteDetectsNaNAndInfinityInEachCoordinate) {
  EXPECT_TRUE(two_paths3().finite());
  for (int k = 0; k < 3; ++k)
    for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                       -std::numeric_limits<double>::infinity()}) {
      Polyline3 c = two_paths3();
      double* coordinate[3] = {&c.points[4].x, &c.points[4].y, &c.points[4].z};
      *coordinate[k] = bad;
      EXPECT_FALSE(c.finite()) << "coordinate " << k << " = " << bad;
    }
}

TEST(Polyline, FiniteDetectsNaNAndInfinity) {
  Polyline c = Polyline::single({{0, 0}, {1, 1}});
  EXPECT_TRUE(c.finite());
  c.points[1].y = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(c.finite());
  c.points[1].y = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(c.finite());
}

TEST(Polyline3, ClosePathEndsThePathAndIgnoresAnEmptyOne) {
  Polyline3 c;
  c.close_path();  // nothing yet: no empty path
  EXPECT_EQ(c.paths(), 0u);
  c.points = {{0, 0, 0}, {1, 0, 0}};
  c.close_path();
  EXPECT_EQ(c.path_ends, (std::vector<std::size_t>{2}));
  c.close_path();  // no new points: still one path
  EXPECT_EQ(c.path_ends, (std::vector<std::size_t>{2}));
  c.points.push_back({5, 5, 5});
  c.points.push_back({5, 5, 6});
  c.points.push_back({5, 5, 8});
  c.close_path();
  EXPECT_EQ(c.path_ends, (std::vector<std::size_t>{2, 5}));
  EXPECT_EQ(c.segments(), 3u);
  EXPECT_DOUBLE_EQ(c.length(), 1 + 1 + 2);
}

TEST(Polyline3, SingleIsOnePath) {
  const Polyline3 c = Polyline3::single({{0, 0, 0}, {0, 0, 1}, {0, 1, 1}});
  EXPECT_EQ(c.paths(), 1u);
  EXPECT_EQ(c.path_ends, (std::vector<std::size_t>{3}));
  EXPECT_EQ(c.segments(), 2u);
  EXPECT_DOUBLE_EQ(c.length(), 2);
  EXPECT_EQ(Polyline3::single({}).paths(), 0u);  // no points, no path
}

TEST(Polyline, SingleIsOnePath) {
  const Polyline c = Polyline::single({{0, 0}, {3, 4}});
  EXPECT_EQ(c.paths(), 1u);
  EXPECT_EQ(c.segments(), 1u);
  EXPECT_DOUBLE_EQ(c.length(), 5);
}

TEST(Polyline3, BytesGrowWithFields) {
  Polyline3 c = two_paths3();
  const std::size_t bare = c.bytes();
  EXPECT_GE(bare, c.points.size() * sizeof(Vec3));
  c.point_fields.set(real_field("thickness", std::vector<double>(5, 1.0)));
  const std::size_t with_point_field = c.bytes();
  EXPECT_GE(with_point_field, bare + 5 * sizeof(double));
  c.cell_fields.set(int_field("curve", {1, 2}));
  EXPECT_GE(c.bytes(), with_point_field + 2 * sizeof(std::int32_t));
}

TEST(Polyline, PointsAre16BytesAndPolyline3Points24) {
  static_assert(sizeof(Polyline::Point) == 16);
  static_assert(sizeof(Polyline3::Point) == 24);
  Polyline c;
  c.points.reserve(1000);
  EXPECT_GE(c.bytes(), 16000u);
  EXPECT_LT(c.bytes(), 17000u);
}
