#include "kernels/region/volume.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_set>
#include <utility>

#include "kernels/base/check.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/geom/point_text.h"
#include "kernels/region/box_mesh.h"

namespace selfsim {

Volume Volume::box(Vec3 lo, Vec3 hi) {
  if (!(is_finite(lo) && is_finite(hi))) throw Error("options 'min' and 'max' must be finite points");
  if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
    throw Error("option 'max' must be above 'min' in every coordinate, got min = " + point_text(lo) +
                ", max = " + point_text(hi));
  Volume v;
  v.kind = Kind::box;
  v.lo = lo;
  v.hi = hi;
  v.bounds = {lo, hi};
  v.held_bytes = sizeof(Volume);
  return v;
}

Volume Volume::sphere(Vec3 centre, double radius) {
  if (!is_finite(centre)) throw Error("option 'center' must be a finite point");
  check_between(radius, 1e-300, 1e300, "option 'radius'");
  Volume v;
  v.kind = Kind::sphere;
  v.centre = centre;
  v.radius = radius;
  v.bounds = {centre - Vec3{radius, radius, radius}, centre + Vec3{radius, radius, radius}};
  v.held_bytes = sizeof(Volume);
  return v;
}

Volume Volume::closed_mesh(Mesh m, Progress& progress) {
  m.validate();
  if (m.triangles.empty()) throw Error("the mesh has no triangles");
  const std::string open = first_open_edge(m);
  if (!open.empty()) throw Error("the mesh is not closed: " + open);
  const MeshTopology topology = mesh_topology(m);
  if (!topology.manifold()) throw Error("the mesh is not a manifold: " + topology.first_problem);
  if (const auto pair = first_intersection(m, progress))
    throw Error("the mesh crosses itself: its triangles " + std::to_string(pair->first + 1) + " and " +
                std::to_string(pair->second + 1) + " meet near " + point_text(pair->where));
  const double v = enclosed_volume(m);
  if (!(std::abs(v) > 0)) throw Error("the mesh encloses no volume");
  if (v < 0)
    for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  m.point_fields = {};
  m.face_fields = {};
  Volume out;
  out.kind = Kind::mesh;
  out.mesh = std::make_shared<const Mesh>(std::move(m));
  out.bounds = out.mesh->bbox();
  out.held_bytes = static_cast<double>(sizeof(Volume) + out.mesh->bytes());
  return out;
}

Volume Volume::combine(Kind kind, std::vector<std::shared_ptr<const Volume>> parts) {
  if (parts.size() < 2) throw Error("takes at least two volumes, got " + std::to_string(parts.size()));
  Volume v;
  v.kind = kind;
  v.parts = std::move(parts);
  v.held_bytes = static_cast<double>(sizeof(Volume) + v.parts.capacity() * sizeof(v.parts[0]));
  if (kind == Kind::subtract) v.bounds = v.parts[0]->bounds;
  std::unordered_set<const Volume*> counted;  // union{ v, v }: v's bytes once
  for (std::size_t i = 0; i < v.parts.size(); ++i) {
    const Volume& p = *v.parts[i];
    v.depth = std::max(v.depth, p.depth + 1);
    // A part combined the same way (a union in a union, a difference as a difference's first part) is
    // flattened into this one when converted; any other is converted by a call of its own.
    const bool flattened = p.kind == kind && (kind == Kind::unite || i == 0);
    v.conversion_depth = std::max(v.conversion_depth, p.conversion_depth + (flattened ? 0 : 1));
    if (kind == Kind::unite) v.bounds.add(p.bounds);
    if (counted.insert(&p).second) v.held_bytes = std::min(v.held_bytes + p.held_bytes, 0x1p62);
  }
  if (v.depth > max_volume_depth || v.conversion_depth > max_conversion_depth)
    throw Error(v.depth > max_volume_depth
                    ? "nests volumes more than " + std::to_string(max_volume_depth) +
                          " deep: give the parts to one call, volume.union{ a, b, c, ... }"
                    : "alternates unions and differences more than " + std::to_string(max_conversion_depth) +
                          " times deep: combine the unions' parts in one call first");
  return v;
}

BBox3 Volume::bbox() const { return bounds; }

std::size_t Volume::bytes() const { return static_cast<std::size_t>(held_bytes); }

std::vector<const Volume*> combined_parts(const Volume& v) {
  std::vector<const Volume*> out, stack;
  std::unordered_set<const Volume*> seen;
  auto keep = [&](const Volume* p) {
    if (seen.insert(p).second) out.push_back(p);
  };
  if (v.kind == Volume::Kind::subtract) {
    // (a − b) − c is a − b − c: the first parts followed down, the parts taken away innermost first.
    std::vector<const Volume*> chain{&v};
    while (chain.back()->kind == Volume::Kind::subtract) chain.push_back(chain.back()->parts[0].get());
    out.push_back(chain.back());
    for (auto d = chain.rbegin() + 1; d != chain.rend(); ++d)
      for (std::size_t i = 1; i < (*d)->parts.size(); ++i) keep((*d)->parts[i].get());
    return out;
  }
  std::unordered_set<const Volume*> opened;  // a union met again adds nothing: union{ v, v } is v
  for (auto p = v.parts.rbegin(); p != v.parts.rend(); ++p) stack.push_back(p->get());
  while (!stack.empty()) {
    const Volume* p = stack.back();
    stack.pop_back();
    if (p->kind != Volume::Kind::unite)
      keep(p);
    else if (opened.insert(p).second)
      for (auto q = p->parts.rbegin(); q != p->parts.rend(); ++q) stack.push_back(q->get());
  }
  return out;
}

std::vector<const Volume*> volume_leaves(const Volume& v) {
  std::vector<const Volume*> out, stack{&v};
  std::unordered_set<const Volume*> seen;
  while (!stack.empty()) {
    const Volume* p = stack.back();
    stack.pop_back();
    if (!seen.insert(p).second) continue;
    if (p->exact())
      out.push_back(p);
    else
      for (auto q = p->parts.rbegin(); q != p->parts.rend(); ++q) stack.push_back(q->get());
  }
  return out;
}

std::string Volume::summary() const {
  std::string s;
  switch (kind) {
    case Kind::box:
      s = "box " + point_text(lo) + " to " + point_text(hi);
      break;
    case Kind::sphere:
      s = "sphere at " + point_text(centre) + ", radius " + number_text(radius);
      break;
    case Kind::mesh:
      s = "mesh of " + std::to_string(mesh->triangles.size()) + " triangles";
      break;
    case Kind::unite:
    case Kind::subtract:
      s = std::string(kind == Kind::unite ? "union" : "difference") + " of " + std::to_string(parts.size()) +
          " volumes";
      break;
  }
  return "Volume(" + s + (voxel > 0 ? ", voxel " + number_text(voxel) : std::string()) + ")";
}

double Volume::default_voxel() const {
  if (voxel > 0) return voxel;
  const Vec3 s = bbox().size();
  const double side = std::max({s.x, s.y, s.z});
  if (!std::isfinite(side))
    throw Error(
        "the volume's extent overflows double precision (no side may reach about 1.8e308), so it has no "
        "voxel size");
  return side / 128;
}

namespace {

// Splits in sphere_mesh for a tolerance. A face's deepest point is its centre, which lies radius (1 - cos b)
// inside, b the angle from the centre to a corner: a / sqrt(3) for a face of edge angle a, with a margin of
// 1.2 because splitting makes the faces in the middle of an icosahedron's face larger than the rest. The
// icosahedron's edges span atan(2) = 63.4 degrees, halved by each split.
int sphere_splits(double radius, double tolerance) {
  double angle = 1.1071487177940904;
  int splits = 0;
  while (splits < 7 && radius * (1 - std::cos(1.2 * angle / std::sqrt(3.0))) > tolerance) {
    angle /= 2;
    ++splits;
  }
  return splits;
}

}  // namespace

double sphere_triangles(double radius, double tolerance) {
  return 20 * std::pow(4.0, sphere_splits(radius, tolerance));
}

Mesh sphere_mesh(Vec3 centre, double radius, double tolerance) {
  const double g = (1 + std::sqrt(5.0)) / 2;
  std::vector<Vec3> unit{{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                         {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
  for (Vec3& p : unit) p = normalized(p);
  std::vector<Triangle> faces{{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                              {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
                              {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int s = sphere_splits(radius, tolerance); s > 0; --s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> middle;
    auto mid = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto found = middle.find(key);
      if (found != middle.end()) return found->second;
      unit.push_back(normalized(unit[a] + unit[b]));
      return middle[key] = static_cast<std::uint32_t>(unit.size() - 1);
    };
    std::vector<Triangle> finer;
    finer.reserve(4 * faces.size());
    for (const Triangle& t : faces) {
      const std::uint32_t ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
      finer.push_back({t[0], ab, ca});
      finer.push_back({t[1], bc, ab});
      finer.push_back({t[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    faces = std::move(finer);
  }
  Mesh m;
  m.triangles = std::move(faces);
  m.points.reserve(unit.size());
  for (Vec3 u : unit) m.points.push_back(centre + radius * u);
  return m;
}

}  // namespace selfsim
