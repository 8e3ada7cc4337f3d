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

TEST(Similarity2, MirroredMapsCompose) {
  const Similarity2 m{{0, 2}, {1, 0}, true};  // z -> 2i·conj(z) + 1
  const Vec2 z{0.25, 0.5};
  EXPECT_EQ(m(z), (Vec2{2, 0.5}));  // 2i·(0.25 - 0.5i) + 1 = 1 + 1 + 0.5i
  const Similarity2 mm = m.after(m);
  EXPECT_FALSE(mm.mirrored);  // two reflections make a direct similarity
  EXPECT_NEAR(norm(mm(z) - m(m(z))), 0, 1e-15);
  const Similarity2 d{{0.5, 0.5}, {0, 1}};
  EXPECT_NEAR(norm(m.after(d)(z) - m(d(z))), 0, 1e-15);
  EXPECT_NEAR(norm(d.after(m)(z) - d(m(z))), 0, 1e-15);
}

TEST(Polyline, TransformedKeepsPaths) {
  Polyline c;
  c.points = {{0, 0}, {1, 0}, {5, 5}, {5, 6}};
  c.path_ends = {2, 4};
  c.point_fields.set(uniform_int("level", 3));
  const Polyline t = transformed(c, {{0, 1}, {1, 1}});  // quarter turn, then shift by (1, 1)
  EXPECT_EQ(t.path_ends, c.path_ends);
  ASSERT_NE(t.point_fields.find("level"), nullptr);
  EXPECT_EQ(t.point_fields.find("level")->at(0), 3);
  EXPECT_EQ(t.points[1], (Vec2{1, 2}));
  EXPECT_DOUBLE_EQ(t.length(), c.length());
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
