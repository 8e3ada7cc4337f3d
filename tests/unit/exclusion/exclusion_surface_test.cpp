// The exclusion surface (seed 004 in 3D): the invariants the issue names, on small runs in a cube.
#include "kernels/exclusion/exclusion_surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernels/geom/box_mesh.h"
#include "kernels/geom/distance3.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/geom/winding_number.h"

using namespace selfsim;
using namespace selfsim::exclusion;

namespace {

Mesh triangles(std::vector<Vec3> points) {
  Mesh m;
  m.points = std::move(points);
  for (std::uint32_t i = 0; i + 2 < m.points.size(); i += 3) m.triangles.push_back({i, i + 1, i + 2});
  return m;
}

double boundary_distance(const Mesh& boundary, Vec3 p) {
  double d = INFINITY;
  for (const Triangle& t : boundary.triangles)
    d = std::min(d, point_triangle_distance(p, boundary.points[t[0]], boundary.points[t[1]], boundary.points[t[2]]));
  return d;
}

SurfaceOptions options(int levels) {
  SurfaceOptions o;
  o.radius = 0.1;
  o.factor = 0.8;
  o.levels = levels;
  return o;
}

}  // namespace

TEST(ExclusionSurface, OneTriangleInACubeKeepsEveryInvariant) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh start = triangles({{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.5, 0.8, 0.5}});
  const int levels = 5;
  const SurfaceResult r = exclusion_surface(cube, start, options(levels), no_progress());
  EXPECT_EQ(r.surface.faces(), std::size_t{1} << (2 * levels));  // 4^levels times the start's one
  const MeshTopology t = mesh_topology(r.surface);
  EXPECT_TRUE(t.manifold()) << t.first_problem;
  EXPECT_EQ(t.boundary_loops, 1u);  // a disc, as it started
  EXPECT_EQ(t.euler(), 1);
  EXPECT_FALSE(first_intersection(r.surface, no_progress()).has_value());
  // The midpoint of two points the radius from a convex region's boundary is too, so in a cube every point
  // keeps the last level's radius.
  const double last = 0.1 * std::pow(0.8, levels - 1);
  for (Vec3 p : r.surface.points) {
    EXPECT_GT(winding_number(cube, p), 0.5);
    EXPECT_GE(boundary_distance(cube, p), last * (1 - 1e-6));
  }
  // The surface grew out of its plane, and the report counts every midpoint of every level.
  double spread = 0;
  for (Vec3 p : r.surface.points) spread = std::max(spread, std::abs(p.z - 0.5));
  EXPECT_GT(spread, 0.05);
  ASSERT_EQ(r.levels.size(), static_cast<std::size_t>(levels));
  EXPECT_EQ(r.levels[0].splits, 3u);
  EXPECT_EQ(r.levels[1].splits, 9u);  // a level's midpoints are the edges before it: 3, 9, 30, ...
  EXPECT_EQ(r.surface.point_fields.find("level")->at(0), 0);
  EXPECT_EQ(r.surface.point_fields.find("level")->at(r.surface.points.size() - 1), levels);
}

TEST(ExclusionSurface, TwoSurfacesGrowWithoutMeetingAndKeepTheirNumbers) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh start =
      triangles({{0.2, 0.2, 0.3}, {0.8, 0.2, 0.3}, {0.5, 0.8, 0.3}, {0.2, 0.2, 0.7}, {0.5, 0.8, 0.7}, {0.8, 0.2, 0.7}});
  const SurfaceResult r = exclusion_surface(cube, start, options(4), no_progress());
  EXPECT_EQ(r.surface.faces(), 2u * 256u);
  EXPECT_FALSE(first_intersection(r.surface, no_progress()).has_value());
  const Field* surface = r.surface.face_fields.find("surface");
  ASSERT_NE(surface, nullptr);
  EXPECT_EQ(surface->at(0), 1);
  EXPECT_EQ(surface->at(r.surface.faces() - 1), 2);
  EXPECT_EQ(mesh_topology(r.surface).components, 2u);
}

TEST(ExclusionSurface, BadStartsAndOptionsAreRefusedByName) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  auto message = [&](const Mesh& start, SurfaceOptions o) {
    try {
      exclusion_surface(cube, start, o, no_progress());
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const Mesh inside = triangles({{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.5, 0.8, 0.5}});
  EXPECT_EQ(message(triangles({{0.2, 0.2, 0.5}, {1.8, 0.2, 0.5}, {0.5, 0.8, 0.5}}), options(1)),
            "start point 2 lies outside the region");
  EXPECT_EQ(message(triangles({{0.2, 0.2, 0.5}, {1.0, 0.2, 0.5}, {0.5, 0.8, 0.5}}), options(1)),
            "start triangle 1 crosses or touches the region's boundary");
  EXPECT_EQ(
      message(
          triangles(
              {{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.5, 0.8, 0.5}, {0.5, 0.5, 0.2}, {0.5, 0.5, 0.8}, {0.5, 0.9, 0.5}}),
          options(1)),
      "start triangles 1 and 2 cross or touch");
  EXPECT_EQ(message(triangles({{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.5, 0.2, 0.5}}), options(1)),
            "start triangle 1 has no area");
  Mesh crossed = cube;  // a corner pushed through the opposite face: still closed, but crossing itself
  crossed.points[0] = {0.5, 0.5, 1.5};
  try {
    exclusion_surface(crossed, inside, options(1), no_progress());
    ADD_FAILURE() << "a region crossing itself was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the region's boundary crosses itself"), std::string::npos) << e.what();
  }
  SurfaceOptions o = options(1);
  o.radius = 0;
  EXPECT_NE(message(inside, o).find("option 'radius'"), std::string::npos);
  o = options(1);
  o.factor = 1.5;
  EXPECT_NE(message(inside, o).find("option 'factor'"), std::string::npos);
  o = options(21);
  EXPECT_NE(message(inside, o).find("option 'levels'"), std::string::npos);
  o = options(12);
  o.budget.limit = 1e6;  // 4^12 = 16.8 million triangles
  EXPECT_NE(message(inside, o).find("levels = 12 (16777216 triangles"), std::string::npos) << message(inside, o);
}
