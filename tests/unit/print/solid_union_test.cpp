// One solid from several: solids apart are joined exactly (their triangles, nothing remeshed), one inside
// another is dropped, a cut inside a solid is a sealed cavity; solids that meet are combined on a grid into
// one closed solid of the right volume; a cut through a solid makes a hole.
#include "kernels/print/solid_union.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/print/grid_tube.h"
#include "kernels/region/box_mesh.h"
#include "kernels/region/level_set.h"
#include "kernels/region/volume.h"

using namespace selfsim;
using namespace selfsim::print;

namespace {

UnionResult united(const std::vector<Mesh>& parts, UnionOptions opt = {}) {
  std::vector<const Mesh*> p;
  for (const Mesh& m : parts) p.push_back(&m);
  return solid_union(p, opt, no_progress());
}

UnionResult cut(const Mesh& from, const std::vector<Mesh>& cuts, UnionOptions opt = {}) {
  std::vector<const Mesh*> p;
  for (const Mesh& m : cuts) p.push_back(&m);
  return solid_difference(from, p, opt, no_progress());
}

void expect_closed(const Mesh& m) {
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.closed()) << t.first_problem;
  EXPECT_GT(enclosed_volume(m), 0);
  EXPECT_FALSE(first_intersection(m, no_progress()));
}

}  // namespace

TEST(SolidUnion, SolidsApartAreJoinedExactly) {
  const std::vector<Mesh> boxes{box_mesh({0, 0, 0}, {2, 2, 2}), box_mesh({5, 0, 0}, {6, 1, 1}),
                                box_mesh({0, 5, 0}, {1, 6, 3})};
  const UnionResult r = united(boxes);
  EXPECT_TRUE(r.exact);
  EXPECT_EQ(r.how, "exact (3 disjoint solids)");
  EXPECT_EQ(r.solid.triangles.size(), 36u);  // the sum: nothing remeshed
  expect_closed(r.solid);
  EXPECT_NEAR(enclosed_volume(r.solid), 8 + 1 + 3, 1e-9);
  EXPECT_EQ(mesh_topology(r.solid).components, 3u);
}

TEST(SolidUnion, OneInsideAnotherIsDropped) {
  Mesh inward = box_mesh({1, 1, 1}, {2, 2, 2});
  for (Triangle& t : inward.triangles) std::swap(t[1], t[2]);  // either facing is taken
  const UnionResult r = united({inward, box_mesh({0, 0, 0}, {4, 4, 4})});
  EXPECT_TRUE(r.exact);
  EXPECT_EQ(r.how, "exact (1 solid, 1 inside another dropped)");
  EXPECT_EQ(r.solid.triangles.size(), 12u);
  EXPECT_NEAR(enclosed_volume(r.solid), 64, 1e-9);
}

TEST(SolidUnion, ARimAndABaseBecomeOneClosedSolid) {
  // A plate 30 x 30 x 2 mm and a ring tube (radius 1 mm) lying on it, its axis 1.5 mm up: a quarter of the
  // ring's section sinks into the plate.
  const Mesh base = box_mesh({-15, -15, 0}, {15, 15, 2});
  Polyline3 ring;
  const int n = 96;
  const double R = 10, pi = std::numbers::pi;
  for (int i = 0; i <= n; ++i) ring.points.push_back({R * std::cos(2 * pi * i / n), R * std::sin(2 * pi * i / n), 2});
  ring.path_ends.push_back(ring.points.size());
  const Mesh rim = grid_tube(ring, {.radius = 1, .voxel = 0.1}, no_progress());
  const UnionResult r = united({base, rim});
  EXPECT_FALSE(r.exact);
  EXPECT_EQ(r.how, "on a 0.2 mm grid (solid 1 and solid 2 meet)");
  expect_closed(r.solid);
  const MeshTopology t = mesh_topology(r.solid);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.euler(), 2);  // one ball's topology: the ring's hole is filled by the plate
  // The sum less the overlap: the half of the ring's volume inside the plate (its axis on the plate's top).
  const double ring_volume = enclosed_volume(rim), want = 30 * 30 * 2 + ring_volume / 2;
  EXPECT_NEAR(enclosed_volume(r.solid), want, 0.01 * want);
}

TEST(SolidUnion, ACutThroughMakesAHoleAndOneInsideACavity) {
  const Mesh plate = box_mesh({0, 0, 0}, {10, 10, 2});
  const UnionResult hole = cut(plate, {box_mesh({4, 4, -1}, {6, 6, 3})}, {.voxel = 0.1});
  EXPECT_FALSE(hole.exact);
  EXPECT_EQ(hole.how, "on a 0.1 mm grid (the solid and cut 1 meet)");
  expect_closed(hole.solid);
  EXPECT_EQ(mesh_topology(hole.solid).euler(), 0);  // a hole through: a torus's topology
  EXPECT_NEAR(enclosed_volume(hole.solid), 200 - 8, 0.01 * 192);
  // A cut wholly inside, touching nothing: the plate with the cut's triangles turned in.
  const UnionResult cavity = cut(plate, {box_mesh({4, 4, 0.5}, {6, 6, 1.5})});
  EXPECT_TRUE(cavity.exact);
  EXPECT_EQ(cavity.how, "exact (1 sealed cavity)");
  EXPECT_EQ(cavity.solid.triangles.size(), 24u);
  EXPECT_NEAR(enclosed_volume(cavity.solid), 200 - 4, 1e-9);
  expect_closed(cavity.solid);
  // A cut apart takes nothing.
  const UnionResult apart = cut(plate, {box_mesh({20, 0, 0}, {21, 1, 1})});
  EXPECT_TRUE(apart.exact);
  EXPECT_EQ(apart.solid.triangles.size(), 12u);
}

TEST(SolidUnion, RefusesOpenSolidsAndEmptyResults) {
  Mesh open = box_mesh({0, 0, 0}, {1, 1, 1});
  open.triangles.pop_back();
  try {
    united({box_mesh({0, 0, 0}, {1, 1, 1}), open});
    FAIL() << "an open mesh was taken";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("solid 2 is not closed"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("solid.thicken"), std::string::npos) << e.what();
  }
  EXPECT_THROW(cut(box_mesh({1, 1, 1}, {2, 2, 2}), {box_mesh({0, 0, 0}, {4, 4, 4})}), Error);
  EXPECT_THROW(united({}), Error);
  // Solids that meet, at a grid over the budget: refused before any work.
  UnionOptions small;
  small.budget.limit = 1000;
  EXPECT_THROW(united({box_mesh({0, 0, 0}, {2, 2, 2}), box_mesh({1, 1, 1}, {3, 3, 3})}, small), BudgetError);
}

TEST(SolidUnion, StopsWhenAsked) {
  struct Stop : Progress {
    bool cancelled() override { return true; }
  } stop;
  const Mesh a = box_mesh({0, 0, 0}, {2, 2, 2}), b = box_mesh({1, 1, 1}, {3, 3, 3});
  const std::vector<const Mesh*> both{&a, &b};
  EXPECT_THROW(solid_union(both, {}, stop), Cancelled);
}

TEST(SolidUnion, TheGridsBudgetCountsTheCopiesHeldWhileItIsBuilt) {
  // Two capsules that cross: the grid. Its prediction alone fits the budget, but the solids' work copies turned
  // outwards are held while it is built: with them it does not, and it is refused before any work.
  const std::vector<Mesh> parts{grid_tube(Polyline3::single({{0, 0, 0}, {10, 0, 0}}), {.radius = 1}, no_progress()),
                                grid_tube(Polyline3::single({{5, -5, 0}, {5, 5, 0}}), {.radius = 1}, no_progress())};
  const double voxel = 0.25;
  std::vector<std::shared_ptr<const Volume>> volumes;
  double held = 0;
  for (const Mesh& m : parts) {
    volumes.push_back(std::make_shared<const Volume>(Volume::closed_mesh(m, no_progress())));
    held += static_cast<double>(m.points.size() + m.triangles.size());
  }
  const double grid = boundary_size(Volume::combine(Volume::Kind::unite, volumes), voxel);
  UnionOptions opt{.voxel = voxel};
  opt.budget.limit = grid + held / 2;
  EXPECT_THROW(united(parts, opt), BudgetError);
  opt.budget.limit = grid + held + 1;
  EXPECT_FALSE(united(parts, opt).exact);
  // The binding's prediction of the copies: each solid twice and the intersection search's 150 bytes a triangle.
  const std::vector<Mesh> boxes{box_mesh({0, 0, 0}, {1, 1, 1}), box_mesh({2, 0, 0}, {3, 1, 1})};
  const std::vector<const Mesh*> p{&boxes[0], &boxes[1]};
  EXPECT_DOUBLE_EQ(union_work_size(p), 2 * 2 * (8 + 12) + 24 * 150.0 / 16);
}

TEST(SolidUnion, SaysWhichSolidsMeet) {
  // A capsule whose end sinks into a box, the capsule first. The crossing found is a capsule triangle
  // numbered past the capsule's count of points: when the pair's triangle numbers were compared with that
  // count, it read "solid 2 touches itself".
  const Mesh capsule = grid_tube(Polyline3::single({{-5, 0, 0}, {5, 0, 0}}), {.radius = 1}, no_progress());
  const Mesh box = box_mesh({3, -3, -3}, {8, 3, 3});
  Mesh both = capsule;
  const auto base = static_cast<std::uint32_t>(capsule.points.size());
  both.points.insert(both.points.end(), box.points.begin(), box.points.end());
  for (const Triangle& t : box.triangles) both.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  const auto pair = first_intersection(both, no_progress());
  ASSERT_TRUE(pair);
  ASSERT_GE(pair->first, base);  // the case above
  ASSERT_LT(pair->first, capsule.triangles.size());
  EXPECT_EQ(united({capsule, box}, {.voxel = 0.25}).how, "on a 0.25 mm grid (solid 1 and solid 2 meet)");
  EXPECT_EQ(united({box, capsule}, {.voxel = 0.25}).how, "on a 0.25 mm grid (solid 1 and solid 2 meet)");
}

TEST(SolidUnion, AVoxelThatWouldLoseASolidIsRefused) {
  // Two 10 mm cubes overlapping by half on a 10 mm grid made one 10 mm cube, silently: the second lost.
  const std::vector<Mesh> cubes{box_mesh({-5, -5, -5}, {5, 5, 5}), box_mesh({0, -5, -5}, {10, 5, 5})};
  for (const double voxel : {10.0, 2.6}) {
    try {
      united(cubes, {.voxel = voxel});
      ADD_FAILURE() << "not refused at voxel " << voxel;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("option 'voxel' must be a positive length at most a quarter of the thinnest "
                                           "side of any solid's box (2.5 mm of 10 mm)"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_THROW(cut(cubes[0], {box_mesh({4, 4, 4}, {6, 6, 6})}, {.voxel = 1}), Error);  // the cut is 2 mm
  const BBox3 b = united(cubes, {.voxel = 2.5}).solid.bbox();                          // a quarter: both kept
  EXPECT_NEAR(b.min.x, -5, 0.3);
  EXPECT_NEAR(b.max.x, 10, 0.3);
}

TEST(SolidUnion, ASolidCrossingItselfGoesToTheGrid) {
  // Two overlapping cubes in one mesh, and a cube apart: the exact union kept the crossing ("exact (2 disjoint
  // solids)", and the check said it crosses itself). The grid merges it.
  Mesh cross = box_mesh({0, 0, 0}, {10, 10, 10});
  const Mesh second = box_mesh({5, 5, 5}, {15, 15, 15});
  const auto base = static_cast<std::uint32_t>(cross.points.size());
  cross.points.insert(cross.points.end(), second.points.begin(), second.points.end());
  for (const Triangle& t : second.triangles) cross.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  const UnionResult r = united({cross, box_mesh({40, 0, 0}, {42, 2, 2})}, {.voxel = 0.5});
  EXPECT_FALSE(r.exact);
  EXPECT_EQ(r.how, "on a 0.5 mm grid (solid 1 touches itself)");
  expect_closed(r.solid);
  EXPECT_NEAR(enclosed_volume(r.solid), 2 * 1000 - 125 + 8, 20);
  // Cut from: a cavity inside it would have been sealed in the crossing solid.
  const UnionResult c = cut(cross, {box_mesh({1, 1, 1}, {3, 3, 3})}, {.voxel = 0.25});
  EXPECT_EQ(c.how, "on a 0.25 mm grid (the solid touches itself)");
  expect_closed(c.solid);
}

TEST(SolidUnion, ASolidLessItselfSaysNothingIsLeft) {
  // It said "the volume is empty at voxel size 0.2 ... give a smaller 'voxel'", which no voxel helps.
  const Mesh c = box_mesh({0, 0, 0}, {10, 10, 10});
  try {
    cut(c, {c});
    ADD_FAILURE() << "not refused";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).find("nothing is left: the cuts cover the whole solid"), 0u) << e.what();
  }
}
