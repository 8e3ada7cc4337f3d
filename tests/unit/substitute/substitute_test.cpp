#include "kernels/substitute/substitute.h"

#include <gtest/gtest.h>

#include <cmath>

#include "../lsystem/table1.h"
#include "kernels/base/error.h"
#include "kernels/lsystem/turtle/turtle2d.h"

using namespace selfsim;
using namespace selfsim::substitute;

namespace {

const double s3 = std::sqrt(3.0);
const Polyline koch_generator = Polyline::single({{0, 0}, {1.0 / 3, 0}, {0.5, -s3 / 6}, {2.0 / 3, 0}, {1, 0}});
const Polyline unit = Polyline::single({{0, 0}, {1, 0}});
const Polyline tent = Polyline::single({{0, 0}, {0.5, 0.5}, {1, 0}});

Polyline run(const Polyline& path, const Polyline& generator, int levels, std::vector<SegmentTransform> t = {}) {
  return substitute::substitute(path, generator, {.levels = levels, .transforms = std::move(t)}, no_progress());
}

// Points of two curves agree to rounding.
void expect_same(const Polyline& a, const Polyline& b, int level) {
  ASSERT_EQ(a.points.size(), b.points.size()) << level;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    ASSERT_NEAR(norm(a.points[i] - b.points[i]), 0, 1e-12) << level << " " << i;
}

}  // namespace

TEST(Substitute, KochSnowflakeEqualsTheLSystem) {
  const Polyline triangle = Polyline::single({{0, 0}, {1, 0}, {0.5, s3 / 2}, {0, 0}});
  for (int n = 0; n <= 6; ++n) {
    const Polyline a = run(triangle, koch_generator, n);
    const Polyline b = lsystem::turtle2d(table1::koch_snowflake(), {.level = n}, no_progress());
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i)
      ASSERT_NEAR(norm(a.points[i] - b.points[i]), 0, 1e-12) << n << " " << i;
  }
}

TEST(Substitute, HeighwayDragonIsATentWithItsSecondHalfTurned) {
  // f1(z) = (1+i)z/2 and f2(z) = 1 - (1-i)z/2: the second copy is the half-turned one, walked backwards.
  using enum SegmentTransform;
  for (int n = 0; n <= 10; ++n)
    expect_same(run(unit, tent, n, {Identity, HalfTurn}),
                lsystem::turtle2d(table1::dragon(), {.level = n}, no_progress()), n);
}

TEST(Substitute, TerdragonIsItsFirstLevel) {
  const Polyline first = lsystem::turtle2d(table1::terdragon(), {.level = 1}, no_progress());
  for (int n = 0; n <= 6; ++n)
    expect_same(run(unit, first, n), lsystem::turtle2d(table1::terdragon(), {.level = n}, no_progress()), n);
}

TEST(Substitute, CountsAndLevel) {
  const Polyline c = run(unit, koch_generator, 5);
  EXPECT_EQ(c.segments(), 1024u);
  ASSERT_NE(c.point_fields.find("level"), nullptr);
  EXPECT_EQ(c.point_fields.find("level")->at(0), 5);
  EXPECT_EQ(run(unit, koch_generator, 0).segments(), 1u);
}

// An asymmetric generator, so that all four transforms differ. Its first segment is a = 0.25 + 0.5i.
const Polyline hook = Polyline::single({{0, 0}, {0.25, 0.5}, {1, 0}});

TEST(Substitute, TheFourTransformsOnTheFirstSegment) {
  using enum SegmentTransform;
  // Level 2, first point after the start: the copy of `hook` on segment 0 (0,0)-(0.25,0.5), worked by
  // hand in complex numbers with a = 0.25 + 0.5i and g1 = a.
  const std::pair<SegmentTransform, Vec2> cases[] = {
      {Identity, {-0.1875, 0.25}},        // a·g1
      {ReflectSegment, {0.3125, 0}},      // a·conj(g1)
      {ReflectBisector, {-0.0625, 0.5}},  // a·(1 - conj(g1)), copy walked backwards
      {HalfTurn, {0.4375, 0.25}},         // a·(1 - g1), copy walked backwards
  };
  for (const auto& [t, expected] : cases) {
    const Polyline c = run(unit, hook, 2, {t, Identity});
    ASSERT_EQ(c.points.size(), 5u);
    EXPECT_NEAR(norm(c.points[1] - expected), 0, 1e-15) << static_cast<int>(t);
    EXPECT_NEAR(norm(c.points[2] - Vec2{0.25, 0.5}), 0, 1e-15);  // the copy still ends where the segment does
    EXPECT_NEAR(norm(c.points[4] - Vec2{1, 0}), 0, 1e-15);
  }
}

TEST(Substitute, ReflectionsComposeAcrossLevels) {
  using enum SegmentTransform;
  // Kaplan's KOCH(T∘Ti, level−1) with T0 reflected: level 3's first point is M0(M0(g1)) for
  // M0(z) = a·conj(z), i.e. a·|a|^2 = (0.078125, 0.15625); without reflection it would be a^3.
  EXPECT_NEAR(norm(run(unit, hook, 3, {ReflectSegment, Identity}).points[1] - Vec2{0.078125, 0.15625}), 0, 1e-15);
  EXPECT_NEAR(norm(run(unit, hook, 3, {Identity, Identity}).points[1] - Vec2{-0.171875, -0.03125}), 0, 1e-15);
}

TEST(Substitute, Errors) {
  EXPECT_THROW(run(unit, Polyline::single({{0, 0}, {0.5, 0.5}}), 1), Error);  // generator not ending at 1
  EXPECT_THROW(run(unit, tent, 1, {SegmentTransform::Identity}), Error);      // one transform for two segments
  EXPECT_THROW(run(unit, tent, -1), Error);
  EXPECT_THROW(substitute::substitute(unit, tent, {.levels = 60, .budget = {1e6}}, no_progress()), Error);
}

TEST(Substitute, EveryPathOfASeveralPathCurveOnItsOwn) {
  // Two paths: the unit segment, and a segment two units up walked backwards. Each becomes its own tent
  // chain; neither joins the other, and the cell fields (a group's member numbers) are kept.
  Polyline two = unit;
  two.points.push_back({1, 2});
  two.points.push_back({0, 2});
  two.close_path();
  two.cell_fields.set(int_field("curve", {1, 2}));
  const Polyline r = run(two, tent, 3);
  ASSERT_EQ(r.paths(), 2u);
  EXPECT_EQ(r.path(0).size(), 9u);
  EXPECT_EQ(r.path(1).size(), 9u);
  Polyline second = Polyline::single({{1, 2}, {0, 2}});
  const Polyline alone = run(second, tent, 3);
  for (std::size_t i = 0; i < 9; ++i) {
    EXPECT_NEAR(norm(r.path(0)[i] - run(unit, tent, 3).points[i]), 0, 1e-15);
    EXPECT_NEAR(norm(r.path(1)[i] - alone.points[i]), 0, 1e-15);
  }
  ASSERT_NE(r.cell_fields.find("curve"), nullptr);
  EXPECT_EQ(r.cell_fields.find("curve")->at(1), 2);
  EXPECT_NO_THROW(r.cell_fields.check(r.paths(), "cell"));
}
