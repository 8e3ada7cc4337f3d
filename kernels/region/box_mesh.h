// The closed surface of an axis-aligned box: 8 points, 12 triangles facing outwards. A region for the
// exclusion surface (volume.box) and a shape for tests.
#pragma once

#include "kernels/geom/mesh.h"

namespace selfsim {

inline Mesh box_mesh(Vec3 lo, Vec3 hi) {
  Mesh m;
  for (int k = 0; k < 8; ++k) m.points.push_back({k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z});
  // Each face's corners counterclockwise seen from outside, split along one diagonal.
  const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    m.triangles.push_back(
        {static_cast<std::uint32_t>(f[0]), static_cast<std::uint32_t>(f[1]), static_cast<std::uint32_t>(f[2])});
    m.triangles.push_back(
        {static_cast<std::uint32_t>(f[0]), static_cast<std::uint32_t>(f[2]), static_cast<std::uint32_t>(f[3])});
  }
  return m;
}

}  // namespace selfsim
