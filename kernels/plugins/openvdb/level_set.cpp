// Every OpenVDB conversion of selfsim lives here, in one translation unit of the OpenVDB plugin (plugin.h;
// reading .vdb files is vdb_read.cpp): volumes converted to level sets in a local frame, their
// boundaries, .vdb files, and the walls' distance grid (wall_grid.h).
#include "kernels/region/level_set.h"

#include <openvdb/io/Stream.h>
#include <openvdb/openvdb.h>
#include <openvdb/tools/Composite.h>
#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetRebuild.h>
#include <openvdb/tools/MeshToVolume.h>
#include <openvdb/tools/SignedFloodFill.h>
#include <openvdb/tools/VolumeToMesh.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <mutex>
#include <numbers>
#include <sstream>
#include <utility>
#include <vector>

#include "kernels/base/check.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/plugins/openvdb/grid_frame.h"
#include "kernels/plugins/openvdb/winding_sign.h"
#include "kernels/region/box_mesh.h"
#include "kernels/region/wall_grid.h"

namespace selfsim {

using namespace vdb;

namespace {

// The surface area of a volume's distinct boxes, spheres and meshes, each of which becomes a level set.
double parts_area(const Volume& v) {
  double a = 0;
  for (const Volume* p : volume_leaves(v)) {
    switch (p->kind) {
      case Volume::Kind::box: {
        const Vec3 s = p->hi - p->lo;
        a += 2 * (s.x * s.y + s.y * s.z + s.z * s.x);
        break;
      }
      case Volume::Kind::sphere:
        a += 4 * std::numbers::pi * p->radius * p->radius;
        break;
      default:
        a += surface_area(*p->mesh);
    }
  }
  return a;
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

// The level set of any volume in frame f, `band` voxels either side of every part: parts converted, then
// combined in order (nested unions and differences flattened, each distinct part once: combined_parts).
Grid::Ptr volume_level_set(const Volume& v, const Frame& f, Interrupter& interrupt, float band = 3) {
  if (v.exact()) return mesh_grid(exact_boundary(v, f.voxel), true, f, interrupt, band);
  const std::vector<const Volume*> parts = combined_parts(v);
  Grid::Ptr result = volume_level_set(*parts[0], f, interrupt, band);
  for (std::size_t i = 1; i < parts.size(); ++i) {
    Grid::Ptr next = volume_level_set(*parts[i], f, interrupt, band);
    if (v.kind == Volume::Kind::unite)
      openvdb::tools::csgUnion(*result, *next);
    else
      openvdb::tools::csgDifference(*result, *next);
  }
  return result;
}

// The corners of a volume's parts: where the level sets' trees grow.
void part_corners(const Volume& v, std::vector<Vec3>& out) {
  for (const Volume* p : volume_leaves(v)) {
    if (p->kind == Volume::Kind::mesh) {
      out.insert(out.end(), p->mesh->points.begin(), p->mesh->points.end());
    } else {
      const BBox3 b = p->bbox();
      for (int k = 0; k < 8; ++k)
        out.push_back({k & 1 ? b.max.x : b.min.x, k & 2 ? b.max.y : b.min.y, k & 4 ? b.max.z : b.min.z});
    }
  }
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

struct WallGrid::Data {
  Frame frame;
  Grid::Ptr grid;  // in the frame's voxels, negative inside
};

namespace {

// Voxels of the band inside (or outside) the walls: the depth asked for and two more.
float band(double voxel, double depth) { return static_cast<float>(std::ceil(depth / voxel) + 2); }
// Outside: at least the 3 voxels a level set keeps.
float outside_band(double voxel, double outside) { return std::max(3.0f, band(voxel, outside)); }

// Budget points of the tree a .vdb file's voxels make: OpenVDB's nodes (4096, 128 and 8 voxels wide, about
// 270 KB, 34 KB and 2 KB each) for every cell of those widths a voxel falls in, so that a crafted file
// scattering its voxels far apart is refused before each one takes a node of every size.
double samples_size(const GridSamples& s) {
  double bytes = 0;
  for (const auto& [shift, node] : {std::pair{12, 270e3}, std::pair{7, 34e3}, std::pair{3, 2.1e3}}) {
    std::vector<std::array<std::int32_t, 3>> cells;
    cells.reserve(s.index.size());
    for (const auto& i : s.index) cells.push_back({i[0] >> shift, i[1] >> shift, i[2] >> shift});
    std::sort(cells.begin(), cells.end());
    bytes += node * static_cast<double>(std::unique(cells.begin(), cells.end()) - cells.begin());
  }
  return bytes / 16;
}

}  // namespace

double WallGrid::size(const Volume& v, double voxel, double depth, double outside) {
  if (v.samples) voxel = v.samples->voxel;
  const Frame f = frame_for(v.bbox(), voxel);
  std::vector<Vec3> corners;
  part_corners(v, corners);
  // The parts' narrow bands (7 voxels across) or the file's voxels, and the rebuilt band (the depth inside,
  // and outside 3 voxels or more).
  // A mesh's unsigned distance (WallGrid's constructor) is as wide outside as inside.
  const double across = std::max(7.0 + 1 + outside_band(voxel, outside) + band(voxel, depth),
                                 v.kind == Volume::Kind::mesh ? 1.0 + 2 * band(voxel, std::max(depth, outside)) : 0.0);
  return tree_size(corners, parts_area(v), f, across) + (v.samples ? samples_size(*v.samples) : 0);
}

namespace {

// A .vdb file's level set from its voxels, in its own frame (index (0, 0, 0) at its origin), the inside
// below its band made negative again.
Grid::Ptr samples_grid(const GridSamples& s) {
  const Grid::Ptr g = Grid::create(static_cast<float>(s.background / s.voxel));
  auto access = g->getAccessor();
  for (std::size_t i = 0; i < s.index.size(); ++i)
    access.setValue(openvdb::Coord(s.index[i][0], s.index[i][1], s.index[i][2]),
                    static_cast<float>(s.value[i] / s.voxel));
  openvdb::tools::signedFloodFill(g->tree());
  g->setGridClass(openvdb::GRID_LEVEL_SET);
  return g;
}

}  // namespace

WallGrid::WallGrid(const Volume& v, double voxel, double depth, const PointBudget& budget, Progress& progress,
                   double outside) {
  if (v.samples) voxel = v.samples->voxel;  // the file's own lattice
  const Frame f = v.samples ? Frame{v.samples->origin, voxel} : frame_for(v.bbox(), voxel);
  check_budget(size(v, voxel, depth, outside), budget,
               "the region's distance grid at voxel size " + number_text(voxel) + " (set a larger 'voxel')");
  initialise_openvdb();
  Interrupter interrupt{progress};
  auto data = std::make_shared<Data>();
  data->frame = f;
  // The volume's level set as its boundary is made (a union or difference combined on narrow bands), then
  // its zero surface measured again (levelSetRebuild): the distance to the region's own walls, deep inside
  // it. The combined bands alone read a union's parts' distances, so a wall where two parts touch.
  data->grid = openvdb_call([&] {
    // A mesh's distances are measured from its triangles directly, as deep as asked: two voxels each side
    // when nothing deeper is asked (OpenVDB then skips widening the band, the costly step; beyond it the
    // sign is still right everywhere). Its unsigned distance, signed by its winding number (winding_sign.h):
    // OpenVDB's own sign, and the "self-intersecting" voxels it then removes, fill gaps narrower than about
    // 2.5 voxels, which would then read as no gap at all.
    if (!v.samples && v.kind == Volume::Kind::mesh) {
      Grid::Ptr g = mesh_grid(*v.mesh, false, f, interrupt, std::max(band(voxel, outside), band(voxel, depth)));
      if (!progress.cancelled()) sign_by_winding(*g, *v.mesh, f, interrupt);
      return g;
    }
    const Grid::Ptr combined = v.samples ? samples_grid(*v.samples) : volume_level_set(v, f, interrupt);
    if (progress.cancelled()) throw Cancelled();
    return openvdb::tools::levelSetRebuild(*combined, 0.0f, outside_band(voxel, outside), band(voxel, depth), nullptr,
                                           &interrupt);
  });
  if (progress.cancelled()) throw Cancelled();
  data_ = std::move(data);
}

void WallGrid::clearances(std::span<const Vec3> points, std::span<double> out) const {
  // An accessor per call: OpenVDB's caches are not to be shared between threads.
  const auto access = data_->grid->getConstUnsafeAccessor();
  const Frame& f = data_->frame;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 q = (1 / f.voxel) * (centre_ + (1 / scale_) * points[i] - f.origin);
    const double value = openvdb::tools::BoxSampler::sample(access, openvdb::Vec3R(q.x, q.y, q.z));
    out[i] = -value * f.voxel * scale_;
  }
}

double WallGrid::voxel() const { return data_->frame.voxel * scale_; }

}  // namespace selfsim
