#include "kernels/geom/length_fields.h"

#include <gtest/gtest.h>

#include "kernels/geom/polyline.h"
#include "kernels/geom/similarity3.h"

using namespace selfsim;

TEST(LengthFields, ASimilarityScalesWidthsAndDistancesWithTheCurve) {
  Polyline c = Polyline::single({{0, 0}, {0, 1}});
  c.point_fields.set(real_field("width", {10, 1}));
  c.point_fields.set(int_field("root_distance", {0, 1}));
  c.point_fields.set(int_field("branch_order", {0, 1}));
  c.point_fields.set(uniform_int("level", 3));
  const Polyline t = transformed(c, Similarity2{{0, 0.5}, {3, 3}});  // turned a quarter, half the size
  EXPECT_DOUBLE_EQ(t.point_fields.find("width")->at(0), 5);
  EXPECT_DOUBLE_EQ(t.point_fields.find("root_distance")->at(1), 0.5);
  EXPECT_EQ(t.point_fields.find("branch_order")->ints()[1], 1);  // not a length
  EXPECT_EQ(t.point_fields.find("level")->at(1), 3);
  Polyline3 d;
  d.points = {{0, 0, 0}, {0, 1, 0}};
  d.path_ends = {2};
  d.point_fields.set(real_field("width", {10, 1}));
  EXPECT_DOUBLE_EQ(transformed(d, Similarity3::scaling(3)).point_fields.find("width")->at(1), 3);
}
