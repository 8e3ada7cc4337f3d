#include "kernels/print/print_size.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/geom/length_fields.h"
#include "kernels/geom/point_text.h"

namespace selfsim::print {

namespace {

template <class C>
C scaled_curve(C c, double k) {
  for (auto& p : c.points) p = k * p;
  scale_length_fields(c.point_fields, k);  // cell fields are no lengths (length_fields.h)
  if (!c.finite()) throw Error("scaling by " + number_text(k) + " overflows");
  return c;
}

}  // namespace

void SizeOptions::validate() const {
  const bool fitting = fit != Vec3{};
  if ((size > 0) == fitting) throw Error("give one of 'size' (mm, the largest side) and 'fit' (a box {x, y, z}, mm)");
  if (fitting) {
    for (double side : {fit.x, fit.y, fit.z}) check_between(side, 1e-6, 1e6, "each side of option 'fit' (mm)");
  } else {
    check_between(size, 1e-6, 1e6, "option 'size' (mm)");
  }
  if (axis < -1 || axis > 2) throw Error("internal error: axis out of range");
}

double size_factor(const BBox3& box, const SizeOptions& opt) {
  opt.validate();
  const Vec3 s = box.size();
  const std::array<double, 3> sides{s.x, s.y, s.z};
  if (opt.fit != Vec3{}) {
    // The largest factor that keeps every side inside the box's.
    const std::array<double, 3> room{opt.fit.x, opt.fit.y, opt.fit.z};
    double k = std::numeric_limits<double>::infinity();
    for (int i = 0; i < 3; ++i)
      if (sides[i] > 0) k = std::min(k, room[i] / sides[i]);
    if (!std::isfinite(k)) throw Error("the shape has no extent to fit into the box");
    return k;
  }
  const double side = opt.axis >= 0 ? sides[static_cast<std::size_t>(opt.axis)] : std::max({s.x, s.y, s.z});
  if (!(side > 0))
    throw Error(opt.axis >= 0 ? std::string("the shape has no extent along ") + "xyz"[opt.axis] + " to scale"
                              : "the shape has no extent to scale");
  return opt.size / side;
}

Mesh scaled_by(Mesh m, double k) {
  for (Vec3& p : m.points) p = k * p;
  scale_length_fields(m.point_fields, k);
  scale_length_fields(m.face_fields, k);
  if (!m.finite()) throw Error("scaling by " + number_text(k) + " overflows");
  return m;
}

Polyline scaled_by(Polyline c, double k) { return scaled_curve(std::move(c), k); }
Polyline3 scaled_by(Polyline3 c, double k) { return scaled_curve(std::move(c), k); }

std::string size_text(Vec3 s) {
  return short_number(s.x) + " x " + short_number(s.y) + " x " + short_number(s.z) + " mm";
}

}  // namespace selfsim::print
