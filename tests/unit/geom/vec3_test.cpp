#include "kernels/geom/vec3.h"

#include <gtest/gtest.h>

#include <limits>
#include <vector>

#include "kernels/geom/bbox.h"

using namespace selfsim;

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST(Vec3, ArithmeticAndAll) {
  EXPECT_EQ((Vec3{1, 2, 3} + Vec3{4, 5, 6}), (Vec3{5, 7, 9}));
  EXPECT_EQ((Vec3{1, 2, 3} - Vec3{4, 5, 6}), (Vec3{-3, -3, -3}));
  EXPECT_EQ((-Vec3{1, -2, 3}), (Vec3{-1, 2, -3}));
  EXPECT_EQ((2 * Vec3{1, 2, 3}), (Vec3{2, 4, 6}));
  EXPECT_EQ((Vec3{1, 2, 3} * 2), (Vec3{2, 4, 6}));
  EXPECT_EQ((Vec3{2, 4, 6} / 2), (Vec3{1, 2, 3}));
  EXPECT_EQ(Vec3::all(1.5), (Vec3{1.5, 1.5, 1.5}));
  Vec3 a{1, 1, 1};
  a += Vec3{1, 2, 3};
  EXPECT_EQ(a, (Vec3{2, 3, 4}));
  a -= Vec3{2, 3, 4};
  EXPECT_EQ(a, Vec3{});
}

TEST(Vec3, Dot) {
  EXPECT_EQ(dot(Vec3{1, 2, 3}, Vec3{4, -5, 6}), 4 - 10 + 18);
  EXPECT_EQ(dot(Vec3{1, 0, 0}, Vec3{0, 1, 0}), 0);
  static_assert(dot(Vec3{1, 2, 3}, Vec3{1, 2, 3}) == 14);
}

TEST(Vec3, CrossIsRightHanded) {
  const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
  EXPECT_EQ(cross(x, y), z);
  EXPECT_EQ(cross(y, z), x);
  EXPECT_EQ(cross(z, x), y);
  EXPECT_EQ(cross(y, x), -z);
  EXPECT_EQ(cross(x, x), Vec3{});
}

TEST(Vec3, CrossIsAntiCommutativeAndOrthogonal) {
  const Vec3 a{1, 2, 3}, b{-4, 0.5, 2};
  EXPECT_EQ(cross(a, b), -cross(b, a));
  EXPECT_EQ(cross(a, b), (Vec3{2 * 2 - 3 * 0.5, 3 * -4 - 1 * 2, 1 * 0.5 - 2 * -4}));
  EXPECT_NEAR(dot(cross(a, b), a), 0, 1e-12);
  EXPECT_NEAR(dot(cross(a, b), b), 0, 1e-12);
}

TEST(Vec3, Norm) {
  EXPECT_EQ(norm(Vec3{2, 3, 6}), 7);
  EXPECT_EQ(norm(Vec3{0, 0, -4}), 4);
  EXPECT_EQ(norm(Vec3{}), 0);
  // hypot does not overflow where the sum of squares would.
  EXPECT_NEAR(norm(Vec3{3e200, 4e200, 0}) / 5e200, 1, 1e-15);
}

TEST(Vec3, Lerp) {
  const Vec3 a{1, 2, 3}, b{3, 6, -1};
  EXPECT_EQ(lerp(a, b, 0), a);
  EXPECT_EQ(lerp(a, b, 1), b);
  EXPECT_EQ(lerp(a, b, 0.5), (Vec3{2, 4, 1}));
  EXPECT_EQ(lerp(a, b, 2), (Vec3{5, 10, -5}));
}

TEST(Vec3, NormalizedHasLengthOneAndZeroStaysZero) {
  const Vec3 n = normalized(Vec3{2, 3, 6});
  EXPECT_NEAR(norm(n), 1, 1e-15);
  EXPECT_NEAR(n.x, 2.0 / 7, 1e-15);
  EXPECT_NEAR(n.y, 3.0 / 7, 1e-15);
  EXPECT_NEAR(n.z, 6.0 / 7, 1e-15);
  EXPECT_EQ(normalized(Vec3{0, 0, -5}), (Vec3{0, 0, -1}));
  const Vec3 zero = normalized(Vec3{});
  EXPECT_EQ(zero, Vec3{});
  EXPECT_TRUE(is_finite(zero));  // no 0/0
}

TEST(Vec3, IsFinite) {
  EXPECT_TRUE(is_finite(Vec3{1, -2, 1e308}));
  EXPECT_FALSE(is_finite(Vec3{kNaN, 0, 0}));
  EXPECT_FALSE(is_finite(Vec3{0, kInf, 0}));
  EXPECT_FALSE(is_finite(Vec3{0, 0, -kInf}));
}

TEST(Vec3, MinEachAndMaxEach) {
  const Vec3 a{1, 5, -2}, b{3, -1, -2};
  EXPECT_EQ(min_each(a, b), (Vec3{1, -1, -2}));
  EXPECT_EQ(max_each(a, b), (Vec3{3, 5, -2}));
  EXPECT_EQ(min_each(b, a), min_each(a, b));
  EXPECT_EQ(max_each(b, a), max_each(a, b));
}

TEST(BBox3, OfPoints) {
  const std::vector<Vec3> pts{{1, 2, 3}, {-1, 5, 0}, {4, -2, 7}};
  const BBox3 b = bbox_of<Vec3>(pts);
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.min, (Vec3{-1, -2, 0}));
  EXPECT_EQ(b.max, (Vec3{4, 5, 7}));
  EXPECT_EQ(b.size(), (Vec3{5, 7, 7}));
}

TEST(BBox3, EmptyAndSinglePoint) {
  const BBox3 none = bbox_of<Vec3>(std::vector<Vec3>{});
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(none.size(), Vec3{});
  const BBox3 one = bbox_of<Vec3>(std::vector<Vec3>{{1, 2, 3}});
  EXPECT_FALSE(one.empty());
  EXPECT_EQ(one.min, (Vec3{1, 2, 3}));
  EXPECT_EQ(one.max, (Vec3{1, 2, 3}));
  EXPECT_EQ(one.size(), Vec3{});
}
