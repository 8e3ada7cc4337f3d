// .vdb: what Blender and Houdini open as a volume. A closed mesh (a region, a thickened surface) is written
// as its signed-distance level set, an open one (an exclusion surface) as its unsigned distance field, one
// float grid either way, narrow-banded 3 voxels either side (level_set.h does the OpenVDB work).
#include <algorithm>

#include "kernels/base/check.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/io/save.h"
#include "kernels/io/writers.h"
#include "kernels/region/level_set.h"

namespace selfsim::io {

double vdb_voxel(const Mesh& m, const SaveOptions& opt) {
  if (opt.voxel > 0) return opt.voxel;
  const Vec3 s = m.bbox().size();
  return std::max({s.x, s.y, s.z}) / 128;
}

void write_vdb(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress) {
  const Mesh& m = *std::get<const Mesh*>(v);  // the registry sends only meshes here
  const bool closed = mesh_topology(m).closed();
  out.write(distance_vdb(m, closed, vdb_voxel(m, opt), closed ? "surface" : "distance", opt.budget, progress));
}

}  // namespace selfsim::io
