// Fewer triangles for a slicer (which slows down, and may give up, past a few million): VTK's quadric
// decimation (Garland and Heckbert's edge collapses, vtkQuadricDecimation, in the VTK plugin's
// decimate.cpp), never a hand-written one. It keeps a closed mesh closed and reaches the count asked for
// on closed meshes (on open ones to within a few triangles). Fields do not survive: collapsed edges merge
// points, and VTK drops point data it cannot weigh.
#pragma once

#include <cstddef>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"

namespace selfsim::print {

// m with about `triangles` triangles. Throws Error when `triangles` is not below m's count (naming both)
// or below 4, or when a closed mesh came back open (naming the first open edge).
Mesh decimate(const Mesh& m, double triangles, Progress& progress);

}  // namespace selfsim::print
