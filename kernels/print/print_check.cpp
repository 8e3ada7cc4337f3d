#include "kernels/print/print_check.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include "kernels/base/count_text.h"
#include "kernels/base/error.h"
#include "kernels/geom/point_text.h"
#include "kernels/geom/triangle_bvh.h"
#include "kernels/print/print_samples.h"
#include "kernels/print/print_size.h"
#include "kernels/print/thin_patches.h"
#include "kernels/print/wall_rays.h"
#include "kernels/region/volume.h"
#include "kernels/region/wall_grid.h"

namespace selfsim::print {

namespace {

// The solid's closed shells (its pieces joined across edges): each face's, and each shell's enclosed volume
// and box.
struct Shells {
  std::vector<std::uint32_t> of_face;
  std::vector<double> volume;
  std::vector<BBox3> box;
};

Shells shells_of(const Mesh& m, Progress& progress) {
  Shells s;
  s.of_face = face_components(m, progress);
  const BBox3 b = m.bbox();
  const Vec3 o = 0.5 * (b.min + b.max);
  for (std::size_t f = 0; f < m.faces(); ++f) {
    const std::uint32_t k = s.of_face[f];
    if (k >= s.volume.size()) {
      s.volume.resize(k + 1, 0);
      s.box.resize(k + 1);
    }
    s.volume[k] += volume_term(m, m.triangles[f], o);
    for (std::uint32_t v : m.triangles[f]) s.box[k].add(m.points[v]);
  }
  return s;
}

// Faces of closed shells that face inwards inside the solid: a sealed cavity's walls (their enclosed volume
// is negative). The distance grid reads a cavity as empty (winding_sign.h), so a ray from a cavity's wall
// would read its width as a gap. Those gaps are not measured (the cavity is empty space a printer walls in,
// not a gap that fuses).
std::vector<char> cavity_faces(const Mesh& m, const Shells& shells) {
  std::vector<char> cavity(m.faces());
  for (std::size_t f = 0; f < m.faces(); ++f) cavity[f] = shells.volume[shells.of_face[f]] < 0;
  return cavity;
}

// Shells that may lie partly inside another: all when the solid crosses itself, else those whose box
// meets another solid (not cavity) shell's box. Their points are tested before they are measured
// (ExactRays::may_be_buried); a solid of one shell that does not cross itself tests none.
std::vector<char> overlapping_shells(const Shells& shells, bool crosses) {
  const std::size_t n = shells.volume.size();
  std::vector<char> out(n, crosses ? 1 : 0);
  if (crosses || n < 2) return out;
  // Sorted by the boxes' lowest x, each box is compared with those that start before it ends.
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t k = 0; k < n; ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return shells.box[a].min.x < shells.box[b].min.x; });
  const auto meet = [](const BBox3& a, const BBox3& b) {
    return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y && a.min.z <= b.max.z &&
           b.min.z <= a.max.z;
  };
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n && shells.box[order[j]].min.x <= shells.box[order[i]].max.x; ++j) {
      const std::uint32_t a = order[i], b = order[j];
      if (!meet(shells.box[a], shells.box[b])) continue;
      if (shells.volume[b] > 0) out[a] = 1;
      if (shells.volume[a] > 0) out[b] = 1;
    }
  return out;
}

// A point's values: the area-weighted means of its triangles' (for ParaView's point colouring), of the walls
// and the gaps in one pass (each face's area worked out once).
std::array<std::vector<double>, 2> at_points(const Mesh& m, const std::vector<double>& wall,
                                             const std::vector<double>& gap) {
  std::vector<double> w(m.points.size(), 0), g(m.points.size(), 0), weight(m.points.size(), 0);
  for (std::size_t f = 0; f < m.faces(); ++f) {
    const double area = norm(area_normal(m, m.triangles[f]));
    for (std::uint32_t v : m.triangles[f]) {
      w[v] += area * wall[f];
      g[v] += area * gap[f];
      weight[v] += area;
    }
  }
  for (std::size_t i = 0; i < w.size(); ++i) {
    w[i] = weight[i] > 0 ? w[i] / weight[i] : 0;
    g[i] = weight[i] > 0 ? g[i] / weight[i] : 0;
  }
  return {std::move(w), std::move(g)};
}

// The smallest value under `threshold`, where, how many triangles (and how much of their area) are under it,
// and the places they make (thin_patches.h): the speck rule judges each place by its own area.
Spot spot_of(const Mesh& m, const Samples& s, const std::vector<double>& values, double threshold) {
  Spot spot;
  spot.measured = true;
  spot.value = std::numeric_limits<double>::infinity();
  std::vector<char> flagged(m.faces(), 0);
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] < threshold) {
      spot.area_under += s.area[i];
      spot.under += !flagged[s.face[i]];
      flagged[s.face[i]] = 1;
    }
    if (values[i] < spot.value) {
      spot.value = values[i];
      spot.where = s.points[i];
    }
  }
  if (spot.under > 0) {
    const Patches p = thin_patches(m, flagged);
    spot.places = p.count;
    spot.largest_place = p.largest;
  }
  return spot;
}

// Each triangle's value: the least of its points' (a thin strip along one edge of a coarse face shows); the
// cap on one with no point kept (all beside a sharp edge: nothing measured there).
std::vector<double> at_faces(const Mesh& m, const Samples& s, const std::vector<double>& values, double cap) {
  std::vector<double> out(m.faces(), cap);
  std::vector<char> seen(m.faces(), 0);
  for (std::size_t i = 0; i < values.size(); ++i) {
    out[s.face[i]] = seen[s.face[i]] ? std::min(out[s.face[i]], values[i]) : values[i];
    seen[s.face[i]] = 1;
  }
  return out;
}

// How many points to measure at, and where (r.spacing apart, set here), with `held` budget points already
// taken by what measures them. Points every `spacing` on each triangle: the nozzle's width, or a voxel if
// wider (a thin spot that fits between points is under about the nozzle's spot, no finding), sparser when
// that would be more points than the budget allows (each point and its rays' readings hold about 80 bytes,
// five budget points) or 2 million (the triangle budget: the time a slicer's finest mesh takes): the
// summary then says how sparse. A mesh gets at least a point on every triangle, as many as it already holds.
SamplePlan plan_points(const Mesh& m, double held, const PointBudget& budget, Progress& progress, PrintReport& r) {
  const double most = std::max(static_cast<double>(m.faces()), std::min(2e6, 0.2 * (budget.left() - held)));
  SamplePlan plan = plan_samples(m, std::max(r.voxel, r.rules.nozzle), r.area, most, progress);
  r.spacing = plan.spacing;
  return plan;
}

// The walls and gaps on the distance grid of m (its parts as OpenVDB meshes them into one level set), at the
// voxel the rules ask for: walls and gaps read within its interpolation error.
bool measure_on_grid(const Mesh& m, const PointBudget& budget, Progress& progress, PrintReport& r, Samples& s,
                     std::vector<double>& wall, std::vector<double>& gap) {
  r.voxel = r.rules.voxel;
  Volume v;
  v.kind = Volume::Kind::mesh;
  // m itself, not a copy: the grid reads it while it is built and keeps nothing of it (an owner-less
  // shared_ptr, which m outlives).
  v.mesh = std::shared_ptr<const Mesh>(std::shared_ptr<const Mesh>{}, &m);
  v.bounds = m.bbox();
  // The rays need the distance only near the surfaces they cross, and its sign everywhere: the grid's
  // narrowest band (two voxels each side). Deeper in a wall (or a gap) they read the band's edge and leap by
  // it, a voxel at a time. A wider band took three quarters of the check's time and changed no result.
  const double depth = 0, outside = 0;
  // OpenVDB's frames hold 2^20 voxels across (grid_frame.h); a solid wider than that (150 m at 0.13 mm) is
  // no print, and the report says so rather than failing.
  const Vec3 extent = m.bbox().size();
  const double across = std::max({extent.x, extent.y, extent.z}) / r.voxel;
  if (!(across + 64 < 1048576.0)) {
    r.skipped = "walls and gaps not measured: the solid is " + count_text(across) + " voxels of " + mm_text(r.voxel) +
                " across, more than a distance grid holds (sizes are millimetres)";
    return false;
  }
  const double size = WallGrid::size(v, r.voxel, depth, outside);
  if (size > budget.left()) {
    r.skipped = "walls and gaps not measured: the distance grid at a " + mm_text(r.voxel) + " voxel would take " +
                count_text(size) + " points' worth of memory, over the limit (a larger voxel: solid.check's " +
                "'voxel', info --print's --voxel; or a larger --max-points)";
    return false;
  }
  const SamplePlan plan = plan_points(m, size, budget, progress, r);
  ProgressStage build(progress, 0.3, 0.7);
  const WallGrid grid(v, r.voxel, depth, budget, build, outside);
  r.error = grid.error();
  s = samples_of(m, r.inward, plan);
  clear_of_edges(m, s, r.voxel);
  wall.resize(s.points.size());
  gap.resize(s.points.size());
  ProgressStage rays(progress, 0.7, 1);
  measure_rays(
      s.points, s.normals, [&](std::span<const Vec3> p, std::span<double> out) { grid.clearances(p, out); },
      {.step = r.voxel / 2, .wall_cap = r.wall_cap, .gap_cap = r.gap_cap}, wall, gap, rays);
  return true;
}

// The walls and gaps by exact rays against m's triangles (a TriangleBvh): no grid, no interpolation error
// (r.error stays 0); r.voxel is the rays' rounding width (a ten-billionth of the solid's size: crossings
// closer than that are one, and none is counted nearer than that to a ray's start), the finest reading they
// resolve. No point is left out beside a sharp edge: a ray from beside one runs along the face beyond it
// without crossing it, exactly.
bool measure_exactly(const Mesh& m, const Shells& shells, const PointBudget& budget, Progress& progress, PrintReport& r,
                     Samples& s, std::vector<double>& wall, std::vector<double>& gap) {
  const Vec3 extent = r.box.size();
  r.voxel = 1e-10 * std::max({extent.x, extent.y, extent.z});
  const double size = TriangleBvh::size(m.faces());
  if (size > budget.left()) {
    r.skipped = "walls and gaps not measured: the triangles' search tree would take " + count_text(size) +
                " points' worth of memory, over the limit (a larger --max-points)";
    return false;
  }
  const SamplePlan plan = plan_points(m, size, budget, progress, r);
  ProgressStage build(progress, 0.3, 0.4);
  const TriangleBvh bvh(m, build);
  s = samples_of(m, r.inward, plan);
  wall.resize(s.points.size());
  gap.resize(s.points.size());
  ExactRays how{.bvh = &bvh, .faces = s.face, .tmin = r.voxel, .orientation = r.inward ? -1.0 : 1.0};
  const std::vector<char> overlapping = overlapping_shells(shells, r.crossing.has_value());
  std::vector<char> buried;
  if (std::find(overlapping.begin(), overlapping.end(), 1) != overlapping.end()) {
    buried.resize(s.points.size());
    for (std::size_t i = 0; i < buried.size(); ++i) buried[i] = overlapping[shells.of_face[s.face[i]]];
    how.may_be_buried = buried;
    how.far = 2 * norm(extent) + 1;
  }
  ProgressStage rays(progress, 0.4, 1);
  measure_rays_exact(s.points, s.normals, how, {.step = 1, .wall_cap = r.wall_cap, .gap_cap = r.gap_cap}, wall, gap,
                     rays);
  return true;
}

// The walls and gaps: exactly, or on a distance grid when the rules give a voxel.
void measure(const Mesh& m, const PointBudget& budget, Progress& progress, PrintReport& r, Mesh* marked) {
  r.wall_cap = 1.5 * r.rules.min_wall;
  r.gap_cap = 1.5 * r.rules.min_gap;
  Samples s;
  std::vector<double> wall, gap;
  const Shells shells = shells_of(m, progress);
  const bool measured = r.rules.voxel > 0 ? measure_on_grid(m, budget, progress, r, s, wall, gap)
                                          : measure_exactly(m, shells, budget, progress, r, s, wall, gap);
  if (!measured) return;
  if (!r.inward) {
    const std::vector<char> cavity = cavity_faces(m, shells);
    for (std::size_t i = 0; i < gap.size(); ++i)
      if (cavity[s.face[i]]) gap[i] = r.gap_cap;
  }
  r.wall = spot_of(m, s, wall, r.rules.min_wall);
  r.gap = spot_of(m, s, gap, r.rules.min_gap);
  if (marked == nullptr) return;
  std::vector<double> face_wall = at_faces(m, s, wall, r.wall_cap), face_gap = at_faces(m, s, gap, r.gap_cap);
  *marked = m;
  auto [point_wall, point_gap] = at_points(m, face_wall, face_gap);
  marked->point_fields.set(real_field("wall", std::move(point_wall)));
  marked->point_fields.set(real_field("gap", std::move(point_gap)));
  marked->face_fields.set(real_field("wall", std::move(face_wall)));
  marked->face_fields.set(real_field("gap", std::move(face_gap)));
}

}  // namespace

PrintReport check_print(const Mesh& m, const PrintRules& rules, const PointBudget& budget, Progress& progress,
                        Mesh* marked) {
  rules.validate();
  m.validate();
  if (m.triangles.empty()) throw Error("the mesh has no triangles: nothing to print");
  progress.start("print check");
  PrintReport r;
  r.rules = rules;
  r.triangles = m.faces();
  r.area = surface_area(m);
  r.box = corner_bbox(m);  // the solid's size: the points its triangles use
  r.topology = mesh_topology(m, progress);
  if (r.topology.boundary_edges > 0)
    throw Error("the mesh is open (" + first_open_edge(m) +
                "): a print needs a closed solid; thicken the surface first (solid.thicken)");
  r.volume = enclosed_volume(m);
  r.inward = r.volume < 0;
  progress.fraction(0.1);
  ProgressStage crossing(progress, 0.1, 0.3);
  survey_contact(m, r, crossing);  // crossings, creases, specks (print_survey.cpp)
  // A mesh that is no 2-manifold (edges of three faces or more: a triangle repeated, solids stacked on one
  // another) has no inside for a ray to cross (every ray would count each copy) and will fail anyway.
  if (r.topology.manifold()) {
    measure(m, budget, progress, r, marked);
  } else {
    r.skipped = "walls and gaps not measured: not a 2-manifold";
  }
  if (marked != nullptr && r.skipped.size() > 0) *marked = m;
  add_overhang(m, r, marked);
  add_findings(r);
  progress.fraction(1);
  return r;
}

}  // namespace selfsim::print
