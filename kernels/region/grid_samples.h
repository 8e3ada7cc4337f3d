// A level set's own voxels as a .vdb file holds them (kernels/io/vdb/vdb_read.h reads them): where a region's
// walls exist only as a grid, WallGrid measures them on that grid (its lattice and its zero surface) rather
// than on one converted again from the region's mesh.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "kernels/geom/vec3.h"

namespace selfsim {

struct GridSamples {
  double voxel = 0;                                // the grid's voxel size, the same along every axis
  Vec3 origin;                                     // where voxel (0, 0, 0)'s centre lies
  double background = 0;                           // the value outside its band, positive
  std::vector<std::array<std::int32_t, 3>> index;  // each active voxel
  std::vector<float> value;                        // its signed distance, negative inside

  std::size_t bytes() const { return sizeof(GridSamples) + index.capacity() * 12 + value.capacity() * 4; }
};

}  // namespace selfsim
