#include "kernels/exclusion/curve_at_level.h"

#include <cstdint>
#include <vector>

#include "kernels/base/error.h"

namespace selfsim::exclusion {

Polyline curve_at_level(const Polyline& curve, int k, Progress& progress) {
  const Field* level = curve.point_fields.find("level");
  if (level == nullptr || level->scalar() != Scalar::Int32 || level->components != 1)
    throw Error("the curve has no integer point field 'level' to take a level from");
  std::vector<std::size_t> kept;
  Polyline out;
  for (std::size_t p = 0; p < curve.paths(); ++p) {
    for (std::size_t i = curve.path_begin(p); i < curve.path_ends[p]; ++i) {
      if ((i & 0xfffff) == 0xfffff && progress.cancelled()) throw Cancelled();
      if (level->at(i) > k) continue;
      kept.push_back(i);
      out.points.push_back(curve.points[i]);
    }
    out.path_ends.push_back(out.points.size());
  }
  out.point_fields = picked_fields<std::size_t>(curve.point_fields, kept, progress);
  out.cell_fields = curve.cell_fields;
  return out;
}

}  // namespace selfsim::exclusion
