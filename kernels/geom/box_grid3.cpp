#include "kernels/geom/box_grid3.h"

#include <algorithm>
#include <cmath>

#include "kernels/base/error.h"

namespace selfsim {

BoxGrid3::BoxGrid3(const BBox3& bounds, double cell) : bounds_(bounds), cell_(cell) {
  if (!(cell > 0 && std::isfinite(cell))) throw Error("a box grid needs a positive cell size");
  if (bounds.empty() || !is_finite(bounds.min) || !is_finite(bounds.max)) throw Error("a box grid needs finite bounds");
  const Vec3 size = bounds.size();
  constexpr double most = 2097152;  // 2^21 cells: 48 MiB of empty cell lists
  const double wanted = (size.x / cell_ + 1) * (size.y / cell_ + 1) * (size.z / cell_ + 1);
  if (wanted > most) cell_ *= std::cbrt(wanted / most) * 1.01;
  nx_ = static_cast<int>(size.x / cell_) + 1;
  ny_ = static_cast<int>(size.y / cell_) + 1;
  nz_ = static_cast<int>(size.z / cell_) + 1;
  cells_.resize(static_cast<std::size_t>(nx_) * ny_ * nz_);
}

BoxGrid3::Index BoxGrid3::index(Vec3 p) const {
  auto at = [&](double x, double lo, int n) {
    return static_cast<int>(std::clamp(std::floor((x - lo) / cell_), 0.0, n - 1.0));
  };
  return {at(p.x, bounds_.min.x, nx_), at(p.y, bounds_.min.y, ny_), at(p.z, bounds_.min.z, nz_)};
}

void BoxGrid3::insert(std::uint32_t id, const BBox3& box) {
  if (cells_.empty()) throw Error("a box grid without cells cannot list boxes");
  if (box.empty()) return;
  const Index lo = index(box.min), hi = index(box.max);
  for (int k = lo.k; k <= hi.k; ++k)
    for (int j = lo.j; j <= hi.j; ++j)
      for (int i = lo.i; i <= hi.i; ++i) cells_[(static_cast<std::size_t>(k) * ny_ + j) * nx_ + i].push_back(id);
}

}  // namespace selfsim
