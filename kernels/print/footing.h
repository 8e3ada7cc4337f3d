// Whether a solid standing on the bed stays standing: its centre of mass above what touches the bed. A
// tilted plate resting on a rim point touches the bed with a patch of a square millimetre far to one side
// of its centre; it stands only while the first layer's grip holds it against its weight's lever, so
// solid.orient{ least = "overhang" } prefers poses that stand by themselves (orient.h).
#pragma once

#include "kernels/geom/mesh.h"

namespace selfsim::print {

// The centre of the volume a closed mesh encloses (either facing); for an open or flat one (no volume) the
// centre of corner_bbox.
Vec3 mass_centre(const Mesh& m);

// Whether `centre`, seen from above, lies within `margin` (mm) of the convex hull of m's triangle corners
// within `contact` (mm) of its lowest corner: the footprint it stands on, with +z up.
bool centre_over_footprint(const Mesh& m, Vec3 centre, double contact, double margin);

}  // namespace selfsim::print
