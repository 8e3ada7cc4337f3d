// Thickening: a closed, consistently oriented manifold (a disk gives a sphere, an annulus a torus), the two
// sheets half the thickness away along the normal, fields on both.
#include "kernels/print/thicken.h"

#include <gtest/gtest.h>

#include <vector>

#include "../lsystem/table1.h"
#include "kernels/base/error.h"
#include "kernels/develop/develop.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/lsystem/turtle/turtle2d.h"

using namespace selfsim;
using namespace selfsim::print;
using selfsim::develop::develop_surface;
using selfsim::develop::DevelopOptions;

namespace {

// The unit square in the plane z = 0 as two triangles, normal +z, thickness 0.2.
Mesh square() {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.point_fields.set(real_field("thickness", {0.2, 0.2, 0.2, 0.2}));
  m.face_fields.set(int_field("tile", {7, 8}));
  return m;
}

Mesh developed(const lsystem::Grammar& g, int top, DevelopOptions opt) {
  std::vector<Polyline> levels;
  for (int l = 0; l <= top; ++l) levels.push_back(lsystem::turtle2d(g, {.level = l}, no_progress()));
  std::vector<const Polyline*> p;
  for (const Polyline& c : levels) p.push_back(&c);
  return develop_surface(p, opt, no_progress());
}

}  // namespace

TEST(Thicken, ASquareBecomesASlab) {
  const Mesh s = thicken(square(), no_progress());
  ASSERT_EQ(s.points.size(), 8u);
  EXPECT_EQ(s.faces(), 2u * 2 + 2 * 4);  // two sheets, and two rim triangles per boundary edge
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(s.points[i].z, 0.1);
    EXPECT_EQ(s.points[4 + i].z, -0.1);
  }
  const MeshTopology t = mesh_topology(s);
  EXPECT_TRUE(t.closed()) << t.first_problem;
  EXPECT_EQ(t.euler(), 2);
  // The top sheet keeps the surface's orientation (normal +z), so the solid's normals point outwards.
  EXPECT_GT(area_normal(s, s.triangles[0]).z, 0);
  EXPECT_LT(area_normal(s, s.triangles[2]).z, 0);
  EXPECT_EQ(s.face_fields.find("tile")->at(3), 8);
  EXPECT_EQ(s.point_fields.find("thickness")->at(7), 0.2);
}

TEST(Thicken, DevelopedSurfacesBecomeClosedSolids) {
  const Mesh dragon = developed(table1::dragon(), 6, {.smooth = 2, .thickness = 0.05});
  const MeshTopology d = mesh_topology(dragon);
  EXPECT_TRUE(d.closed()) << d.first_problem;
  EXPECT_EQ(d.euler(), 2);  // a disk thickened: a sphere
  const Mesh snowflake = developed(table1::koch_snowflake(), 3, {.smooth = 1, .thickness = 0.05});
  const MeshTopology k = mesh_topology(snowflake);
  EXPECT_TRUE(k.closed()) << k.first_problem;
  EXPECT_EQ(k.euler(), 0);  // an annulus thickened: a torus
}

TEST(Thicken, ThicknessShrinksWithTheSegmentsOrByTheRate) {
  // Without smoothing the control points keep their level's thickness exactly (the level-4 dragon stack touches
  // itself: kept).
  const Mesh self_similar = developed(table1::dragon(), 4, {.thickness = 0.1, .check = false});
  const Mesh slower = developed(table1::dragon(), 4, {.thickness = 0.1, .thickness_rate = 0.9, .check = false});
  const Field* t = self_similar.point_fields.find("thickness");
  const Field* level = self_similar.point_fields.find("level");
  const Field* r = slower.point_fields.find("thickness");
  for (std::size_t i = 0; i < self_similar.points.size(); ++i) {
    const double l = level->at(i);
    EXPECT_NEAR(t->at(i), 0.1 * std::pow(std::sqrt(0.5), l), 1e-12) << i;
    EXPECT_NEAR(r->at(i), 0.1 * std::pow(0.9, l), 1e-12) << i;
  }
}

TEST(Thicken, Errors) {
  Mesh m = square();
  m.point_fields.set(real_field("thickness", {0.2, 0, 0.2, 0.2}));
  EXPECT_THROW(thicken(m, no_progress()), Error);
  Mesh none = square();
  none.point_fields = {};
  EXPECT_THROW(thicken(none, no_progress()), Error);
  EXPECT_THROW(developed(table1::dragon(), 3, {.thickness = -1}), Error);
  EXPECT_THROW(developed(table1::dragon(), 3, {.thickness = 0.1, .thickness_rate = 2}), Error);
}

TEST(Develop, SizeIsPredictedExactlyBeforeAnyWork) {
  for (auto [g, closed] : {std::pair{table1::dragon(), false}, std::pair{table1::koch_snowflake(), true}})
    for (DevelopOptions opt :
         {DevelopOptions{}, DevelopOptions{.smooth = 2}, DevelopOptions{.smooth = 1, .thickness = 0.05}}) {
      std::vector<Polyline> levels;
      for (int l = 0; l <= 3; ++l) levels.push_back(lsystem::turtle2d(g, {.level = l}, no_progress()));
      std::vector<const Polyline*> p;
      std::vector<double> segments;
      for (const Polyline& c : levels) {
        p.push_back(&c);
        segments.push_back(static_cast<double>(c.segments()));
      }
      const Mesh m = develop_surface(p, opt, no_progress());
      EXPECT_EQ(developed_size(segments, closed, opt), static_cast<double>(m.points.size() + m.faces()))
          << closed << " " << opt.smooth << " " << opt.thickness;
    }
}

// Thickness is in the curve's units: a stack 1e150 across is thickened as one of size 1 is (issue 21: an
// absolute cap of 1e6 refused it, while a stack 1e-150 across could be thickened).
TEST(Thicken, ThicknessIsRelativeToTheSurfacesSize) {
  for (const double scale : {1e-150, 1.0, 1e150}) {
    std::vector<Polyline> levels;
    for (int l = 0; l <= 3; ++l) {
      Polyline c = lsystem::turtle2d(table1::dragon(), {.level = l}, no_progress());
      for (Vec2& p : c.points) p = scale * p;
      levels.push_back(std::move(c));
    }
    std::vector<const Polyline*> p;
    for (const Polyline& c : levels) p.push_back(&c);
    DevelopOptions opt;
    opt.thickness = 0.02 * scale;
    const Mesh m = develop_surface(p, opt, no_progress());
    EXPECT_TRUE(mesh_topology(m).closed()) << scale;
    opt.thickness = 1e7 * scale;
    EXPECT_THROW(develop_surface(p, opt, no_progress()), Error) << scale;
  }
}

// The progress bar names develop's stages, not the L-system drawn before them (issue 21: "L-system"
// stayed up through the whole of develop).
TEST(Develop, ProgressNamesItsStages) {
  struct Names : Progress {
    std::vector<std::string> seen;
    void start(const char* what) override { seen.emplace_back(what); }
    void rename(const char* what) override { seen.emplace_back(what); }
  } names;
  names.start("L-system");
  std::vector<Polyline> levels;
  for (int l = 0; l <= 4; ++l) levels.push_back(lsystem::turtle2d(table1::dragon(), {.level = l}, no_progress()));
  std::vector<const Polyline*> p;
  for (const Polyline& c : levels) p.push_back(&c);
  develop_surface(p, {.smooth = 1, .thickness = 0.05}, names);
  const auto at = [&](const char* name) { return std::find(names.seen.begin(), names.seen.end(), name); };
  ASSERT_NE(at("developing surface"), names.seen.end());
  ASSERT_NE(at("thickening"), names.seen.end());
  EXPECT_LT(at("developing surface"), at("thickening"));
  EXPECT_NE(names.seen.back(), "L-system");
}
