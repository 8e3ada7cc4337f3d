// Seed 004's closing section, built: the exclusion-radius surface. Every triangle of the growing surfaces is
// split 1 -> 4 at its edge midpoints, and each midpoint moves along a line perpendicular to its edge, to
// whichever side lets it go farther, as far as it can while the new point and the triangles around it keep
// the exclusion radius from every other part of every surface and from the region's boundary
// (fan_reach.h says exactly what is measured). The radius is multiplied by `factor` at each level. The
// surfaces grow inside the region and never cross or touch.
//
// The line. For an edge inside a surface, the line through the midpoint perpendicular to the edge that
// bisects the dihedral angle of the two triangles sharing it; its positive side is the side of the first
// triangle's normal (the surface's front: right-hand rule). For an edge on a surface's boundary, the line in
// the owning triangle's plane; its positive side points away from the triangle.
//
// Order. Level by level; within a level, every triangle is first split flat (its midpoints on its edges),
// then the midpoints move one after another in rounds of spatially separate midpoints (surface_net.h,
// order_rounds), each move seeing every move before it; rounds are measured in parallel and checked, with
// the one-after-another result. Ties go to
// the positive side unless the negative side reaches farther by more than one part in 10^9; a point that can
// move less than 10^-6 of its half edge on both sides stays at the midpoint and is counted as stuck.
#pragma once

#include <cmath>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/exclusion/level_report.h"
#include "kernels/geom/mesh.h"
#include "kernels/region/wall_grid.h"

namespace selfsim::exclusion {

// Which pieces a move may bring nearer than the radius (docs/exclusion.md, "What the output guarantees",
// says what each keeps).
//   neighbourhood: pieces of the moving point's own neighbourhood — corners within `neighbourhood` radii of
//     it along the mesh's edges — that are already nearer than the radius may come as near as `near` radii
//     (or, starting nearer, no nearer); every other piece keeps the radius.
//   strict: the rule before issue 23. No piece may come nearer than the radius, and one already nearer (its
//     parent's neighbour, where the larger radius of the level before excepted it) no nearer; the fan's own
//     static edges count as obstacles at the radius too. Deep levels mostly stop moving.
enum class SurfaceRule { neighbourhood, strict };

struct SurfaceOptions {
  double radius = 0.1;  // exclusion radius of the first level
  double factor = 0.8;  // radius multiplied by this at each level, in (0, 1]
  int levels = 1;       // levels of splitting, each making four triangles of one, in [0, 20]
  SurfaceRule rule = SurfaceRule::neighbourhood;
  double neighbourhood = 6;  // in radii along the mesh, (0, 1000] or infinite (the whole surface)
  double near = 0.01;        // in radii, [1e-6, 1)
  bool keep_levels = false;  // hand back the surface as it was after each level (SurfaceResult::steps)
  PointBudget budget;

  void validate() const;
};

// Where the start already lies nearer than the first radius to the walls, or one surface to another: those
// gaps are kept (no nearer) but cannot grow to the radius, so the guarantees hold only from there.
struct StartGaps {
  double wall = INFINITY;             // the least gap below the radius between a start triangle and the walls
  std::size_t wall_triangle = 0;      // that start triangle, from 0
  double between = INFINITY;          // the least gap below the radius between two start surfaces
  std::size_t first = 0, second = 0;  // those start triangles, from 0
};

struct SurfaceResult {
  Mesh surface;  // point field `level` (0: a start point); face fields `level` (the oldest corner's),
                 // `surface` (from 1: the start's face-connected pieces, in order) and `clearance`
                 // (uniform: the last level's radius, or a nearer start's gap between surfaces: what pieces
                 // once apart keep from each other, docs/exclusion.md)
  std::vector<LevelReport> levels;
  StartGaps start_gaps;
  std::vector<Mesh> steps;  // with keep_levels: the surface after levels 0 (the start), 1, ..., levels − 1, with
                            // the same fields (the last level is `surface`)
};

// Points of the result and working memory, in budget points, for `levels` levels grown from `start` (and,
// with keep_levels, the points and triangles of the earlier levels' meshes).
double surface_size(const Mesh& start, int levels, bool keep_levels = false,
                    SurfaceRule rule = SurfaceRule::neighbourhood);

// Grows the surfaces from `start` inside the closed, outward-oriented triangle mesh `boundary`. Throws Error
// for a start that is not inside, crosses itself or is not a manifold, and for options out of range. With
// `walls`, the same region's distance grid, the growth keeps the radius from the walls as that grid measures
// it (wall_reach.h) instead of from the boundary's triangles; the start is still checked against `boundary`.
SurfaceResult exclusion_surface(const Mesh& boundary, const Mesh& start, const SurfaceOptions& opt, Progress& progress,
                                const WallGrid* walls = nullptr);

}  // namespace selfsim::exclusion
