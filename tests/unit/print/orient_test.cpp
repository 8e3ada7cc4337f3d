// Poses on the bed: a tilted box back on its largest face (no overhang), a mushroom on its cap's top (by
// either goal, from upright or tilted), a sphere left as it is (no flat face), and the turn and the shift
// that put them there.
#include "kernels/print/orient.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernels/geom/mesh_transform.h"
#include "kernels/print/footing.h"
#include "kernels/print/overhang.h"
#include "tests/unit/print/lathe_fixture.h"

using namespace selfsim;
using namespace selfsim::print;
using namespace lathe_fixture;

namespace {

// A 40 x 20 x 10 mm box tilted 30 degrees about x and 10 about z.
Mesh tilted_box() {
  Mesh b = lathe({{1, 0}, {1, 1}}, 0, 1, 4, 45);  // a cube of side sqrt(2)
  b = transformed(b, MeshTransform{.scale = {40 / std::sqrt(2.0), 20 / std::sqrt(2.0), 10}}.map());
  b = transformed(b, MeshTransform{.degrees = 30, .axis = {1, 0, 0}}.map());
  return transformed(b, MeshTransform{.degrees = 10, .axis = {0, 0, 1}}.map());
}

// m as best_orientation turns it.
Mesh turned(const Mesh& m, const Orientation& o) { return transformed(m, o.turn); }

double overhang(const Mesh& m) { return overhang_of(m, {}).area; }

}  // namespace

TEST(Orient, ATiltedBoxLiesBackOnItsLargestFace) {
  const Mesh b = tilted_box();
  ASSERT_NEAR(overhang(b), 800, 1e-6);  // its bottom, 60 degrees below horizontal
  for (bool least : {false, true}) {
    const Orientation o = best_orientation(b, {.least_overhang = least});
    EXPECT_NEAR(o.face, 800, 1e-6) << least;
    EXPECT_NEAR(o.overhang_before, 800, 1e-6);
    EXPECT_NEAR(o.overhang, 0, 1e-9);
    const Mesh t = turned(b, o);
    EXPECT_NEAR(t.bbox().size().z, 10, 1e-9) << least;  // on a 40 x 20 face, not on its ends or sides
    EXPECT_EQ(overhang(t), 0);
  }
}

TEST(Orient, AMushroomStandsOnItsCap) {
  const Mesh upright = mushroom(3, 10);
  const Mesh leaning = transformed(upright, MeshTransform{.degrees = 30, .axis = {1, 1, 0}}.map());
  const double cap = polygon_area(32, 10), ring = cap - polygon_area(32, 3);
  for (const Mesh* m : {&upright, &leaning})
    for (bool least : {false, true}) {
      const Orientation o = best_orientation(*m, {.least_overhang = least});
      EXPECT_NEAR(o.face, cap, 1e-6 * cap) << least;
      EXPECT_EQ(o.overhang, 0);
      const Mesh t = turned(*m, o);
      EXPECT_EQ(overhang(t), 0);
      // Upside down: the cap's points (radius 10 about the axis, now vertical) are in the lowest 4 mm.
      const double low = t.bbox().min.z;
      const Vec3 axis_point = t.points.back();  // the top fan's centre, now at the bottom
      EXPECT_NEAR(axis_point.z, low, 1e-9);
      for (const Vec3& p : t.points)
        if (std::hypot(p.x - axis_point.x, p.y - axis_point.y) > 9) EXPECT_LE(p.z - low, 4 + 1e-9);
    }
  EXPECT_NEAR(best_orientation(upright, {}).overhang_before, ring, 1e-9);
}

TEST(Orient, AFacetedBallStaysAsItCame) {
  // Every facet of a convex polyhedron bounds it, but the largest (a quad at the equator, 0.6 mm²) adds
  // little to the cap a ball of radius 10 stands on anyway (2 pi R h, 6.3 mm² a tenth of a millimetre up):
  // it is not turned for a faceting's difference.
  const Mesh s = sphere(10);
  const Orientation o = best_orientation(s, {});
  EXPECT_TRUE(o.kept);
  EXPECT_NEAR(o.first_layer, 2 * std::numbers::pi * 10 * 0.1, 0.15 * 2 * std::numbers::pi);
}

// A disc of radius r, h thick, its rim rounded: no flat face of its own (the fans at its centres are
// cones, a hair off flat).
Mesh lens(double r, double h) {
  std::vector<Ring> rings;
  for (int i = 1; i < 24; ++i) {
    const double a = -std::numbers::pi / 2 + std::numbers::pi * i / 24;
    rings.push_back({r + 0.5 * h * std::cos(a), 0.5 * h * std::sin(a)});
  }
  return lathe(rings, -0.5 * h * 0.999, 0.5 * h * 0.999, 64);
}

// A flat piece with no flat face of its own (tubes laid in a plane; here a disc stood on edge) lies down
// across its thinnest side, its principal axis: it stands on far more so. Least overhang too, when on edge
// it stands on less than a first layer needs.
TEST(Orient, AFlatPieceWithNoFlatFaceLiesDown) {
  const Mesh on_edge = transformed(lens(20, 3), MeshTransform{.degrees = 90, .axis = {1, 0, 0}}.map());
  const Orientation o = best_orientation(on_edge, {});
  EXPECT_FALSE(o.kept);
  EXPECT_NEAR(std::abs(o.up.y), 1, 1e-6);  // the disc's axis, turned along y, points up again
  EXPECT_GT(o.first_layer, 100);
  const Mesh coin = transformed(lens(3, 0.3), MeshTransform{.degrees = 90, .axis = {1, 0, 0}}.map());
  ASSERT_LT(orientation_by(coin, Affine3{}, {}).first_layer, OrientOptions{}.least_first_layer());
  const Orientation fewest = best_orientation(coin, {.least_overhang = true});
  EXPECT_GT(fewest.first_layer, 10);
}

TEST(Orient, ASpikyBallHasNoFlatFaceAndStays) {
  // A cube of side 2 with a pyramid 3 high on each face: the spikes' tips span every plane that bounds it,
  // so no face lies on one and the pose is kept.
  Mesh m;
  for (int i = 0; i < 8; ++i) m.points.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  const std::uint32_t sides[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                                     {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : sides) {
    Vec3 centre{};
    for (std::uint32_t v : q) centre += 0.25 * m.points[v];
    const auto tip = static_cast<std::uint32_t>(m.points.size());
    m.points.push_back(4 * centre);
    for (int k = 0; k < 4; ++k) m.triangles.push_back({q[k], q[(k + 1) % 4], tip});
  }
  ASSERT_GT(enclosed_volume(m), 0);
  const Orientation o = best_orientation(m, {});
  EXPECT_EQ(o.face, 0);
  EXPECT_EQ(o.up.z, 1);
  EXPECT_NEAR(o.overhang, o.overhang_before, 1e-12);
}

TEST(Orient, TheTurnTakesUpToZ) {
  for (Vec3 up :
       {Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{1, 0, 0}, normalized(Vec3{1, -2, 3}), normalized(Vec3{1e-9, 0, -1})}) {
    const Affine3 t = turn_up(up);
    const Vec3 z = t.linear(up);
    EXPECT_NEAR(z.x, 0, 1e-12);
    EXPECT_NEAR(z.y, 0, 1e-12);
    EXPECT_NEAR(z.z, 1, 1e-12);
    EXPECT_NEAR(t.determinant(), 1, 1e-12);  // a rotation, never a mirror
  }
}

TEST(Orient, RestingAreaCountsEveryFootOnThePlane) {
  // Two boxes side by side, one taller: standing, both feet rest; upside down only the taller's top.
  Mesh two = box(10, 10);
  Mesh tall = transformed(box(10, 20), MeshTransform{.translate = {30, 0, 0}}.map());
  const auto n = static_cast<std::uint32_t>(two.points.size());
  two.points.insert(two.points.end(), tall.points.begin(), tall.points.end());
  for (Triangle t : tall.triangles) two.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  EXPECT_NEAR(resting_area(two, {0, 0, 1}), 200, 1e-9);
  EXPECT_NEAR(resting_area(two, {0, 0, -1}), 100, 1e-9);
}

TEST(Orient, BedShiftPutsTheLowestPointOnZeroCentred) {
  const Vec3 s = bed_shift({{2, -4, 3}, {6, 10, 8}});
  EXPECT_EQ(s.x, -4);
  EXPECT_EQ(s.y, -3);
  EXPECT_EQ(s.z, -3);
}

namespace {

// A coaster: a disc of radius 20, 3 mm thick, with a lip of radius 25, 0.1 mm thick, round its middle. Flat,
// the lip's underside overhangs (about 7 cm²); stood on the lip's rim, far less overhangs, but it would
// stand on a sliver of 0.1 mm² with its centre high above it.
Mesh coaster() { return lathe({{20, 0}, {20, 1.5}, {25, 1.5}, {25, 1.6}, {20, 1.6}, {20, 3}}, 0, 3, 128); }

// A faceted sphere of radius 5: its largest facets are 0.16 mm², under a 0.4 mm nozzle's first layer.
Mesh small_sphere() { return sphere(5); }

Mesh with_stray_point(Mesh m, Vec3 p) {
  m.points.push_back(p);
  return m;
}

}  // namespace

TEST(Orient, ACoasterStaysFlatForTheLeastOverhang) {
  // By overhang alone, standing on the lip's rim wins (what solid.orient did before it measured first layers).
  ASSERT_LT(overhang_of(coaster(), {.up = {1, 0, 0}}).area, 0.5 * overhang(coaster()));
  const Mesh c = transformed(coaster(), MeshTransform{.degrees = 20, .axis = {1, 0, 0}}.map());
  for (bool least : {false, true}) {
    const Orientation o = best_orientation(c, {.least_overhang = least});
    const Mesh t = turned(c, o);
    EXPECT_NEAR(t.bbox().size().z, 3, 1e-6) << least;  // flat, not on the lip's rim
    EXPECT_NEAR(o.first_layer, polygon_area(128, 20), 1e-3) << least;
    EXPECT_GE(o.first_layer, OrientOptions{}.least_first_layer());
  }
}

TEST(Orient, TheLeastOverhangIsNeverWorseThanThePoseAsItCame) {
  const Mesh c = coaster();
  const Orientation o = best_orientation(c, {.least_overhang = true});
  EXPECT_LE(o.overhang, o.overhang_before + 1e-3 * surface_area(c));
  EXPECT_GE(o.first_layer, OrientOptions{}.least_first_layer());
}

TEST(Orient, NoFlatFaceAsLargeAsAFirstLayerKeepsThePose) {
  const Mesh s = transformed(small_sphere(), MeshTransform{.degrees = 30, .axis = {1, 2, 0}}.map());
  const Orientation o = best_orientation(s, {});
  EXPECT_TRUE(o.kept);
  EXPECT_EQ(o.up.z, 1);
  EXPECT_LT(o.face, OrientOptions{}.least_first_layer());
  // A finer nozzle starts on a facet.
  const Orientation fine = best_orientation(s, {.nozzle = 0.1});
  EXPECT_FALSE(fine.kept);
  EXPECT_GT(fine.face, 0.1);
}

TEST(Orient, PointsNoTriangleUsesDoNotDecideTheLowest) {
  // A 20 mm cube on its bottom face, and a point 3 mm below it that no triangle uses.
  const Mesh cube = with_stray_point(box(20, 10), {5, 5, -3});
  const Orientation o = best_orientation(cube, {});
  EXPECT_TRUE(o.kept);
  EXPECT_NEAR(o.face, 400, 1e-9);
  EXPECT_EQ(o.overhang_before, 0);
  EXPECT_NEAR(resting_area(cube, {0, 0, 1}), 400, 1e-9);
  EXPECT_NEAR(o.first_layer, 400, 1e-9);  // measured half a layer above the cube's bottom, not the point
  EXPECT_NEAR(best_orientation(cube, {.least_overhang = true}).first_layer, 400, 1e-9);
}

TEST(Orient, AGivenTurnIsMeasuredLikeAPose) {
  const Mesh m = mushroom(3, 10);
  const Affine3 flip = MeshTransform{.degrees = 180, .axis = {1, 0, 0}}.map();
  const Orientation o = orientation_by(m, flip, {});
  EXPECT_NEAR(o.up.z, -1, 1e-12);
  EXPECT_EQ(o.overhang, 0);
  EXPECT_NEAR(o.overhang_before, polygon_area(32, 10) - polygon_area(32, 3), 1e-9);
  EXPECT_NEAR(o.face, polygon_area(32, 10), 1e-9);
  EXPECT_NEAR(o.first_layer, polygon_area(32, 10), 1e-6);
  EXPECT_FALSE(o.kept);
  EXPECT_NEAR(orientation_by(m, Affine3{}, {}).first_layer, polygon_area(32, 3), 1e-6);
}

TEST(Orient, ASolidStandsWhenItsCentreIsOverItsFootprint) {
  const Mesh b = box(20, 10);
  const Vec3 c = mass_centre(b);
  EXPECT_NEAR(c.x, 0, 1e-9);
  EXPECT_NEAR(c.y, 0, 1e-9);
  EXPECT_NEAR(c.z, 5, 1e-9);
  EXPECT_TRUE(centre_over_footprint(b, c, 0.2, 0.2));
  // Tilted 30 degrees it rests on one bottom edge, its centre 5 mm beside it: it would fall back.
  const Affine3 tilt = MeshTransform{.degrees = 30, .axis = {1, 0, 0}}.map();
  const Mesh t = transformed(b, tilt);
  EXPECT_FALSE(centre_over_footprint(t, tilt(c), 0.2, 0.2));
  // A mushroom upright stands on its stem: its centre is on the axis.
  const Mesh m = mushroom(3, 10);
  EXPECT_TRUE(centre_over_footprint(m, mass_centre(m), 0.2, 0.2));
  EXPECT_GT(mass_centre(m).z, 10);  // most of its volume is the cap
}
