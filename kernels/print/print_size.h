// Sizes in millimetres: the factor that brings a shape to the size asked for, and the shape scaled by it
// about the origin (positions kept in proportion, so parts sized alike still fit together). Length fields
// (`thickness`, `radius`, `width`, `wall`, `gap`) scale with it; others (levels, classes) do not.
#pragma once

#include <string>

#include "kernels/geom/bbox.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"

namespace selfsim::print {

struct SizeOptions {
  double size = 0;  // mm: the largest side, or side `axis`'s
  int axis = -1;    // 0, 1, 2: x, y, z; −1: the largest side
  Vec3 fit{};       // mm: the largest size that fits in this box (any zero: not used)

  // Exactly one of size and fit, sides in [1e-6, 1e6] mm. Throws Error naming the option.
  void validate() const;
};

// The factor for a shape of bounding box `box`. Throws Error when the side it measures is zero.
double size_factor(const BBox3& box, const SizeOptions& opt);

// m (or c) scaled by k about the origin, with its length fields. Throws Error if a point overflows.
Mesh scaled_by(Mesh m, double k);
Polyline scaled_by(Polyline c, double k);
Polyline3 scaled_by(Polyline3 c, double k);

// "120 x 80.2 x 40 mm": a size as the run prints it.
std::string size_text(Vec3 size);

}  // namespace selfsim::print
