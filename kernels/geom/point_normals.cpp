#include "kernels/geom/point_normals.h"

namespace selfsim {

std::vector<Vec3> area_normals(const Mesh& m, Progress& progress) {
  std::vector<Vec3> normal(m.points.size(), Vec3{});
  for (std::size_t f = 0; f < m.faces(); ++f) {
    if ((f & 0xffff) == 0xffff && progress.cancelled()) throw Cancelled();
    const Vec3 a = area_normal(m, m.triangles[f]);
    for (std::uint32_t v : m.triangles[f]) normal[v] += a;
  }
  return normal;
}

}  // namespace selfsim
