// The first layer: what the solid stands on. A slicer cuts its first layer through the middle of the lowest
// `layer` mm; a solid that stands on a point or a knife edge has little or nothing there, and PrusaSlicer then
// stops ("no extrusions in the first layer"). Measured as the area of the solid's cross-section at that
// height, from the triangles the plane cuts: each cut segment, directed so that the solid's inside is on
// its left (its triangle's outward normal on its right), adds its shoelace term, so the area is exact for
// any closed mesh facing outwards, holes and separate feet included.
#pragma once

#include "kernels/geom/mesh.h"

namespace selfsim::print {

// mm² of m's cross-section at its lowest z plus half of `layer` (mm), for a closed mesh facing either way.
double first_layer_area(const Mesh& m, double layer);

}  // namespace selfsim::print
