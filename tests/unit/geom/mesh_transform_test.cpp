// Mesh:transform's map: scale, then rotate, then translate; a mirror keeps the solid facing outwards;
// normal fields follow the faces (inverse transpose, length kept), length fields scale or go; bad options.
#include "kernels/geom/mesh_transform.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"
#include "tests/unit/print/lathe_fixture.h"

using namespace selfsim;

namespace {

void expect_near(Vec3 a, Vec3 b, double tolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

// The mushroom with its faces' unit normals as a face field `normal` and its points' (area-weighted, not
// unit) as a point field `Normals`, as VTK names them.
Mesh with_normals() {
  Mesh m = lathe_fixture::mushroom();
  std::vector<double> faces, points(3 * m.points.size(), 0.0);
  for (const Triangle& t : m.triangles) {
    const Vec3 n = area_normal(m, t), u = normalized(n);
    faces.insert(faces.end(), {u.x, u.y, u.z});
    for (std::uint32_t v : t) points[3 * v] += n.x, points[3 * v + 1] += n.y, points[3 * v + 2] += n.z;
  }
  m.face_fields.set(real_field("normal", faces, 3));
  m.point_fields.set(real_field("Normals", points, 3));
  return m;
}

Vec3 tuple(const Field& f, std::size_t i) { return {f.at(i, 0), f.at(i, 1), f.at(i, 2)}; }

}  // namespace

TEST(MeshTransform, ScaleThenRotateThenTranslate) {
  const Affine3 a = MeshTransform{.scale = {2, 2, 2}, .degrees = 90, .axis = {0, 0, 5}, .translate = {0, 0, 5}}.map();
  expect_near(a({1, 0, 0}), {0, 2, 5}, 1e-12);  // (2, 0, 0), turned to (0, 2, 0), moved up
  const Affine3 b = MeshTransform{.scale = {1, 3, 1}, .degrees = 90, .axis = {1, 0, 0}}.map();
  expect_near(b({0, 1, 0}), {0, 0, 3}, 1e-12);  // stretched along y before the turn takes y to z
}

TEST(MeshTransform, AMirrorStillFacesOutwards) {
  const Mesh m = lathe_fixture::mushroom();
  const double volume = enclosed_volume(m);
  ASSERT_GT(volume, 0);
  for (Vec3 scale : {Vec3{-1, 1, 1}, Vec3{1, -2, 1}, Vec3{-1, -1, -1}, Vec3{-1, -1, 1}}) {
    const Mesh t = transformed(m, MeshTransform{.scale = scale, .degrees = 37, .axis = {1, 2, 3}}.map());
    const double factor = std::abs(scale.x * scale.y * scale.z);
    EXPECT_NEAR(enclosed_volume(t), factor * volume, 1e-9 * volume) << scale.x << " " << scale.y << " " << scale.z;
    EXPECT_TRUE(mesh_topology(t).closed());
  }
}

TEST(MeshTransform, NormalFieldsFollowTheFaces) {
  const Mesh m = with_normals();
  for (Vec3 scale : {Vec3{1, 1, 1}, Vec3{2, 0.5, 3}, Vec3{-1, 2, 1}}) {
    const Mesh t = transformed(m, MeshTransform{.scale = scale, .degrees = 30, .axis = {1, 2, 3}}.map());
    const Field& faces = *t.face_fields.find("normal");
    for (std::size_t f = 0; f < t.faces(); ++f)
      expect_near(tuple(faces, f), normalized(area_normal(t, t.triangles[f])), 1e-9);
    // The point field kept its length; turned without a scale, it is the same field recomputed.
    const Field& before = *m.point_fields.find("Normals");
    const Field& after = *t.point_fields.find("Normals");
    for (std::size_t p = 0; p < t.points.size(); ++p)
      EXPECT_NEAR(norm(tuple(after, p)), norm(tuple(before, p)), 1e-9 * norm(tuple(before, p)));
  }
  // A quarter turn about x takes a face looking up to one looking towards -y.
  const Mesh turned = transformed(m, MeshTransform{.degrees = 90, .axis = {1, 0, 0}}.map());
  const Field& faces = *turned.face_fields.find("normal");
  expect_near(tuple(faces, turned.faces() - 1), {0, -1, 0}, 1e-12);  // the cap's top fan
}

TEST(MeshTransform, LengthFieldsScaleWithAUniformFactorOnly) {
  Mesh m = lathe_fixture::box(10, 10);
  m.point_fields.set(real_field("thickness", std::vector<double>(m.points.size(), 1.5)));
  m.face_fields.set(int_field("level", std::vector<std::int32_t>(m.faces(), 3)));
  const Mesh doubled = transformed(m, MeshTransform{.scale = {-2, -2, -2}, .degrees = 10}.map());
  EXPECT_NEAR(doubled.point_fields.find("thickness")->at(0), 3, 1e-12);
  EXPECT_EQ(doubled.face_fields.find("level")->at(0), 3);
  const Mesh stretched = transformed(m, MeshTransform{.scale = {1, 2, 1}}.map());
  EXPECT_EQ(stretched.point_fields.find("thickness"), nullptr);  // no one factor describes it
  EXPECT_NE(stretched.face_fields.find("level"), nullptr);
}

TEST(MeshTransform, RefusesZeroAndNonFinite) {
  EXPECT_THROW((MeshTransform{.scale = {1, 0, 1}}.validate()), Error);
  EXPECT_THROW((MeshTransform{.scale = Vec3::all(NAN)}.validate()), Error);
  EXPECT_THROW((MeshTransform{.scale = Vec3::all(INFINITY)}.validate()), Error);
  EXPECT_THROW((MeshTransform{.axis = {0, 0, 0}}.validate()), Error);
  EXPECT_THROW((MeshTransform{.degrees = NAN}.validate()), Error);
  EXPECT_THROW((MeshTransform{.translate = {0, INFINITY, 0}}.validate()), Error);
  // A finite scale that overflows the coordinates.
  EXPECT_THROW(transformed(lathe_fixture::box(10, 10), MeshTransform{.scale = Vec3::all(1e308)}.map()), Error);
}

TEST(MeshTransform, OverhangFieldsGoWhenTheSolidTilts) {
  // The print check's `overhang` (degrees below horizontal) holds while +z stays up and faces keep their tilt.
  Mesh m = lathe_fixture::box(10, 10);
  m.face_fields.set(real_field("overhang", std::vector<double>(m.faces(), 0)));
  m.point_fields.set(real_field("Overhang", std::vector<double>(m.points.size(), 0)));
  m.face_fields.set(int_field("level", std::vector<std::int32_t>(m.faces(), 3)));
  const auto keeps = [&](const MeshTransform& t) {
    const Mesh out = transformed(m, t.map());
    EXPECT_NE(out.face_fields.find("level"), nullptr);  // other fields stay
    const bool face = out.face_fields.find("overhang") != nullptr, point = out.point_fields.find("Overhang") != nullptr;
    EXPECT_EQ(face, point);
    return face;
  };
  EXPECT_FALSE(keeps({.degrees = 30, .axis = {1, 0, 0}}));  // the bug: a tilted solid kept the old angles
  EXPECT_FALSE(keeps({.scale = {1, 1, -1}}));               // upside down
  EXPECT_FALSE(keeps({.scale = {1, 1, 2}}));                // steeper walls
  EXPECT_TRUE(keeps({.degrees = 75, .axis = {0, 0, 1}, .translate = {3, 4, 5}}));
  EXPECT_TRUE(keeps({.scale = {2.5, 2.5, 2.5}}));
  EXPECT_TRUE(keeps({.scale = {-1, 1, 1}}));  // a mirror across a vertical plane
}

TEST(MeshTransform, CornerBoxLeavesOutPointsNoTriangleUses) {
  Mesh m = lathe_fixture::box(20, 10);
  m.points.push_back({5, 5, -3});
  EXPECT_EQ(m.bbox().min.z, -3);
  const BBox3 b = corner_bbox(m);
  EXPECT_NEAR(b.min.z, 0, 1e-12);
  EXPECT_NEAR(b.max.z, 10, 1e-12);
  EXPECT_NEAR(b.size().x, 20, 1e-9);
  EXPECT_TRUE(corner_bbox(Mesh{}).empty());
}
