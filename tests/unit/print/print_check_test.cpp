// The print check on solids whose walls and gaps are known: a 20 mm cube passes; a 0.4 mm plate has thin
// walls (and says where); two blocks 0.2 mm apart have a narrow gap; an open surface is refused; a solid
// turned inside out, one crossing itself and one over the triangle budget or the bed are findings.
#include "kernels/print/print_check.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "kernels/base/error.h"
#include "kernels/region/box_mesh.h"
#include "print_fixtures.h"

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
  EXPECT_NE(speck.summary().find("mm² speck, smaller than the nozzle's spot"), std::string::npos) << speck.summary();
  // Both facing sides.
  EXPECT_NEAR(speck.gap.area_under, 200, 1e-6);
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

  const Mesh crossing = joined(box_mesh({0, 0, 0}, {10, 10, 10}), box_mesh({5, 5, 5}, {15, 15, 15}));
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
  const PrintReport r = check_print(box_mesh({0, 0, 0}, {200000, 10, 10}), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(r, "walls and gaps not measured: the solid is")) << r.summary();
  EXPECT_FALSE(r.wall.measured);
}
