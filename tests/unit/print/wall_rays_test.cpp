// The rays of the print check on exact signed distances: a slab's walls read as its thickness, the gap
// between two slabs as its width, thick bodies read as the caps, and the convex edge of a thick box is not
// a thin wall.
#include "kernels/print/wall_rays.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "kernels/region/box_mesh.h"

using namespace selfsim;
using namespace selfsim::print;

namespace {

// Signed distance, positive inside, of the slab lo <= z <= hi.
double slab(Vec3 p, double lo, double hi) { return std::min(p.z - lo, hi - p.z); }

Clearance of(double (*f)(Vec3)) {
  return [f](std::span<const Vec3> p, std::span<double> out) {
    for (std::size_t i = 0; i < p.size(); ++i) out[i] = f(p[i]);
  };
}

struct Measured {
  std::vector<double> wall, gap;
};

Measured rays(const std::vector<Vec3>& points, const std::vector<Vec3>& normals, const Clearance& c, RayLimits limits) {
  Measured m{std::vector<double>(points.size()), std::vector<double>(points.size())};
  measure_rays(points, normals, c, limits, m.wall, m.gap, no_progress());
  return m;
}

}  // namespace

TEST(WallRays, ASlabsWallIsItsThickness) {
  // A slab 0.3 thick: from its top face inwards the far side is 0.3 away, whatever the step.
  const auto thin = [](Vec3 p) { return slab(p, 0, 0.3); };
  for (double step : {0.01, 0.07, 0.2}) {
    const Measured m = rays({{0, 0, 0.3}}, {{0, 0, 1}}, of(+thin), {.step = step, .wall_cap = 2, .gap_cap = 1});
    EXPECT_NEAR(m.wall[0], 0.3, 1e-12) << step;  // the distance is linear: interpolation is exact
    EXPECT_EQ(m.gap[0], 1) << step;              // nothing above it: the cap
  }
}

TEST(WallRays, TheGapBetweenTwoSlabsIsItsWidth) {
  // Slabs 0 <= z <= 1 and 1.25 <= z <= 2: from the lower one's top face, a gap of 0.25.
  const auto two = [](Vec3 p) { return std::max(slab(p, 0, 1), slab(p, 1.25, 2)); };
  const Measured m = rays({{0, 0, 1}}, {{0, 0, 1}}, of(+two), {.step = 0.05, .wall_cap = 0.5, .gap_cap = 1});
  EXPECT_NEAR(m.gap[0], 0.25, 1e-12);
  EXPECT_EQ(m.wall[0], 0.5);  // a wall 1 thick reads as the cap
}

TEST(WallRays, ABoxsConvexEdgeIsNotAThinWall) {
  // The unit cube; a point on its top face 0.05 from an edge: the ray inwards runs beside the side face.
  const auto cube = [](Vec3 p) { return std::min({p.x, 1 - p.x, p.y, 1 - p.y, p.z, 1 - p.z}); };
  const Measured m = rays({{0.05, 0.5, 1}}, {{0, 0, 1}}, of(+cube), {.step = 0.02, .wall_cap = 0.8, .gap_cap = 0.4});
  EXPECT_EQ(m.wall[0], 0.8);
  EXPECT_EQ(m.gap[0], 0.4);
}

TEST(WallRays, AWallThinnerThanAStepReadsAsHalfAStep) {
  const auto sheet = [](Vec3 p) { return slab(p, 0, 0.01); };
  const Measured m = rays({{0, 0, 0.01}}, {{0, 0, 1}}, of(+sheet), {.step = 0.1, .wall_cap = 1, .gap_cap = 1});
  EXPECT_DOUBLE_EQ(m.wall[0], 0.05);
}

TEST(WallRays, AZeroNormalReadsAsTheCapsAndManyPointsAgreeWithOne) {
  const auto thin = [](Vec3 p) { return slab(p, 0, 0.3); };
  std::vector<Vec3> points, normals;
  for (int i = 0; i < 5000; ++i) {  // several chunks, in parallel
    points.push_back({i * 0.001, 0, i % 2 == 0 ? 0.3 : 0.0});
    normals.push_back(i % 7 == 0 ? Vec3{} : Vec3{0, 0, i % 2 == 0 ? 1.0 : -1.0});
  }
  const Measured m = rays(points, normals, of(+thin), {.step = 0.05, .wall_cap = 1, .gap_cap = 0.7});
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_NEAR(m.wall[i], i % 7 == 0 ? 1 : 0.3, 1e-12) << i;
    EXPECT_EQ(m.gap[i], 0.7) << i;
  }
}

TEST(WallRays, RefusesANonPositiveStep) {
  std::vector<double> w(1), g(1);
  EXPECT_THROW(measure_rays(std::vector<Vec3>{{0, 0, 0}}, std::vector<Vec3>{{0, 0, 1}}, of(+[](Vec3) { return 1.0; }),
                            {.step = 0, .wall_cap = 1, .gap_cap = 1}, w, g, no_progress()),
               Error);
}

TEST(WallRays, TheFarFlankOfAGrooveIsNotAGapButFacingWallsAre) {
  // A V-shaped groove opening upwards, 60 degrees wide, the solid below its flanks: the ray from a point on
  // one flank along its normal meets the other flank at 120 degrees to its normal (it does not face back).
  const auto groove = [](Vec3 p) {
    return std::max(0.866025403784 * p.x - 0.5 * p.z, -0.866025403784 * p.x - 0.5 * p.z);
  };
  const Vec3 on{0.05, 0, 0.0866025403784}, n{-0.866025403784, 0, 0.5};
  EXPECT_EQ(rays({on}, {n}, of(+groove), {.step = 0.005, .wall_cap = 1, .gap_cap = 1}).gap[0], 1);
  // Without the facing rule the ray reads the groove's width there.
  EXPECT_NEAR(rays({on}, {n}, of(+groove), {.step = 0.005, .wall_cap = 1, .gap_cap = 1, .gap_facing = -2}).gap[0],
              0.173205080757, 1e-6);
  // A slot 0.3 wide between two blocks: its walls face each other, a gap.
  const auto slot = [](Vec3 p) { return std::max(-p.x, p.x - 0.3); };
  EXPECT_NEAR(rays({{0, 0, 0}}, {{1, 0, 0}}, of(+slot), {.step = 0.01, .wall_cap = 1, .gap_cap = 1}).gap[0], 0.3, 1e-9);
}

TEST(WallRays, AWedgesOtherFaceIsNotAWallUnlessItFaces) {
  // A wedge pointing up with a 60-degree edge (its faces' normals 120 degrees apart), solid below: the ray
  // inwards from one face leaves through the other at 60 degrees to facing along it: not a thin wall.
  const auto wedge = [](Vec3 p) {
    return std::min(-(0.866025403784 * p.x + 0.5 * p.z), -(-0.866025403784 * p.x + 0.5 * p.z));
  };
  const Vec3 n{0.866025403784, 0, 0.5}, on{0.1, 0, -0.173205080757};
  EXPECT_EQ(rays({on}, {n}, of(+wedge), {.step = 0.005, .wall_cap = 1, .gap_cap = 1}).wall[0], 1);
  EXPECT_NEAR(rays({on}, {n}, of(+wedge), {.step = 0.005, .wall_cap = 1, .gap_cap = 1, .wall_facing = -2}).wall[0],
              0.346410161514, 1e-6);
}

TEST(WallRays, ANarrowCreasesBottomIsNotAGapButANarrowWedgeIsAThinWall) {
  // A folded sheet's inner side: a V-groove 30 degrees wide (its flanks' normals 150 degrees apart). Its
  // bottom fills without joining anything: not a gap (gaps count within 20 degrees of facing).
  static const double c = std::cos(0.2617993877991), s = std::sin(0.2617993877991);  // 15 degrees
  const auto groove = [](Vec3 p) { return std::max(c * p.x - s * p.z, -c * p.x - s * p.z); };
  const Vec3 on{0.05 * s, 0, 0.05 * c}, n{-c, 0, s};
  EXPECT_EQ(rays({on}, {n}, of(+groove), {.step = 0.001, .wall_cap = 1, .gap_cap = 1}).gap[0], 1);
  // The same angle as a solid wedge (its edge 30 degrees) is thin near the edge: walls count within 45.
  const auto wedge = [](Vec3 p) { return -std::max(c * p.x - s * p.z, -c * p.x - s * p.z); };
  EXPECT_NEAR(rays({on}, {-1.0 * n}, of(+wedge), {.step = 0.001, .wall_cap = 1, .gap_cap = 1}).wall[0],
              0.05 * std::tan(0.5235987755983), 1e-6);
}

// Exact rays against the triangles (measure_rays_exact): the same readings, to rounding, without a step.
namespace {

Mesh joined_boxes(std::initializer_list<std::pair<Vec3, Vec3>> boxes) {
  Mesh m;
  for (const auto& [lo, hi] : boxes) {
    const Mesh b = box_mesh(lo, hi);
    const auto base = static_cast<std::uint32_t>(m.points.size());
    m.points.insert(m.points.end(), b.points.begin(), b.points.end());
    for (const Triangle& t : b.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  return m;
}

// The face of m whose plane holds p and whose triangle holds it (the point's own, not counted).
std::uint32_t face_at(const Mesh& m, Vec3 p) {
  for (std::uint32_t f = 0; f < m.faces(); ++f) {
    const Vec3 a = m.points[m.triangles[f][0]], b = m.points[m.triangles[f][1]], c = m.points[m.triangles[f][2]];
    const Vec3 n = cross(b - a, c - a);
    if (std::abs(dot(n, p - a)) > 1e-12 * norm(n)) continue;
    if (dot(cross(b - a, p - a), n) >= 0 && dot(cross(c - b, p - b), n) >= 0 && dot(cross(a - c, p - c), n) >= 0)
      return f;
  }
  return UINT32_MAX;
}

Measured exact(const Mesh& m, const std::vector<Vec3>& points, const std::vector<Vec3>& normals, RayLimits limits,
               bool test_burial = false) {
  const TriangleBvh bvh(m, no_progress());
  std::vector<std::uint32_t> faces;
  for (const Vec3& p : points) faces.push_back(face_at(m, p));
  std::vector<char> maybe(points.size(), test_burial ? 1 : 0);
  Measured out{std::vector<double>(points.size()), std::vector<double>(points.size())};
  measure_rays_exact(points, normals, {.bvh = &bvh, .faces = faces, .tmin = 1e-9, .may_be_buried = maybe, .far = 100},
                     limits, out.wall, out.gap, no_progress());
  return out;
}

}  // namespace

TEST(WallRays, ExactRaysReadSlabsAndGapsToRounding) {
  // Slabs 0.3 and 0.03 thick (a grid's step would read the second as half a step), and a gap of 0.25
  // between two boxes, each read from points whose rays cross the far side where its two triangles meet
  // (x = y on box_mesh's diagonals): counted once.
  for (double h : {0.3, 0.03}) {
    const Mesh slab = box_mesh({0, 0, 0}, {1, 1, h});
    const Measured m =
        exact(slab, {{0.5, 0.5, h}, {0.3, 0.6, h}}, {{0, 0, 1}, {0, 0, 1}}, {.wall_cap = 2, .gap_cap = 1});
    EXPECT_NEAR(m.wall[0], h, 1e-12);
    EXPECT_NEAR(m.wall[1], h, 1e-12);
    EXPECT_EQ(m.gap[0], 1);
  }
  const Mesh two = joined_boxes({{{0, 0, 0}, {1, 1, 1}}, {{0, 0, 1.25}, {1, 1, 2}}});
  const Measured g = exact(two, {{0.5, 0.5, 1}}, {{0, 0, 1}}, {.wall_cap = 0.5, .gap_cap = 1});
  EXPECT_NEAR(g.gap[0], 0.25, 1e-12);
  EXPECT_EQ(g.wall[0], 0.5);  // a wall 1 thick reads as the cap
}

TEST(WallRays, ExactRaysBesideAnEdgeAndThroughOverlaps) {
  // The unit cube; a point on its top face 1e-6 from an edge: the ray inwards runs beside the side face,
  // exactly, and reads the cap (no point need be left out beside an edge).
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const Measured m = exact(cube, {{1e-6, 0.5, 1}}, {{0, 0, 1}}, {.wall_cap = 0.8, .gap_cap = 0.4});
  EXPECT_EQ(m.wall[0], 0.8);
  EXPECT_EQ(m.gap[0], 0.4);
  // Two boxes overlapping by half: one solid 1.5 long. From the first box's end (x = 0) inwards the ray
  // enters the second box at 0.5 and leaves the first at 1: still inside, the wall goes on to 1.5.
  const Mesh overlap = joined_boxes({{{0, 0, 0}, {1, 1, 1}}, {{0.5, 0, 0}, {1.5, 1, 1}}});
  const Measured o = exact(overlap, {{0, 0.3, 0.6}}, {{-1, 0, 0}}, {.wall_cap = 2, .gap_cap = 1});
  EXPECT_NEAR(o.wall[0], 1.5, 1e-12);
  // The second box's end at x = 0.5 lies inside the first: no surface of the solid. Unless tested, its ray
  // inwards (+x) leaves the first box at x = 1 and reads a wall of 0.5; tested, it reads both caps.
  const Measured buried = exact(overlap, {{0.5, 0.3, 0.6}}, {{-1, 0, 0}}, {.wall_cap = 2, .gap_cap = 1});
  EXPECT_NEAR(buried.wall[0], 0.5, 1e-12);
  const Measured tested = exact(overlap, {{0.5, 0.3, 0.6}}, {{-1, 0, 0}}, {.wall_cap = 2, .gap_cap = 1}, true);
  EXPECT_EQ(tested.wall[0], 2);
  EXPECT_EQ(tested.gap[0], 1);
  // A point on the surface, tested, is measured as untested.
  const Measured outer = exact(overlap, {{0, 0.3, 0.6}}, {{-1, 0, 0}}, {.wall_cap = 2, .gap_cap = 1}, true);
  EXPECT_NEAR(outer.wall[0], 1.5, 1e-12);
}

TEST(WallRays, ExactRaysKeepTheFacingRules) {
  // A wedge of 20 degrees (two flanks meeting at an edge along y, the solid between): from a point on a
  // flank s from the edge the ray inwards leaves through the other flank s tan 20° away, facing it within
  // 20 degrees: a thin wall. With a facing rule stricter than that (0.99: 8 degrees), the cap.
  const double half = std::tan(10 * 3.14159265358979 / 180);
  Mesh w;
  for (double y : {0.0, 1.0}) {
    w.points.push_back({0, y, 0});
    w.points.push_back({3, y, 3 * half});
    w.points.push_back({3, y, -3 * half});
  }
  w.triangles = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {0, 3, 5}, {0, 5, 2}, {1, 2, 5}, {1, 5, 4}};
  const Vec3 n = normalized({-half, 0, 1});  // the upper flank's outward normal
  const Vec3 on{1, 0.5, half};
  const Measured m = exact(w, {on}, {n}, {.wall_cap = 2, .gap_cap = 1});
  EXPECT_NEAR(m.wall[0], norm(on - Vec3{0, 0.5, 0}) * std::tan(20 * 3.14159265358979 / 180), 1e-9);
  EXPECT_EQ(exact(w, {on}, {n}, {.wall_cap = 2, .gap_cap = 1, .wall_facing = 0.99}).wall[0], 2);
}

TEST(WallRays, ExactRaysStopWhenCancelled) {
  struct Stopped : Progress {
    bool cancelled() override { return true; }
  };
  const Mesh slab = box_mesh({0, 0, 0}, {1, 1, 0.3});
  const TriangleBvh bvh(slab, no_progress());
  const std::vector<Vec3> points(5000, Vec3{0.5, 0.5, 0.3}), normals(5000, Vec3{0, 0, 1});
  const std::vector<std::uint32_t> faces(5000, face_at(slab, {0.3, 0.6, 0.3}));
  std::vector<double> wall(5000, -1), gap(5000, -1);
  Stopped stop;
  EXPECT_THROW(measure_rays_exact(points, normals, {.bvh = &bvh, .faces = faces, .tmin = 1e-9},
                                  {.wall_cap = 1, .gap_cap = 1}, wall, gap, stop),
               Cancelled);
  // Refused: a face for each point is needed.
  EXPECT_THROW(measure_rays_exact(points, normals, {.bvh = &bvh, .faces = {}, .tmin = 1e-9},
                                  {.wall_cap = 1, .gap_cap = 1}, wall, gap, no_progress()),
               Error);
}
