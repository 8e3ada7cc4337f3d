// How far a fan may move while keeping the radius from the region's walls, measured on the walls' distance
// grid (wall_grid.h) instead of against the boundary's triangles: the exclusion surface's walls = "grid".
//
// Every point of the moving fan (fan_reach.h) must keep an interpolated clearance of at least r. A triangle's
// least clearance is bounded from below by branch and bound: the clearance at its centroid less
// WallGrid::slope times the farthest corner, split 1 -> 4 where that is not enough, down to max_wall_depth.
// From a place t_k of the point where that bound is b, no point of the fan moves more than |t - t_k| by t, so
// the fan keeps r while |t - t_k| <= (b - r) / slope: the point steps that far and measures again (sphere
// tracing), until the step falls below 1/100 of the half edge or the reach already found. A move the walls
// stop keeps a quarter of its half edge beyond r (wall_reach.cpp says why), unless it starts nearer. The true
// clearance is then at least r - WallGrid::error().
#pragma once

#include "kernels/exclusion/fan_reach.h"
#include "kernels/region/wall_grid.h"

namespace selfsim::exclusion {

inline constexpr int max_wall_depth = 5;

// Narrows `reach` by the walls for the fan `f` of a split with half edge h, first to `far` at most (farther
// than any wall).
void limit_by_walls(const FanMove& f, const WallGrid& walls, double r, double h, double far, Reach& reach);

}  // namespace selfsim::exclusion
