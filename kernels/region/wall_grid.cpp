// WallGrid's arithmetic, apart from OpenVDB (the grid itself is the OpenVDB plugin's: level_set.cpp).
#include "kernels/region/wall_grid.h"

#include <cmath>

namespace selfsim {

double WallGrid::clearance(Vec3 p) const {
  double c = 0;
  clearances({&p, 1}, {&c, 1});
  return c;
}

double WallGrid::error() const { return std::sqrt(3.0) / 2 * voxel(); }

WallGrid WallGrid::in_frame(Vec3 centre, double scale) const {
  // q = scale·(p − centre) and this view's p = scale_·(w − centre_): q = scale·scale_·(w − centre_ − centre/scale_).
  WallGrid g = *this;
  g.centre_ = centre_ + (1 / scale_) * centre;
  g.scale_ = scale_ * scale;
  return g;
}

}  // namespace selfsim
