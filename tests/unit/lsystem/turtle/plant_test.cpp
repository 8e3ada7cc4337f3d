// The placement rule (kernels/lsystem/turtle/plant.h): plants keep the turtle's frame and units, heading up;
// other open curves are normalised; normalize, when given, decides.
#include "kernels/lsystem/turtle/plant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../module_grammar.h"
#include "../table1.h"
#include "kernels/lsystem/turtle/module_turtle.h"

using namespace selfsim;
using namespace selfsim::lsystem;

namespace {

std::vector<std::int32_t> ints(const Field* f) {
  if (f == nullptr) return {};
  return {f->ints().begin(), f->ints().end()};
}

Grammar module(const std::string& axiom, const std::vector<std::string>& rules, double angle = 90) {
  Grammar g = test::module_grammar(axiom, rules);
  g.angle = angle;
  return g;
}

}  // namespace

TEST(Plant, WhatIsAPlant) {
  EXPECT_FALSE(is_plant(table1::dragon()));
  EXPECT_TRUE(is_plant(Grammar{.axiom = "X", .rules = {{'X', "F[+X]F"}}}));  // '[' in a rule, not the axiom
  EXPECT_TRUE(is_plant(Grammar{.axiom = "F[+F]F"}));
  EXPECT_TRUE(is_plant(module("A", {"A -> F [ +A ] A"})));
  EXPECT_TRUE(is_plant(module("F & F", {})));  // draws in 3D
  // A bracket written only by an interpretation rule (what is drawn) still branches the drawing.
  Grammar drawn = module("A", {"A -> A B"});
  drawn.interpretation = test::rules_of({"B -> F [ +F ] F"});
  EXPECT_TRUE(is_plant(drawn));
  EXPECT_FALSE(is_plant(module("A", {"A -> F + A"})));
}

TEST(Plant, Branched2DStartsAtTheOriginHeadingUpInUnitSteps) {
  const Grammar g{.axiom = "X", .rules = {{'X', "F[+X]F[-X]X"}}, .angle = 30};
  for (int level : {1, 3}) {
    const Polyline c = turtle2d(g, {.level = level}, no_progress());
    EXPECT_EQ(c.points[0], (Vec2{0, 0}));
    EXPECT_NEAR(norm(c.points[1] - Vec2{0, 1}), 0, 1e-15) << level;  // heading +y, a unit step
  }
  // Every level keeps the turtle's unit: the main axis of level 4 is 8 steps tall, not 1.
  const Polyline c = turtle2d(g, {.level = 4}, no_progress());
  EXPECT_GE(c.bbox().max.y, 8 - 1e-12);
  // shrink scales the steps by shrink^level, as it does closed curves.
  Grammar shrunk = g;
  shrunk.shrink = 0.5;
  const Polyline s = turtle2d(shrunk, {.level = 2}, no_progress());
  EXPECT_NEAR(norm(s.points[1] - Vec2{0, 0.25}), 0, 1e-15);
  // The module turtle places the same way: F(l) steps l.
  const Polyline m = module_turtle2d(module("F(2.5) [ +F ] F", {}), {.level = 0}, no_progress());
  EXPECT_EQ(m.points[0], (Vec2{0, 0}));
  EXPECT_NEAR(norm(m.points[1] - Vec2{0, 2.5}), 0, 1e-15);
  // A start_angle the grammar gives wins.
  Grammar tilted = g;
  tilted.start_angles = {0};
  EXPECT_NEAR(norm(turtle2d(tilted, {.level = 1}, no_progress()).points[1] - Vec2{1, 0}), 0, 1e-15);
}

TEST(Plant, ThreeDHeadsUpWithLeftAlongMinusXAndUpAlongZ) {
  auto end = [](const std::string& axiom) {
    return module_turtle3d(module(axiom, {}), {.level = 0}, no_progress()).points.back();
  };
  EXPECT_NEAR(norm(end("F & F") - Vec3{0, 1, -1}), 0, 1e-15);   // H = +y; pitch down: toward -U = -z
  EXPECT_NEAR(norm(end("F & +F") - Vec3{-1, 1, 0}), 0, 1e-15);  // yaw left: toward L = -x
  EXPECT_NEAR(norm(end("F & ^F") - Vec3{0, 2, 0}), 0, 1e-15);
  // The polygons of a plant are placed as its curve: a leaf at the top of a unit stem.
  Grammar leaf = module("F & { . F . +F . }", {});
  const Mesh m = module_polygons(leaf, {.level = 0}, no_progress());
  ASSERT_EQ(m.points.size(), 3u);
  EXPECT_NEAR(norm(m.points[0] - Vec3{0, 1, 0}), 0, 1e-15);
  EXPECT_NEAR(norm(m.points[1] - Vec3{0, 1, -1}), 0, 1e-15);
}

TEST(Plant, NormalizeTrueMapsAPlantAsBefore) {
  // As before this change: heading 0, the end onto (1,0), the same points as a grammar that says so.
  const Grammar g{.axiom = "X", .rules = {{'X', "F[+X]F[-X]X"}}, .angle = 30};
  const Polyline c = turtle2d(g, {.level = 3, .normalize = true}, no_progress());
  Grammar old = g;
  old.start_angles = {0};
  const Polyline d = turtle2d(old, {.level = 3, .normalize = true}, no_progress());
  EXPECT_EQ(c.points, d.points);
  EXPECT_EQ(c.points.front(), (Vec2{0, 0}));
  EXPECT_NEAR(norm(c.points.back() - Vec2{1, 0}), 0, 1e-12);
  const Polyline3 t = module_turtle3d(module("F & F [ +F ] F", {}), {.level = 0, .normalize = true}, no_progress());
  EXPECT_NEAR(norm(t.points.back() - Vec3{1, 0, 0}), 0, 1e-12);
}

TEST(Plant, UnbranchedOpenCurvesAreStillNormalised) {
  for (const Grammar& g : {table1::dragon(), table1::koch(), table1::gosper(), table1::hilbert()}) {
    const Polyline c = turtle2d(g, {.level = 4}, no_progress());
    EXPECT_EQ(c.points.front(), (Vec2{0, 0}));
    EXPECT_NEAR(norm(c.points.back() - Vec2{1, 0}), 0, 1e-12);
    // The same points as normalize = true, and no plant fields.
    EXPECT_EQ(c.points, turtle2d(g, {.level = 4, .normalize = true}, no_progress()).points);
    EXPECT_EQ(c.point_fields.find("branch_order"), nullptr);
  }
  // normalize = false leaves an unbranched curve heading 0 in unit steps, as before.
  const Polyline c = turtle2d(table1::koch(), {.level = 1, .normalize = false}, no_progress());
  EXPECT_NEAR(norm(c.points[1] - Vec2{1, 0}), 0, 1e-15);
  EXPECT_NEAR(norm(module_turtle2d(module("F + F", {}), {.level = 0}, no_progress()).points.back() - Vec2{1, 0}), 0,
              1e-12);
}

TEST(Plant, BranchOrderIsTheBracketDepth) {
  // F [ +F [ -F ] F ] F: the trunk (0), a branch (1) holding a twig (2), the branch again, the trunk.
  const Grammar g{.axiom = "F[+F[-F]F]F", .angle = 45};
  const Polyline c = turtle2d(g, {.level = 0}, no_progress());
  // Paths: trunk into the branch into the twig; the branch's second step; the trunk's second step.
  EXPECT_EQ(ints(c.point_fields.find("branch_order")), (std::vector<std::int32_t>{0, 0, 1, 2, 1, 1, 0, 0}));
  const Polyline m = module_turtle2d(module("F [ +F [ -F ] F ] F", {}), {.level = 0}, no_progress());
  EXPECT_EQ(ints(m.point_fields.find("branch_order")), (std::vector<std::int32_t>{0, 0, 1, 2, 1, 1, 0, 0}));
  // A grammar that branches carries it at every level, even one whose string has no bracket yet.
  const Polyline seed = turtle2d(Grammar{.axiom = "F", .rules = {{'F', "F[+F]F"}}}, {.level = 0}, no_progress());
  EXPECT_EQ(ints(seed.point_fields.find("branch_order")), (std::vector<std::int32_t>{0, 0}));
}
