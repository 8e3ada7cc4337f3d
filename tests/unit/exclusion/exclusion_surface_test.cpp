// The exclusion surface (seed 004 in 3D): the invariants the issue names, on small runs in a cube.
#include "kernels/exclusion/exclusion_surface.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernels/geom/distance3.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/geom/winding_number.h"
#include "kernels/region/box_mesh.h"
#include "kernels/region/volume.h"
#include "kernels/region/wall_grid.h"

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

// The distance between two triangles: the least of their corners' distances to the other and their edges'.
double triangle_distance(const Mesh& m, const Triangle& a, const Triangle& b) {
  double d = INFINITY;
  for (int pass = 0; pass < 2; ++pass) {
    const Triangle& s = pass == 0 ? a : b;
    const Triangle& t = pass == 0 ? b : a;
    for (std::uint32_t v : s)
      d = std::min(d, point_triangle_distance(m.points[v], m.points[t[0]], m.points[t[1]], m.points[t[2]]));
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      d = std::min(d, segment_segment_distance(m.points[a[i]], m.points[a[(i + 1) % 3]], m.points[b[j]],
                                               m.points[b[(j + 1) % 3]]));
  return d;
}

// A closed surface or a fold grown in the cube: a manifold of the start's topology without crossings, every
// point inside and the last radius from the walls.
void expect_grown_like_its_start(const Mesh& cube, const Mesh& start, const SurfaceOptions& o) {
  const SurfaceResult r = exclusion_surface(cube, start, o, no_progress());
  EXPECT_EQ(r.surface.faces(), start.faces() << (2 * o.levels));
  const MeshTopology before = mesh_topology(start), after = mesh_topology(r.surface);
  EXPECT_TRUE(after.manifold()) << after.first_problem;
  EXPECT_EQ(after.boundary_loops, before.boundary_loops);
  EXPECT_EQ(after.euler(), before.euler());
  EXPECT_FALSE(first_intersection(r.surface, no_progress()).has_value());
  const double last = o.radius * std::pow(o.factor, o.levels - 1);
  for (Vec3 p : r.surface.points) {
    EXPECT_GT(winding_number(cube, p), 0.5);
    EXPECT_GE(boundary_distance(cube, p), last * (1 - 1e-6));
  }
  std::size_t moved = 0;
  for (const LevelReport& l : r.levels) moved += l.splits - l.stuck;
  EXPECT_GT(moved, r.levels.back().splits / 10);  // it grew, not only split
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
  // The two share no point, so every triangle of one keeps the last radius from every triangle of the other
  // (their starts are 0.4 apart, more than the first radius, so no term starts within it).
  const double last = 0.1 * std::pow(0.8, 3);
  double closest = INFINITY;
  for (std::size_t a = 0; a < r.surface.faces(); ++a)
    for (std::size_t b = 0; b < r.surface.faces(); ++b)
      if (surface->at(a) == 1 && surface->at(b) == 2)
        closest = std::min(closest, triangle_distance(r.surface, r.surface.triangles[a], r.surface.triangles[b]));
  EXPECT_GE(closest, last * (1 - 1e-6));
  EXPECT_LT(closest, 0.2);  // and they grew towards each other
}

// A closed start, a tetrahedron, stays a closed surface of genus 0 (Euler characteristic 2).
TEST(ExclusionSurface, AClosedStartStaysClosed) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  Mesh tetrahedron;
  tetrahedron.points = {{0.4, 0.4, 0.4}, {0.6, 0.4, 0.4}, {0.5, 0.6, 0.4}, {0.5, 0.5, 0.6}};
  tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  SurfaceOptions o = options(3);
  o.radius = 0.05;
  expect_grown_like_its_start(cube, tetrahedron, o);
}

// Two triangles folded 30 degrees apart about their shared edge: the sharp dihedral angle's bisector moves
// the fold's midpoints out of the narrow wedge, and the wedge's sides never meet.
TEST(ExclusionSurface, ASharpFoldDoesNotCloseOnItself) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const double angle = 30 * 3.141592653589793 / 180;
  Mesh fold;
  fold.points = {{0.5, 0.3, 0.5},
                 {0.5, 0.7, 0.5},
                 {0.8, 0.5, 0.5},
                 {0.5 + 0.3 * std::cos(angle), 0.5, 0.5 + 0.3 * std::sin(angle)}};
  fold.triangles = {{0, 1, 2}, {1, 0, 3}};
  SurfaceOptions o = options(4);
  o.radius = 0.02;
  expect_grown_like_its_start(cube, fold, o);
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
  o = options(1);
  o.neighbourhood = 0;
  EXPECT_NE(message(inside, o).find("option 'neighbourhood'"), std::string::npos);
  o = options(1);
  o.near = 1;
  EXPECT_NE(message(inside, o).find("option 'near'"), std::string::npos);
  o = options(12);
  o.budget.limit = 1e6;  // 4^12 = 16.8 million triangles
  EXPECT_NE(message(inside, o).find("levels = 12 (16777216 triangles"), std::string::npos) << message(inside, o);
}

// Issue 23: under the neighbourhood rule a sheet keeps growing, where the strict rule (the rule before it)
// leaves most points of a deep level stuck; both keep every invariant.
TEST(ExclusionSurface, TheNeighbourhoodRuleKeepsGrowingWhereTheStrictRuleStops) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh start = triangles({{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.5, 0.8, 0.5}});
  const int levels = 6;
  auto stuck_share = [](const LevelReport& l) { return static_cast<double>(l.stuck) / static_cast<double>(l.splits); };
  SurfaceOptions o = options(levels);
  const SurfaceResult grown = exclusion_surface(cube, start, o, no_progress());
  for (int level = 3; level <= levels; ++level) EXPECT_LE(stuck_share(grown.levels[level - 1]), 0.25) << level;
  expect_grown_like_its_start(cube, start, o);
  o.rule = SurfaceRule::strict;
  const SurfaceResult strict = exclusion_surface(cube, start, o, no_progress());
  EXPECT_GE(stuck_share(strict.levels.back()), 0.5);
  EXPECT_GT(grown.levels.back().area, 1.2 * strict.levels.back().area);  // the area each report gives
  expect_grown_like_its_start(cube, start, o);
}

// Two sheets of one surface pressed together: a strip folded into a U whose sides start 0.12 apart, more than
// the first radius. Along the surface their pieces are far apart (around the bend), and they were never
// nearer than the radius, so no neighbourhood lets them come nearer than the last radius: a rule whose
// exemption reached across the gap would let them. The bend's own pieces are each side's neighbours.
TEST(ExclusionSurface, TwoSheetsPressedTogetherKeepTheRadius) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  Mesh u;
  u.points = {{0.2, 0.3, 0.44}, {0.8, 0.3, 0.44}, {0.8, 0.7, 0.44}, {0.2, 0.7, 0.44},   // the lower sheet
              {0.2, 0.3, 0.56}, {0.8, 0.3, 0.56}, {0.8, 0.7, 0.56}, {0.2, 0.7, 0.56}};  // the upper one
  u.triangles = {{0, 1, 2}, {0, 2, 3},   // lower: start triangles 0 and 1
                 {1, 5, 6}, {1, 6, 2},   // the bend at x = 0.8
                 {5, 4, 7}, {5, 7, 6}};  // upper: 4 and 5
  for (const double neighbourhood : {6.0, HUGE_VAL}) {
    SurfaceOptions o = options(4);
    o.neighbourhood = neighbourhood;
    const SurfaceResult r = exclusion_surface(cube, u, o, no_progress());
    EXPECT_FALSE(first_intersection(r.surface, no_progress()).has_value());
    // Each face descends from start triangle face >> 2·levels (a triangle's children are 4t ... 4t + 3).
    const double last = 0.1 * std::pow(0.8, 3);
    double closest = INFINITY;
    for (std::size_t a = 0; a < r.surface.faces(); ++a)
      for (std::size_t b = 0; b < r.surface.faces(); ++b)
        if ((a >> 8) <= 1 && (b >> 8) >= 4)
          closest = std::min(closest, triangle_distance(r.surface, r.surface.triangles[a], r.surface.triangles[b]));
    EXPECT_GE(closest, last * (1 - 1e-6)) << neighbourhood;
    EXPECT_LT(closest, 0.12) << neighbourhood;  // they did grow towards each other
  }
}

// A start nearer than the radius to the walls, or one of its surfaces to another, keeps only that gap there:
// the result says where, so that the binding can warn; a start clear of both says nothing.
TEST(ExclusionSurface, AStartNearerThanTheRadiusIsReported) {
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh start = triangles({{0.2, 0.2, 0.5},
                                {0.8, 0.2, 0.5},
                                {0.5, 0.8, 0.5},
                                {0.2, 0.2, 0.52},
                                {0.8, 0.2, 0.52},
                                {0.5, 0.8, 0.52},
                                {0.005, 0.2, 0.2},
                                {0.005, 0.8, 0.2},
                                {0.005, 0.5, 0.8}});
  const SurfaceResult r = exclusion_surface(cube, start, options(1), no_progress());
  EXPECT_NEAR(r.start_gaps.wall, 0.005, 1e-12);
  EXPECT_EQ(r.start_gaps.wall_triangle, 2u);
  EXPECT_NEAR(r.start_gaps.between, 0.02, 1e-12);
  EXPECT_EQ(r.start_gaps.first, 0u);
  EXPECT_EQ(r.start_gaps.second, 1u);
  const SurfaceResult clear = exclusion_surface(cube, triangles({{0.2, 0.2, 0.5}, {0.8, 0.2, 0.5}, {0.5, 0.8, 0.5}}),
                                                options(1), no_progress());
  EXPECT_TRUE(std::isinf(clear.start_gaps.wall));
  EXPECT_TRUE(std::isinf(clear.start_gaps.between));
}

namespace {

// walls = "grid": in a sphere, every corner (a triangle's farthest point from the centre is a corner) keeps
// the last radius less the grid's error bound and the quarter voxel the sphere is meshed within (a voxel of
// a sixth of the last radius: 0.19 of it in all), and the radius itself as the grid reads it; the rest of the
// invariants hold as with the boundary's triangles.
TEST(ExclusionSurface, GridWallsKeepTheRadiusLessTheGridsError) {
  const Volume ball = Volume::sphere({0, 0, 0}, 1);
  SurfaceOptions o = options(5);
  o.radius = 0.2;
  const double last = o.radius * std::pow(o.factor, o.levels - 1), voxel = last / 6;
  const Mesh boundary = sphere_mesh({0, 0, 0}, 1, voxel / 4);
  const WallGrid walls(ball, voxel, 2 * o.radius, {}, no_progress());
  const Mesh start = triangles({{-.6, -.4, 0}, {.6, -.4, 0}, {0, .6, 0}});
  const SurfaceResult r = exclusion_surface(boundary, start, o, no_progress(), &walls);
  EXPECT_FALSE(first_intersection(r.surface, no_progress()).has_value());
  EXPECT_TRUE(mesh_topology(r.surface).manifold());
  double least = INFINITY;
  for (Vec3 p : r.surface.points) least = std::min(least, 1 - norm(p));
  EXPECT_GE(least, last - walls.error() - voxel / 4);
  EXPECT_LT(least, 1.5 * last);  // it grew out to the walls
  // As the grid reads it, every point keeps the radius itself.
  for (Vec3 p : r.surface.points) EXPECT_GE(walls.clearance(p), last * (1 - 1e-9));
  std::size_t moved = 0;
  for (const LevelReport& l : r.levels) moved += l.splits - l.stuck;
  EXPECT_GT(moved, r.levels.back().splits / 2);
}

// A point whose neighbour has gone out to the walls still moves: a move the walls stop keeps a margin
// beyond the radius, so the fans that share its point can prove they keep the radius (stopped exactly at
// the radius, it left both other midpoints of the first level stuck, 0.85 from any wall).
TEST(ExclusionSurface, GridWallsLeaveTheNeighboursOfAStoppedPointFree) {
  const Volume box = Volume::box({-1, -1, -1}, {1, 1, 1});
  const WallGrid walls(box, 0.04, 0.2, {}, no_progress());
  const Mesh start = triangles({{-.3, -.2, 0}, {.3, -.2, 0}, {0, .2, 0}});
  const SurfaceResult r =
      exclusion_surface(box_mesh({-1, -1, -1}, {1, 1, 1}), start, options(2), no_progress(), &walls);
  ASSERT_EQ(r.levels.size(), 2u);
  EXPECT_EQ(r.levels[0].stuck, 0u);
  EXPECT_LE(r.levels[1].stuck, 1u);
  double nearest = INFINITY;  // one point went out to the walls
  for (Vec3 p : r.surface.points) nearest = std::min(nearest, walls.clearance(p));
  EXPECT_LT(nearest, 0.2);
  EXPECT_GE(nearest, 0.08 * (1 - 1e-9));
}

// Nor do static corners near the walls hold a move back: only the moving point must keep the margin, and the
// parts of the fan near a static corner, which move slowly, keep the radius. Held to the margin as a whole,
// with the margin then dropped, this start (corners 0.28 from a sphere's wall, within radius and margin) left
// 2 of the first level's 3 points stuck.
TEST(ExclusionSurface, GridWallsLetAFanMoveBesideCornersNearTheWalls) {
  const Volume ball = Volume::sphere({0, 0, 0}, 1);
  const WallGrid walls(ball, 0.05, 0.4, {}, no_progress());
  const Mesh start = triangles({{-.6, -.4, 0}, {.6, -.4, 0}, {0, .6, 0}});
  SurfaceOptions o = options(2);
  o.radius = 0.2;
  const SurfaceResult r = exclusion_surface(sphere_mesh({0, 0, 0}, 1, 0.05 / 4), start, o, no_progress(), &walls);
  EXPECT_EQ(r.levels[0].stuck, 0u);
  EXPECT_EQ(r.levels[1].stuck, 0u);
}

}  // namespace
