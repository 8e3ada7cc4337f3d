// The one place selfsim's Mesh meets OpenMesh's half-edge mesh (the STL/OBJ/PLY writers, and later Loop
// subdivision). Include only from .cpp files: OpenMesh headers are heavy.
#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "kernels/geom/mesh.h"

namespace selfsim::io {

struct OpenMeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;  // selfsim's coordinates are doubles; keep them
  using Normal = OpenMesh::Vec3d;
};
using OMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshTraits>;

// m as an OpenMesh mesh. OpenMesh holds only manifold meshes: throws Error naming the first triangle it
// refuses (an edge of three faces, a bowtie, a flipped neighbour) rather than dropping it.
OMesh to_openmesh(const Mesh& m);

}  // namespace selfsim::io
