#include "kernels/geom/wall_grid.h"

#include <openvdb/tools/Interpolation.h>
#include <openvdb/tools/LevelSetRebuild.h>
#include <openvdb/tools/SignedFloodFill.h>

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "kernels/geom/check.h"
#include "kernels/geom/openvdb_grid.h"

namespace selfsim {

struct WallGrid::Data {
  vdb::Frame frame;
  vdb::Grid::Ptr grid;  // in the frame's voxels, negative inside
};

namespace {

// Voxels of the band inside the walls: the depth asked for and two more.
float inside_band(double voxel, double depth) { return static_cast<float>(std::ceil(depth / voxel) + 2); }

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

double WallGrid::size(const Volume& v, double voxel, double depth) {
  if (v.samples) voxel = v.samples->voxel;
  const vdb::Frame f = vdb::frame_for(v.bbox(), voxel);
  std::vector<Vec3> corners;
  vdb::part_corners(v, corners);
  // The parts' narrow bands (7 voxels across) or the file's voxels, and the rebuilt band (3 outside, the
  // depth inside).
  return vdb::tree_size(corners, vdb::parts_area(v), f, 7 + 4 + inside_band(voxel, depth)) +
         (v.samples ? samples_size(*v.samples) : 0);
}

namespace {

// A .vdb file's level set from its voxels, in its own frame (index (0, 0, 0) at its origin), the inside
// below its band made negative again.
vdb::Grid::Ptr samples_grid(const GridSamples& s) {
  const vdb::Grid::Ptr g = vdb::Grid::create(static_cast<float>(s.background / s.voxel));
  auto access = g->getAccessor();
  for (std::size_t i = 0; i < s.index.size(); ++i)
    access.setValue(openvdb::Coord(s.index[i][0], s.index[i][1], s.index[i][2]),
                    static_cast<float>(s.value[i] / s.voxel));
  openvdb::tools::signedFloodFill(g->tree());
  g->setGridClass(openvdb::GRID_LEVEL_SET);
  return g;
}

}  // namespace

WallGrid::WallGrid(const Volume& v, double voxel, double depth, const PointBudget& budget, Progress& progress) {
  if (v.samples) voxel = v.samples->voxel;  // the file's own lattice
  const vdb::Frame f = v.samples ? vdb::Frame{v.samples->origin, voxel} : vdb::frame_for(v.bbox(), voxel);
  check_budget(size(v, voxel, depth), budget,
               "the region's distance grid at voxel size " + number_text(voxel) + " (set a larger 'voxel')");
  vdb::initialise_openvdb();
  vdb::Interrupter interrupt{progress};
  auto data = std::make_shared<Data>();
  data->frame = f;
  // The volume's level set as its boundary is made (a union or difference combined on narrow bands), then
  // its zero surface measured again (levelSetRebuild): the distance to the region's own walls, deep inside
  // it. The combined bands alone read a union's parts' distances, so a wall where two parts touch.
  data->grid = vdb::openvdb_call([&] {
    const vdb::Grid::Ptr combined = v.samples ? samples_grid(*v.samples) : vdb::volume_level_set(v, f, interrupt);
    if (progress.cancelled()) throw Cancelled();
    return openvdb::tools::levelSetRebuild(*combined, 0.0f, 3.0f, inside_band(voxel, depth), nullptr, &interrupt);
  });
  if (progress.cancelled()) throw Cancelled();
  data_ = std::move(data);
}

void WallGrid::clearances(std::span<const Vec3> points, std::span<double> out) const {
  // An accessor per call: OpenVDB's caches are not to be shared between threads.
  const auto access = data_->grid->getConstUnsafeAccessor();
  const vdb::Frame& f = data_->frame;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 q = (1 / f.voxel) * (centre_ + (1 / scale_) * points[i] - f.origin);
    const double value = openvdb::tools::BoxSampler::sample(access, openvdb::Vec3R(q.x, q.y, q.z));
    out[i] = -value * f.voxel * scale_;
  }
}

double WallGrid::clearance(Vec3 p) const {
  double c = 0;
  clearances({&p, 1}, {&c, 1});
  return c;
}

double WallGrid::voxel() const { return data_->frame.voxel * scale_; }

double WallGrid::error() const { return std::sqrt(3.0) / 2 * voxel(); }

WallGrid WallGrid::in_frame(Vec3 centre, double scale) const {
  // q = scale·(p − centre) and this view's p = scale_·(w − centre_): q = scale·scale_·(w − centre_ − centre/scale_).
  WallGrid g = *this;
  g.centre_ = centre_ + (1 / scale_) * centre;
  g.scale_ = scale_ * scale;
  return g;
}

}  // namespace selfsim
