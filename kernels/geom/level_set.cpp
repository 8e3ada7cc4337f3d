// Every OpenVDB call of selfsim lives here, in one translation unit (see level_set.h for why).
#include "kernels/geom/level_set.h"

#include <openvdb/io/Stream.h>
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
#include "kernels/geom/mesh_intersections.h"
#include "kernels/geom/openvdb_grid.h"

namespace selfsim {

namespace {

using namespace vdb;

// The zero surface of a level set in frame f as triangles facing outwards, each quad split along its
// shorter diagonal.
Mesh zero_surface(const Grid& g, const Frame& f) {
  std::vector<openvdb::Vec3s> points;
  std::vector<openvdb::Vec3I> triangles;
  std::vector<openvdb::Vec4I> quads;
  openvdb::tools::volumeToMesh(g, points, triangles, quads, 0.0, 0.0);
  Mesh m;
  m.points.reserve(points.size());
  for (const auto& p : points) m.points.push_back(f.world(p));
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
  if (enclosed_volume(m) < 0)
    for (Triangle& t : m.triangles) std::swap(t[1], t[2]);
  return m;
}

// Where a shape's surface passes exactly through lattice points (a sphere of radius 1 at voxel 0.04, a box's
// corner), the mesher puts several points at one place and makes zero-area triangles that cross their
// neighbours. The boundary is then meshed again with the lattice moved by a fraction of a voxel: the first
// placement is the shape's lowest corner; the others are moved by amounts no simple shape lines up with.
constexpr Vec3 lattice_shifts[] = {{0, 0, 0},
                                   {0.3819660113, 0.2360679775, 0.1458980338},
                                   {0.7071067812, 0.5773502692, 0.4472135955},
                                   {0.1415926536, 0.7182818285, 0.4142135624}};

// Why a closed mesh from the mesher is not a valid boundary ("has a triangle of zero area (triangle 12)",
// "crosses itself (triangles 3 and 40 meet near {...})"), or empty when it is valid.
std::string degenerate_surface(const Mesh& m, Progress& progress) {
  const BBox3 box = m.bbox();
  const double size = norm(box.max - box.min);
  for (std::size_t i = 0; i < m.triangles.size(); ++i)
    if (!(norm(area_normal(m, m.triangles[i])) > 1e-18 * size * size))
      return "has a triangle of zero area (triangle " + std::to_string(i + 1) + ")";
  if (const auto pair = first_intersection(m, progress))
    return "crosses itself (triangles " + std::to_string(pair->first + 1) + " and " + std::to_string(pair->second + 1) +
           " meet near {" + number_text(pair->where.x) + ", " + number_text(pair->where.y) + ", " +
           number_text(pair->where.z) + "})";
  return "";
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
  const Frame f = frame_for(v.bbox(), voxel);
  std::vector<Vec3> corners;
  part_corners(v, corners);
  const double area = parts_area(v);
  return tree_size(corners, area, f) + 3 * area / (voxel * voxel);  // and the meshed result's triangles and points
}

Mesh volume_boundary(const Volume& v, double voxel, const PointBudget& budget, Progress& progress) {
  if (v.exact()) {
    if (v.kind == Volume::Kind::sphere) frame_for(v.bbox(), voxel);  // its voxel sets its triangles
    check_budget(boundary_size(v, voxel), budget, "the volume's boundary at voxel size " + number_text(voxel));
    return exact_boundary(v, voxel);
  }
  const Frame first = frame_for(v.bbox(), voxel);
  check_budget(boundary_size(v, voxel), budget, "the volume's boundary at voxel size " + number_text(voxel));
  initialise_openvdb();
  Interrupter interrupt{progress};
  std::string problem;
  for (const Vec3 shift : lattice_shifts) {
    const Frame f{first.origin - voxel * shift, voxel};
    Mesh m = openvdb_call([&] { return zero_surface(*volume_level_set(v, f, interrupt), f); });
    if (m.triangles.empty())
      throw Error("the volume is empty at voxel size " + number_text(voxel) +
                  " (parts thinner than about a voxel vanish: give a smaller 'voxel' if they are there)");
    const MeshTopology t = mesh_topology(m);
    if (!t.closed())
      throw Error("the volume's boundary at voxel size " + number_text(voxel) +
                  " is not a closed surface (a part thinner than a voxel, or parts touching?): " + t.first_problem +
                  "; give a smaller voxel");
    problem = degenerate_surface(m, progress);
    if (problem.empty()) return m;
  }
  throw Error("the volume's boundary at voxel size " + number_text(voxel) + " " + problem +
              " at every placement of the voxel lattice tried; give another voxel size");
}

std::string distance_vdb(const Mesh& m, bool closed, double voxel, const std::string& name, const PointBudget& budget,
                         Progress& progress) {
  const Frame f = frame_for(m.bbox(), voxel);
  // OpenVDB's transforms, written into the file and rebuilt by every reader, refuse a voxel whose cube is
  // below 3e-15: no .vdb can hold a finer grid, whatever writes it.
  if (voxel * voxel * voxel < 3.0 * openvdb::math::Tolerance<double>::value())
    throw Error("a .vdb cannot hold voxels smaller than " + number_text(min_vdb_voxel) + ", got " + number_text(voxel) +
                " (OpenVDB's limit; the default voxel is 1/128 of the longest side): give " +
                "'voxel' of at least that, or scale the shape up (a part measured in metres: use millimetres)");
  check_budget(tree_size(m.points, surface_area(m), f), budget,
               "a distance grid at voxel size " + number_text(voxel) + " (set a larger 'voxel')");
  initialise_openvdb();
  Interrupter interrupt{progress};
  return openvdb_call([&] {
    Grid::Ptr g = mesh_grid(m, closed, f, interrupt);
    if (!closed) g->setGridClass(openvdb::GRID_UNKNOWN);  // a distance, not a level set: no inside
    // Distances in the caller's units, as level sets keep them, at the real voxel size and corner (OpenVDB
    // throws for a voxel too small for its transforms).
    const float scale = static_cast<float>(voxel);
    for (auto value = g->beginValueAll(); value; ++value) value.setValue(*value * scale);
    g->tree().root().setBackground(g->background() * scale, false);
    const auto xform = openvdb::math::Transform::createLinearTransform(voxel);
    xform->postTranslate(openvdb::Vec3d(f.origin.x, f.origin.y, f.origin.z));
    g->setTransform(xform);
    g->setName(name);
    g->insertMeta("creator", openvdb::StringMetadata("selfsim"));
    std::ostringstream bytes;
    openvdb::io::Stream(bytes).write(openvdb::GridCPtrVec{g});
    return with_content_uuid(bytes.str());
  });
}

}  // namespace selfsim
