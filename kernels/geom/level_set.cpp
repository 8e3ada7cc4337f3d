// Every OpenVDB call of selfsim lives here, in one translation unit (see level_set.h for why).
#include "kernels/geom/level_set.h"

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <numbers>
#include <sstream>

#include "kernels/geom/box_mesh.h"
#include "kernels/geom/check.h"
#include "kernels/geom/mesh_check.h"

namespace selfsim {

namespace {

// OpenVDB's interrupter concept over our Progress: its conversions ask wasInterrupted() as they go.
struct Interrupter {
  Progress& progress;
  void start(const char* = nullptr) {}
  void end() {}
  bool wasInterrupted(int = -1) { return progress.cancelled(); }
};

void initialise_openvdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

// The surface area of a volume's parts, each of which becomes a level set.
double parts_area(const Volume& v) {
  switch (v.kind) {
    case Volume::Kind::box: {
      const Vec3 s = v.hi - v.lo;
      return 2 * (s.x * s.y + s.y * s.z + s.z * s.x);
    }
    case Volume::Kind::sphere:
      return 4 * std::numbers::pi * v.radius * v.radius;
    case Volume::Kind::mesh:
      return surface_area(*v.mesh);
    default: {
      double a = 0;
      for (const auto& p : v.parts) a += parts_area(*p);
      return a;
    }
  }
}

void check_voxel(double voxel) {
  if (!(voxel > 0 && std::isfinite(voxel)))
    throw Error("the voxel size must be a positive number, got " + number_text(voxel));
}

// The exact boundary of a box, sphere or mesh.
Mesh exact_boundary(const Volume& v, double voxel) {
  switch (v.kind) {
    case Volume::Kind::box:
      return box_mesh(v.lo, v.hi);
    case Volume::Kind::sphere:
      return sphere_mesh(v.centre, v.radius, voxel / 4);
    default:
      return *v.mesh;
  }
}

using Grid = openvdb::FloatGrid;

Grid::Ptr mesh_level_set(const Mesh& m, const openvdb::math::Transform& xform, Interrupter& interrupt) {
  std::vector<openvdb::Vec3s> points;
  points.reserve(m.points.size());
  for (Vec3 p : m.points)
    points.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
  std::vector<openvdb::Vec3I> triangles;
  triangles.reserve(m.triangles.size());
  for (const Triangle& t : m.triangles) triangles.emplace_back(t[0], t[1], t[2]);
  Grid::Ptr g = openvdb::tools::meshToLevelSet<Grid>(interrupt, xform, points, triangles, 3.0f);
  if (interrupt.progress.cancelled()) throw Cancelled();
  return g;
}

// The level set of any volume: parts converted, then combined in order.
Grid::Ptr volume_level_set(const Volume& v, double voxel, const openvdb::math::Transform& xform,
                           Interrupter& interrupt) {
  if (v.exact()) return mesh_level_set(exact_boundary(v, voxel), xform, interrupt);
  Grid::Ptr result = volume_level_set(*v.parts[0], voxel, xform, interrupt);
  for (std::size_t i = 1; i < v.parts.size(); ++i) {
    Grid::Ptr next = volume_level_set(*v.parts[i], voxel, xform, interrupt);
    if (v.kind == Volume::Kind::unite)
      openvdb::tools::csgUnion(*result, *next);
    else
      openvdb::tools::csgDifference(*result, *next);
  }
  return result;
}

double signed_volume(const Mesh& m) {
  double s = 0;
  for (const Triangle& t : m.triangles) s += dot(m.points[t[0]], cross(m.points[t[1]], m.points[t[2]]));
  return s;
}

// The zero surface of a level set as triangles facing outwards, each quad split along its shorter diagonal.
Mesh zero_surface(const Grid& g) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(g, points, triangles, quads, 0.0, 0.0);
  Mesh m;
  m.points.reserve(points.size());
  for (const auto& p : points) m.points.push_back({p.x(), p.y(), p.z()});
  m.triangles.reserve(triangles.size() + 2 * quads.size());
  for (const auto& t : triangles) m.triangles.push_back({t[0], t[1], t[2]});
  for (const auto& q : quads) {
    if (norm(m.points[q[0]] - m.points[q[2]]) <= norm(m.points[q[1]] - m.points[q[3]])) {
      m.triangles.push_back({q[0], q[1], q[2]});
      m.triangles.push_back({q[0], q[2], q[3]});
    } else {
      m.triangles.push_back({q[0], q[1], q[3]});
      m.triangles.push_back({q[1], q[2], q[3]});
    }
  }
  if (signed_volume(m) < 0)
    for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

// OpenVDB stamps every file with a random UUID (36 characters of text after the 21-byte magic and version
// header), so the same recipe would write different bytes each run. Readers use it only to tell files
// apart; one derived from the content (two FNV-1a hashes of it) keeps that meaning and makes runs repeat.
std::string with_content_uuid(std::string file) {
  constexpr std::size_t at = 21, length = 36;
  if (file.size() < at + length || file[at + 8] != '-') throw Error("OpenVDB wrote an unexpected .vdb header");
  std::uint64_t h[2] = {1469598103934665603ull, 1099511628211ull * 7};
  for (std::size_t i = at + length; i < file.size(); ++i)
    for (std::uint64_t& x : h) x = (x ^ static_cast<unsigned char>(file[i])) * 1099511628211ull;
  char text[37];
  std::snprintf(text, sizeof text, "%08x-%04x-%04x-%04x-%012llx", static_cast<unsigned>(h[0] >> 32),
                static_cast<unsigned>((h[0] >> 16) & 0xffff), static_cast<unsigned>(h[0] & 0xffff),
                static_cast<unsigned>(h[1] >> 48), static_cast<unsigned long long>(h[1] & 0xffffffffffffull));
  file.replace(at, length, text, length);
  return file;
}

}  // namespace

double boundary_size(const Volume& v, double voxel) {
  if (v.kind == Volume::Kind::box) return 20;
  if (v.kind == Volume::Kind::sphere) return 1.5 * sphere_triangles(v.radius, voxel / 4);
  if (v.kind == Volume::Kind::mesh) return static_cast<double>(v.mesh->points.size() + v.mesh->triangles.size());
  const double faces = parts_area(v) / (voxel * voxel);
  return 7 * faces + 3 * faces;  // the parts' narrow bands, then the meshed result's triangles and points
}

Mesh volume_boundary(const Volume& v, double voxel, const PointBudget& budget, Progress& progress) {
  check_voxel(voxel);
  check_budget(boundary_size(v, voxel), budget, "the volume's boundary at voxel size " + number_text(voxel));
  if (v.exact()) return exact_boundary(v, voxel);
  initialise_openvdb();
  Interrupter interrupt{progress};
  const auto xform = openvdb::math::Transform::createLinearTransform(voxel);
  const Grid::Ptr g = volume_level_set(v, voxel, *xform, interrupt);
  Mesh m = zero_surface(*g);
  if (m.triangles.empty()) throw Error("the volume is empty at voxel size " + number_text(voxel));
  const MeshTopology t = mesh_topology(m);
  if (!t.closed())
    throw Error("the volume's boundary at voxel size " + number_text(voxel) +
                " is not a closed surface (a part thinner than a voxel, or parts touching?): " + t.first_problem +
                "; give a smaller voxel");
  return m;
}

double distance_size(double area, double voxel) { return 7 * area / (voxel * voxel); }

std::string distance_vdb(const Mesh& m, bool closed, double voxel, const std::string& name, const PointBudget& budget,
                         Progress& progress) {
  check_voxel(voxel);
  // OpenVDB's coordinates are 32-bit integers, and a needle of no area passes any budget of area.
  const Vec3 s = m.bbox().size();
  if (!(std::max({s.x, s.y, s.z}) / voxel <= 1 << 20))
    throw Error("the voxel size " + number_text(voxel) + " is too small for a mesh " +
                number_text(std::max({s.x, s.y, s.z})) + " across (at most 2^20 voxels across)");
  check_budget(distance_size(surface_area(m), voxel), budget,
               "a distance grid at voxel size " + number_text(voxel) + " (set a larger 'voxel')");
  initialise_openvdb();
  Interrupter interrupt{progress};
  const auto xform = openvdb::math::Transform::createLinearTransform(voxel);
  Grid::Ptr g;
  if (closed) {
    g = mesh_level_set(m, *xform, interrupt);
  } else {
    std::vector<openvdb::Vec3s> points;
    for (Vec3 p : m.points)
      points.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z));
    std::vector<openvdb::Vec3I> triangles;
    for (const Triangle& t : m.triangles) triangles.emplace_back(t[0], t[1], t[2]);
    g = openvdb::tools::meshToUnsignedDistanceField<Grid>(interrupt, *xform, points, triangles, {}, 3.0f);
    if (progress.cancelled()) throw Cancelled();
    g->setGridClass(openvdb::GRID_UNKNOWN);  // a distance, not a level set: no inside
  }
  g->setName(name);
  g->insertMeta("creator", openvdb::StringMetadata("selfsim"));
  std::ostringstream bytes;
  openvdb::io::Stream(bytes).write(openvdb::GridCPtrVec{g});
  return with_content_uuid(bytes.str());
}

}  // namespace selfsim
