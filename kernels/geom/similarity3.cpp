#include "kernels/geom/similarity3.h"

namespace selfsim {

Polyline3 transformed(const Polyline3& c, const Similarity3& t) {
  Polyline3 out = c;
  for (Vec3& p : out.points) p = t(p);
  return out;
}

}  // namespace selfsim
