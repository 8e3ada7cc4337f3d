#include "kernels/lsystem/turtle/module_turtle.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "../module_grammar.h"
#include "../table1.h"
#include "kernels/base/budget.h"
#include "kernels/lsystem/rule_parser.h"

using namespace selfsim;
using namespace selfsim::lsystem;

namespace {

Grammar grammar(const std::string& axiom, const std::vector<std::string>& rules) {
  return test::module_grammar(axiom, rules);
}

Polyline at(const Grammar& g, int level, bool normalize = true) {
  return module_turtle2d(g, {.level = level, .normalize = normalize}, no_progress());
}

}  // namespace

TEST(ModuleTurtle, DrawsWhatTheByteTurtleDraws) {
  for (const Grammar& plain : {table1::koch(), table1::dragon(), table1::hilbert()}) {
    Grammar g = plain;
    std::vector<std::string> rules;
    for (const auto& [symbol, rule] : plain.rules) rules.push_back(std::string(1, symbol) + " -> " + rule);
    const Grammar m = [&] {
      Grammar out = grammar(plain.axiom, rules);
      out.angle = plain.angle;
      out.start_angles = plain.start_angles;
      return out;
    }();
    for (int n = 0; n <= 6; ++n) {
      const Polyline a = turtle2d(plain, {.level = n}, no_progress()), b = at(m, n);
      ASSERT_EQ(a.points.size(), b.points.size()) << plain.axiom << " level " << n;
      for (std::size_t i = 0; i < a.points.size(); ++i)
        ASSERT_NEAR(norm(a.points[i] - b.points[i]), 0, 1e-9) << plain.axiom << " level " << n << " point " << i;
    }
  }
}

TEST(ModuleTurtle, ParametersSetLengthsAndAngles) {
  Grammar g = grammar("F(2) +(90) F(1) -(45) f(3) F", {});
  const Polyline c = at(g, 0, false);
  ASSERT_EQ(c.paths(), 2u);
  ASSERT_EQ(c.points.size(), 5u);
  EXPECT_NEAR(norm(c.points[1] - Vec2{2, 0}), 0, 1e-12);
  EXPECT_NEAR(norm(c.points[2] - Vec2{2, 1}), 0, 1e-12);
  const Vec2 moved = Vec2{2, 1} + 3 * Vec2{std::sqrt(0.5), std::sqrt(0.5)};
  EXPECT_NEAR(norm(c.points[3] - moved), 0, 1e-12);
  EXPECT_NEAR(norm(c.points[4] - (moved + Vec2{std::sqrt(0.5), std::sqrt(0.5)})), 0, 1e-12);
}

TEST(ModuleTurtle, ParametricTreeHasItsBranchesAndFields) {
  const Grammar g = grammar("A(1)", {"A(x) -> F(x) [+(30) A(x*0.5)] [-(30) A(x*0.5)]"});
  const Polyline c = at(g, 6);
  // 2^6 - 1 segments: the trunk and two children per fork, each a path of its own after a branch.
  EXPECT_EQ(c.segments(), 63u);
  EXPECT_NEAR(norm(c.points.front()), 0, 1e-12);
  // The turtle ends at the top of the trunk: normalised, the trunk runs (0,0)-(1,0).
  EXPECT_NEAR(norm(c.points[1] - Vec2{1, 0}), 0, 1e-12);
  ASSERT_NE(c.point_fields.find("branch_order"), nullptr);
  ASSERT_NE(c.point_fields.find("root_distance"), nullptr);
  // Symmetric branching: the tree's extent above and below the trunk agrees.
  const auto box = c.bbox();
  EXPECT_NEAR(box.max.y, -box.min.y, 1e-12);
}

TEST(ModuleTurtle, WidthAndColourBecomePointFields) {
  const Grammar g = grammar("!(3) F '(2) F ! ' F", {});
  const Polyline c = at(g, 0, false);
  const Field* width = c.point_fields.find("width");
  const Field* color = c.point_fields.find("color");
  ASSERT_NE(width, nullptr);
  ASSERT_NE(color, nullptr);
  ASSERT_EQ(c.points.size(), 4u);
  EXPECT_EQ(width->at(3), 2);
  EXPECT_EQ(color->at(2), 2);
  EXPECT_EQ(color->at(3), 3);
  EXPECT_EQ(at(grammar("F", {}), 0).point_fields.find("width"), nullptr);
  // Each field only where the grammar sets it: colours alone leave the line width to the writer.
  const Polyline coloured = at(grammar("F '(4) F", {}), 0, false);
  EXPECT_EQ(coloured.point_fields.find("width"), nullptr);
  ASSERT_NE(coloured.point_fields.find("color"), nullptr);
  EXPECT_EQ(coloured.point_fields.find("color")->at(2), 4);
  const Polyline widened = at(grammar("!(5) F", {}), 0, false);
  EXPECT_EQ(widened.point_fields.find("color"), nullptr);
  ASSERT_NE(widened.point_fields.find("width"), nullptr);
}

TEST(ModuleTurtle, PointsBeyondTheBudgetAreRefused) {
  const Grammar g = grammar("A", {"A -> FA"});
  TurtleOptions opt{.level = 200};
  opt.budget.limit = 100;
  EXPECT_THROW(module_turtle2d(g, opt, no_progress()), BudgetError);
  const Grammar idle = grammar("A", {"A -> BA", "B -> BB"});
  opt.level = 60;
  EXPECT_THROW(module_turtle2d(idle, opt, no_progress()), BudgetError);  // rewrites, never draws
}

TEST(ModuleTurtle, SegmentsAreCounted) {
  const Grammar g = grammar("A(1)", {"A(x) -> F(x) [+(30) A(x*0.5)] [-(30) A(x*0.5)]"});
  EXPECT_EQ(module_segments(g, 10, 1e9, no_progress()), 1023);
}

namespace {

// ABOP Figure 1.8: the 3D Hilbert curve.
Grammar hilbert3d() {
  Grammar g = grammar("A", {"A -> B-F+CFC+F-D&F^D-F+&&CFC+F+B//", "B -> A&F^CFB^F^D^^-F-D^|F^B|FC^F^A//",
                            "C -> |D^|F^B-F+C^F^A&&FA&F^C+F+B^F^D//", "D -> |CFB-F+B|FA&F^A&&FB-F+B|FC//"});
  g.angle = 90;
  return g;
}

}  // namespace

TEST(ModuleTurtle3, HilbertCurveVisitsEveryLatticePointOnce) {
  // A wrong sense of any one 3D turn makes the curve leave its cube or cross itself.
  for (int n = 1; n <= 3; ++n) {
    const Polyline3 c = module_turtle3d(hilbert3d(), {.level = n, .normalize = false}, no_progress());
    const int side = 1 << n;
    ASSERT_EQ(c.points.size(), static_cast<std::size_t>(side * side * side));
    std::set<std::array<long, 3>> seen;
    for (const Vec3& p : c.points) {
      const std::array<long, 3> k{std::lround(p.x), std::lround(p.y), std::lround(p.z)};
      EXPECT_EQ(p, (Vec3{double(k[0]), double(k[1]), double(k[2])}));  // quarter turns are exact
      seen.insert(k);
    }
    EXPECT_EQ(seen.size(), c.points.size()) << "level " << n;
    const auto box = c.bbox();
    EXPECT_EQ(box.max.x - box.min.x, side - 1);
    EXPECT_EQ(box.max.y - box.min.y, side - 1);
    EXPECT_EQ(box.max.z - box.min.z, side - 1);
  }
}

TEST(ModuleTurtle3, TurnsFollowTheirDocumentedSense) {
  auto end = [](const std::string& axiom) {
    Grammar g = grammar(axiom, {});
    g.angle = 90;
    g.start_angles = {0};  // H = +x, L = +y, U = +z
    return module_turtle3d(g, {.level = 0, .normalize = false}, no_progress()).points.back();
  };
  EXPECT_EQ(end("F"), (Vec3{1, 0, 0}));
  EXPECT_EQ(end("+F"), (Vec3{0, 1, 0}));  // yaw left: toward L (+y)
  EXPECT_EQ(end("-F"), (Vec3{0, -1, 0}));
  EXPECT_EQ(end("&F"), (Vec3{0, 0, -1}));  // pitch down: toward -U
  EXPECT_EQ(end("^F"), (Vec3{0, 0, 1}));
  EXPECT_EQ(end("\\+F"), (Vec3{0, 0, -1}));  // roll left: L toward -U, so a left turn then heads down
  EXPECT_EQ(end("/+F"), (Vec3{0, 0, 1}));
  EXPECT_EQ(end("|F"), (Vec3{-1, 0, 0}));
}

TEST(ModuleTurtle3, PlanarGrammarsDrawWhatThe2DTurtleDraws) {
  Grammar g = grammar("A(1)", {"A(x) -> F(x) [+(30) A(x*0.5)] [-(40) A(x*0.6)]"});
  for (bool normalize : {false, true}) {
    const Polyline a = module_turtle2d(g, {.level = 5, .normalize = normalize}, no_progress());
    const Polyline3 b = module_turtle3d(g, {.level = 5, .normalize = normalize}, no_progress());
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i)
      EXPECT_NEAR(norm(Vec3{a.points[i].x, a.points[i].y, 0} - b.points[i]), 0, 1e-12);
  }
}

TEST(ModuleTurtle3, RollToHorizontalAndTropism) {
  Grammar level = grammar("+(90) \\(40) $ +(90) F", {});  // heading up (+y), rolled, then levelled
  level.start_angles = {0};
  const Vec3 p = module_turtle3d(level, {.level = 0, .normalize = false}, no_progress()).points.back();
  EXPECT_NEAR(p.y, 0, 1e-12);  // after '$' a yaw stays horizontal
  EXPECT_NEAR(std::hypot(p.x, p.z), 1, 1e-12);
  Grammar bent = grammar("F F F F", {});
  bent.tropism = {0, -0.3, 0};
  bent.start_angles = {0};  // along +x, bending down toward -y
  const Polyline3 c = module_turtle3d(bent, {.level = 0, .normalize = false}, no_progress());
  for (std::size_t i = 2; i < c.points.size(); ++i)
    EXPECT_LT(c.points[i].y - c.points[i - 1].y, c.points[i - 1].y - c.points[i - 2].y + 1e-15);  // bending down
  EXPECT_LT(c.points.back().y, -0.5);
}

TEST(ModuleTurtle3, PolygonsBecomeTriangles) {
  // ABOP's leaf: a polygon from f moves, not drawn as lines.
  Grammar g = grammar("F [ '(3) { -f +f +f - | - f +f +f } ] F", {});
  g.angle = 45;
  const Polyline3 c = module_turtle3d(g, {.level = 0, .normalize = false}, no_progress());
  EXPECT_EQ(c.segments(), 2u);  // the two F, not the leaf's edges
  const Mesh m = module_polygons(g, {.level = 0, .normalize = false}, no_progress());
  EXPECT_EQ(m.triangles.size(), m.points.size() - 2);
  EXPECT_GE(m.points.size(), 5u);
  EXPECT_GT(surface_area(m), 0.5);
  ASSERT_NE(m.face_fields.find("color"), nullptr);
  EXPECT_EQ(m.face_fields.find("color")->at(0), 3);
  EXPECT_EQ(m.face_fields.find("polygon")->at(0), 0);
}

TEST(ModuleTurtle3, OpenCurvesAreNormalisedOntoTheXAxisWhenAsked) {
  const Polyline3 c = module_turtle3d(hilbert3d(), {.level = 2, .normalize = true}, no_progress());
  EXPECT_NEAR(norm(c.points.front()), 0, 1e-12);
  EXPECT_NEAR(norm(c.points.back() - Vec3{1, 0, 0}), 0, 1e-12);
}

TEST(ModuleTurtle3, DimensionFollowsTheSymbols) {
  Grammar g = grammar("F+F", {});
  EXPECT_FALSE(draws_in_3d(g));
  g.tropism = {0, -1, 0};
  EXPECT_TRUE(draws_in_3d(g));
  Grammar h = hilbert3d();
  EXPECT_TRUE(draws_in_3d(h));
  h.dimension = 2;
  EXPECT_FALSE(draws_in_3d(h));
}

TEST(ModuleTurtle3, PolygonsClosedByWalkingBackAreNotSlivers) {
  Grammar g = grammar("{ F + F + F + }", {});  // a triangle walked all the way round
  g.angle = 120;
  const Mesh m = module_polygons(g, {.level = 0, .normalize = false}, no_progress());
  EXPECT_EQ(m.points.size(), 3u);
  EXPECT_EQ(m.triangles.size(), 1u);
  Grammar line = grammar("{ . F . F . F . }", {});  // corners on one line fill nothing
  EXPECT_EQ(module_polygons(line, {.level = 0, .normalize = false}, no_progress()).triangles.size(), 0u);
  EXPECT_EQ(module_segments(grammar("F{F+F+F}F", {}), 0, 1e6, no_progress()), 2);  // polygon steps draw no line
}
