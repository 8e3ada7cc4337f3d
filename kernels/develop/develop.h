// Developing fractal curves (seed 002), by two routes. Route 1: the level stack's control mesh
// (control_mesh.h), smoothed by Loop subdivision (loop_subdivision.h) with the stack's four corners kept (the
// ends of its first and last levels: a closed stack, an annulus, has none), so the smooth surface still spans
// the coarsest and finest curves, its tiles classed by similarity (tile_classes.h). Route 2: the direct
// parameterisation (bezier_surface.h). Either, given a thickness, is thickened into a closed solid
// (thicken.h). The thickness is a point field: by default it shrinks as the curve's segments do (the
// self-similar, "correct" thickness of §3.1.2), a `thickness_rate` shrinks it more slowly, as a print needs.
// Route 1 sets it on the control mesh, level by level, and subdivides it with the same weights as the
// positions (§3.2); route 2 interpolates it geometrically between levels along the smooth `level` field.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "kernels/develop/bezier_surface.h"
#include "kernels/develop/control_mesh.h"
#include "kernels/develop/loop_subdivision.h"

namespace selfsim::develop {

// Route 1 (§3.2): the control mesh smoothed by Loop subdivision, for stacks that refine segment by segment
// (dragon, terdragon, arrowhead, Koch, Gosper); route 2 (§3.1): each level smoothed by Bezier arcs and the
// levels joined by Hermite curves (bezier_surface.h), for any stack (Hilbert too).
enum class Method { loop, bezier };

struct DevelopOptions {
  Method method = Method::loop;  // the DSL's `method`: route 1 or route 2
  int resolution = 0;            // route 2: samples per Bezier piece, in [1, 64]; 0 for its default, 4
  double height = 1;             // gap between levels l and l+1, in segment lengths of level l
  double corner_shift = 0;       // inward shift of each level's inner points, in [0, 0.5] (control_mesh.h)
  int smooth = 0;                // rounds of Loop subdivision, in [0, 12]
  bool bounded = false;          // Loop's bounded-curvature rules (loop_subdivision.h) instead of the classic ones
  double thickness = 0;          // thickness at level 0, in the curve's units; 0 for the open surface itself
  double thickness_rate = 0;     // factor per level, in [1e-6, 1]; 0 for the curve's own segment ratio
  double size = 0;               // scale the result so its largest side is this (thickness too); 0: as built
  int size_level = -1;           // with size: the level whose curve's larger side becomes `size`; −1: the whole
  double scale = 0;              // with size: scale by this factor rather than measure one (the earlier steps of a
                                 // growth series scale as their last did); 0 to measure
  bool check = true;             // refuse a surface that meets itself; warn when the thickened solid does
  PointBudget budget;            // refuse (before subdividing) a result predicted not to fit

  void validate() const;
};

// Route 1's points plus triangles, from the levels' segment counts alone, before any work: the control
// mesh's V points and F triangles with E = V + F − χ edges (χ = 1 for a disk, 0 for an annulus), Loop's
// V' = V + E, E' = 2E + 3F, F' = 4F, and thickening's two sheets and rim (two triangles a boundary edge).
double developed_size(std::span<const double> segments, bool closed, const DevelopOptions& opt);

// Checks developed_size (route 2: bezier_counts) against opt.budget before building anything. With
// opt.check, the surface (before thickening) must not meet itself: Error naming the first pair of triangles
// that do (a curve whose levels touch themselves, unshifted and unsmoothed, does); and when the thickened
// solid meets itself, its thickness is too large for the narrowest gap between the surface's parts, which
// `warnings` (if given) says, naming where.
// `scaled_by`, if given, receives the factor the result was scaled by for option `size` (1 without it).
Mesh develop_surface(std::span<const Polyline* const> levels, const DevelopOptions& opt, Progress& progress,
                     std::vector<std::string>* warnings = nullptr, double* scaled_by = nullptr);

}  // namespace selfsim::develop
