// How every picture draws a curve's point field `width` (a grammar's '!'): the SVG and EPS writers, the
// preview, the studio's 3D view and the ParaView view (paraview_view_body.py, with_tubes) all follow this one
// rule, so a plant looks the same in each. Widths are drawn relative to the drawing, whatever unit a grammar
// writes them in (ABOP's Figure 2.6 gives its trunk !(10) on unit steps, a recipe may give !(0.05)): the widest
// point is a line of diameter 2 × widest_radius × the drawing's diagonal, the others in proportion to |width|,
// none thinner than a tenth of the widest (a width lowered to 0 would vanish).
#pragma once

#include <algorithm>
#include <cmath>

namespace selfsim::io {

inline constexpr double widest_radius = 0.012;    // of the drawing's diagonal
inline constexpr double thinnest_fraction = 0.1;  // of the widest

// The radius a point of width `width` is drawn with, when the widest is `widest` (> 0) and the drawing's
// diagonal `diagonal`; a width that is not finite (or every width 0) draws as the thinnest.
inline double drawn_radius(double width, double widest, double diagonal) {
  const double share = std::isfinite(width) && widest > 0 ? std::abs(width) / widest : 0;
  return widest_radius * diagonal * std::clamp(share, thinnest_fraction, 1.0);
}

}  // namespace selfsim::io
