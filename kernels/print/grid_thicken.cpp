// GridThickenOptions' checks, apart from OpenVDB (the conversion is the plugin's: grid_solid.cpp).
#include "kernels/print/grid_thicken.h"

#include "kernels/base/check.h"

namespace selfsim::print {

void GridThickenOptions::validate() const {
  if (!(thickness > 0) || !std::isfinite(thickness))
    throw Error("option 'thickness' must be a positive length (mm), got " + number_text(thickness));
  if (voxel != 0 && (!(voxel > 0) || !std::isfinite(voxel) || voxel > thickness))
    throw Error("option 'voxel' must be a positive length no larger than the thickness " + number_text(thickness) +
                ", got " + number_text(voxel));
  check_between(adaptivity, 0, 1, "option 'adaptivity'");
}

}  // namespace selfsim::print
