#include "kernels/print/grid_tube.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "kernels/base/check.h"
#include "kernels/base/count_text.h"
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

// How many pieces a segment of length l is cut into: none longer than twice its larger radius and 16 voxels
// (a long slanted segment's box would hold many blocks of voxels far from it, and the pieces are the same
// solid, round_cone.h), and at most a million.
double pieces_of(double l, double ra, double rb, double voxel) {
  return std::min(1e6, std::ceil(l / std::max(2 * std::max(ra, rb), 16 * voxel)));
}

template <class V>
void check_radii_of(const PolylineT<V>& c, std::span<const double> radii) {
  if (radii.size() != c.points.size())
    throw Error("the tube has " + std::to_string(radii.size()) + " radii for " + std::to_string(c.points.size()) +
                " points");
}

// Calls visit(a, b, ra, rb) for each segment of c of length > 0.
template <class V, class Visit>
void each_segment(const PolylineT<V>& c, std::span<const double> radii, Visit&& visit) {
  check_radii_of(c, radii);
  std::size_t begin = 0;
  for (std::size_t end : c.path_ends) {
    for (std::size_t i = begin; i + 1 < end; ++i) {
      const Vec3 a = lifted(c.points[i]), b = lifted(c.points[i + 1]);
      if (norm(b - a) > 0) visit(a, b, radii[i], radii[i + 1]);
    }
    begin = end;
  }
}

// Budget points the pieces take before round_tube_size has counted them: the list of cones and the two
// corners of each that the size estimate gathers.
constexpr double piece_points = static_cast<double>(sizeof(RoundSegment) + 2 * sizeof(Vec3)) / 16;

// The number of round cones cones_of makes at `voxel`, counted without making them.
template <class V>
double count_cones(const PolylineT<V>& c, std::span<const double> radii, double voxel) {
  double n = 0;
  each_segment(c, radii, [&](Vec3 a, Vec3 b, double ra, double rb) { n += pieces_of(norm(b - a), ra, rb, voxel); });
  return n;
}

// Throws BudgetError, before they are made, when the cones at `voxel` would not fit the budget.
template <class V>
void check_cones(const PolylineT<V>& c, std::span<const double> radii, double voxel, const PointBudget& budget) {
  const double n = count_cones(c, radii, voxel);
  check_budget(n * piece_points, budget,
               "a tube on a grid at voxel size " + voxel_text(voxel) + " (its " + count_text(n) +
                   " round cones; set a larger 'voxel')");
}

// The round cones of c's segments of length > 0, each cut into pieces_of pieces.
template <class V>
std::vector<RoundSegment> cones_of(const PolylineT<V>& c, std::span<const double> radii, double voxel) {
  std::vector<RoundSegment> out;
  out.reserve(static_cast<std::size_t>(count_cones(c, radii, voxel)));
  each_segment(c, radii, [&](Vec3 a, Vec3 b, double ra, double rb) {
    const auto pieces = static_cast<std::size_t>(pieces_of(norm(b - a), ra, rb, voxel));
    for (std::size_t k = 0; k < pieces; ++k) {
      const double t0 = static_cast<double>(k) / static_cast<double>(pieces);
      const double t1 = static_cast<double>(k + 1) / static_cast<double>(pieces);
      out.push_back({a + t0 * (b - a), a + t1 * (b - a), ra + t0 * (rb - ra), ra + t1 * (rb - ra)});
    }
  });
  if (out.empty()) throw Error("the curve has no segment of non-zero length to make a tube of");
  return out;
}

void check_radii(std::span<const double> radii) {
  for (std::size_t i = 0; i < radii.size(); ++i)
    if (!(radii[i] > 0) || !std::isfinite(radii[i]))
      throw Error("the radius at point " + std::to_string(i + 1) + " is " + number_text(radii[i]) +
                  ": it must be positive");
}

// The voxel a tube of these radii is built at, and its cones when they were made on the way (empty when not).
struct Choice {
  double voxel = 0;
  std::vector<RoundSegment> cones;
};

template <class V>
Choice choose_voxel(const PolylineT<V>& c, std::span<const double> radii, const GridTubeOptions& opt) {
  check_radii(radii);
  if (radii.empty()) throw Error("the curve has no points to make a tube of");
  check_radii_of(c, radii);
  const auto [thinnest, thickest] = std::minmax_element(radii.begin(), radii.end());
  check_between(opt.adaptivity, 0, 1, "option 'adaptivity'");
  if (opt.voxel != 0) {
    if (!(opt.voxel > 0) || !std::isfinite(opt.voxel) || opt.voxel > *thinnest / 2)
      throw Error("option 'voxel' must be a positive length at most half the thinnest radius (" +
                  voxel_text(*thinnest / 2) + "), got " + number_text(opt.voxel) +
                  ": a coarser grid makes the tube thinner");
    return {opt.voxel, {}};
  }
  // Coarser while over the budget, down to a quarter of the largest radius: the thickest part still round.
  // The cones are counted before they are made, and made once for each voxel tried: a long thin curve at a
  // fine voxel is millions of them.
  double voxel = *thinnest / 4;
  for (;; voxel *= 1.25) {
    const bool last = voxel * 1.25 > *thickest / 4;
    if (count_cones(c, radii, voxel) * piece_points > opt.budget.left()) {
      if (last) return {voxel, {}};  // the build refuses them
      continue;
    }
    std::vector<RoundSegment> cones = cones_of(c, radii, voxel);
    if (last || round_tube_size(cones, voxel) <= opt.budget.left()) return {voxel, std::move(cones)};
  }
}

template <class V>
Mesh tube_on_grid(const PolylineT<V>& c, std::span<const double> radii, const GridTubeOptions& opt,
                  Progress& progress) {
  check_radii(radii);
  if (!radii.empty() && std::all_of(radii.begin(), radii.end(), [&](double r) { return r == radii[0]; })) {
    GridTubeOptions one = opt;
    one.radius = radii[0];
    return tube_on_grid(c, one, progress);  // one radius: capsules, as before
  }
  Choice choice = choose_voxel(c, radii, opt);
  GridTubeOptions cones = opt;
  cones.voxel = choice.voxel;
  if (choice.cones.empty()) {
    check_cones(c, radii, choice.voxel, opt.budget);
    choice.cones = cones_of(c, radii, choice.voxel);
  }
  return round_tube_on_grid(choice.cones, cones, progress);
}

}  // namespace

void GridTubeOptions::validate() const {
  if (!(radius > 0) || !std::isfinite(radius))
    throw Error("option 'radius' must be a positive length (mm), got " + number_text(radius));
  // Coarser, the mesher cuts the round wall short: radius 1 at voxel 1 came out 0.5 across the axis.
  if (voxel != 0 && (!(voxel > 0) || !std::isfinite(voxel) || voxel > radius / 2))
    throw Error("option 'voxel' must be a positive length at most half the radius (" + voxel_text(radius / 2) +
                "), got " + number_text(voxel) + ": a coarser grid makes the tube thinner");
  check_between(adaptivity, 0, 1, "option 'adaptivity'");
}

Mesh grid_tube(const Polyline3& c, const GridTubeOptions& opt, Progress& progress) {
  return tube_on_grid(c, opt, progress);
}
Mesh grid_tube(const Polyline& c, const GridTubeOptions& opt, Progress& progress) {
  return tube_on_grid(c, opt, progress);
}

Mesh grid_tube(const Polyline3& c, std::span<const double> radii, const GridTubeOptions& opt, Progress& progress) {
  return tube_on_grid(c, radii, opt, progress);
}
Mesh grid_tube(const Polyline& c, std::span<const double> radii, const GridTubeOptions& opt, Progress& progress) {
  return tube_on_grid(c, radii, opt, progress);
}

double grid_tube_voxel(const Polyline3& c, std::span<const double> radii, const GridTubeOptions& opt) {
  return choose_voxel(c, radii, opt).voxel;
}
double grid_tube_voxel(const Polyline& c, std::span<const double> radii, const GridTubeOptions& opt) {
  return choose_voxel(c, radii, opt).voxel;
}

}  // namespace selfsim::print
