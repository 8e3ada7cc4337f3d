#include "kernels/geom/similarity3.h"

#include "kernels/geom/length_fields.h"

namespace selfsim {

Polyline3 transformed(const Polyline3& c, const Similarity3& t) {
  Polyline3 out = c;
  for (Vec3& p : out.points) p = t(p);
  scale_length_fields(out.point_fields, t.scale());
  return out;
}

}  // namespace selfsim
