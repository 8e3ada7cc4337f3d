#include "kernels/print/solid_union.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "kernels/base/check.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/geom/point_text.h"
#include "kernels/geom/winding_number.h"
#include "kernels/region/level_set.h"
#include "kernels/region/volume.h"

namespace selfsim::print {

namespace {

// A copy of a closed solid facing outwards; `name` ("solid 2", "cut 1") for the error.
Mesh outward(const Mesh& m, const std::string& name, Progress& progress) {
  m.validate();
  const MeshTopology t = mesh_topology(m, progress);
  if (!t.closed()) {
    const std::string why = t.faces == 0               ? "it has no triangles"
                            : !t.first_problem.empty() ? t.first_problem
                                                       : first_open_edge(m);
    throw Error(name + " is not closed (" + why +
                "): make a surface a solid first, solid.thicken(mesh, { thickness = 1, method = \"grid\" })");
  }
  Mesh out = m;
  const double v = enclosed_volume(out);
  if (!(std::abs(v) > 0)) throw Error(name + " encloses no volume");
  if (v < 0)
    for (Triangle& tri : out.triangles) std::swap(tri[1], tri[2]);
  return out;
}

bool boxes_meet(const BBox3& a, const BBox3& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y && a.min.z <= b.max.z &&
         b.min.z <= a.max.z;
}

// The meshes' triangles and points one after the other, the fields all of them have kept.
Mesh joined(const std::vector<const Mesh*>& parts) {
  Mesh out;
  std::vector<const Fields*> point_fields, face_fields;
  std::vector<std::size_t> points, faces, skip(parts.size(), 0);
  for (const Mesh* m : parts) {
    const auto base = static_cast<std::uint32_t>(out.points.size());
    out.points.insert(out.points.end(), m->points.begin(), m->points.end());
    for (const Triangle& t : m->triangles) out.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    point_fields.push_back(&m->point_fields);
    face_fields.push_back(&m->face_fields);
    points.push_back(m->points.size());
    faces.push_back(m->triangles.size());
  }
  out.point_fields = join_fields(point_fields, points, skip, {});
  out.face_fields = join_fields(face_fields, faces, skip, {});
  return out;
}

// How two solids lie: their triangles meet (or one touches itself, which tells nothing), one inside the
// other, or apart.
enum class Lie { meet, first_touches_itself, second_touches_itself, first_inside, second_inside, apart };

// The triangles of m whose boxes reach `box`, added to `into` with the points they use.
void add_near(const Mesh& m, const BBox3& box, Mesh& into) {
  std::vector<std::uint32_t> index(m.points.size(), std::numeric_limits<std::uint32_t>::max());
  for (const Triangle& t : m.triangles) {
    BBox3 tb;
    for (int k = 0; k < 3; ++k) tb.add(m.points[t[k]]);
    if (!boxes_meet(tb, box)) continue;
    Triangle copy;
    for (int k = 0; k < 3; ++k) {
      if (index[t[k]] == std::numeric_limits<std::uint32_t>::max()) {
        index[t[k]] = static_cast<std::uint32_t>(into.points.size());
        into.points.push_back(m.points[t[k]]);
      }
      copy[k] = index[t[k]];
    }
    into.triangles.push_back(copy);
  }
}

Lie how_they_lie(const Mesh& a, const Mesh& b, Progress& progress) {
  const BBox3 ba = a.bbox(), bb = b.bbox();
  if (!boxes_meet(ba, bb)) return Lie::apart;
  // Only triangles that reach the boxes' overlap (grown by first_intersection's tolerance) can meet the other
  // solid: those of each, in one mesh, a's first. A solid touching itself elsewhere tells nothing here.
  BBox3 all = ba;
  all.add(bb);
  const double d = 1e-9 * norm(all.size());
  const BBox3 overlap{max_each(ba.min, bb.min) - Vec3::all(d), min_each(ba.max, bb.max) + Vec3::all(d)};
  Mesh both;
  add_near(a, overlap, both);
  const auto base = static_cast<std::uint32_t>(both.triangles.size());  // triangles, as the pair counts them
  add_near(b, overlap, both);
  if (const auto pair = first_intersection(both, progress)) {
    if (pair->second < base) return Lie::first_touches_itself;
    return pair->first >= base ? Lie::second_touches_itself : Lie::meet;
  }
  // Not meeting, each lies wholly on one side of the other's surface: one point of it tells which.
  if (winding_number(b, a.points[a.triangles[0][0]]) > 0.5) return Lie::first_inside;
  if (winding_number(a, b.points[b.triangles[0][0]]) > 0.5) return Lie::second_inside;
  return Lie::apart;
}

// Why two solids (named) need the grid, or empty when they do not.
std::string grid_reason(Lie lie, const std::string& first, const std::string& second) {
  if (lie == Lie::meet) return first + " and " + second + " meet";
  if (lie == Lie::first_touches_itself) return first + " touches itself";
  if (lie == Lie::second_touches_itself) return second + " touches itself";
  return "";
}

// Why the grid must take the parts, "solid 2 touches itself" (named by `name(i)`), or empty: an exact result
// keeps each part as it is, crossings and all. Only the parts `tested` says; whole meshes, O(F), with
// first_intersection's index over one solid at a time (union_work_size counts it).
template <class Name>
std::string touching_itself(const std::vector<Mesh>& parts, const std::vector<bool>& tested, Name&& name,
                            Progress& progress) {
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (tested[i] && first_intersection(parts[i], progress)) return name(i) + " touches itself";
  return "";
}

// Throws Error when a given voxel is over a quarter of the thinnest side of any solid's box: the grid would
// lose or move solids that thin (two 10 mm cubes on a 10 mm grid made one).
void check_voxel(double voxel, std::span<const Mesh* const> solids) {
  if (voxel == 0) return;
  double thinnest = std::numeric_limits<double>::infinity();
  for (const Mesh* m : solids) {
    const Vec3 s = m->bbox().size();
    thinnest = std::min({thinnest, s.x, s.y, s.z});
  }
  const auto text = [](double v) { return v >= 0.01 ? mm_text(v) : short_number(v, 2) + " mm"; };
  if (!(voxel > 0) || !std::isfinite(voxel) || voxel > thinnest / 4)
    throw Error("option 'voxel' must be a positive length at most a quarter of the thinnest side of any solid's box (" +
                text(thinnest / 4) + " of " + text(thinnest) + "), got " + number_text(voxel) +
                ": a coarser grid loses or moves solids");
}

// Budget points a mesh holds (16 bytes each): its points and triangles, as the run counts a mesh value.
double mesh_points(const Mesh& m) { return static_cast<double>(m.points.size() + m.triangles.size()); }

// The parts (moved in, not copied again) on a grid. The grid's prediction is checked against the budget
// less the parts, which are held while it is built.
UnionResult on_grid(Volume::Kind kind, std::vector<Mesh> parts, const UnionOptions& opt, const std::string& why,
                    Progress& progress) {
  std::vector<const Mesh*> p;
  for (const Mesh& m : parts) p.push_back(&m);
  const double voxel = opt.voxel > 0 ? opt.voxel : union_voxel(p);
  PointBudget budget = opt.budget;
  std::vector<std::shared_ptr<const Volume>> volumes;
  for (Mesh& m : parts) {
    budget.held += mesh_points(m);
    // The solid as it is (Volume::closed_mesh would refuse one touching itself, which a level set takes).
    Volume v;
    v.kind = Volume::Kind::mesh;
    m.point_fields = m.face_fields = {};
    v.mesh = std::make_shared<const Mesh>(std::move(m));
    v.bounds = v.mesh->bbox();
    v.held_bytes = static_cast<double>(sizeof(Volume) + v.mesh->bytes());
    volumes.push_back(std::make_shared<const Volume>(std::move(v)));
  }
  const Volume all = Volume::combine(kind, std::move(volumes));
  UnionResult r;
  try {
    r.solid = volume_boundary(all, voxel, budget, progress);
  } catch (const BudgetError&) {
    throw;
  } catch (const Error& e) {
    // The voxel is at most a quarter of every solid's thinnest side (check_voxel, union_voxel): an empty
    // difference is the cuts covering the solid, which no voxel changes.
    if (kind != Volume::Kind::subtract || std::string_view(e.what()).find("the volume is empty") != 0) throw;
    throw Error("nothing is left: the cuts cover the whole solid (on a " + mm_text(voxel) +
                " grid, a quarter of its thinnest side or finer: no smaller voxel changes that)");
  }
  r.voxel = voxel;
  r.how = "on a " + mm_text(voxel) + " grid (" + why + ")";
  return r;
}

}  // namespace

double union_work_size(std::span<const Mesh* const> solids) {
  double points = 0, triangles = 0;
  for (const Mesh* m : solids) {
    points += mesh_points(*m);
    triangles += static_cast<double>(m->triangles.size());
  }
  return 2 * points + triangles * 150 / 16;
}

double union_voxel(std::span<const Mesh* const> solids) {
  double thinnest = 0.8;  // 4 x 0.2 mm
  for (const Mesh* m : solids) {
    const Vec3 s = m->bbox().size();
    thinnest = std::min({thinnest, s.x, s.y, s.z});
  }
  return thinnest / 4;
}

UnionResult solid_union(std::span<const Mesh* const> solids, const UnionOptions& opt, Progress& progress) {
  if (solids.empty()) throw Error("takes at least one solid, got none");
  std::vector<Mesh> parts;
  for (std::size_t i = 0; i < solids.size(); ++i)
    parts.push_back(outward(*solids[i], "solid " + std::to_string(i + 1), progress));
  check_voxel(opt.voxel, solids);
  std::vector<bool> kept(parts.size(), true);
  for (std::size_t i = 0; i < parts.size(); ++i)
    for (std::size_t j = i + 1; j < parts.size() && kept[i]; ++j) {
      if (!kept[j]) continue;
      const Lie lie = how_they_lie(parts[i], parts[j], progress);
      const std::string why = grid_reason(lie, "solid " + std::to_string(i + 1), "solid " + std::to_string(j + 1));
      if (!why.empty()) return on_grid(Volume::Kind::unite, std::move(parts), opt, why, progress);
      if (lie == Lie::first_inside) kept[i] = false;
      if (lie == Lie::second_inside) kept[j] = false;
    }
  // Every solid, the dropped ones too: whether one lies inside another was told by one point of it.
  const std::string itself = touching_itself(
      parts, std::vector<bool>(parts.size(), true), [](std::size_t i) { return "solid " + std::to_string(i + 1); },
      progress);
  if (!itself.empty()) return on_grid(Volume::Kind::unite, std::move(parts), opt, itself, progress);
  std::vector<const Mesh*> keep;
  for (std::size_t i = 0; i < parts.size(); ++i)
    if (kept[i]) keep.push_back(&parts[i]);
  UnionResult r;
  r.solid = joined(keep);
  r.exact = true;
  const std::size_t inner = parts.size() - keep.size();
  r.how = "exact (" + std::to_string(keep.size()) + (keep.size() == 1 ? " solid" : " disjoint solids") +
          (inner > 0 ? ", " + std::to_string(inner) + " inside another dropped" : std::string()) + ")";
  return r;
}

UnionResult solid_difference(const Mesh& from, std::span<const Mesh* const> cuts, const UnionOptions& opt,
                             Progress& progress) {
  if (cuts.empty()) throw Error("takes at least one solid to cut away, got none");
  std::vector<Mesh> parts{outward(from, "the solid cut from", progress)};
  for (std::size_t i = 0; i < cuts.size(); ++i)
    parts.push_back(outward(*cuts[i], "cut " + std::to_string(i + 1), progress));
  std::vector<const Mesh*> all{&from};
  all.insert(all.end(), cuts.begin(), cuts.end());
  check_voxel(opt.voxel, all);
  // Each cut: apart from the solid (nothing to take), inside it (a cavity), or meeting it (the grid).
  std::vector<std::size_t> cavities;
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const Lie lie = how_they_lie(parts[0], parts[i], progress);
    const std::string why = grid_reason(lie, "the solid", "cut " + std::to_string(i));
    if (!why.empty()) return on_grid(Volume::Kind::subtract, std::move(parts), opt, why, progress);
    if (lie == Lie::first_inside)
      throw Error("the solid cut from lies wholly inside cut " + std::to_string(i) + ": nothing is left");
    if (lie == Lie::second_inside) cavities.push_back(i);
  }
  // Cavities that meet each other: the grid; one inside another adds nothing.
  std::vector<bool> kept(parts.size(), false);
  for (const std::size_t i : cavities) kept[i] = true;
  for (std::size_t a = 0; a < cavities.size(); ++a)
    for (std::size_t b = a + 1; b < cavities.size(); ++b) {
      const std::size_t i = cavities[a], j = cavities[b];
      if (!kept[i] || !kept[j]) continue;
      const Lie lie = how_they_lie(parts[i], parts[j], progress);
      const std::string why = grid_reason(lie, "cut " + std::to_string(i), "cut " + std::to_string(j));
      if (!why.empty()) return on_grid(Volume::Kind::subtract, std::move(parts), opt, why, progress);
      if (lie == Lie::first_inside) kept[i] = false;
      if (lie == Lie::second_inside) kept[j] = false;
    }
  // The solid and its cavities; a cut apart from the solid takes nothing from it.
  kept[0] = true;
  const std::string itself = touching_itself(
      parts, kept, [](std::size_t i) { return i == 0 ? std::string("the solid") : "cut " + std::to_string(i); },
      progress);
  if (!itself.empty()) return on_grid(Volume::Kind::subtract, std::move(parts), opt, itself, progress);
  std::vector<const Mesh*> keep{&parts[0]};
  std::size_t sealed = 0;
  for (std::size_t i = 1; i < parts.size(); ++i)
    if (kept[i]) {
      for (Triangle& t : parts[i].triangles) std::swap(t[1], t[2]);  // facing into the cavity
      keep.push_back(&parts[i]);
      ++sealed;
    }
  UnionResult r;
  r.solid = joined(keep);
  r.exact = true;
  r.how = sealed == 0 ? "exact (no cut meets the solid: it is unchanged)"
                      : "exact (" + std::to_string(sealed) + " sealed " + (sealed == 1 ? "cavity" : "cavities") + ")";
  return r;
}

}  // namespace selfsim::print
