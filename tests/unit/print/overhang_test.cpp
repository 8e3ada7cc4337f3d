// Overhang against areas known in closed form: none on a cube standing on the bed, a mushroom's cap's
// underside (the ring between stem and rim), a sphere's cap below the overhang angle, a tilted box's bottom;
// faces on the bed overhang nothing; per-face angles.
#include "kernels/print/overhang.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernels/geom/mesh_transform.h"
#include "tests/unit/print/lathe_fixture.h"

using namespace selfsim;
using namespace selfsim::print;
using namespace lathe_fixture;

namespace {

constexpr double pi = std::numbers::pi;

double overhang(const Mesh& m, double angle = 45, Vec3 up = {0, 0, 1}) {
  return overhang_of(m, {.angle = angle, .up = up}).area;
}

}  // namespace

TEST(Overhang, ACubeOnTheBedHasNone) {
  const Mesh cube = box(20, 20);
  EXPECT_EQ(overhang(cube), 0);
  EXPECT_EQ(overhang(cube, 45, {0, 0, -1}), 0);  // upside down it rests on its top
  EXPECT_EQ(overhang(cube, 45, {1, 0, 0}), 0);   // or on a side
}

TEST(Overhang, ACubeInTheAirHasItsBottom) {
  // Lifted above a 1 mm peg under its centre, the cube's bottom is a ceiling (the peg's foot rests).
  const Mesh m = lathe({{0.5, 0}, {0.5, 5}, {10 * std::sqrt(2.0), 5}, {10 * std::sqrt(2.0), 25}}, 0, 25, 4, 45);
  EXPECT_NEAR(overhang(m), 400 - polygon_area(4, 0.5), 1e-9);
}

TEST(Overhang, AMushroomHasItsCapsUnderside) {
  const Mesh m = mushroom(3, 10);
  const Overhang o = overhang_of(m, {}, true);
  const double ring = polygon_area(32, 10) - polygon_area(32, 3);
  EXPECT_NEAR(o.area, ring, 1e-9);
  EXPECT_NEAR(o.where.z, 10, 1e-12);  // the largest such face is in the underside
  // Steeper thresholds keep the flat underside (a ceiling, 90 degrees past horizontal).
  EXPECT_NEAR(overhang(m, 80), ring, 1e-9);
  // Upside down, on its cap's top, nothing overhangs.
  EXPECT_EQ(overhang(m, 45, {0, 0, -1}), 0);
  // Per face: the underside at 90 degrees, the stem's sides at 0, the foot on the bed at 0.
  ASSERT_EQ(o.angle.size(), m.faces());
  for (std::size_t f = 0; f < m.faces(); ++f) {
    const Vec3 n = area_normal(m, m.triangles[f]);
    const double expected = n.z < -0.99 * norm(n) && m.points[m.triangles[f][1]].z > 1 ? 90 : 0;
    EXPECT_NEAR(o.angle[f], expected, 1e-9) << "face " << f;
  }
}

TEST(Overhang, ASphereHasItsLowerCap) {
  // Faces whose normal is more than `angle` below horizontal: the cap within 90 - angle of the south pole,
  // 2 pi r^2 (1 - cos(90 - angle)); a faceted sphere is close.
  const double r = 10;
  const Mesh s = sphere(r);
  for (double angle : {30.0, 45.0, 60.0}) {
    const double cap = 2 * pi * r * r * (1 - std::cos((90 - angle) * pi / 180));
    EXPECT_NEAR(overhang(s, angle), cap, 0.03 * cap) << angle << " degrees";
  }
}

TEST(Overhang, ATiltedBoxHasItsBottomFace) {
  // Tilted 30 degrees, the bottom's normal is 60 below horizontal (past 45); the sides' at most 30.
  const Mesh b = transformed(box(20, 10), MeshTransform{.degrees = 30, .axis = {1, 0, 0}}.map());
  EXPECT_NEAR(overhang(b), 400, 1e-9);
  EXPECT_EQ(overhang(b, 70), 0);  // a 60 degree face is within 70
}

TEST(Overhang, AFaceOnTheBedIsLeftOut) {
  // A single downward triangle is on the bed when it is the lowest thing; with another part's triangle below
  // it overhangs.
  Mesh m;
  m.points = {{0, 0, 0}, {0, 10, 0}, {10, 0, 0}};
  m.triangles = {{0, 1, 2}};
  EXPECT_EQ(overhang(m), 0);
  m.points.insert(m.points.end(), {{20, 0, -1}, {20, 1, -1}, {21, 0, -1}});  // another part's triangle, below
  m.triangles.push_back({3, 4, 5});
  EXPECT_NEAR(overhang(m), 50, 1e-12);
}

TEST(Overhang, APointNoTriangleUsesDoesNotLiftTheBed) {
  // A cube on the bed and a stray point 3 mm below it: the cube's bottom still rests.
  Mesh cube = box(20, 10);
  cube.points.push_back({5, 5, -3});
  EXPECT_EQ(overhang(cube), 0);
}
