// What the print check measures is what is there: gaps narrower than a few voxels read their width
// (OpenVDB's own sign fill closed them: two slabs 0.2 mm apart read "under 0.07 mm"), and a coarse CAD
// file's faces are measured all over, not at one point each (a 20 degree wedge of 8 triangles passed
// although a strip of it 2.3 mm wide is thinner than 0.8 mm). Without a voxel the rays are exact (a
// TriangleBvh): readings are the widths to rounding; with one, the grid's tolerances hold.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <numbers>
#include <utility>

#include "kernels/geom/triangle_bvh.h"
#include "kernels/print/print_check.h"
#include "kernels/region/box_mesh.h"
#include "kernels/region/volume.h"
#include "kernels/region/wall_grid.h"
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

// The box from lo to hi with each face cut into n x n quads of two triangles each (n = 100 on a 20 x 20 x 3
// mm box: sides of 0.2 x 0.03 mm slivers).
Mesh split_box(Vec3 lo, Vec3 hi, int n) {
  Mesh m;
  // Points by their place on the n x n x n lattice, shared between faces (closed stays closed).
  std::map<std::array<int, 3>, std::uint32_t> index;
  const auto at = [&](std::array<int, 3> k) {
    const auto [it, fresh] = index.emplace(k, static_cast<std::uint32_t>(m.points.size()));
    if (fresh)
      m.points.push_back(
          {lo.x + (hi.x - lo.x) * k[0] / n, lo.y + (hi.y - lo.y) * k[1] / n, lo.z + (hi.z - lo.z) * k[2] / n});
    return it->second;
  };
  // Each face: the axis it is across and its side (0 or n); its quads counterclockwise seen from outside.
  for (int f = 0; f < 6; ++f) {
    const int across = f / 2, side = f % 2;
    int u = (across + 1) % 3, v = (across + 2) % 3;  // u x v is along the axis
    if (side == 0) std::swap(u, v);
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const auto corner = [&](int di, int dj) {
          std::array<int, 3> k{};
          k[across] = side * n;
          k[u] = i + di;
          k[v] = j + dj;
          return at(k);
        };
        const std::uint32_t a = corner(0, 0), b = corner(1, 0), c = corner(1, 1), e = corner(0, 1);
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, e});
      }
  }
  if (enclosed_volume(m) < 0)
    for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

}  // namespace

TEST(PrintMeasure, TheVerdictDoesNotDependOnTessellation) {
  // Slivers along a box's edges put points a hundredth of a millimetre from them, whose rays ran beside the
  // next face: the box of 120,000 triangles had "walls thinner than 0.8 mm at 808 places" where the same box
  // of 12 passed. Points are kept a voxel from the solid's sharp edges, however its faces are cut.
  for (const double height : {3.0, 1.0})
    for (const int n : {1, 100}) {
      const Mesh box = split_box({0, 0, 0}, {20, 20, height}, n);
      ASSERT_EQ(box.faces(), 12u * n * n);
      const PrintReport r = check_print(box, PrintRules{}, PointBudget{}, no_progress());
      EXPECT_TRUE(r.passes()) << n << " x " << n << ": " << r.summary();
      EXPECT_EQ(r.wall.under, 0u) << n << " x " << n << ": " << r.summary();
      // 3 mm: over the cap (1.2 mm); 1 mm: its height, within the grid's fifth of a voxel.
      EXPECT_NEAR(std::min(r.wall.value, r.wall_cap), std::min(height, r.wall_cap), r.voxel / 5)
          << n << " x " << n << ": " << r.summary();
    }
}

TEST(PrintMeasure, AWallOrGapTooThinToResolveSaysATrueBound) {
  // On a grid (a voxel asked for), slabs and gaps of 0.08 to 0.12 mm read "under 0.07 mm": a bound they are
  // not under. Whatever is said holds: the width measured (within a fifth of a voxel), or a bound at least
  // the width. By exact rays (no voxel) every width reads itself, to rounding.
  PrintRules on_grid;
  on_grid.voxel = 0.4 / 3;
  for (const double width : {0.03, 0.08, 0.10, 0.12, 0.15, 0.2})
    for (const PrintRules& rules : {on_grid, PrintRules{}}) {
      const PrintReport slab = check_print(box_mesh({0, 0, 0}, {10, 10, width}), rules, PointBudget{}, no_progress());
      const PrintReport gap =
          check_print(joined(box_mesh({0, 0, 0}, {10, 10, 2}), box_mesh({0, 0, 2 + width}, {10, 10, 4})), rules,
                      PointBudget{}, no_progress());
      for (const auto& [r, spot] : {std::pair{&slab, &slab.wall}, std::pair{&gap, &gap.gap}}) {
        if (rules.voxel == 0) {
          EXPECT_NEAR(spot->value, width, 1e-9) << width << ": " << r->summary();
          EXPECT_EQ(r->summary().find("finer than it resolves"), std::string::npos) << r->summary();
        } else if (r->summary().find("under") != std::string::npos) {
          EXPECT_TRUE(r->summary().find(r->unresolved()) != std::string::npos) << width << ": " << r->summary();
          EXPECT_GE(2 * r->voxel, width) << r->summary();
        } else {
          EXPECT_NEAR(spot->value, width, r->voxel / 5) << width << ": " << r->summary();
        }
      }
      if (width <= 0.12 && rules.voxel > 0) EXPECT_TRUE(mentions(slab, "the thinnest under 0.27 mm")) << slab.summary();
      if (width <= 0.12 && rules.voxel > 0) EXPECT_TRUE(mentions(gap, "the narrowest under 0.27 mm")) << gap.summary();
    }
}

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
  // 0.03 mm apart: no voxel centre (0.133 mm apart) need fall in the gap, whose reading on a grid then says
  // why. Exact rays read it.
  const Mesh slabs = joined(box_mesh({0, 0, 0}, {10, 10, 2}), box_mesh({0, 0, 2.03}, {10, 10, 4.03}));
  PrintRules on_grid;
  on_grid.voxel = 0.4 / 3;
  const PrintReport r = check_print(slabs, on_grid, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(r,
                       "the narrowest under 0.27 mm (two of the distance grid's 0.13 mm voxels: finer than it "
                       "resolves)"))
      << r.summary();
  const PrintReport exact = check_print(slabs, PrintRules{}, PointBudget{}, no_progress());
  EXPECT_TRUE(mentions(exact, "the narrowest 0.03 mm")) << exact.summary();
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
  // A 30 mm cube at points a nozzle's width apart takes over 100,000 points; a budget leaving room for what
  // measures them (the grid, or the triangles' tree) and 10,000 points (five budget points each) spreads
  // them wider, and the summary says so.
  const Mesh cube = box_mesh({0, 0, 0}, {30, 30, 30});
  Volume v;
  v.kind = Volume::Kind::mesh;
  v.mesh = std::make_shared<const Mesh>(cube);
  v.bounds = cube.bbox();
  PointBudget on_grid_budget;
  on_grid_budget.limit = WallGrid::size(v, 0.4 / 3, 0, 0) + 5 * 10000;
  PrintRules on_grid;
  on_grid.voxel = 0.4 / 3;
  const PrintReport g = check_print(cube, on_grid, on_grid_budget, no_progress());
  EXPECT_GT(g.spacing, 1.0) << g.summary();
  EXPECT_NE(g.summary().find("mm (the point budget)"), std::string::npos) << g.summary();
  PointBudget budget;
  budget.limit = TriangleBvh::size(cube.faces()) + 5 * 10000;
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
