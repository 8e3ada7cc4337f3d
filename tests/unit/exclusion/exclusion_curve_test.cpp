// Seed 004's exclusion-radius curve: the invariants of the result, the grid against brute force, errors.
#include "kernels/exclusion/exclusion_curve.h"

#include <gtest/gtest.h>

#include <string>

#include "kernels/base/error.h"
#include "kernels/exclusion/discs.h"
#include "kernels/geom/segment2.h"

using namespace selfsim;
using namespace selfsim::exclusion;

namespace {

const std::vector<Vec2> unit_square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};

struct Seg {
  Vec2 a, b;
  std::size_t path, index;
};

std::vector<Seg> segments_of(const Polyline& c) {
  std::vector<Seg> s;
  for (std::size_t i = 0; i < c.paths(); ++i) {
    const auto p = c.path(i);
    for (std::size_t k = 0; k + 1 < p.size(); ++k) s.push_back({p[k], p[k + 1], i, k});
  }
  return s;
}

// No two segments meet unless they follow each other along one path (or close a closed one), and those
// share only their common point.
void expect_simple(const Polyline& c) {
  const std::vector<Seg> s = segments_of(c);
  for (std::size_t i = 0; i < s.size(); ++i)
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const bool same = s[i].path == s[j].path;
      const std::size_t n = c.path(s[i].path).size() - 1;
      const bool closed = c.path(s[i].path).front() == c.path(s[i].path).back();
      if (same && (s[j].index == s[i].index + 1 || (closed && s[i].index == 0 && s[j].index == n - 1))) {
        const Vec2 far = s[j].index == s[i].index + 1 ? s[j].b : s[j].a;
        ASSERT_GT(point_segment_distance(far, s[i].a, s[i].b), 0) << "segments " << i << " and " << j << " fold";
        continue;
      }
      ASSERT_FALSE(segments_meet(s[i].a, s[i].b, s[j].a, s[j].b))
          << "path " << s[i].path << " segment " << s[i].index << " meets path " << s[j].path << " segment "
          << s[j].index;
    }
}

// Every point inside the region; off its boundary except an open curve's two ends.
void expect_inside(const Polyline& c, const Region& region) {
  for (std::size_t i = 0; i < c.paths(); ++i) {
    const auto p = c.path(i);
    const bool closed = p.front() == p.back();
    for (std::size_t k = 0; k < p.size(); ++k) {
      ASSERT_TRUE(region.contains(p[k])) << "path " << i << " point " << k;
      if (closed || (k > 0 && k + 1 < p.size())) {
        ASSERT_GT(region.distance(p[k]), 0) << "path " << i << " point " << k;
      }
    }
  }
}

CurveResult run(const Region& region, const Polyline& start, CurveOptions o) {
  return exclusion_curve(region, start, o, no_progress());
}

std::string error_of(const Region& region, const Polyline& start, CurveOptions o) {
  try {
    run(region, start, o);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(ExclusionCurve, Figure3IsSimpleInsideAndDoubles) {
  const Region square({unit_square});
  CurveOptions o;
  o.levels = 9;
  const CurveResult r = run(square, Polyline::single({{0, 0}, {1, 1}}), o);
  EXPECT_EQ(r.curve.points.size(), 513u);  // each level doubles the segments
  ASSERT_EQ(r.levels.size(), 9u);
  for (int l = 0; l < 9; ++l) EXPECT_EQ(r.levels[l].splits, std::size_t{1} << l);
  EXPECT_EQ(r.curve.points[0], (Vec2{0, 0}));
  EXPECT_EQ(r.curve.points[512], (Vec2{1, 1}));
  expect_simple(r.curve);
  expect_inside(r.curve, square);
  // The first split breaks the diagonal's symmetry to the left (the top-left corner), as in Figure 4.
  const Vec2 first = r.curve.points[256];
  EXPECT_LT(first.x, 0.2);
  EXPECT_GT(first.y, 0.8);
  // The curve fills the square: it is many times longer than its start.
  EXPECT_GT(r.curve.length(), 15 * std::sqrt(2.0));
}

TEST(ExclusionCurve, GridAgreesWithBruteForceInEveryOrderAndMode) {
  const Region square({unit_square});
  for (const Mode mode : {Mode::exact, Mode::vertex})
    for (const Order order : {Order::breadth, Order::depth})
      for (const Scan scan : {Scan::alternate, Scan::forward}) {
        if (order == Order::depth && scan == Scan::forward) continue;
        CurveOptions o;
        o.levels = 8;
        o.exclusion = mode;
        o.order = order;
        o.scan = scan;
        const CurveResult grid = run(square, Polyline::single({{0, 0}, {1, 1}}), o);
        o.brute_force = true;
        const CurveResult brute = run(square, Polyline::single({{0, 0}, {1, 1}}), o);
        const std::string what = "mode " + std::to_string(int(mode)) + " order " + std::to_string(int(order)) +
                                 " scan " + std::to_string(int(scan));
        ASSERT_EQ(grid.curve.points.size(), brute.curve.points.size()) << what;
        for (std::size_t k = 0; k < grid.curve.points.size(); ++k)
          ASSERT_EQ(grid.curve.points[k], brute.curve.points[k]) << what << " point " << k;
        EXPECT_EQ(grid.stuck(), brute.stuck());
        if (mode == Mode::exact) {
          expect_simple(grid.curve);
          expect_inside(grid.curve, square);
        }
      }
}

TEST(ExclusionCurve, ScanOrderChangesTheCurve) {
  const Region square({unit_square});
  CurveOptions o;
  o.levels = 6;
  const CurveResult alternate = run(square, Polyline::single({{0, 0}, {1, 1}}), o);
  o.scan = Scan::forward;
  const CurveResult forward = run(square, Polyline::single({{0, 0}, {1, 1}}), o);
  o.order = Order::depth;
  const CurveResult depth = run(square, Polyline::single({{0, 0}, {1, 1}}), o);
  auto differ = [](const Polyline& x, const Polyline& y) {
    return !std::equal(x.points.begin(), x.points.end(), y.points.begin());
  };
  EXPECT_TRUE(differ(alternate.curve, forward.curve));
  EXPECT_TRUE(differ(forward.curve, depth.curve));
  expect_simple(depth.curve);
  expect_inside(depth.curve, square);
}

TEST(ExclusionCurve, ClosedStartInAnLWithAHoleStaysClosedAndSimple) {
  // An L-shaped region with a square hole in its long limb; a closed start (a triangle) in the short limb
  // and an open start in the long one, grown against each other.
  const Region l_shape(
      {{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {{1.3, 0.3}, {1.3, 0.6}, {1.6, 0.6}, {1.6, 0.3}}});
  Polyline start;
  for (Vec2 p : {Vec2{0.2, 1.2}, Vec2{0.8, 1.2}, Vec2{0.5, 1.8}, Vec2{0.2, 1.2}}) start.points.push_back(p);
  start.close_path();
  for (Vec2 p : {Vec2{0.2, 0.2}, Vec2{0.8, 0.8}, Vec2{1.8, 0.8}}) start.points.push_back(p);
  start.close_path();
  CurveOptions o;
  o.levels = 7;
  o.radius = 0.05;
  const CurveResult r = run(l_shape, start, o);
  ASSERT_EQ(r.curve.paths(), 2u);
  EXPECT_EQ(r.curve.path(0).size(), 3u * 128 + 1);
  EXPECT_EQ(r.curve.path(1).size(), 2u * 128 + 1);
  EXPECT_EQ(r.curve.path(0).front(), r.curve.path(0).back());
  expect_simple(r.curve);
  expect_inside(r.curve, l_shape);
  const Field* curve = r.curve.cell_fields.find("curve");
  ASSERT_NE(curve, nullptr);
  const Field* level = r.curve.point_fields.find("level");
  ASSERT_NE(level, nullptr);
}

TEST(ExclusionCurve, BadStartsAndOptionsAreRefusedByName) {
  const Region square({unit_square});
  CurveOptions o;
  EXPECT_NE(error_of(square, Polyline::single({{2, 2}, {3, 3}}), o).find("lies outside the region"), std::string::npos);
  EXPECT_NE(error_of(square, Polyline::single({{0.5, 0.5}, {1.5, 0.5}}), o).find("crosses or touches the region's"),
            std::string::npos);
  EXPECT_NE(error_of(square, Polyline::single({{0.5, 0.5}, {1, 0.5}, {0.5, 0.7}}), o).find("on the region's boundary"),
            std::string::npos);
  EXPECT_EQ(error_of(square, Polyline::single({{0, 0.5}, {1, 0.5}}), o), "");  // ends on the boundary: allowed
  EXPECT_NE(error_of(square, Polyline::single({{0.2, 0.2}, {0.2, 0.2}, {0.5, 0.5}}), o).find("zero length"),
            std::string::npos);
  EXPECT_NE(error_of(square, Polyline::single({{0.1, 0.1}, {0.9, 0.9}, {0.9, 0.1}, {0.1, 0.9}}), o).find("meets"),
            std::string::npos);
  EXPECT_NE(error_of(square, Polyline::single({{0.1, 0.1}, {0.9, 0.1}, {0.5, 0.1}}), o).find("folds back"),
            std::string::npos);
  o.radius = 0;
  EXPECT_NE(error_of(square, Polyline::single({{0.1, 0.1}, {0.9, 0.9}}), o).find("radius"), std::string::npos);
  o.radius = 0.1;
  o.factor = 1.5;
  EXPECT_NE(error_of(square, Polyline::single({{0.1, 0.1}, {0.9, 0.9}}), o).find("factor"), std::string::npos);
  o.factor = 0.8;
  o.levels = 30;
  o.budget.limit = 1e6;
  EXPECT_NE(error_of(square, Polyline::single({{0.1, 0.1}, {0.9, 0.9}}), o).find("--max-points"), std::string::npos);
}

TEST(ExclusionCurve, DiscsHaveEachPointsRadius) {
  const Region square({unit_square});
  CurveOptions o;
  o.levels = 3;
  o.radius = 0.1;
  o.factor = 0.5;
  const CurveResult r = run(square, Polyline::single({{0, 0}, {1, 1}}), o);
  DiscOptions d;
  d.radius = 0.1;
  d.factor = 0.5;
  d.samples = 12;
  const Polyline discs = exclusion_discs(r.curve, d, no_progress());
  ASSERT_EQ(discs.paths(), 7u);  // 1 + 2 + 4 points made at levels 1..3
  const Field* made = r.curve.point_fields.find("level");
  std::size_t disc = 0;
  for (std::size_t i = 0; i < r.curve.points.size(); ++i) {
    const int l = static_cast<int>(made->at(i));
    if (l < 1) continue;
    const auto p = discs.path(disc++);
    ASSERT_EQ(p.size(), 13u);
    EXPECT_EQ(p.front(), p.back());
    for (Vec2 q : p) EXPECT_NEAR(norm(q - r.curve.points[i]), 0.1 * std::pow(0.5, l - 1), 1e-12);
  }
  d.level = 2;
  EXPECT_EQ(exclusion_discs(r.curve, d, no_progress()).paths(), 2u);
  EXPECT_THROW(exclusion_discs(Polyline::single({{0, 0}, {1, 1}}), d, no_progress()), Error);  // no level field
}

TEST(ExclusionCurve, AnyScaleAndPlaceStaysSimple) {
  // The closed-form limits square coordinates several times over: the kernel works at the region's own size.
  for (const double scale : {1e-150, 1e-55, 1e55, 1e150})
    for (const double offset : {0.0, 1e8}) {
      const Vec2 o{offset * scale, offset * scale};
      std::vector<Vec2> ring;
      for (Vec2 p : unit_square) ring.push_back(o + scale * p);
      const Region square({ring});
      CurveOptions opt;
      opt.levels = 8;
      opt.radius = 0.1 * scale;
      const CurveResult r = run(square, Polyline::single({o, o + Vec2{scale, scale}}), opt);
      expect_simple(r.curve);
      expect_inside(r.curve, square);
      EXPECT_EQ(r.curve.points.front(), o);  // start points come back exactly as given
      EXPECT_GT(r.curve.length(), 10 * scale);
    }
}

TEST(ExclusionCurve, StartsTouchingTheBoundaryOnlyAtTheirEndsAreAccepted) {
  // A short stub standing on an edge, and the diagonal of a long thin rectangle (a shallow angle to its
  // edges): the distance test alone would call both touching.
  const Region square({unit_square});
  CurveOptions o;
  o.levels = 3;
  EXPECT_EQ(error_of(square, Polyline::single({{0.5, 0}, {0.5, 1e-4}, {0.6, 0.5}}), o), "");
  const Region thin({{{0, 0}, {1000, 0}, {1000, 1}, {0, 1}}});
  o.radius = 0.05;
  EXPECT_EQ(error_of(thin, Polyline::single({{0, 0}, {1000, 1}}), o), "");
  EXPECT_NE(error_of(square, Polyline::single({{0.5, 0}, {0.7, 0}, {0.6, 0.5}}), o), "");  // along an edge
}
