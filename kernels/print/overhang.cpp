#include "kernels/print/overhang.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace selfsim::print {

Overhang overhang_of(const Mesh& m, const OverhangOptions& opt, bool per_face) {
  constexpr double degrees = 180 / 3.14159265358979323846;
  Overhang out;
  if (per_face) out.angle.assign(m.faces(), 0);
  double lowest = std::numeric_limits<double>::infinity();
  // The bed: the lowest of the triangles' corners (a point no triangle uses holds nothing up).
  for (const Triangle& t : m.triangles)
    for (std::uint32_t v : t) lowest = std::min(lowest, dot(m.points[v], opt.up));
  // sin of the overhang angle: a unit normal whose downward part is past it overhangs.
  const double past = std::sin(opt.angle / degrees);
  double largest = 0;
  for (std::size_t f = 0; f < m.faces(); ++f) {
    const Triangle& t = m.triangles[f];
    const Vec3 n = area_normal(m, t);
    const double twice_area = norm(n);
    if (!(twice_area > 0)) continue;
    const double down = -dot(n, opt.up) / twice_area;  // sin of the angle below horizontal
    if (!(down > 0)) continue;
    const bool on_bed = std::all_of(t.begin(), t.end(),
                                    [&](std::uint32_t v) { return dot(m.points[v], opt.up) - lowest <= opt.on_bed; });
    if (on_bed) continue;
    const double angle = std::asin(std::min(1.0, down)) * degrees;
    if (per_face) out.angle[f] = angle;
    if (!(down > past)) continue;
    const double area = 0.5 * twice_area;
    out.area += area;
    if (area > largest) {
      largest = area;
      out.where = (1.0 / 3) * (m.points[t[0]] + m.points[t[1]] + m.points[t[2]]);
    }
  }
  return out;
}

}  // namespace selfsim::print
