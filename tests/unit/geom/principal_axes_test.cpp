// A surface's principal axes: a thin box turned any way has its thinnest side among them.
#include "kernels/geom/principal_axes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "kernels/geom/mesh_transform.h"
#include "kernels/region/box_mesh.h"

using namespace selfsim;

TEST(PrincipalAxes, AThinBoxLiesAcrossItsThinnestSide) {
  const Affine3 turn = MeshTransform{.degrees = 37, .axis = {1, 2, 3}}.map();
  const Mesh plate = transformed(box_mesh({0, 0, 0}, {40, 20, 2}), turn);
  const std::vector<Vec3> axes = principal_directions(plate);
  ASSERT_EQ(axes.size(), 6u);
  for (const Vec3 side : {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}}) {
    const Vec3 turned = turn.linear(side);
    double best = -1;  // each box side is one of the axes (one way or the other)
    for (Vec3 a : axes) best = std::max(best, dot(a, turned));
    EXPECT_NEAR(best, 1, 1e-9);
  }
  EXPECT_TRUE(principal_directions(Mesh{}).empty());
}
