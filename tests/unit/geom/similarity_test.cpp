#include "kernels/geom/similarity.h"

#include <gtest/gtest.h>

#include "kernels/geom/polyline.h"

using namespace selfsim;

TEST(Vec2, ComplexArithmetic) {
  EXPECT_EQ((Vec2{1, 2} * Vec2{3, 4}), (Vec2{-5, 10}));
  const Vec2 q = Vec2{-5, 10} / Vec2{3, 4};
  EXPECT_NEAR(q.x, 1, 1e-15);
  EXPECT_NEAR(q.y, 2, 1e-15);
  EXPECT_EQ(conj(Vec2{1, 2}), (Vec2{1, -2}));
}

TEST(Similarity2, SegmentMapsAndTheirInverse) {
  const Vec2 p{1, 2}, q{-3, 5};
  const Similarity2 f = Similarity2::from_segment(p, q), g = Similarity2::to_unit(p, q);
  EXPECT_EQ(f(Vec2{0, 0}), p);
  EXPECT_EQ(f(Vec2{1, 0}), q);
  EXPECT_NEAR(norm(g(p)), 0, 1e-15);
  EXPECT_NEAR(norm(g(q) - Vec2{1, 0}), 0, 1e-15);
  const Vec2 z{0.3, -0.7};
  EXPECT_NEAR(norm(g(f(z)) - z), 0, 1e-15);
}

TEST(Polyline, PathsAndLength) {
  Polyline c;
  c.points = {{0, 0}, {3, 4}, {3, 5}, {10, 10}, {10, 12}};
  c.close_path();
  EXPECT_EQ(c.paths(), 1u);
  c.path_ends = {3, 5};
  EXPECT_EQ(c.segments(), 3u);
  EXPECT_DOUBLE_EQ(c.length(), 5 + 1 + 2);
  c.close_path();  // nothing new since the last path: no empty path
  EXPECT_EQ(c.paths(), 2u);
}
