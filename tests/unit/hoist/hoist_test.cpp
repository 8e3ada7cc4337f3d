// Seed 000's identities and invariants: hoisting the reference segment gives P, multiplicity 1 gives P,
// results run (0,0)→(1,0) with (n − 1)·m^k + 1 points, boundary modes behave as §2.1 says at the joints.
#include "kernels/hoist/hoist.h"

#include <gtest/gtest.h>

#include <cmath>

#include "kernels/base/error.h"
#include "kernels/hoist/iterate.h"
#include "kernels/hoist/multiply.h"
#include "kernels/hoist/spline.h"

using namespace selfsim;
using namespace selfsim::hoist;

namespace {

Polyline spline(std::vector<Vec2> points, SplineKind kind = SplineKind::BSpline, double flatness = 1e-4) {
  return sample_spline({.kind = kind, .points = std::move(points), .flatness = flatness}, no_progress());
}

// A wavy base curve whose end tangents are not horizontal.
const std::vector<Vec2> wave{{0, 0}, {0.2, 0.4}, {0.5, -0.1}, {0.8, 0.3}, {1, 0}};
// Symmetric about x = 1/2.
const std::vector<Vec2> arch{{0, 0}, {0.1, 0.3}, {0.35, 0.45}, {0.65, 0.45}, {0.9, 0.3}, {1, 0}};

Polyline tent() { return Polyline::single({{0, 0}, {0.5, 0.5}, {1, 0}}); }

void expect_ends(const Polyline& c) {
  ASSERT_EQ(c.paths(), 1u);
  EXPECT_LT(norm(c.points.front()), 1e-12);
  EXPECT_LT(norm(c.points.back() - Vec2{1, 0}), 1e-12);
}

double distance_to_polyline(Vec2 p, const Polyline& c) {
  double best = INFINITY;
  for (std::size_t i = 1; i < c.points.size(); ++i) {
    const Vec2 a = c.points[i - 1], d = c.points[i] - a;
    const double w = std::clamp(dot(p - a, d) / dot(d, d), 0.0, 1.0);
    best = std::min(best, norm(p - (a + w * d)));
  }
  return best;
}

}  // namespace

TEST(Spline, PinnedEndsUnitTangentsAndArclengthParameter) {
  for (SplineKind kind : {SplineKind::BSpline, SplineKind::CatmullRom}) {
    const Polyline p = spline(wave, kind);
    expect_ends(p);
    const Field* tangent = p.point_fields.find("tangent");
    const Field* t = p.point_fields.find("t");
    ASSERT_TRUE(tangent && t);
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      EXPECT_NEAR(std::hypot(tangent->at(i, 0), tangent->at(i, 1)), 1, 1e-12);
      if (i > 0) EXPECT_GT(t->at(i), t->at(i - 1));
    }
    EXPECT_EQ(t->at(0), 0);
    EXPECT_EQ(t->at(p.points.size() - 1), 1);
    // The phantom end points make the start tangent P1 − P0.
    const Vec2 start = wave[1] - wave[0];
    EXPECT_NEAR(tangent->at(0, 0), start.x / norm(start), 1e-12);
  }
}

TEST(Spline, CatmullRomPassesThroughItsControlPoints) {
  const Polyline p = spline(wave, SplineKind::CatmullRom);
  for (Vec2 q : wave) EXPECT_LT(distance_to_polyline(q, p), 1e-12) << q.x;
  // A B-spline only approximates them.
  EXPECT_GT(distance_to_polyline(wave[1], spline(wave)), 0.05);
}

TEST(Spline, FlatnessBoundsTheDistanceToTheCurve) {
  const Polyline coarse = spline(wave, SplineKind::BSpline, 1e-2), fine = spline(wave, SplineKind::BSpline, 1e-6);
  EXPECT_GT(fine.points.size(), 4 * coarse.points.size());
  // Every fine sample (on the curve to 1e-6) lies within about the flatness of the coarse polyline.
  for (Vec2 q : fine.points) EXPECT_LT(distance_to_polyline(q, coarse), 1.5e-2);
}

TEST(Spline, Errors) {
  EXPECT_THROW(spline({{0, 0}, {1, 0}}), Error);              // fewer than 3 control points
  EXPECT_THROW(spline({{0, 0}, {0.5, 1}, {2, 0}}), Error);    // not ending at (1,0)
  EXPECT_THROW(spline(wave, SplineKind::BSpline, 0), Error);  // flatness <= 0
  EXPECT_THROW(spline(wave, SplineKind::BSpline, NAN), Error);
  EXPECT_THROW(spline({{0, 0}, {0.5, NAN}, {1, 0}}), Error);
  const Polyline moved = sample_spline({.points = {{2, 2}, {3, 3}, {4, 2}}, .normalize = true}, no_progress());
  expect_ends(moved);  // normalize maps the first point to (0,0) and the last to (1,0)
  SplineOptions tight{.points = wave, .flatness = 1e-9};
  tight.budget.limit = 100;
  EXPECT_THROW(sample_spline(tight, no_progress()), BudgetError);
}

TEST(Hoist, TheReferenceSegmentHoistedOntoPIsP) {
  const Polyline p = spline(wave);
  const BaseCurve base(p);
  // Q: the reference segment, sampled where P's samples lie along its arclength.
  Polyline q;
  for (std::size_t i = 0; i < p.points.size(); ++i) q.points.push_back({p.point_fields.find("t")->at(i), 0});
  q.close_path();
  const Polyline h = hoist_onto(q, base, Boundary::Clamp, no_progress());
  for (std::size_t i = 0; i < p.points.size(); ++i) EXPECT_LT(norm(h.points[i] - p.points[i]), 1e-12) << i;
  // A point above the segment moves along P's normal.
  Polyline up = Polyline::single({{0, 0.1}});
  const Vec2 n = base.at(0, Boundary::Clamp).normal();
  EXPECT_LT(norm(hoist_onto(up, base, Boundary::Clamp, no_progress()).points[0] - 0.1 * n), 1e-12);
}

// MULTIPLY(C, 1) is C, so iterating with multiplicity 1 hoists P onto itself again and again (seed 000 §2.2's
// ITERATE starts from C = P). That is P only where P is the reference segment: HOIST(P, P) = P(px) + py·N(px)
// moves every point of a curved P.
TEST(Hoist, IterateWithMultiplicityOneHoistsPOntoItself) {
  const Polyline p = spline(arch);
  const BaseCurve base(p);
  const Polyline zero = iterate(p, {.multiplicity = 3, .generations = 0}, no_progress());
  for (std::size_t i = 0; i < p.points.size(); ++i) EXPECT_EQ(zero.points[i], p.points[i]);
  const Polyline two = iterate(p, {.multiplicity = 1, .generations = 2}, no_progress());
  const Polyline by_hand =
      hoist_onto(hoist_onto(p, base, Boundary::Clamp, no_progress()), base, Boundary::Clamp, no_progress());
  ASSERT_EQ(two.points.size(), p.points.size());
  for (std::size_t i = 0; i < p.points.size(); ++i) EXPECT_LT(norm(two.points[i] - by_hand.points[i]), 1e-12);
  EXPECT_EQ(two.point_fields.find("generation")->at(0), 2);
  // A straight P (control points on the axis) is the reference segment: multiplicity 1 keeps it.
  const Polyline line = spline({{0, 0}, {0.3, 0}, {0.7, 0}, {1, 0}});
  const Polyline kept = iterate(line, {.multiplicity = 1, .generations = 3}, no_progress());
  for (std::size_t i = 0; i < line.points.size(); ++i) EXPECT_LT(norm(kept.points[i] - line.points[i]), 1e-12);
}

TEST(Hoist, IntegerMultiplicityRunsFromZeroToOneWithPredictedCounts) {
  const Polyline p = spline(wave);
  const std::size_t n = p.points.size();
  for (Boundary b : {Boundary::Clamp, Boundary::Repeat, Boundary::ReflectY, Boundary::ReflectX, Boundary::Rotate})
    for (int m : {2, 3, 5}) {
      const Polyline c = iterate(p, {.multiplicity = double(m), .generations = 2, .boundary = b}, no_progress());
      expect_ends(c);
      EXPECT_EQ(c.points.size(), (n - 1) * m * m + 1);
      const Field* t = c.point_fields.find("t");
      ASSERT_TRUE(t);
      EXPECT_EQ(t->at(c.points.size() - 1), 1);
    }
}

TEST(Hoist, RotateIsTangentContinuousAtTheJointsWhereRepeatIsNot) {
  const BaseCurve base(spline(wave));
  // The end tangents of `wave` are not horizontal, so only rotate joins copies smoothly.
  auto jump = [&](double t, Boundary b) {
    const double e = 1e-9;
    return norm(base.at(t + e, b).tangent - base.at(t - e, b).tangent);
  };
  for (double joint : {0.0, 1.0, 2.0, -1.0}) {
    EXPECT_LT(jump(joint, Boundary::Rotate), 1e-6) << joint;
    EXPECT_GT(jump(joint, Boundary::Repeat), 0.1) << joint;
    EXPECT_GT(jump(joint, Boundary::ReflectX), 0.1) << joint;
  }
  // Positions are continuous in every mode.
  for (Boundary b : {Boundary::Clamp, Boundary::Repeat, Boundary::ReflectY, Boundary::ReflectX, Boundary::Rotate})
    for (double joint : {0.0, 1.0, 2.0, -1.0})
      EXPECT_LT(norm(base.at(joint + 1e-12, b).position - base.at(joint - 1e-12, b).position), 1e-9);
}

TEST(Hoist, ClampKeepsConstantSpeedAcrossTheEnds) {
  const BaseCurve base(spline(wave));
  const double e = 1e-6, L = base.length();
  for (double joint : {0.0, 1.0}) {
    const Vec2 at = base.at(joint, Boundary::Clamp).position;
    EXPECT_NEAR(norm(base.at(joint + e, Boundary::Clamp).position - at) / e, L, 1e-3 * L) << joint;
    EXPECT_NEAR(norm(base.at(joint - e, Boundary::Clamp).position - at) / e, L, 1e-3 * L) << joint;
  }
  EXPECT_LT(norm(base.at(2, Boundary::Clamp).position - Vec2{1 + L, 0}), 1e-12);
}

TEST(Hoist, MirrorSymmetricPGivesAMirrorSymmetricResult) {
  const Polyline p = spline(arch);
  for (Boundary b : {Boundary::Clamp, Boundary::Rotate, Boundary::ReflectY}) {
    const Polyline c = iterate(p, {.multiplicity = 3, .generations = 2, .boundary = b}, no_progress());
    for (std::size_t i = 0; i < c.points.size(); i += 7) {
      const Vec2 q = c.points[i];
      EXPECT_LT(distance_to_polyline({1 - q.x, q.y}, c), 1e-6) << i;
    }
  }
}

TEST(Multiply, CopiesUnderTheirTransformsScaledBack) {
  const Polyline c =
      multiply(tent(), {.multiplicity = 2, .transforms = {SegmentTransform::Identity, SegmentTransform::HalfTurn}},
               no_progress());
  const std::vector<Vec2> want{{0, 0}, {0.25, 0.25}, {0.5, 0}, {0.75, -0.25}, {1, 0}};
  ASSERT_EQ(c.points.size(), want.size());
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_LT(norm(c.points[i] - want[i]), 1e-15) << i;
  // t runs along the copies; the half-turned copy is walked backwards, so its t still increases.
  const Field* t = c.point_fields.find("t");
  for (std::size_t i = 0; i < want.size(); ++i) EXPECT_NEAR(t->at(i), 0.25 * double(i), 1e-15);
}

TEST(Multiply, NonIntegerMultiplicityEndsWithPartOfACopyTurnedBackOntoTheAxis) {
  const Polyline c = multiply(tent(), {.multiplicity = 2.5}, no_progress());
  expect_ends(c);
  // Two whole tents (5 points) and half of a third: its apex, cut exactly there.
  EXPECT_EQ(c.points.size(), 6u);
  EXPECT_EQ(c.point_fields.find("t")->at(5), 1);
  // Before turning back, the end was the third copy's apex at (2.5, 0.5): every point is that picture
  // divided by (2.5 + 0.5i).
  const Vec2 apex = Vec2{0.5, 0.5} / Vec2{2.5, 0.5};
  EXPECT_LT(norm(c.points[1] - apex), 1e-15);
}

// A fractional multiplicity of a curve whose t is not its arclength fraction (a spline's parameter): the cut
// falls at a fraction of the arclength, and t still runs from 0 to 1, increasing (issue 21: past 1).
TEST(Multiply, FractionalMultiplicityKeepsTInZeroToOne) {
  Polyline c = tent();
  std::vector<double> t{0, 0.8, 1};  // the apex at t = 0.8, halfway along the arclength
  c.point_fields.set(real_field("t", t));
  for (const double m : {1.5, 2.25, 2.5, 3.7}) {
    const Polyline r = multiply(c, {.multiplicity = m}, no_progress());
    const Field* f = r.point_fields.find("t");
    EXPECT_EQ(f->at(0), 0) << m;
    EXPECT_EQ(f->at(r.points.size() - 1), 1) << m;
    for (std::size_t i = 1; i < r.points.size(); ++i) EXPECT_GT(f->at(i), f->at(i - 1)) << m << " at " << i;
  }
}

TEST(Multiply, Errors) {
  EXPECT_THROW(multiply(tent(), {.multiplicity = 0.5}, no_progress()), Error);
  EXPECT_THROW(multiply(tent(), {.multiplicity = NAN}, no_progress()), Error);
  EXPECT_THROW(multiply(Polyline::single({{0, 0}, {2, 0}}), {.multiplicity = 2}, no_progress()), Error);
  MultiplyOptions big{.multiplicity = 1000};
  big.budget.limit = 1000;
  EXPECT_THROW(multiply(tent(), big, no_progress()), BudgetError);
  IterateOptions deep{.multiplicity = 5, .generations = 20};
  deep.budget.limit = 1e9;
  EXPECT_THROW(iterate(spline(wave), deep, no_progress()), BudgetError);
}

TEST(Spline, HugeControlPointsNormaliseToTheSameCurve) {
  const std::vector<Vec2> arc{{1, 0}, {0, 1}, {-1, 0}};
  std::vector<Vec2> huge;
  for (Vec2 p : arc) huge.push_back(1e200 * p);
  const Polyline a = sample_spline({.points = arc, .normalize = true}, no_progress());
  const Polyline b = sample_spline({.points = huge, .normalize = true}, no_progress());
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_LT(norm(a.points[i] - b.points[i]), 1e-12);
  EXPECT_LT(a.bbox().min.y, -0.3);  // the arch, not a flat line
  // Ends a billionth of the polygon's size apart would blow the curve up: refused.
  EXPECT_THROW(sample_spline({.points = {{0, 0}, {0.5, 1}, {1e-12, 0}}, .normalize = true}, no_progress()), Error);
}

TEST(Spline, RepeatedControlPointsGiveDistinctSamplesAndUnitTangents) {
  for (SplineKind kind : {SplineKind::BSpline, SplineKind::CatmullRom}) {
    const Polyline p = spline({{0, 0}, {0, 0}, {0, 0}, {0.5, 0.5}, {1, 0}, {1, 0}}, kind);
    const Field* tangent = p.point_fields.find("tangent");
    for (std::size_t i = 0; i < p.points.size(); ++i) {
      if (i > 0) EXPECT_NE(p.points[i], p.points[i - 1]) << i;
      EXPECT_NEAR(std::hypot(tangent->at(i, 0), tangent->at(i, 1)), 1, 1e-12) << i;
    }
    EXPECT_NO_THROW(p.point_fields.check(p.points.size(), "point"));
  }
}

TEST(Hoist, APolylineIsFramedSegmentBySegment) {
  // Without a tangent field, each segment's own direction is the frame: the middle segment runs backwards,
  // so a point above the reference segment's middle lands below it.
  const BaseCurve zigzag(Polyline::single({{0, 0}, {1, 0}, {0, 0}, {1, 0}}));
  const Polyline h = hoist_onto(Polyline::single({{0.5, 0.1}}), zigzag, Boundary::Clamp, no_progress());
  EXPECT_LT(norm(h.points[0] - Vec2{0.5, -0.1}), 1e-12);
  // A repeated vertex changes nothing.
  const BaseCurve tent(Polyline::single({{0, 0}, {0.5, 0.5}, {1, 0}}));
  const BaseCurve doubled(Polyline::single({{0, 0}, {0.5, 0.5}, {0.5, 0.5}, {1, 0}}));
  const Polyline q = Polyline::single({{0.25, 0.1}});
  EXPECT_EQ(hoist_onto(q, tent, Boundary::Clamp, no_progress()).points[0],
            hoist_onto(q, doubled, Boundary::Clamp, no_progress()).points[0]);
}

TEST(Multiply, FractionalMultiplicityIsCheckedByItsExactCount) {
  // 2.5 tents: 5 points whole, then the cut apex: 6 points, which a budget of 6 admits.
  MultiplyOptions opt{.multiplicity = 2.5};
  opt.budget.limit = 6;
  EXPECT_EQ(multiply(tent(), opt, no_progress()).points.size(), 6u);
  opt.budget.limit = 5;
  EXPECT_THROW(multiply(tent(), opt, no_progress()), BudgetError);
  // An end that lands almost on the start is refused rather than scaled up a billion times.
  const Polyline hook = Polyline::single({{0, 0}, {-1, 0}, {-1, -1}, {1, -1}, {1, 0}});
  EXPECT_THROW(multiply(hook, {.multiplicity = 1.2000000001}, no_progress()), Error);
}
