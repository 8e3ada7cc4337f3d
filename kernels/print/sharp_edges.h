// Where a solid's surface turns sharply (its box's edges and corners, a sheet's rim), found from the mesh's
// geometry, not from how it is cut into triangles: the print check leaves out rays that start within about
// a voxel of such an edge (print_check.cpp), since they run along the face beyond it, within the distance
// grid's interpolation error of crossing it. A flat face split into 20,000 slivers has the same sharp edges
// as the same face in two triangles.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "kernels/geom/mesh.h"

namespace selfsim::print {

class SharpEdges {
 public:
  // The edges of m between two triangles whose normals differ by more than 25 degrees (or where more than
  // two triangles meet), within `reach` of which distances are told apart (reach > 0).
  SharpEdges(const Mesh& m, double reach);
  // The distance from p to the nearest sharp edge, or `reach` when none is nearer.
  double distance(Vec3 p) const;
  // Each triangle's smooth patch: triangles joined across edges that are not sharp, numbered from 0.
  const std::vector<std::uint32_t>& patches() const { return patch_; }
  std::uint32_t patch_count() const { return patch_count_; }
  std::size_t count() const { return edges_.size(); }

 private:
  std::uint64_t key(long x, long y, long z) const;
  double reach_, cell_;
  Vec3 origin_;
  std::vector<std::pair<Vec3, Vec3>> edges_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> cells_;  // (cell key, edge), sorted
  std::vector<std::uint32_t> patch_;
  std::uint32_t patch_count_ = 0;
};

}  // namespace selfsim::print
