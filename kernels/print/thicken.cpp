#include "kernels/print/thicken.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "kernels/base/cancellable_sort.h"
#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/point_normals.h"

namespace selfsim::print {

namespace {

// The directed boundary edges u → v (as their face traverses them) of a manifold mesh, with that face.
struct RimEdge {
  std::uint32_t u, v, face;
};

std::vector<RimEdge> boundary_edges(const Mesh& m, Progress& progress) {
  struct Side {
    std::uint32_t lo, hi;
    RimEdge edge;
  };
  std::vector<Side> sides;
  sides.reserve(3 * m.faces());
  for (std::uint32_t f = 0; f < m.faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = m.triangles[f][k], v = m.triangles[f][(k + 1) % 3];
      sides.push_back({std::min(u, v), std::max(u, v), {u, v, f}});
    }
  cancellable_sort(
      sides.begin(), sides.end(),
      [](const Side& a, const Side& b) {
        return std::tie(a.lo, a.hi, a.edge.face) < std::tie(b.lo, b.hi, b.edge.face);
      },
      progress);
  std::vector<RimEdge> out;
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t j = i + 1;
    while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi) ++j;
    if (j - i == 1) out.push_back(sides[i].edge);
    i = j;
  }
  return out;
}

}  // namespace

Mesh thicken(const Mesh& m, Progress& progress) {
  progress.start("thickening");
  const MeshTopology topology = mesh_topology(m, progress);
  if (!topology.manifold()) throw Error("thickening needs a manifold surface: " + topology.first_problem);
  const Field* thickness = m.point_fields.find("thickness");
  if (thickness == nullptr || thickness->components != 1) throw Error("thickening needs a point field 'thickness'");
  const std::size_t n = m.points.size();

  // Cancellation is looked for every 65,536 points or faces.
  auto stop = [&](std::size_t i) {
    if ((i & 0xffff) == 0xffff && progress.cancelled()) throw Cancelled();
  };
  const std::vector<Vec3> normal = area_normals(m, progress);
  Mesh out;
  out.points.resize(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    stop(i);
    const double t = thickness->at(i);
    if (!(t > 0 && std::isfinite(t)))
      throw Error("the thickness at point " + std::to_string(i + 1) + " is not a positive number");
    const double length = norm(normal[i]);
    if (!(length > 0 && std::isfinite(length)))
      throw Error("point " + std::to_string(i + 1) +
                  " has no normal (its triangles cancel out): it cannot be thickened");
    const Vec3 offset = (0.5 * t / length) * normal[i];
    out.points[i] = m.points[i] + offset;
    out.points[n + i] = m.points[i] - offset;
  }
  if (progress.cancelled()) throw Cancelled();

  const auto shift = static_cast<std::uint32_t>(n);
  const auto rim = boundary_edges(m, progress);
  out.triangles.reserve(2 * m.faces() + 2 * rim.size());
  std::vector<std::uint32_t> face_source;
  face_source.reserve(out.triangles.capacity());
  for (std::uint32_t f = 0; f < m.faces(); ++f) {
    stop(f);
    out.triangles.push_back(m.triangles[f]);
    face_source.push_back(f);
  }
  for (std::uint32_t f = 0; f < m.faces(); ++f) {
    stop(f);
    const Triangle& t = m.triangles[f];
    out.triangles.push_back({t[0] + shift, t[2] + shift, t[1] + shift});  // the bottom sheet faces the other way
    face_source.push_back(f);
  }
  for (const auto& [u, v, face] : rim) {
    // The top sheet runs u → v along this edge, the bottom v' → u': the rim runs v → u on top and u' → v'
    // below, so every edge is shared by two faces in opposite directions. The rim takes its face's fields.
    out.triangles.push_back({v, u, u + shift});
    out.triangles.push_back({v, u + shift, v + shift});
    face_source.push_back(face);
    face_source.push_back(face);
  }
  std::vector<std::uint32_t> point_source(2 * n);
  for (std::uint32_t i = 0; i < n; ++i) point_source[i] = point_source[n + i] = i;
  out.point_fields = picked_fields<std::uint32_t>(m.point_fields, point_source, progress);
  out.face_fields = picked_fields<std::uint32_t>(m.face_fields, face_source, progress);
  if (!out.finite()) throw Error("thickening gave non-finite points (the thickness is too large)");
  return out;
}

}  // namespace selfsim::print
