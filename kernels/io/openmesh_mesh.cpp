#include "kernels/io/openmesh_mesh.h"

#include <OpenMesh/Core/System/omstream.hh>
#include <iostream>
#include <string>

#include "kernels/geom/error.h"

namespace selfsim::io {

void quiet_openmesh(std::ostream* complaints) {
  static bool done = false;
  if (!done) {
    omlog().disable();
    omout().disable();
    omerr().disconnect(std::cerr);
    done = true;
  }
  if (complaints != nullptr)
    omerr().connect(*complaints);
  else
    omerr().disable();
}

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

Mesh from_openmesh(const OMesh& om) {
  Mesh m;
  m.points.reserve(om.n_vertices());
  for (const auto& vh : om.vertices()) {
    const OMesh::Point& p = om.point(vh);
    m.points.push_back({p[0], p[1], p[2]});
  }
  m.triangles.reserve(om.n_faces());
  for (const auto& fh : om.faces()) {
    Triangle t{};
    int k = 0;
    for (const auto& vh : om.fv_range(fh))
      if (k < 3) t[k++] = static_cast<std::uint32_t>(vh.idx());
    m.triangles.push_back(t);
  }
  return m;
}

}  // namespace selfsim::io
