// What the print check measures is what is there: gaps narrower than a few voxels read their width
// (OpenVDB's own sign fill closed them: two slabs 0.2 mm apart read "under 0.07 mm"), and a coarse CAD
// file's faces are measured all over, not at one point each (a 20 degree wedge of 8 triangles passed
// although a strip of it 2.3 mm wide is thinner than 0.8 mm).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "kernels/geom/box_mesh.h"
#include "kernels/geom/volume.h"
#include "kernels/geom/wall_grid.h"
#include "kernels/print/print_check.h"
#include "print_fixtures.h"

using namespace selfsim;
using namespace selfsim::print;
using print_fixtures::joined;
using print_fixtures::mentions;

namespace {

// A prism whose cross-section is an isosceles triangle with a 20 degree apex, `depth` mm from its apex edge
// (along x) to its back and `length` mm long (along y): 8 triangles. It is thinner than 0.8 mm within
// 0.8 / (2 tan 10°) = 2.27 mm of the apex edge (measured across from a flank: 0.8 / sin 20° = 2.34 mm).
Mesh wedge(double depth, double length) {
  const double half = depth * std::tan(10 * std::numbers::pi / 180);
  Mesh m;
  for (double y : {0.0, length}) {
    m.points.push_back({0, y, 0});
    m.points.push_back({depth, y, half});
    m.points.push_back({depth, y, -half});
  }
  // Ends 0 1 2 and 3 4 5; flanks 0 1 4 3 (upper) and 0 3 5 2 (lower); back 1 2 5 4.
  m.triangles = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {0, 3, 5}, {0, 5, 2}, {1, 2, 5}, {1, 5, 4}};
  if (enclosed_volume(m) < 0)
    for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

// Each triangle cut into four at its edges' midpoints, `levels` times (shared midpoints kept shared: closed
// stays closed).
Mesh subdivided(Mesh m, int levels) {
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
    const auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto [at, fresh] = middle.emplace(key, static_cast<std::uint32_t>(m.points.size()));
      if (fresh) m.points.push_back(0.5 * (m.points[a] + m.points[b]));
      return at->second;
    };
    std::vector<Triangle> finer;
    for (const Triangle& t : m.triangles) {
      const std::uint32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.insert(finer.end(), {{t[0], ab, ca}, {ab, t[1], bc}, {ca, bc, t[2]}, {ab, bc, ca}});
    }
    m.triangles = std::move(finer);
  }
  return m;
}

}  // namespace

TEST(PrintMeasure, GapsBetweenSlabsReadTheirWidth) {
  // Two 10 x 10 mm slabs 2 mm thick, at two placements against the grid's lattice (its voxel is 0.133 mm).
  // Within a fifth of a voxel (0.027 mm), all of it the grid's: the gap is read from its distances at voxel
  // centres, between which they are interpolated.
  for (const double gap : {0.2, 0.3, 0.35})
    for (const double thickness : {2.0, 2.05}) {
      const Mesh slabs = joined(box_mesh({0, 0, 0}, {10, 10, thickness}),
                                box_mesh({0, 0, thickness + gap}, {10, 10, 2 * thickness + gap}));
      const PrintReport r = check_print(slabs, PrintRules{}, PointBudget{}, no_progress());
      EXPECT_NEAR(r.gap.value, gap, r.voxel / 5) << "gap " << gap << ", slabs " << thickness << ": " << r.summary();
      EXPECT_TRUE(mentions(r, "gaps narrower than 0.4 mm")) << r.summary();
      EXPECT_EQ(r.summary().find("under"), std::string::npos) << r.summary();
      // The facing sides (2 x 100 mm²) are the narrow places, nothing else is.
      EXPECT_NEAR(r.gap.area_under, 200, 10) << r.summary();
    }
}

TEST(PrintMeasure, AGapFinerThanTheGridSaysSo) {
  // 0.03 mm apart: no voxel centre (0.133 mm apart) need fall in the gap, whose reading then says why.
  const Mesh slabs = joined(box_mesh({0, 0, 0}, {10, 10, 2}), box_mesh({0, 0, 2.03}, {10, 10, 4.03}));
  const PrintReport r = check_print(slabs, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(r, "the narrowest under 0.07 mm (finer than the distance grid's 0.13 mm voxel resolves)"))
      << r.summary();
}

TEST(PrintMeasure, AHollowsThinShellIsThin) {
  // A 10 mm cube hollowed to a 0.3 mm shell (the cavity's faces turned inwards): the winding number reads
  // the sealed cavity as empty, so the shell is measured to it.
  Mesh cavity = box_mesh({0.3, 0.3, 0.3}, {9.7, 9.7, 9.7});
  for (Triangle& t : cavity.triangles) std::swap(t[1], t[2]);
  const PrintReport r =
      check_print(joined(box_mesh({0, 0, 0}, {10, 10, 10}), cavity), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(r, "walls thinner than 0.8 mm")) << r.summary();
  EXPECT_NEAR(r.wall.value, 0.3, r.voxel / 5) << r.summary();
  EXPECT_FALSE(mentions(r, "gaps narrower")) << r.summary();
}

TEST(PrintMeasure, ACoarseWedgeHasItsThinStrip) {
  const Mesh coarse = wedge(10, 10);
  ASSERT_EQ(coarse.triangles.size(), 8u);
  const Mesh fine = subdivided(coarse, 4);  // 2,048 triangles
  for (const Mesh* m : {&coarse, &fine}) {
    const PrintReport r = check_print(*m, PrintRules{}, PointBudget{}, no_progress());
    EXPECT_TRUE(mentions(r, "walls thinner than 0.8 mm")) << m->faces() << " triangles: " << r.summary();
    // The flanks' strips within 2.34 mm of the apex: 2 x 2.34 x 10 mm², less the first voxel or so
    // along each edge, which is not sampled.
    EXPECT_GT(r.wall.area_under, 35) << m->faces() << " triangles: " << r.summary();
    EXPECT_LT(r.wall.area_under, 52) << m->faces() << " triangles: " << r.summary();
    EXPECT_LT(r.wall.where.x, 2.34) << m->faces() << " triangles: " << r.summary();
  }
  // A coarse cube still passes: points near its edges do not read as thin.
  const PrintReport cube = check_print(box_mesh({0, 0, 0}, {20, 20, 20}), PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(cube.passes()) << cube.summary();
  EXPECT_EQ(cube.wall.under, 0u) << cube.summary();
}

TEST(PrintMeasure, PointsSpreadWiderWithinTheBudget) {
  // A 30 mm cube at points a nozzle's width apart takes over 100,000 points; a budget leaving room for the
  // grid and 10,000 points (five budget points each) spreads them wider, and the summary says so.
  const Mesh cube = box_mesh({0, 0, 0}, {30, 30, 30});
  Volume v;
  v.kind = Volume::Kind::mesh;
  v.mesh = std::make_shared<const Mesh>(cube);
  v.bounds = cube.bbox();
  PointBudget budget;
  budget.limit = WallGrid::size(v, 0.4 / 3, 0, 0) + 5 * 10000;
  const PrintReport r = check_print(cube, PrintRules{}, budget, no_progress());
  EXPECT_TRUE(r.wall.measured);
  EXPECT_GT(r.spacing, 1.0) << r.summary();
  EXPECT_NE(r.summary().find("mm (the point budget)"), std::string::npos) << r.summary();
  EXPECT_TRUE(r.passes()) << r.summary();
  // With room, a nozzle's width apart, and nothing said.
  const PrintReport roomy = check_print(cube, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_DOUBLE_EQ(roomy.spacing, 0.4);
  EXPECT_EQ(roomy.summary().find("point budget"), std::string::npos) << roomy.summary();
}
