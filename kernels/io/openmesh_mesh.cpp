#include "kernels/io/openmesh_mesh.h"

#include <OpenMesh/Core/System/omstream.hh>
#include <string>

#include "kernels/geom/error.h"

namespace selfsim::io {

namespace {

// OpenMesh prints progress and complaints to the terminal; selfsim reports through its own messages.
void quiet_openmesh() {
  static const bool done = [] {
    omlog().disable();
    omout().disable();
    omerr().disable();
    return true;
  }();
  (void)done;
}

}  // namespace

OMesh to_openmesh(const Mesh& m) {
  quiet_openmesh();
  OMesh om;
  om.reserve(m.points.size(), 3 * m.faces() / 2 + m.points.size(), m.faces());
  std::vector<OMesh::VertexHandle> v;
  v.reserve(m.points.size());
  for (const Vec3& p : m.points) v.push_back(om.add_vertex(OMesh::Point(p.x, p.y, p.z)));
  for (std::size_t f = 0; f < m.faces(); ++f) {
    const Triangle& t = m.triangles[f];
    if (!om.add_face(v[t[0]], v[t[1]], v[t[2]]).is_valid())
      throw Error(
          "triangle " + std::to_string(f + 1) +
          " makes the mesh non-manifold (an edge of three faces, two faces meeting at a point, or a "
          "flipped neighbour): STL, OBJ and PLY are written through OpenMesh, which holds manifold meshes only");
  }
  return om;
}

}  // namespace selfsim::io
