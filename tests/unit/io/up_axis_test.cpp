// Which axis a preview stands a 3D dataset on (kernels/io/view/up_axis.h): +y unless a `level` follows
// one axis strongly, whichever way it runs.
#include "kernels/io/view/up_axis.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace selfsim;

namespace {

// A column of points along `axis`, `level` rising (or falling) with it, a little wobble across.
io::Dataset stack(int axis, double direction) {
  io::Dataset d;
  for (int i = 0; i < 20; ++i) {
    std::array<double, 3> p{0.1 * (i % 3), 0.05 * (i % 2), 0.02 * (i % 5)};
    p[static_cast<std::size_t>(axis)] = direction * i;
    d.points.push_back(p);
    d.point_fields["level"].values.push_back(i / 4);
  }
  return d;
}

}  // namespace

TEST(UpAxis, YWithoutALevel) {
  io::Dataset d;
  d.points = {{0, 0, 0}, {0, 0, 5}, {1, 0, 0}};
  EXPECT_EQ(io::up_axis(d), 1);
}

TEST(UpAxis, TheAxisALevelFollows) {
  EXPECT_EQ(io::up_axis(stack(2, 1)), 2);
  EXPECT_EQ(io::up_axis(stack(0, 1)), 0);
  EXPECT_EQ(io::up_axis(stack(2, -1)), 2);  // a surface developing downwards hangs along z
}

// A stack far from the origin (moved by a transform, or in a file's world units) stands as it does at the
// origin: the sums of squares at 1e9 lost the stack's own spread to rounding.
TEST(UpAxis, FarFromTheOrigin) {
  for (const double offset : {1e6, 1e9, -3e12})
    for (int axis : {0, 2}) {
      io::Dataset d = stack(axis, 1);
      for (auto& p : d.points)
        for (double& x : p) x += offset;
      for (double& l : d.point_fields["level"].values) l += offset;
      EXPECT_EQ(io::up_axis(d), axis) << offset;
    }
}

TEST(UpAxis, ALevelThatFollowsNoAxisLeavesY) {
  io::Dataset d;
  for (int i = 0; i < 20; ++i) {
    d.points.push_back({std::cos(i * 1.3), std::sin(i * 1.3), std::cos(i * 2.1)});
    d.point_fields["level"].values.push_back(i % 2);
  }
  EXPECT_EQ(io::up_axis(d), 1);
}

TEST(UpAxis, ACellLevelAtEachCellsCentre) {
  io::Dataset d;
  d.shapes = io::CellShapes::polygons;
  for (int i = 0; i < 10; ++i) {
    const std::size_t first = d.points.size();
    d.points.push_back({0, 0, double(i)});
    d.points.push_back({1, 0, double(i)});
    d.points.push_back({0, 1, double(i) + 0.5});
    d.cell_points.insert(d.cell_points.end(), {first, first + 1, first + 2});
    d.cell_ends.push_back(d.cell_points.size());
    d.cell_fields["level"].values.push_back(i);
  }
  EXPECT_EQ(io::up_axis(d), 2);
}

TEST(UpAxis, Names) {
  EXPECT_EQ(io::axis_from_name("x"), 0);
  EXPECT_EQ(io::axis_from_name("z"), 2);
  EXPECT_EQ(io::axis_from_name("w"), -1);
}

TEST(UpAxis, OfAValueAboutToBeSaved) {
  Polyline3 c;
  for (int i = 0; i < 10; ++i) c.points.push_back({double(i), 0.1 * (i % 2), 0});
  c.path_ends = {c.points.size()};
  c.point_fields.set(real_field("level", {0, 0, 1, 1, 2, 2, 3, 3, 4, 4}));
  EXPECT_EQ(io::up_axis(io::ValueRef{&c}), 0);
  Mesh m;
  for (int i = 0; i < 4; ++i) {
    const auto first = static_cast<std::uint32_t>(m.points.size());
    m.points.push_back({0, 0, double(i)});
    m.points.push_back({1, 0, double(i)});
    m.points.push_back({0, 1, double(i)});
    m.triangles.push_back({first, first + 1, first + 2});
  }
  m.face_fields.set(int_field("level", {0, 1, 2, 3}));
  EXPECT_EQ(io::up_axis(io::ValueRef{&m}), 2);
  Polyline flat;
  flat.points = {{0, 0}, {1, 1}};
  flat.path_ends = {2};
  EXPECT_EQ(io::up_axis(io::ValueRef{&flat}), 1);
}
