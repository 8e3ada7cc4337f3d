// The print check's survey besides walls and gaps (print_check.h): where the surface meets itself, told
// apart by what a slicer makes of it (self_contact.h), the overhang (overhang.h) with its field, and what it
// stands on (first_layer.h).
#include <algorithm>
#include <cmath>

#include "kernels/geom/point_text.h"
#include "kernels/print/first_layer.h"
#include "kernels/print/overhang.h"
#include "kernels/print/print_check.h"

namespace selfsim::print {

void survey_contact(const Mesh& m, PrintReport& r, Progress& progress) {
  r.contact = self_contact(m, r.rules.nozzle, progress);
  // Any crossing that counts: one through itself (will fail) or between solids (an overlap, may fail). Either
  // may bury points of one part in another, which the walls' rays then test (print_check.cpp).
  r.crossing = r.contact.crossing ? r.contact.crossing : r.contact.overlap;
}

void add_overhang(const Mesh& m, PrintReport& r, Mesh* marked) {
  const Overhang o = overhang_of(m, {.angle = r.rules.overhang}, marked != nullptr);
  r.overhang = o.area;
  r.overhang_where = o.where;
  // The first layer is about half the nozzle's width high (0.2 mm for 0.4 mm).
  r.first_layer = first_layer_area(m, 0.5 * r.rules.nozzle);
  if (marked == nullptr) return;
  // A point's angle: the steepest of its faces' (a point on a ceiling's rim is on the ceiling).
  std::vector<double> at_points(m.points.size(), 0);
  for (std::size_t f = 0; f < m.faces(); ++f)
    for (std::uint32_t v : m.triangles[f]) at_points[v] = std::max(at_points[v], o.angle[f]);
  marked->point_fields.set(real_field("overhang", std::move(at_points)));
  marked->face_fields.set(real_field("overhang", o.angle));
}

void flag_model_box(PrintReport& r, const std::vector<BBox3>& boxes) {
  const auto longest = [](Vec3 s) { return std::max({s.x, s.y, s.z}); };
  const double side = longest(r.box.size());
  if (side < 5) return;  // said already (under 5 mm)
  for (const BBox3& b : boxes) {
    const double unit = longest(b.size());
    const bool whole = unit >= 1 && unit <= 10 && std::abs(unit - std::round(unit)) <= 1e-9 * unit;
    // As large as the box, or a little larger: a surface filling it thickened, a curve in it as a tube.
    if (!whole || side < (1 - 1e-3) * unit || side > 1.2 * unit) continue;
    add_problem(r, Severity::may_fail,
                "it is " + mm_text(side) + " across, the size of a box the recipe grew it in (" + short_number(unit) +
                    " units): probably still in model units (sizes are mm)",
                "solid.size(s, 80)");
    return;
  }
}

}  // namespace selfsim::print
