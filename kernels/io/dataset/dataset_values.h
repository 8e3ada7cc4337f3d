// A Dataset read from a file as a value a recipe can use (load()) or `selfsim info` can check: a curve
// (polyline cells) or a mesh (polygon cells, split into triangles as fans). Fields come along as float64
// fields under their names (a file's own integer types are not kept).
#pragma once

#include <variant>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"
#include "kernels/io/dataset/dataset.h"

namespace selfsim::io {

// The dataset's value: a Polyline when its cells are lines and every z is 0, a Polyline3 for lines
// otherwise, a Mesh for polygons. Throws Error for mixed cells, a polygon of fewer than 3 points, or a
// polygon using one point twice.
std::variant<Polyline, Polyline3, Mesh> dataset_value(const Dataset& d, Progress& progress = no_progress());

// The dataset's polygons as a mesh (fan triangulation; cell fields repeated on each triangle).
Mesh dataset_mesh(const Dataset& d, Progress& progress = no_progress());

}  // namespace selfsim::io
