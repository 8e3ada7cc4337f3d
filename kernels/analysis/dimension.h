// Fractal dimension estimates of a 2D curve (seed 004, §Simulation and statistics).
//
// Length scaling: a curve grown by splitting every segment (an exclusion curve) carries in its point field
// `level` the level each point was made at, so the curve at level N is its points of level <= N, in order.
// With L_N that curve's length and L_0 the start's, the paper fits ln L_N = d·ln(2^N / L_0) + c: the slope
// d, its standard error, and D = d + 1.
// Box counting: N(k), the boxes of side s_k = S / 2^k (S: the larger side of the curve's bounding box) that
// the curve passes through, for k = from..to; D is the slope of ln N(k) against ln(2^k).
#pragma once

#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"

namespace selfsim::analysis {

// A least-squares line y = slope·x + intercept through the points, with the slope's standard error. Two
// points leave no residual degree of freedom: the error is undefined, and `has_error` false.
struct LineFit {
  std::vector<double> x, y;
  double slope = 0, intercept = 0, error = 0;
  bool has_error = false;
};

// Fits a line to at least two points with distinct x; throws Error otherwise.
LineFit fit_line(std::vector<double> x, std::vector<double> y);

struct Dimension {
  LineFit fit;             // the points and the line through them
  double dimension = 0;    // D
  std::vector<int> steps;  // the level N, or the box step k, of each point
};

// Throws Error when the curve has no `level` point field, fewer than two levels in [from, to], or a level
// of zero length. to < 0: up to the curve's last level.
Dimension length_scaling(const Polyline& c, int from, int to);

// Throws Error for a curve without extent or segments, or a range outside [0, 11] (2^22 boxes) or with fewer than two
// steps; Cancelled.
Dimension box_counting(const Polyline& c, int from, int to, Progress& progress);

}  // namespace selfsim::analysis
