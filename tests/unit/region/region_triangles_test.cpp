// The even-odd region of closed curves cut into triangles: counts by formula (n − 2 for a polygon, n + 2h − 2
// with h holes), areas equal to the region's, every triangle counter-clockwise and every boundary edge used
// once, on Koch snowflakes, nested rings, staircases and combs (equal y-coordinates, collinear runs), and
// every malformed input refused naming its path and point.
#include "kernels/region/region_triangles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <utility>

#include "kernels/base/error.h"

using namespace selfsim;

namespace {

using Ring = std::vector<Vec2>;

// A curve of closed paths: each ring's first point repeated at its end.
Polyline curve(const std::vector<Ring>& rings) {
  Polyline c;
  for (const Ring& r : rings) {
    for (Vec2 p : r) c.points.push_back(p);
    c.points.push_back(r.front());
    c.close_path();
  }
  return c;
}

double shoelace(const Ring& r) {
  double a = 0;
  for (std::size_t i = 0; i < r.size(); ++i) a += cross(r[i], r[(i + 1) % r.size()]);
  return a / 2;
}

Ring rectangle(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

Ring reversed(Ring r) { return {r.rbegin(), r.rend()}; }

// A Koch snowflake: each level replaces every segment by four a third as long, the middle two bumped out.
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

// A comb: a bar [0, 2T+1] × [0, 1] with T+1 teeth [2k, 2k+1] × [1, 2], its bottom through every integer x.
Ring comb(int teeth) {
  Ring r;
  for (int x = 0; x <= 2 * teeth + 1; ++x) r.push_back({double(x), 0});
  for (int k = teeth; k >= 0; --k) {
    r.push_back({2.0 * k + 1, 2});
    r.push_back({2.0 * k, 2});
    if (k > 0) r.insert(r.end(), {{2.0 * k, 1}, {2.0 * k - 1, 1}});
  }
  return r;
}

// The total area of the triangles, after checking them: each counter-clockwise with positive area, each
// boundary edge (v → next[v]) used once in its direction, every other edge once each way.
double checked_area(const RegionTriangles& t) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  double area = 0;
  for (const auto& tri : t.triangles) {
    const Vec2 a = t.points[tri[0]], b = t.points[tri[1]], c = t.points[tri[2]];
    const double twice = cross(b - a, c - a);
    EXPECT_GT(twice, 0) << "triangle " << tri[0] << " " << tri[1] << " " << tri[2];
    // Not a sliver either: three points on one line to a rounding (a triangle whose height is a rounding
    // error beside its longest side) make a relief's cap touch its walls.
    const double longest = std::max({dot(b - a, b - a), dot(c - b, c - b), dot(a - c, a - c)});
    EXPECT_GT(twice, 1e-9 * longest) << "sliver " << tri[0] << " " << tri[1] << " " << tri[2];
    area += twice / 2;
    for (int k = 0; k < 3; ++k) ++uses[{tri[k], tri[(k + 1) % 3]}];
  }
  for (std::uint32_t v = 0; v < t.points.size(); ++v) {
    EXPECT_EQ(uses.count(std::pair(v, t.next[v])), 1u) << "boundary edge " << v;
    EXPECT_EQ(uses.count(std::pair(t.next[v], v)), 0u) << "boundary edge " << v << " used backwards";
  }
  for (const auto& [e, n] : uses) {
    EXPECT_EQ(n, 1) << "edge " << e.first << " " << e.second;
    const bool boundary = t.next[e.first] == e.second;
    if (!boundary) {
      EXPECT_EQ(uses.count(std::pair(e.second, e.first)), 1u) << "diagonal " << e.first << " " << e.second;
    }
  }
  return area;
}

std::string error_of(const Polyline& c) {
  try {
    region_triangles(c);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(RegionTriangles, UnitSquareEitherWay) {
  for (const Ring& r : {rectangle(0, 0, 1, 1), reversed(rectangle(0, 0, 1, 1))}) {
    const RegionTriangles t = region_triangles(curve({r}));
    EXPECT_EQ(t.points.size(), 4u);
    EXPECT_EQ(t.triangles.size(), 2u);
    EXPECT_DOUBLE_EQ(checked_area(t), 1);
    // Oriented counter-clockwise whatever the input's direction.
    Ring oriented;
    for (std::uint32_t v = 0, k = 0; k < 4; v = t.next[v], ++k) oriented.push_back(t.points[v]);
    EXPECT_DOUBLE_EQ(shoelace(oriented), 1);
  }
}

TEST(RegionTriangles, KochSnowflakeHasNMinusTwoTrianglesAndItsArea) {
  for (int levels : {4, 7}) {  // 768 and 49,152 points
    const Ring r = koch_snowflake(levels);
    const RegionTriangles t = region_triangles(curve({r}));
    ASSERT_EQ(t.points.size(), r.size());
    EXPECT_EQ(t.triangles.size(), r.size() - 2);
    const double area = shoelace(r);
    EXPECT_NEAR(checked_area(t), area, 1e-9 * area);
    EXPECT_NEAR(area, std::sqrt(3.0) / 4 * (1 + 0.6 * (1 - std::pow(4.0 / 9, levels))), 1e-12);  // by formula
  }
}

TEST(RegionTriangles, KochSnowflakeOfFewLevelsHasNoSlivers) {
  // From level 1 on, points of a snowflake lie on one line only to a rounding (the hexagram's top cap:
  // (0, y), (1/3, y), (2/3, y), (1, y) each computed differently), which once gave triangles of three of them,
  // of height 1e-17. Scaled and moved too, so that other roundings are tried.
  for (int levels : {1, 2, 3})
    for (const auto& [scale, shift] : {std::pair{1.0, Vec2{0, 0}}, std::pair{25.4, Vec2{0, 0}},
                                       std::pair{3.7, Vec2{1000, -3}}, std::pair{1e-3, Vec2{0.1, 0.2}}}) {
      Ring r = koch_snowflake(levels);
      for (Vec2& p : r) p = scale * p + shift;
      const RegionTriangles t = region_triangles(curve({r}));
      ASSERT_EQ(t.points.size(), r.size());
      EXPECT_EQ(t.triangles.size(), r.size() - 2) << "level " << levels << " scale " << scale;
      const double area = shoelace(r);
      EXPECT_NEAR(checked_area(t), area, 1e-9 * area) << "level " << levels << " scale " << scale;
    }
}

TEST(RegionTriangles, CollinearPointsApartAlongALine) {
  // Battlements: a bottom of many points on y = 0, merlon tops all on y = 3 (points on one line that are not
  // neighbours), crenels all on y = 2. Then the same exactly slanted (sheared along y = x / 2, integer
  // coordinates), turned by an angle (on one line only to a rounding), and as a hole in a rectangle.
  Ring wall;
  for (int x = 0; x <= 24; ++x) wall.push_back({double(x), 0});
  for (int k = 11; k >= 0; --k)
    wall.insert(wall.end(), {{2.0 * k + 2, 2}, {2.0 * k + 2, 3}, {2.0 * k + 1, 3}, {2.0 * k + 1, 2}});
  wall.push_back({0, 2});
  Ring sheared, turned, hole;
  for (Vec2 p : wall) {
    sheared.push_back({p.x, p.y + p.x / 2});
    turned.push_back(p * polar(0.3217505543966422));  // atan(1/3)
    hole.push_back({p.x + 3, p.y + 3});
  }
  for (const Ring& r : {wall, reversed(wall), sheared, turned}) {
    const RegionTriangles t = region_triangles(curve({r}));
    EXPECT_EQ(t.triangles.size(), r.size() - 2);
    EXPECT_NEAR(checked_area(t), std::abs(shoelace(r)), 1e-9 * std::abs(shoelace(r)));
  }
  const RegionTriangles t = region_triangles(curve({rectangle(0, 0, 30, 9), hole}));
  EXPECT_EQ(t.triangles.size(), 4 + hole.size() + 2 - 2);
  EXPECT_NEAR(checked_area(t), 270 - std::abs(shoelace(hole)), 1e-9);
}

TEST(RegionTriangles, StarsWhosePointsLineUp) {
  // The outlines of star polygons {n/2} and {n/3}: each notch on the line between the tips two (three)
  // apart, so tips and notches line up across the polygon, to a rounding (made with cos and sin); turned by
  // a few angles and scaled. And a star of integer points whose tips and notches line up exactly.
  for (int tips = 5; tips <= 20; ++tips)
    for (int skip : {2, 3}) {
      const double inner = std::cos(skip * std::numbers::pi / tips) / std::cos(std::numbers::pi / tips);
      if (inner < 0.1) continue;
      for (double phase : {0.0, 0.25, 0.5})
        for (double scale : {1.0, 7.3}) {
          Ring r;
          for (int k = 0; k < 2 * tips; ++k)
            r.push_back(scale * (k % 2 ? inner : 1.0) * polar(std::numbers::pi * (k + phase) / tips));
          const RegionTriangles t = region_triangles(curve({r}));
          EXPECT_EQ(t.triangles.size(), r.size() - 2) << "{" << tips << "/" << skip << "}";
          EXPECT_NEAR(checked_area(t), shoelace(r), 1e-9 * shoelace(r))
              << "{" << tips << "/" << skip << "} turned " << phase;
        }
    }
  const Ring exact{{6, 0},  {2, 1},   {6, 6},   {1, 2},   {0, 6},  {-1, 2}, {-6, 6}, {-2, 1},
                   {-6, 0}, {-2, -1}, {-6, -6}, {-1, -2}, {0, -6}, {1, -2}, {6, -6}, {2, -1}};
  const RegionTriangles t = region_triangles(curve({exact}));
  EXPECT_EQ(t.triangles.size(), exact.size() - 2);
  EXPECT_NEAR(checked_area(t), shoelace(exact), 1e-12);
}

TEST(RegionTriangles, HolesAndIslandsEvenOdd) {
  const Ring outer = rectangle(0, 0, 10, 10), hole = rectangle(2, 2, 8, 8), island = rectangle(4, 4, 6, 6);
  // Any direction for any ring: nesting decides.
  const RegionTriangles t = region_triangles(curve({reversed(island), outer, reversed(hole)}));
  EXPECT_EQ(t.triangles.size(), (8u + 2 - 2) + (4u - 2));
  EXPECT_DOUBLE_EQ(checked_area(t), 100 - 36 + 4);
  // The hole runs clockwise, the outline and the island counter-clockwise.
  for (std::uint32_t path = 0; path < 3; ++path) {
    Ring oriented;
    for (std::uint32_t v = path * 4, k = 0; k < 4; v = t.next[v], ++k) oriented.push_back(t.points[v]);
    EXPECT_EQ(shoelace(oriented) > 0, path != 2) << "path " << path;
  }
}

TEST(RegionTriangles, ManyHolesGiveNPlusTwoHMinusTwo) {
  // A square with a grid of star-shaped holes, each of random radii at random angles, and islands in some.
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0, 1);
  auto star = [&](Vec2 centre, double size, int points) {
    std::vector<double> angles;
    for (int k = 0; k < points; ++k) angles.push_back(2 * std::numbers::pi * unit(random));
    std::sort(angles.begin(), angles.end());
    Ring r;
    for (double a : angles) r.push_back(centre + (size * (0.5 + 0.5 * unit(random))) * polar(a));
    return r;
  };
  std::vector<Ring> rings{rectangle(0, 0, 12, 12)};
  double area = 144;
  std::size_t holes = 0, islands = 0, island_points = 0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      rings.push_back(star({2.0 * i + 1, 2.0 * j + 1}, 0.9, 40));
      area -= std::abs(shoelace(rings.back()));
      ++holes;
      if ((i + j) % 3 == 0) {
        rings.push_back(star({2.0 * i + 1, 2.0 * j + 1}, 0.2, 12));
        area += std::abs(shoelace(rings.back()));
        ++islands;
        island_points += 12;
      }
    }
  const RegionTriangles t = region_triangles(curve(rings));
  const std::size_t outline_points = t.points.size() - island_points;
  EXPECT_EQ(t.triangles.size(), (outline_points + 2 * holes - 2) + (island_points - 2 * islands));
  EXPECT_NEAR(checked_area(t), area, 1e-12 * 144);
}

TEST(RegionTriangles, EqualYAndCollinearRuns) {
  // A staircase (every step two vertices of equal y), combs with teeth up, down and sideways (runs of
  // collinear points, many start and end vertices at one y), and a square with points along its sides.
  Ring stairs{{0, 0}};
  for (int k = 0; k < 6; ++k) stairs.insert(stairs.end(), {{6.0 - k, double(k)}, {6.0 - k, k + 1.0}});
  const Ring teeth = comb(8);
  Ring down, sideways;
  for (Vec2 p : teeth) down.push_back({p.x, -p.y}), sideways.push_back({p.y, p.x});
  Ring dotted;
  for (int side = 0; side < 4; ++side)
    for (int k = 0; k < 5; ++k) {
      const double s = k / 5.0;
      const Vec2 corners[] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
      dotted.push_back(lerp(corners[side], corners[side + 1], s));
    }
  for (const Ring& r : {stairs, teeth, reversed(down), sideways, dotted}) {
    const RegionTriangles t = region_triangles(curve({r}));
    EXPECT_EQ(t.triangles.size(), r.size() - 2);
    EXPECT_NEAR(checked_area(t), std::abs(shoelace(r)), 1e-12);
  }
  // Combs nested as outline and hole, and a comb hole whose teeth meet a comb island's at equal y.
  Ring inner = comb(3);
  for (Vec2& p : inner) p = Vec2{p.x + 2, p.y + 2};
  const RegionTriangles t = region_triangles(curve({rectangle(0, 0, 12, 6), inner}));
  EXPECT_EQ(t.triangles.size(), 4 + inner.size() + 2 - 2);
  EXPECT_NEAR(checked_area(t), 72 - std::abs(shoelace(inner)), 1e-12);
}

TEST(RegionTriangles, DeepNestingAndManyPaths) {
  // Twenty concentric squares alternate filled and empty, given in scrambled order and directions.
  std::vector<Ring> rings;
  double area = 0;
  for (int k = 19; k >= 0; k -= 2) {
    rings.push_back(k % 4 == 1 ? reversed(rectangle(-k - 1, -k - 1, k + 1, k + 1))
                               : rectangle(-k - 1, -k - 1, k + 1, k + 1));
  }
  for (int k = 0; k < 20; k += 2) rings.push_back(rectangle(-k - 1, -k - 1, k + 1, k + 1));
  for (int k = 0; k < 20; ++k) area += (k % 2 == 1 ? 1 : -1) * 4.0 * (k + 1) * (k + 1);
  RegionTriangles t = region_triangles(curve(rings));
  EXPECT_EQ(t.triangles.size(), 10u * 8);  // ten square annuli
  EXPECT_DOUBLE_EQ(checked_area(t), area);
  // A 100 × 100 grid of separate small squares, each with a hole: 10,000 outlines and holes.
  rings.clear();
  for (int i = 0; i < 100; ++i)
    for (int j = 0; j < 100; ++j) {
      rings.push_back(rectangle(i, j, i + 0.8, j + 0.8));
      rings.push_back(rectangle(i + 0.2, j + 0.2, i + 0.6, j + 0.6));
    }
  t = region_triangles(curve(rings));
  EXPECT_EQ(t.triangles.size(), 10000u * 8);
  EXPECT_NEAR(checked_area(t), 10000 * (0.64 - 0.16), 1e-8);
}

TEST(RegionTriangles, RandomPolygonsOnAGrid) {
  // Star-shaped polygons with a hole, their points rounded to a coarse grid: ties in y and x, collinear runs
  // and repeated points everywhere. Those that come out touching themselves are refused; the rest must
  // triangulate exactly.
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  auto star = [&](double r0, double r1, int points) {
    std::vector<double> angles;
    for (int k = 0; k < points; ++k) angles.push_back(2 * std::numbers::pi * unit(random));
    std::sort(angles.begin(), angles.end());
    Ring r;
    for (double a : angles) {
      const Vec2 q = (r0 + (r1 - r0) * unit(random)) * polar(a);
      r.push_back({std::round(q.x), std::round(q.y)});
    }
    return r;
  };
  int triangulated = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const Ring outer = star(6, 12, 8 + trial % 40), hole = star(1, 3, 3 + trial % 9);
    const bool with_hole = trial % 2 == 1;
    Polyline c = with_hole ? curve({outer, hole}) : curve({outer});
    RegionTriangles t;
    try {
      t = region_triangles(c);
    } catch (const Error&) {
      continue;
    }
    ++triangulated;
    const double area = std::abs(shoelace(outer)) - (with_hole ? std::abs(shoelace(hole)) : 0);
    const std::size_t outline = t.points.size();
    EXPECT_EQ(t.triangles.size(), outline + (with_hole ? 2 : 0) - 2) << "trial " << trial;
    EXPECT_NEAR(checked_area(t), area, 1e-9) << "trial " << trial;
  }
  EXPECT_GT(triangulated, 100);
}

TEST(RegionTriangles, SideBySideOutlinesAndTheClosingRepeat) {
  // Two outlines apart; a path whose last point is its first to a rounding error, and repeated points.
  Polyline c = curve({rectangle(0, 0, 1, 1), rectangle(2, 0, 3, 1)});
  c.points.insert(c.points.end(), {{5, 0}, {6, 0}, {6, 0}, {6, 1}, {5, 1}, {5 + 1e-15, 1e-15}});
  c.close_path();
  const RegionTriangles t = region_triangles(c);
  EXPECT_EQ(t.points.size(), 12u);
  EXPECT_EQ(t.triangles.size(), 6u);
  EXPECT_NEAR(checked_area(t), 3, 1e-12);
  EXPECT_EQ(t.path_of_point[11], 2u);
  EXPECT_EQ(t.source[10], 13u);  // (6, 1): the repeated (6, 0) dropped
}

TEST(RegionTriangles, RefusesMalformedPaths) {
  Polyline open = curve({rectangle(0, 0, 1, 1)});
  open.points.insert(open.points.end(), {{2, 0}, {3, 0}, {3, 1}});
  open.close_path();
  EXPECT_EQ(error_of(open),
            "a filled region needs closed curves: path 2 is open (it ends at (3, 1), not at its start)");
  EXPECT_EQ(error_of(curve({{{0, 0}, {1, 1}, {0, 0}}})),
            "a filled region needs paths of at least 3 distinct points: path 1 has 2 distinct points");
  EXPECT_EQ(error_of(curve({{{0, 0}, {1, 1}, {2, 2}}})),
            "a filled region needs curves that enclose an area: path 1 encloses none (its points lie on one line)");
  EXPECT_EQ(error_of(curve({{{0, 0}, {1, NAN}, {2, 2}}})),
            "a filled region needs finite points: point 2 of path 1 is (1, NaN)");
  EXPECT_EQ(error_of(Polyline{}), "a filled region needs at least one closed curve");
  EXPECT_EQ(error_of(Polyline::single({{0, 0}, {1, 1}})),
            "a filled region needs paths of at least 3 distinct points: path 1 has 2 points");
  // A bowtie crosses itself; a ring touching another at a corner; a spike folding back on itself.
  EXPECT_EQ(error_of(curve({{{0, 0}, {1, 1}, {1, 0}, {0, 1}}})),
            "a filled region needs simple curves: path 1 crosses or touches itself where its segments from point 1 "
            "(0, 0) and from point 3 (1, 0) meet");
  EXPECT_EQ(error_of(curve({rectangle(0, 0, 4, 4), rectangle(1, 1, 2, 2), rectangle(2, 2, 3, 3)})),
            "a filled region needs curves apart: paths 2 and 3 cross or touch where the segment from point 2 (2, 1) of "
            "path 2 meets the segment from point 1 (2, 2) of path 3");
  EXPECT_NE(error_of(curve({{{0, 0}, {2, 0}, {1, 0}, {1, 1}}})).find("path 1 crosses or touches itself"),
            std::string::npos);
  EXPECT_NE(error_of(curve({rectangle(0, 0, 4, 4), rectangle(2, 1, 6, 3)})).find("paths 1 and 2 cross or touch"),
            std::string::npos);
  // A hole touching its outline along a side.
  EXPECT_NE(error_of(curve({rectangle(0, 0, 4, 4), rectangle(0, 1, 2, 2)})).find("cross or touch"), std::string::npos);
}

TEST(RegionTriangles, StopsWhenCancelled) {
  struct Stop : Progress {
    int steps = 0;
    bool cancelled() override { return ++steps > 2; }
  } stop;
  EXPECT_THROW(region_triangles(curve({koch_snowflake(7)}), stop), Cancelled);
}
