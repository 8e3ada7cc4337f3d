// How far one obstacle lets the midpoint of a split segment move along the segment's perpendicular
// bisector (seed 004), in the two modes of `exclusion.curve`. Pure geometry: the caller collects the
// obstacles (every other segment of every curve and of the region's boundary near the split) and keeps the
// smallest reach on each side.
//
// Exact mode. The point p(t) = m + t·n moves continuously away from the midpoint m; the new segments a-p and
// p-b must keep the radius r from each obstacle segment u-v. Their distance to u-v is the least of four
// point-to-segment distances; the ones that change with t are p to u-v ("point term") and u or v to a-p or
// p-b ("vertex terms"). Vertex terms are skipped for an obstacle point equal to a or b: that is where the
// split segment's neighbours (and boundary edges through a curve's end) meet it, and no radius can hold
// there. A term already below r where the point starts (inherited from a coarser level, where the radius
// was larger but the neighbours were excepted) may not get any smaller: its limit is its own starting value.
// Each term's set of t where it is too small is one interval (a line meets a convex set), so an obstacle
// blocks each side at the first t where it is violated.
//
// Vertex mode is the original program's rule: (a) an obstacle crossing the bisector line stops the point
// where it comes within r of the obstacle, r / sin(crossing angle) before the crossing away from the
// obstacle's ends (the original measured to the obstacle's line; measuring to the segment keeps every
// limit local, so that a grid finds it), and can never be passed, (b) an obstacle point w, other than
// a and b, stops the point where a new segment first touches the disc of radius r around w: where the
// segment from a (or b) meets a tangent from that end to the disc (only points within h + r of the
// bisector can be touched). The original used the whole tangent line; the segment keeps the limit local. A
// disc the split segment already passes through limits nothing.
#pragma once

#include "kernels/exclusion/reach.h"
#include "kernels/geom/vec2.h"

namespace selfsim::exclusion {

// The split of segment a-b: midpoint m, unit direction e (a to b), left normal n (e turned 90° counter-
// clockwise), half length h. a and b must differ.
struct SplitFrame {
  Vec2 a, b, m, e, n;
  double h;

  SplitFrame(Vec2 from, Vec2 to);
  Vec2 at(double t) const { return m + t * n; }
};

// Narrows `reach` by what obstacle segment u-v (u == v: a point) allows with radius r, exactly. The terms
// of an end whose flag is false are left out: a caller that has measured that point already (it ends the
// neighbouring segment too) saves the work.
void limit_exact(const SplitFrame& f, Vec2 u, Vec2 v, double r, Reach& reach, bool u_terms = true, bool v_terms = true);

// Narrows `reach` by what obstacle segment u-v allows under the original program's rules.
void limit_vertex(const SplitFrame& f, Vec2 u, Vec2 v, double r, Reach& reach);

}  // namespace selfsim::exclusion
