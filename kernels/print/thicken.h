// Thickening a surface into a solid (seed 002 §3.2, last paragraph): every point offset along its normal by
// half its thickness to each side, the two sheets joined along the boundary by a rim of quads, into a
// closed, consistently oriented 2-manifold a slicer can print. A disk becomes a sphere (Euler
// characteristic 2), an annulus a torus (0).
#pragma once

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"

namespace selfsim::print {

// m, a manifold surface with a point field `thickness` (> 0 everywhere), thickened. Normals are the
// area-weighted average of the faces around a point. Points: 2V (the top sheet first, at +n·t/2, then the
// bottom one); faces: 2F + 2·(boundary edges): the top sheet as m, the bottom reversed, the rim outwards.
// Every field is carried to both sheets (and to the rim from its face). Throws Error if m is not a manifold,
// lacks a positive finite thickness, or has a point whose faces' normals cancel.
Mesh thicken(const Mesh& m, Progress& progress);

}  // namespace selfsim::print
