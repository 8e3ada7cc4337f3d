// Reliefs (issue 25): closed, outward-oriented solids whose topology and volume follow from the region —
// a square is a box (Euler 2, volume h), a square with a hole a torus (Euler 0), an island in the hole a
// second component, and a base plate joins everything into one solid of volume plate + relief — and every
// bad curve or option refused with its words.
#include "kernels/print/relief.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"

using namespace selfsim;
using namespace selfsim::print;

namespace {

using Ring = std::vector<Vec2>;

Polyline curve(const std::vector<Ring>& rings) {
  Polyline c;
  for (const Ring& r : rings) {
    for (Vec2 p : r) c.points.push_back(p);
    c.points.push_back(r.front());
    c.close_path();
  }
  return c;
}

Ring rectangle(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

ReliefOptions options(double height, double base = 0, double margin = 0) {
  ReliefOptions o;
  o.height = height;
  o.base = base;
  o.margin = margin;
  return o;
}

// A Koch snowflake of `levels` substitutions, 3·4^levels points.
Ring koch_snowflake(int levels) {
  Ring r{{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}};
  for (int l = 0; l < levels; ++l) {
    Ring s;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const Vec2 a = r[i], d = (r[(i + 1) % r.size()] - a) * (1.0 / 3);
      s.insert(s.end(), {a, a + d, a + d + d * polar(-std::numbers::pi / 3), a + 2 * d});
    }
    r = std::move(s);
  }
  return r;
}

std::string error_of(const Polyline& c, const ReliefOptions& o) {
  try {
    relief(c, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Checks the mesh is a closed manifold with sane fields, and returns its topology.
MeshTopology closed_topology(const Mesh& m) {
  m.validate();
  const MeshTopology t = mesh_topology(m);
  EXPECT_TRUE(t.closed()) << t.first_problem;
  const Field* height = m.point_fields.find("height");
  const Field* part = m.face_fields.find("part");
  EXPECT_TRUE(height && part);
  for (std::size_t i = 0; height && i < m.points.size(); ++i) EXPECT_EQ(height->at(i), m.points[i].z);
  return t;
}

}  // namespace

TEST(Relief, UnitSquareIsABox) {
  const double h = 0.3;
  const Mesh m = relief(curve({rectangle(0, 0, 1, 1)}), options(h));
  const MeshTopology t = closed_topology(m);
  EXPECT_EQ(t.euler(), 2);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(m.points.size(), 8u);
  EXPECT_EQ(m.faces(), 12u);
  EXPECT_NEAR(enclosed_volume(m), h, 1e-12);
  EXPECT_NEAR(surface_area(m), 2 + 4 * h, 1e-12);
  // Parts: two bottom, two top, eight walls.
  const Field* part = m.face_fields.find("part");
  int count[3] = {0, 0, 0};
  for (std::size_t f = 0; f < m.faces(); ++f) ++count[static_cast<int>(part->at(f))];
  EXPECT_EQ(count[0], 2);
  EXPECT_EQ(count[1], 2);
  EXPECT_EQ(count[2], 8);
}

TEST(Relief, ClockwiseSquareStillFacesOutwards) {
  const Mesh m = relief(curve({{{0, 0}, {0, 2}, {2, 2}, {2, 0}}}), options(1));
  closed_topology(m);
  EXPECT_NEAR(enclosed_volume(m), 4, 1e-12);
}

TEST(Relief, SquareWithAHoleIsATorus) {
  const double h = 2;
  const Mesh m = relief(curve({rectangle(0, 0, 10, 10), rectangle(3, 3, 7, 7)}), options(h));
  const MeshTopology t = closed_topology(m);
  EXPECT_EQ(t.euler(), 0);
  EXPECT_EQ(t.components, 1u);
  EXPECT_NEAR(enclosed_volume(m), (100 - 16) * h, 1e-9);
}

TEST(Relief, IslandInTheHoleIsASecondComponent) {
  const Mesh m = relief(curve({rectangle(0, 0, 10, 10), rectangle(2, 2, 8, 8), rectangle(4, 4, 6, 6)}), options(1));
  const MeshTopology t = closed_topology(m);
  EXPECT_EQ(t.components, 2u);
  EXPECT_EQ(t.euler(), 0 + 2);  // a torus and a box
  EXPECT_NEAR(enclosed_volume(m), 100 - 36 + 4, 1e-9);
}

TEST(Relief, BasePlateMakesOneSolid) {
  const double h = 0.5, base = 0.25, margin = 1;
  const Mesh m = relief(curve({rectangle(0, 0, 2, 1)}), options(h, base, margin));
  const MeshTopology t = closed_topology(m);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.euler(), 2);
  EXPECT_NEAR(enclosed_volume(m), 4 * 3 * base + 2 * h, 1e-12);
  const BBox3 box = m.bbox();
  EXPECT_DOUBLE_EQ(box.min.z, -base);
  EXPECT_DOUBLE_EQ(box.max.z, h);
  EXPECT_DOUBLE_EQ(box.min.x, -1);
  EXPECT_DOUBLE_EQ(box.max.y, 2);
}

TEST(Relief, BasePlateUnderHolesAndIslands) {
  // A ring with an island in its hole, on a plate: still one solid, a ball's topology (the hole is a pit
  // whose floor is the plate), and the island stands on the plate too.
  const double h = 1, base = 0.5, margin = 2;
  const Mesh m =
      relief(curve({rectangle(0, 0, 10, 10), rectangle(2, 2, 8, 8), rectangle(4, 4, 6, 6)}), options(h, base, margin));
  const MeshTopology t = closed_topology(m);
  EXPECT_EQ(t.components, 1u);
  EXPECT_EQ(t.euler(), 2);
  EXPECT_NEAR(enclosed_volume(m), 14 * 14 * base + (100 - 36 + 4) * h, 1e-9);
}

TEST(Relief, KochSnowflakeVolume) {
  const Ring r = koch_snowflake(5);  // 3,072 points
  double area = 0;
  for (std::size_t i = 0; i < r.size(); ++i) area += cross(r[i], r[(i + 1) % r.size()]) / 2;
  const Mesh m = relief(curve({r}), options(0.1, 0.05, 0.2));
  const MeshTopology t = closed_topology(m);
  EXPECT_EQ(t.euler(), 2);
  const BBox3 box = m.bbox();
  const double plate = (box.max.x - box.min.x) * (box.max.y - box.min.y) * 0.05;
  EXPECT_NEAR(enclosed_volume(m), plate + 0.1 * area, 1e-9 * (plate + area));
  const Mesh bare = relief(curve({r}), options(0.1));
  EXPECT_EQ(mesh_topology(bare).euler(), 2);
  EXPECT_EQ(bare.faces(), 2 * (r.size() - 2) + 2 * r.size());
  EXPECT_NEAR(enclosed_volume(bare), 0.1 * area, 1e-9 * area);
}

TEST(Relief, KochSnowflakesDoNotCrossThemselves) {
  // A snowflake's sides hold points on one line to a rounding; the cap once had triangles of three of them,
  // a rounding high, which touched the walls beside them.
  for (int levels : {1, 2, 3})
    for (double scale : {1.0, 25.4}) {
      Ring r = koch_snowflake(levels);
      for (Vec2& p : r) p = scale * p;
      for (const ReliefOptions& o : {options(2), options(2, 0.5, 0.3 * scale)}) {
        const Mesh m = relief(curve({r}), o);
        EXPECT_TRUE(mesh_topology(m).closed()) << "level " << levels << " base " << o.base;
        const auto crossing = first_intersection(m, no_progress());
        EXPECT_FALSE(crossing.has_value()) << "level " << levels << " scale " << scale << " base " << o.base
                                           << ": triangles " << crossing->first << " and " << crossing->second;
      }
    }
}

TEST(Relief, SizePredictionBoundsTheResult) {
  const Polyline c = curve({rectangle(0, 0, 10, 10), rectangle(3, 3, 7, 7)});
  for (const ReliefOptions& o : {options(1), options(1, 1, 1)}) {
    const Mesh m = relief(c, o);
    EXPECT_GE(relief_size(c, o), static_cast<double>(m.points.size() + m.faces()));
  }
  ReliefOptions small = options(1);
  small.budget.limit = 10;
  EXPECT_THROW(relief(c, small), BudgetError);
}

TEST(Relief, RefusesBadCurvesAndOptions) {
  const Polyline square = curve({rectangle(0, 0, 1, 1)});
  Polyline open = square;
  open.points.insert(open.points.end(), {{2, 0}, {3, 0}, {3, 1}});
  open.close_path();
  EXPECT_EQ(error_of(open, options(1)),
            "a relief needs closed curves: path 2 is open (it ends at (3, 1), not at its start)");
  EXPECT_EQ(error_of(square, options(0)), "option 'height' must be a positive finite number, got 0");
  EXPECT_EQ(error_of(square, options(-1)), "option 'height' must be a positive finite number, got -1");
  EXPECT_EQ(error_of(square, options(NAN)), "option 'height' must be a positive finite number, got NaN");
  EXPECT_EQ(error_of(square, options(INFINITY)), "option 'height' must be a positive finite number, got inf");
  EXPECT_EQ(error_of(square, options(2e6)),
            "option 'height' of 2000000 is absurd beside the region's size of 1 (it must lie within 1e-9 to 1e6 times "
            "it)");
  EXPECT_EQ(error_of(square, options(1e-12)),
            "option 'height' of 1e-12 is absurd beside the region's size of 1 (it must lie within 1e-9 to 1e6 times "
            "it)");
  EXPECT_EQ(error_of(square, options(1, -1, 1)), "option 'base' must be a finite thickness >= 0 (0: no plate), got -1");
  EXPECT_EQ(error_of(square, options(1, NAN, 1)),
            "option 'base' must be a finite thickness >= 0 (0: no plate), got NaN");
  EXPECT_EQ(error_of(square, options(1, 1, -0.5)), "option 'margin' must be a finite distance >= 0, got -0.5");
  EXPECT_EQ(error_of(square, options(1, 1, 0)),
            "option 'margin' must be positive under a base plate (the outlines would touch the plate's edge)");
  // Crossing paths: a bowtie, and two squares overlapping.
  EXPECT_EQ(error_of(curve({{{0, 0}, {1, 1}, {1, 0}, {0, 1}}}), options(1)),
            "a relief needs simple curves: path 1 crosses or touches itself where its segments from point 1 (0, 0) "
            "and from point 3 (1, 0) meet");
  EXPECT_NE(error_of(curve({rectangle(0, 0, 2, 2), rectangle(1, 1, 3, 3)}), options(1, 1, 1))
                .find("a relief needs curves apart: paths 1 and 2 cross or touch"),
            std::string::npos);
}
