#include "kernels/geom/curve_join.h"

#include <gtest/gtest.h>

#include <vector>

using namespace selfsim;

namespace {

Polyline path(std::vector<Vec2> pts, int level) {
  Polyline c = Polyline::single(pts);
  c.point_fields.set(uniform_int("level", level));
  return c;
}

std::vector<Vec2> points_of(const Polyline& c) { return {c.points.begin(), c.points.end()}; }

}  // namespace

TEST(CurveJoin, GroupKeepsEveryPathAndNumbersMembers) {
  Polyline a = path({{0, 0}, {1, 0}}, 3);
  Polyline b = path({{0, 1}, {1, 1}, {2, 1}}, 3);
  b.points.push_back({5, 5});  // b gets a second path
  b.points.push_back({6, 5});
  b.close_path();
  const std::vector<const Polyline*> members{&a, &b};
  const Polyline g = group<Vec2>(members, {}, {}, no_progress());
  EXPECT_EQ(g.paths(), 3u);
  EXPECT_EQ(g.points.size(), 7u);
  EXPECT_TRUE(g.paths_consistent());
  EXPECT_EQ(g.path(1).size(), 3u);
  EXPECT_EQ(g.path(2).front(), (Vec2{5, 5}));
  const Field* curve = g.cell_fields.find("curve");
  ASSERT_NE(curve, nullptr);
  EXPECT_EQ(std::vector<int>(curve->ints().begin(), curve->ints().end()), (std::vector<int>{1, 2, 2}));
  // The same level everywhere stays one uniform value.
  const Field* level = g.point_fields.find("level");
  ASSERT_NE(level, nullptr);
  EXPECT_TRUE(level->uniform);
  EXPECT_EQ(level->at(6), 3);
}

TEST(CurveJoin, GroupExpandsDifferingUniformFieldsAndDropsPartialOnes) {
  Polyline a = path({{0, 0}, {1, 0}}, 2);
  Polyline b = path({{0, 1}, {1, 1}, {2, 1}}, 5);
  a.point_fields.set(real_field("t", {0, 1}));  // only a has t: dropped
  a.cell_fields.set(real_field("path", {0}));   // a path index means nothing after grouping: dropped
  const std::vector<const Polyline*> members{&a, &b};
  const Polyline g = group<Vec2>(members, {}, {}, no_progress());
  const Field* level = g.point_fields.find("level");
  ASSERT_NE(level, nullptr);
  EXPECT_FALSE(level->uniform);
  EXPECT_EQ(std::vector<int>(level->ints().begin(), level->ints().end()), (std::vector<int>{2, 2, 5, 5, 5}));
  EXPECT_EQ(g.point_fields.find("t"), nullptr);
  EXPECT_EQ(g.cell_fields.find("path"), nullptr);
  EXPECT_NO_THROW(g.point_fields.check(g.points.size(), "point"));
  EXPECT_NO_THROW(g.cell_fields.check(g.paths(), "cell"));
}

TEST(CurveJoin, GroupFillsCellDefaultsForMembersWithoutTheField) {
  Polyline a = path({{0, 0}, {1, 0}}, 1), b = path({{0, 1}, {1, 1}}, 1);
  a.cell_fields.set(real_field("width", {3}));
  Fields defaults;
  defaults.set(Field{"width", 1, std::vector<double>{1}, true});
  const std::vector<const Polyline*> members{&a, &b};
  const Polyline g = group<Vec2>(members, {}, defaults, no_progress());
  const Field* width = g.cell_fields.find("width");
  ASSERT_NE(width, nullptr);
  EXPECT_EQ(width->at(0), 3);
  EXPECT_EQ(width->at(1), 1);
  // An override replaces a member's own field (and stands in for a missing one).
  std::vector<Fields> overrides(2);
  overrides[0].set(Field{"width", 1, std::vector<double>{7}, true});
  overrides[1].set(Field{"width", 1, std::vector<double>{8}, true});
  const Polyline h = group<Vec2>(members, overrides, {}, no_progress());
  EXPECT_EQ(h.cell_fields.find("width")->at(0), 7);
  EXPECT_EQ(h.cell_fields.find("width")->at(1), 8);
}

TEST(CurveJoin, GroupRefusesNothingAndEmptyMembers) {
  EXPECT_THROW(group<Vec2>(std::span<const Polyline* const>{}, {}, {}, no_progress()), Error);
  const Polyline empty;
  const std::vector<const Polyline*> members{&empty};
  EXPECT_THROW(group<Vec2>(members, {}, {}, no_progress()), Error);
}

TEST(CurveJoin, ConcatSharesMeetingPointsOnce) {
  const Polyline a = path({{0, 0}, {1, 0}}, 1);
  const Polyline b = path({{1, 1e-17}, {1, 1}}, 1);  // meets a's end to rounding
  const Polyline c = path({{2, 2}, {3, 3}}, 2);      // does not meet: a segment joins them
  const std::vector<const Polyline*> parts{&a, &b, &c};
  const Polyline j = concat<Vec2>(parts, no_progress());
  EXPECT_EQ(j.paths(), 1u);
  EXPECT_EQ(points_of(j), (std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {2, 2}, {3, 3}}));
  const Field* level = j.point_fields.find("level");
  ASSERT_NE(level, nullptr);
  EXPECT_EQ(level->at(2), 1);
  EXPECT_EQ(level->at(3), 2);
  EXPECT_NO_THROW(j.point_fields.check(j.points.size(), "point"));
}

TEST(CurveJoin, ConcatRefusesSeveralPaths) {
  Polyline a = path({{0, 0}, {1, 0}}, 1);
  a.points.push_back({2, 0});
  a.points.push_back({3, 0});
  a.close_path();
  const std::vector<const Polyline*> parts{&a};
  try {
    concat<Vec2>(parts, no_progress());
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("argument 1 has 2 paths"), std::string::npos) << e.what();
  }
}

TEST(CurveJoin, ReversedWalksBackwardsWithItsFields) {
  Polyline c = path({{0, 0}, {1, 0}, {2, 0}}, 4);
  c.points.push_back({5, 5});
  c.points.push_back({6, 6});
  c.close_path();
  c.point_fields.set(real_field("t", {0, 1, 2, 3, 4}));
  c.point_fields.set(real_field("arclength", {0, 1, 2, 0, 1}));
  c.cell_fields.set(int_field("curve", {7, 8}));
  const Polyline r = reversed(c);
  EXPECT_EQ(points_of(r), (std::vector<Vec2>{{6, 6}, {5, 5}, {2, 0}, {1, 0}, {0, 0}}));
  EXPECT_EQ(r.path_ends, (std::vector<std::size_t>{2, 5}));
  EXPECT_EQ(r.point_fields.find("t")->at(0), 4);
  EXPECT_EQ(r.point_fields.find("level")->at(3), 4);
  EXPECT_EQ(r.point_fields.find("arclength"), nullptr);  // recomputed by the writers
  EXPECT_EQ(r.cell_fields.find("curve")->at(0), 8);
  EXPECT_EQ(points_of(reversed(r)), points_of(c));
}
