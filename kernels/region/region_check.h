// The input side of region_triangles.h: the exact orientation test the sweep and the pieces share, the
// input's paths as rings of distinct points (each checked closed, finite, of at least 3 points and some
// area), and the check that no path crosses or touches itself or another (over a uniform grid of segments).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"
#include "kernels/geom/vec2.h"

namespace selfsim::region_detail {

using Index = std::uint32_t;
constexpr Index none = 0xffffffffu;

// The sign of the turn a → b → c: 1 left (counter-clockwise), -1 right, 0 on one line, exactly. The sweep's
// order of edges and the pieces' ear tests must never contradict each other, or the tree of edges and the
// faces fall apart on collinear input (a comb's teeth, a staircase).
int orientation(Vec2 a, Vec2 b, Vec2 c);

// The sweep's order: by y, ties by x (as if the sweep line were turned by an infinitesimal angle).
inline bool before(Vec2 a, Vec2 b) { return a.y < b.y || (a.y == b.y && a.x < b.x); }

// The input's paths as rings of vertices: succ/pred in the input's order, before any turning around.
struct Rings {
  const Polyline* curve = nullptr;
  std::vector<Vec2> pts;
  std::vector<Index> source, path, succ, pred;

  // "point 3 (0.5, 1)": the vertex's point in its input path, counted from 1.
  std::string point(Index v) const;
};

// The input's paths as rings, each point checked finite, each path closed (closed_path), of at least 3
// distinct points and not all on one line; consecutive repeats and the closing repeat dropped. Throws Error,
// one line beginning with `what`.
Rings prepare(const Polyline& c, const std::string& what, Progress& progress);

// Refuses (Error, naming paths and points) paths that cross or touch themselves or each other.
void check_apart(const Rings& r, const std::string& what, Progress& progress);

}  // namespace selfsim::region_detail
