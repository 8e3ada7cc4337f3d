#include "kernels/geom/length_fields.h"

#include <string_view>
#include <utility>
#include <vector>

namespace selfsim {

void scale_length_fields(Fields& point_fields, double factor) {
  if (factor == 1) return;
  for (Field& f : point_fields.list) {
    const std::string_view n = f.name;
    if (f.components != 1 || (n != "width" && n != "root_distance" && n != "arclength")) continue;
    if (f.scalar() == Scalar::Int32) {
      const std::span<const std::int32_t> ints = f.ints();
      f.data = std::vector<double>(ints.begin(), ints.end());
    }
    for (double& v : std::get<1>(f.data)) v *= factor;
  }
}

}  // namespace selfsim
