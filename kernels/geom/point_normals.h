// Normals at a mesh's points: the sum of the area-weighted normals of the triangles around each point, the
// usual choice for offsetting (thickening) and for casting rays from a surface (the print check's walls):
// big triangles weigh more than slivers, and a point's normal follows its fan rather than any one face.
#pragma once

#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"

namespace selfsim {

// One per point of m, not normalised (twice the area-weighted sum: zero where the faces cancel, and at
// points no triangle uses). Looks for a stop every 65,536 faces.
std::vector<Vec3> area_normals(const Mesh& m, Progress& progress);

}  // namespace selfsim
