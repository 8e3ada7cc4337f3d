#include "kernels/print/grid_tube.h"

#include <cmath>
#include <numbers>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/print/grid_thicken.h"

namespace selfsim::print {

namespace {

Vec3 lifted(Vec2 p) { return {p.x, p.y, 0}; }
Vec3 lifted(Vec3 p) { return p; }

// Each segment of length > 0 as a triangle (a, b, b) with three points of its own: the mesh checks refuse a
// triangle naming one point twice, not two points in one place.
template <class V>
Mesh segments_of(const PolylineT<V>& c, double& length) {
  Mesh m;
  length = 0;
  std::size_t begin = 0;
  for (std::size_t end : c.path_ends) {
    for (std::size_t i = begin; i + 1 < end; ++i) {
      const Vec3 a = lifted(c.points[i]), b = lifted(c.points[i + 1]);
      const double l = norm(b - a);
      if (!(l > 0)) continue;
      length += l;
      const auto n = static_cast<std::uint32_t>(m.points.size());
      m.points.insert(m.points.end(), {a, b, b});
      m.triangles.push_back({n, n + 1, n + 2});
    }
    begin = end;
  }
  return m;
}

template <class V>
Mesh tube_on_grid(const PolylineT<V>& c, const GridTubeOptions& opt, Progress& progress) {
  opt.validate();
  double length = 0;
  const Mesh segments_mesh = segments_of(c, length);
  if (segments_mesh.triangles.empty()) throw Error("the curve has no segment of non-zero length to make a tube of");
  GridThickenOptions grid{
      .thickness = 2 * opt.radius, .voxel = opt.voxel_size(), .adaptivity = opt.adaptivity, .budget = opt.budget};
  // The budget as a sheet of this area: its band (both sides, radius + 2 voxels deep) holds at least the
  // capsules' voxels, its two meshed sheets at least their surface (2 pi r L, and a whole ball, 4 pi r²,
  // for each segment: many short segments apart are that many balls). Predicted high rather than low:
  // segments that overlap make less.
  const double reach = opt.radius + 2 * grid.voxel;
  const double segments = static_cast<double>(segments_mesh.triangles.size());
  grid.area = std::numbers::pi * reach * length + 4 * std::numbers::pi * reach * reach * segments;
  return thicken_on_grid(segments_mesh, grid, progress);
}

}  // namespace

void GridTubeOptions::validate() const {
  if (!(radius > 0) || !std::isfinite(radius))
    throw Error("option 'radius' must be a positive length (mm), got " + number_text(radius));
  if (voxel != 0 && (!(voxel > 0) || !std::isfinite(voxel) || voxel > radius))
    throw Error("option 'voxel' must be a positive length no larger than the radius " + number_text(radius) + ", got " +
                number_text(voxel));
  check_between(adaptivity, 0, 1, "option 'adaptivity'");
}

Mesh grid_tube(const Polyline3& c, const GridTubeOptions& opt, Progress& progress) {
  return tube_on_grid(c, opt, progress);
}
Mesh grid_tube(const Polyline& c, const GridTubeOptions& opt, Progress& progress) {
  return tube_on_grid(c, opt, progress);
}

}  // namespace selfsim::print
