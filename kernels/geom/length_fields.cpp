#include "kernels/geom/length_fields.h"

#include <string_view>
#include <utility>
#include <vector>

namespace selfsim {

void scale_length_fields(Fields& fields, double factor) {
  if (factor == 1) return;
  const auto is_length = [](const Field& f) {
    const std::string_view n = f.name;
    return f.components == 1 && (n == "width" || n == "root_distance" || n == "arclength" || n == "thickness" ||
                                 n == "radius" || n == "wall" || n == "gap" || n == "clearance");
  };
  if (!(factor > 0)) {
    std::erase_if(fields.list, is_length);
    return;
  }
  for (Field& f : fields.list) {
    if (!is_length(f)) continue;
    if (f.scalar() == Scalar::Int32) {
      const std::span<const std::int32_t> ints = f.ints();
      f.data = std::vector<double>(ints.begin(), ints.end());
    }
    for (double& v : std::get<1>(f.data)) v *= factor;
  }
}

}  // namespace selfsim
