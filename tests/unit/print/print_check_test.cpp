// The print check on solids whose walls and gaps are known: a 20 mm cube passes; a 0.4 mm plate has thin
// walls (and says where); two blocks 0.2 mm apart have a narrow gap; an open surface is refused; a solid
// turned inside out, one crossing itself and one over the triangle budget or the bed are findings.
#include "kernels/print/print_check.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "kernels/base/error.h"
#include "kernels/region/box_mesh.h"
#include "print_fixtures.h"
#include "tests/unit/print/lathe_fixture.h"

using namespace selfsim;
using namespace selfsim::print;
using print_fixtures::joined;
using print_fixtures::mentions;

TEST(PrintCheck, ACubePasses) {
  const PrintReport r = check_print(box_mesh({0, 0, 0}, {20, 20, 20}), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(r.passes()) << r.summary();
  EXPECT_TRUE(r.wall.measured);
  EXPECT_EQ(r.wall.under, 0u);
  EXPECT_EQ(r.triangles, 12u);
  EXPECT_NE(r.summary().find("passes"), std::string::npos);
  EXPECT_NE(r.summary().find("20 x 20 x 20 mm"), std::string::npos) << r.summary();
}

TEST(PrintCheck, AThinPlateHasThinWallsWhereItIs) {
  Mesh marked;
  const PrintReport r =
      check_print(box_mesh({0, 0, 0}, {10, 10, 0.4}), PrintRules{}, PointBudget{}, no_progress(), &marked);
  EXPECT_FALSE(r.passes());
  EXPECT_TRUE(mentions(r, "walls thinner than 0.8 mm")) << r.summary();
  // The faces' centres read the plate's thickness, to within the grid's error.
  EXPECT_NEAR(r.wall.value, 0.4, r.error + 0.05) << r.summary();
  EXPECT_GE(r.wall.where.z, -0.01);
  EXPECT_LE(r.wall.where.z, 0.41);
  ASSERT_NE(marked.point_fields.find("wall"), nullptr);
  ASSERT_NE(marked.face_fields.find("wall"), nullptr);
  const auto faces = marked.face_fields.find("wall")->reals();
  // The top and bottom faces (4 of the 12 triangles) read about 0.4; the others (side faces) read more.
  EXPECT_EQ(std::count_if(faces.begin(), faces.end(), [&](double w) { return std::abs(w - 0.4) < r.error + 0.05; }), 4);
}

TEST(PrintCheck, TwoBlocksCloseTogetherHaveANarrowGap) {
  const Mesh two = joined(box_mesh({0, 0, 0}, {10, 10, 5}), box_mesh({0, 0, 5.2}, {10, 10, 10}));
  const PrintReport r = check_print(two, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(r, "gaps narrower than 0.4 mm")) << r.summary();
  EXPECT_NEAR(r.gap.value, 0.2, r.voxel / 5);  // print_measure_test.cpp: gaps of a few voxels
  EXPECT_FALSE(mentions(r, "walls thinner"));
  // A narrow gap over less area than the nozzle's spot, and under a tenth of the surface, is no finding
  // (here a 20 mm nozzle, whose disc of 314 mm² covers more than the tall blocks' facing sides, 2 x 100 mm²
  // of 4,400), and the summary says why.
  PrintRules wide;
  wide.nozzle = 20;
  const Mesh tall = joined(box_mesh({0, 0, -45}, {10, 10, 5}), box_mesh({0, 0, 5.2}, {10, 10, 55}));
  const PrintReport speck = check_print(tall, wide, PointBudget{}, no_progress());
  EXPECT_FALSE(mentions(speck, "gaps narrower")) << speck.summary();
  // Both facing sides: two places (they share no corner), each judged by its own area.
  EXPECT_NE(speck.summary().find("gaps 0.2 mm on 2 specks, each smaller than the nozzle's spot"), std::string::npos)
      << speck.summary();
  EXPECT_NEAR(speck.gap.area_under, 200, 1e-6);
  EXPECT_EQ(speck.gap.places, 2u);
  EXPECT_NEAR(speck.gap.largest_place, 100, 1e-6);
  // Judged together, 200 mm² would be a finding at a 15 mm nozzle (177 mm²); place by place it is not.
  wide.nozzle = 15;
  const PrintReport places = check_print(tall, wide, PointBudget{}, no_progress());
  EXPECT_FALSE(mentions(places, "gaps narrower")) << places.summary();
  wide.nozzle = 11;  // 95 mm²: each 100 mm² side is a place of its own that counts
  EXPECT_TRUE(mentions(check_print(tall, wide, PointBudget{}, no_progress()),
                       "gaps narrower than 0.4 mm (they fuse) at 2 places"));
  // The same blocks 1 mm apart pass.
  const Mesh apart = joined(box_mesh({0, 0, 0}, {10, 10, 5}), box_mesh({0, 0, 6}, {10, 10, 11}));
  EXPECT_TRUE(check_print(apart, PrintRules{}, PointBudget{}, no_progress()).passes());
}

TEST(PrintCheck, RefusesAnOpenSurface) {
  Mesh m = box_mesh({0, 0, 0}, {10, 10, 10});
  m.triangles.pop_back();
  try {
    check_print(m, PrintRules{}, PointBudget{}, no_progress());
    FAIL() << "an open mesh was checked";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the mesh is open"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("thicken"), std::string::npos) << e.what();
  }
}

TEST(PrintCheck, InwardCrossingBigAndTinyAreFindings) {
  Mesh inward = box_mesh({0, 0, 0}, {10, 10, 10});
  for (Triangle& t : inward.triangles) std::swap(t[1], t[2]);
  EXPECT_TRUE(mentions(check_print(inward, PrintRules{}, PointBudget{}, no_progress()), "face inwards"));

  // One closed piece through itself: a cube's top corner pushed through its bottom (two overlapping cubes
  // are two solids, which a slicer unites: see OverlappingSolidsMayFailAndSayUnion).
  Mesh crossing = box_mesh({0, 0, 0}, {10, 10, 10});
  crossing.points[7] = {10, 10, -5};
  const PrintReport c = check_print(crossing, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(c, "crosses itself near")) << c.summary();

  PrintRules few;
  few.max_triangles = 10;
  few.bed = {5, 50, 50};
  const PrintReport big = check_print(box_mesh({0, 0, 0}, {10, 10, 10}), few, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(big, "12 triangles, over the 10")) << big.summary();
  EXPECT_TRUE(mentions(big, "larger than the bed")) << big.summary();

  const PrintReport tiny = check_print(box_mesh({0, 0, 0}, {1, 1, 1}), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(tiny, "probably still in model units (sizes are mm): solid.size(s, 80)")) << tiny.summary();
  // Under 5 mm across is flagged (a 2.47 mm blob passed as a print); a 6 mm block is a print.
  const PrintReport small = check_print(box_mesh({0, 0, 0}, {4, 4, 4}), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(small, "probably still in model units")) << small.summary();
  const PrintReport fine = check_print(box_mesh({0, 0, 0}, {6, 6, 6}), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_FALSE(mentions(fine, "model units")) << fine.summary();
}

TEST(PrintCheck, AGridOverTheBudgetIsSaidNotThrown) {
  PointBudget small;
  small.limit = 100;
  const PrintReport r = check_print(box_mesh({0, 0, 0}, {20, 20, 20}), PrintRules{}, small, no_progress());
  EXPECT_FALSE(r.wall.measured);
  EXPECT_TRUE(mentions(r, "not measured")) << r.summary();
}

TEST(PrintCheck, ProfilesAndRules) {
  EXPECT_EQ(PrintRules::named("sla").min_wall, 0.4);
  EXPECT_THROW(PrintRules::named("laser"), Error);
  PrintRules bad;
  bad.min_wall = 0;
  EXPECT_THROW(bad.validate(), Error);
  // The SLA profile passes the 0.4 mm plate's walls (0.4 mm is its minimum) within the grid's error.
  PrintRules sla = PrintRules::named("sla");
  sla.min_wall = 0.3;
  EXPECT_FALSE(
      mentions(check_print(box_mesh({0, 0, 0}, {10, 10, 0.4}), sla, PointBudget{}, no_progress()), "walls thinner"));
}

TEST(PrintCheck, ASolidThinAllOverIsNoSpeck) {
  // A 1 mm square plate 0.1 mm thick: its thin walls cover less than a 20 mm nozzle's spot, but they are
  // most of its surface.
  PrintRules wide;
  wide.nozzle = 20;
  const PrintReport r = check_print(box_mesh({0, 0, 0}, {10, 10, 0.1}), wide, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(r, "walls thinner than 0.8 mm")) << r.summary();
}

TEST(PrintCheck, ASealedCavityIsNoGap) {
  // A 20 mm cube hollowed by a 10 mm cavity (its faces turned inwards): walls 5 mm, no gap anywhere. The
  // cavity's walls' gaps (its width) are not measured.
  Mesh cavity = box_mesh({5, 5, 5}, {15, 15, 15});
  for (Triangle& t : cavity.triangles) std::swap(t[1], t[2]);
  const PrintReport r =
      check_print(joined(box_mesh({0, 0, 0}, {20, 20, 20}), cavity), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(r.passes()) << r.summary();
  // With 0.5 mm walls round the cavity the walls are found.
  Mesh near = box_mesh({0.5, 0.5, 0.5}, {19.5, 19.5, 19.5});
  for (Triangle& t : near.triangles) std::swap(t[1], t[2]);
  const PrintReport thin =
      check_print(joined(box_mesh({0, 0, 0}, {20, 20, 20}), near), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(thin, "walls thinner than 0.8 mm")) << thin.summary();
  EXPECT_FALSE(mentions(thin, "gaps narrower")) << thin.summary();
}

TEST(PrintCheck, ASolidTooWideForAGridIsSaidNotMeasured) {
  // A voxel asked for measures on the distance grid (without, the rays run against the triangles).
  PrintRules on_grid;
  on_grid.voxel = 0.1;
  const PrintReport r = check_print(box_mesh({0, 0, 0}, {200000, 10, 10}), on_grid, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(r, "walls and gaps not measured: the solid is")) << r.summary();
  EXPECT_FALSE(r.wall.measured);
}

// Issue 40: each finding has a severity and the change that fixes it, in the recipe's terms.
TEST(PrintCheck, FindingsSaySeverityAndFix) {
  const auto problem = [](const PrintReport& r, const std::string& words) -> const Problem* {
    for (const Problem& p : r.problems)
      if (p.what.find(words) != std::string::npos) return &p;
    return nullptr;
  };
  // Walls of 0.3 mm are under the 0.4 mm nozzle: will fail; thicken to 0.8 mm or scale up about 2.7x.
  const PrintReport thin = check_print(box_mesh({0, 0, 0}, {10, 10, 0.3}), PrintRules{}, PointBudget{}, no_progress());
  const Problem* w = problem(thin, "walls thinner than 0.8 mm");
  ASSERT_NE(w, nullptr) << thin.summary();
  EXPECT_EQ(w->severity, Severity::will_fail);
  EXPECT_NE(
      w->fix.find("thicken to 0.8 mm (solid.thicken's thickness = 0.8, solid.tube's min_radius = 0.4) or scale up 2."),
      std::string::npos)
      << w->fix;
  EXPECT_NE(thin.summary().find("will fail: walls thinner"), std::string::npos) << thin.summary();
  // 0.6 mm: printable by the nozzle, under two perimeters: may fail.
  const PrintReport weak = check_print(box_mesh({0, 0, 0}, {10, 10, 0.6}), PrintRules{}, PointBudget{}, no_progress());
  ASSERT_NE(problem(weak, "walls thinner"), nullptr) << weak.summary();
  EXPECT_EQ(problem(weak, "walls thinner")->severity, Severity::may_fail);
  // Gaps that fuse: may fail, scale up (0.4 / 0.2 = 2x, within the grid's error) or thinner walls.
  const Mesh two = joined(box_mesh({0, 0, 0}, {10, 10, 5}), box_mesh({0, 0, 5.2}, {10, 10, 10}));
  const PrintReport gap = check_print(two, PrintRules{}, PointBudget{}, no_progress());
  ASSERT_NE(problem(gap, "gaps narrower"), nullptr) << gap.summary();
  EXPECT_EQ(problem(gap, "gaps narrower")->severity, Severity::may_fail);
  EXPECT_NE(problem(gap, "gaps narrower")->fix.find("(solid.size) or thinner walls"), std::string::npos);
  // Triangles and the bed.
  PrintRules few;
  few.max_triangles = 10;
  few.bed = {5, 50, 50};
  const PrintReport big = check_print(box_mesh({0, 0, 0}, {10, 10, 10}), few, PointBudget{}, no_progress());
  EXPECT_EQ(problem(big, "triangles, over")->severity, Severity::may_fail);
  EXPECT_EQ(problem(big, "triangles, over")->fix, "solid.decimate(s, { triangles = 10 })");
  EXPECT_EQ(problem(big, "larger than the bed")->severity, Severity::will_fail);
  EXPECT_EQ(problem(big, "larger than the bed")->fix, "solid.size(s, { fit = {5, 50, 50} })");
  // Will fail comes before may fail, in the summary as in the list.
  EXPECT_EQ(big.problems.front().severity, Severity::will_fail) << big.summary();
  // The newcomer's 2.47 mm blob: will fail, still in model units, said first (the cause of the rest).
  const PrintReport blob = check_print(box_mesh({0, 0, 0}, {2.47, 2, 2}), PrintRules{}, PointBudget{}, no_progress());
  ASSERT_NE(problem(blob, "probably still in model units"), nullptr) << blob.summary();
  EXPECT_EQ(problem(blob, "model units")->severity, Severity::will_fail);
  EXPECT_NE(blob.problems.front().what.find("model units"), std::string::npos) << blob.summary();
  EXPECT_EQ(problem(blob, "model units")->fix, "solid.size(s, 80)");
  EXPECT_FALSE(blob.passes());
  // The warning's brief line keeps to its room, the most serious first with its fix, and says there is more.
  const std::string line = brief(big, 200);
  EXPECT_LE(line.size(), 200u) << line;
  EXPECT_NE(line.find("will fail: it is 10 x 10 x 10 mm, larger than the bed's"), std::string::npos) << line;
  EXPECT_NE(line.find("and more: solid.check lists them"), std::string::npos) << line;
  EXPECT_EQ(brief(blob, 2000), blob.summary());
}

// A solid as large as a box the recipe grew it in (10 units), or a little larger, is probably still in
// model units; one sized to 80 mm is not, nor one as large as a box of 7.5 units (not a whole number: a size chosen).
TEST(PrintCheck, TheRecipesUnitBoxIsModelUnits) {
  PrintReport r = check_print(box_mesh({0, 0, 0}, {10, 10, 10}), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(r.passes());
  BBox3 unit;
  unit.add(Vec3{-5, -5, -5});
  unit.add(Vec3{5, 5, 5});
  flag_model_box(r, {unit});
  EXPECT_FALSE(r.passes());
  EXPECT_TRUE(mentions(r, "the size of a box the recipe grew it in (10 units): probably still in model units"))
      << r.summary();
  // A surface filling the box, thickened by 1 mm: still the box's size, near enough.
  PrintReport thick = check_print(box_mesh({-0.5, 0, 0}, {10.5, 10, 10}), PrintRules{}, PointBudget{}, no_progress());
  flag_model_box(thick, {unit});
  EXPECT_FALSE(thick.passes()) << thick.summary();
  PrintReport sized = check_print(box_mesh({0, 0, 0}, {80, 80, 10}), PrintRules{}, PointBudget{}, no_progress());
  flag_model_box(sized, {unit});
  EXPECT_TRUE(sized.passes()) << sized.summary();
  BBox3 chosen;
  chosen.add(Vec3{0, 0, 0});
  chosen.add(Vec3{7.5, 1, 1});
  PrintReport other = check_print(box_mesh({0, 0, 0}, {7.5, 7.5, 7.5}), PrintRules{}, PointBudget{}, no_progress());
  flag_model_box(other, {chosen});
  EXPECT_TRUE(other.passes()) << other.summary();
}

// A sealed speck (a closed piece under the nozzle's spot) through a solid's side is no crossing: cosmetic. Two blocks
// meeting along an edge touch there: a crease, cosmetic. Two blocks passing through each other cross: will fail,
// suggesting a grid.
TEST(PrintCheck, SpecksAndCreasesAreNotCrossings) {
  const Mesh speck = joined(box_mesh({0, 0, 0}, {20, 20, 20}), box_mesh({19.9, 5, 5}, {20.1, 5.2, 5.2}));
  const PrintReport s = check_print(speck, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_FALSE(mentions(s, "crosses itself")) << s.summary();
  EXPECT_FALSE(s.crossing.has_value());
  EXPECT_EQ(s.contact.specks, 1u);
  EXPECT_NE(s.summary().find("cosmetic: 1 sealed speck smaller than the nozzle's spot"), std::string::npos)
      << s.summary();

  const Mesh edge = joined(box_mesh({0, 0, 0}, {10, 10, 10}), box_mesh({10, 10, 0}, {20, 20, 10}));
  const PrintReport e = check_print(edge, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_FALSE(e.crossing.has_value()) << e.summary();
  EXPECT_GT(e.contact.crease_pairs, 0u);
  EXPECT_NE(e.summary().find("cosmetic: a crease where the surface touches itself near"), std::string::npos)
      << e.summary();
  EXPECT_NE(e.summary().find("a slicer fuses it"), std::string::npos) << e.summary();

  Mesh through = box_mesh({0, 0, 0}, {10, 10, 10});
  through.points[7] = {10, 10, -5};  // its top corner through its bottom: one piece crossing itself
  const PrintReport c = check_print(through, PrintRules{}, PointBudget{}, no_progress());
  ASSERT_TRUE(c.crossing.has_value()) << c.summary();
  EXPECT_GT(c.contact.crossing_length, 1);
  EXPECT_EQ(c.problems.front().severity, Severity::will_fail);
  EXPECT_NE(c.problems.front().fix.find("method = \"grid\""), std::string::npos) << c.problems.front().fix;
}

// Overhang: a mushroom (a stem of radius 5, a cap of radius 15 on it) overhangs by its cap's underside ring;
// a cube on the bed by nothing; a sphere by its lower part past 45 degrees.
TEST(PrintCheck, OverhangOfAMushroomACubeAndASphere) {
  using lathe_fixture::polygon_area;
  const int sides = 32;
  Mesh marked;
  const PrintReport m =
      check_print(lathe_fixture::mushroom(5, 15), PrintRules{}, PointBudget{}, no_progress(), &marked);
  EXPECT_NEAR(m.overhang, polygon_area(sides, 15) - polygon_area(sides, 5), 1e-6) << m.summary();
  EXPECT_NEAR(m.overhang_where.z, 10, 1e-9);
  EXPECT_NE(m.summary().find("overhang 6.2 cm² past 45°"), std::string::npos) << m.summary();
  ASSERT_NE(marked.face_fields.find("overhang"), nullptr);
  ASSERT_NE(marked.point_fields.find("overhang"), nullptr);
  const auto angles = marked.face_fields.find("overhang")->reals();
  EXPECT_EQ(std::count_if(angles.begin(), angles.end(), [](double a) { return std::abs(a - 90) < 1e-9; }), 2 * sides);
  EXPECT_TRUE(m.passes()) << m.summary();  // overhang is no failure: supports print it
  // A cap barely wider than its stem: a little overhang is said, with no advice to turn it (the check cannot
  // tell whether solid.orient turned it already).
  const PrintReport lip = check_print(lathe_fixture::mushroom(5, 5.5), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_GT(lip.overhang, 0);
  EXPECT_NE(lip.summary().find("overhang 16 mm² past 45°"), std::string::npos) << lip.summary();
  EXPECT_EQ(lip.summary().find("solid.orient"), std::string::npos) << lip.summary();

  const PrintReport cube = check_print(box_mesh({0, 0, 0}, {20, 20, 20}), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_EQ(cube.overhang, 0);
  EXPECT_NE(cube.summary().find("no overhang past 45°"), std::string::npos) << cube.summary();

  // A sphere of radius 10: the zone within 45 degrees of its lowest point, 2 pi R^2 (1 - cos 45°), less the
  // faces at the pole (on the bed) and the faceting's error.
  const PrintReport ball = check_print(lathe_fixture::sphere(10), PrintRules{}, PointBudget{}, no_progress());
  const double zone = 2 * 3.14159265358979323846 * 100 * (1 - std::sqrt(0.5));
  EXPECT_NEAR(ball.overhang, zone, 0.03 * zone) << ball.summary();
  PrintRules steep;
  steep.overhang = 60;
  const PrintReport past60 = check_print(lathe_fixture::sphere(10), steep, PointBudget{}, no_progress());
  EXPECT_LT(past60.overhang, 0.6 * ball.overhang);
}

// What a solid stands on: the cube its whole base, the mushroom its stem's section, a ball of radius 10 the
// disc a tenth of a millimetre up (6.3 mm²); a double cone on its tip a point, which a slicer cannot start
// from (will fail: lay it on a face).
TEST(PrintCheck, ASolidOnAPointWillFailItsFirstLayer) {
  using lathe_fixture::polygon_area;
  const PrintReport cube = check_print(box_mesh({0, 0, 0}, {20, 20, 20}), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_NEAR(cube.first_layer, 400, 1e-9);
  EXPECT_FALSE(mentions(cube, "stands on")) << cube.summary();
  // A point no triangle uses (OBJ files have them) is neither what it stands on nor part of its size.
  Mesh stray = box_mesh({0, 0, 0}, {20, 20, 20});
  stray.points.push_back({0, 0, -3});
  const PrintReport unused = check_print(stray, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_NEAR(unused.first_layer, 400, 1e-9);
  EXPECT_NEAR(unused.box.size().z, 20, 1e-12);
  EXPECT_TRUE(unused.passes()) << unused.summary();
  const PrintReport mushroom = check_print(lathe_fixture::mushroom(5, 15), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_NEAR(mushroom.first_layer, polygon_area(32, 5), 1e-9);
  const PrintReport ball = check_print(lathe_fixture::sphere(10), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_NEAR(ball.first_layer, 3.14159265358979 * 2 * 10 * 0.1, 0.2);
  EXPECT_FALSE(mentions(ball, "stands on")) << ball.summary();
  const PrintReport cone =
      check_print(lathe_fixture::lathe({{5, 5}}, 0, 10, 64), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_LT(cone.first_layer, 0.04);
  ASSERT_FALSE(cone.problems.empty());
  EXPECT_EQ(cone.problems.front().severity, Severity::will_fail);
  EXPECT_NE(cone.problems.front().line().find("stands on"), std::string::npos) << cone.summary();
  EXPECT_NE(cone.problems.front().fix.find("solid.orient(s)"), std::string::npos) << cone.summary();
  // A resin print stands on supports: no first-layer finding for sla.
  const PrintReport resin =
      check_print(lathe_fixture::lathe({{5, 5}}, 0, 10, 64), PrintRules::named("sla"), PointBudget{}, no_progress());
  EXPECT_FALSE(mentions(resin, "stands on")) << resin.summary();
  // A pillar of radius 0.3 (0.28 mm²) fails; one of 0.5 (0.79 mm²) stands.
  EXPECT_TRUE(mentions(
      check_print(lathe_fixture::lathe({{0.3, 0}, {0.3, 5}}, 0, 5, 32), PrintRules{}, PointBudget{}, no_progress()),
      "stands on"));
  EXPECT_FALSE(mentions(
      check_print(lathe_fixture::lathe({{0.5, 0}, {0.5, 5}}, 0, 5, 32), PrintRules{}, PointBudget{}, no_progress()),
      "stands on"));
}

// Two overlapping cubes saved as one mesh are two solids: PrusaSlicer 2.5 slices them as their union, so it
// may fail (another slicer may not), and the fix is solid.union. A cavity through its solid's wall still
// crosses itself.
TEST(PrintCheck, OverlappingSolidsMayFailAndSayUnion) {
  const Mesh two = joined(box_mesh({0, 0, 0}, {10, 10, 10}), box_mesh({5, 5, 5}, {15, 15, 15}));
  const PrintReport r = check_print(two, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_FALSE(mentions(r, "crosses itself")) << r.summary();
  ASSERT_FALSE(r.problems.empty());
  EXPECT_EQ(r.problems.front().severity, Severity::may_fail) << r.summary();
  EXPECT_NE(r.problems.front().what.find("2 solids overlap near (10, 5, 10) mm (triangles 3 and 18, along 30 mm)"),
            std::string::npos)
      << r.problems.front().what;
  EXPECT_EQ(r.problems.front().fix, "solid.union{ ... } makes them one solid");
  EXPECT_TRUE(r.crossing.has_value());  // the report's `crossing`: the surfaces pass through each other
  EXPECT_EQ(r.contact.overlap_solids, 2u);

  Mesh cavity = box_mesh({8, 2, 2}, {12, 8, 8});  // faces inwards: a cavity, crossing the cube's wall
  for (Triangle& t : cavity.triangles) std::swap(t[1], t[2]);
  const PrintReport h =
      check_print(joined(box_mesh({0, 0, 0}, {10, 10, 10}), cavity), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(h, "crosses itself near")) << h.summary();
  EXPECT_FALSE(mentions(h, "solids overlap")) << h.summary();
}

// Pairs of triangles are capped at 4,096 (a mesh touching itself everywhere), but touches only: 80 pairs of
// face-touching cubes (more than 4,096 touching pairs of triangles) before, by triangle index, a cube whose
// corner is pushed through its own bottom still crosses itself.
TEST(PrintCheck, ACrossingIsNotHiddenBehindThousandsOfTouches) {
  Mesh m;
  for (int i = 0; i < 80; ++i) {
    const double x = 25.0 * i;
    m = joined(joined(m, box_mesh({x, 0, 0}, {x + 10, 10, 10})), box_mesh({x + 10, 0, 0}, {x + 20, 10, 10}));
  }
  Mesh through = box_mesh({0, 30, 0}, {10, 40, 10});
  through.points[7] = {10, 40, -5};
  m = joined(m, through);
  const PrintReport r = check_print(m, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(r.contact.capped);
  EXPECT_EQ(r.contact.crease_pairs, 4096u);
  ASSERT_TRUE(r.crossing.has_value()) << r.summary();
  EXPECT_GE(r.crossing->first, 80u * 2 * 12);
  EXPECT_TRUE(mentions(r, "crosses itself near")) << r.summary();
  EXPECT_FALSE(r.passes());
}

// A triangle repeated a thousand times is no 2-manifold: it will fail as that, and no ray is sent through
// its copies (each ray counted every one: minutes for a 50 KB file).
TEST(PrintCheck, ANonManifoldMeshIsNotMeasured) {
  // Four copies of a cube on the same points (as an STL reader merges them): every edge has 8 faces.
  Mesh cubes = box_mesh({0, 0, 0}, {10, 10, 10});
  const std::vector<Triangle> once = cubes.triangles;
  for (int k = 0; k < 3; ++k) cubes.triangles.insert(cubes.triangles.end(), once.begin(), once.end());
  const PrintReport r = check_print(cubes, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_FALSE(r.wall.measured);
  EXPECT_TRUE(mentions(r, "walls and gaps not measured: not a 2-manifold")) << r.summary();
  EXPECT_FALSE(r.passes());
}

// A closed mesh around nothing (a flat tetrahedron) will fail, where its walls read >= 1.2 mm.
TEST(PrintCheck, AMeshAroundNoVolumeWillFail) {
  Mesh flat;
  flat.points = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}, {10, 10, 0}};
  flat.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  const PrintReport r = check_print(flat, PrintRules{}, PointBudget{}, no_progress());
  ASSERT_FALSE(r.problems.empty()) << r.summary();
  EXPECT_TRUE(mentions(r, "it encloses no volume")) << r.summary();
}

// What a solid stands on, far from the origin: the shoelace is summed about the solid's own centre.
TEST(PrintCheck, TheFirstLayerFarFromTheOrigin) {
  for (double far : {1e8, 1e9, 1e12}) {
    const PrintReport r =
        check_print(box_mesh({far, far, 0}, {far + 10, far + 10, 10}), PrintRules{}, PointBudget{}, no_progress());
    EXPECT_NEAR(r.first_layer, 100, 1e-3 * far / 1e8) << far;
    EXPECT_FALSE(mentions(r, "stands on")) << r.summary();
  }
}
