#include "kernels/print/print_rules.h"

#include <algorithm>
#include <cmath>

#include "kernels/base/check.h"
#include "kernels/base/error.h"

namespace selfsim::print {

void PrintRules::validate() const {
  check_between(nozzle, 0.01, 100, "option 'nozzle' (mm)");
  check_between(min_wall, 0.01, 100, "option 'min_wall' (mm)");
  check_between(min_gap, 0.01, 100, "option 'min_gap' (mm)");
  check_between(overhang, 1, 89, "option 'overhang' (degrees from vertical)");
  check_between(max_triangles, 4, 1e12, "option 'triangles'");
  if (bed != Vec3{})
    for (double side : {bed.x, bed.y, bed.z})
      if (!(side >= 1 && side <= 1e5))
        throw Error("option 'bed' must be three sides in [1, 100000] (mm), got {" + number_text(bed.x) + ", " +
                    number_text(bed.y) + ", " + number_text(bed.z) + "}");
  // Coarser than half the smaller threshold, the grid cannot tell a wall of that size from none.
  if (voxel != 0) check_between(voxel, 1e-3, std::min(min_wall, min_gap) / 2, "option 'voxel' (mm)");
}

PrintRules PrintRules::named(std::string_view profile) {
  PrintRules r;
  if (profile == "fdm") return r;
  if (profile == "sla") {
    r.profile = "sla";
    r.nozzle = 0.15;
    r.min_wall = 0.4;
    r.min_gap = 0.5;
    return r;
  }
  throw Error("unknown printer profile '" + std::string(profile) + "', expected one of: 'fdm', 'sla'");
}

std::vector<std::string> PrintRules::profiles() { return {"fdm", "sla"}; }

}  // namespace selfsim::print
