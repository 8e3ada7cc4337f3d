// The principal axes of a surface: the eigenvectors of the covariance of its triangles' centres, weighted
// by their areas. A flat piece with no flat face of its own (a plant's tubes laid in a plane) lies across
// its thinnest one (solid.orient). By Jacobi rotations (a 3 x 3 symmetric matrix: a few sweeps).
#pragma once

#include <vector>

#include "kernels/geom/mesh.h"
#include "kernels/geom/vec3.h"

namespace selfsim {

// The six unit directions along the three axes, both ways; none for a mesh of no area.
std::vector<Vec3> principal_directions(const Mesh& m);

}  // namespace selfsim
