#include "kernels/hoist/symmetric_controls.h"

#include <cmath>
#include <string>

#include "kernels/base/error.h"

namespace selfsim::hoist {

namespace {

template <class Image>
std::vector<Vec2> symmetric(const std::vector<Vec2>& half, Image image) {
  if (half.size() < 2)
    throw Error("needs at least 2 points (the first half of the control points), got " + std::to_string(half.size()));
  if (norm(half.front()) > 1e-12) throw Error("the first control point must be (0,0)");
  for (Vec2 p : half)
    if (!is_finite(p)) throw Error("the control points must be finite");
  std::vector<Vec2> out = half;
  const bool middle = norm(image(half.back()) - half.back()) <= 1e-12;
  for (std::size_t i = half.size() - (middle ? 1 : 0); i-- > 0;) out.push_back(image(half[i]));
  out.front() = {0, 0};
  out.back() = {1, 0};
  return out;
}

}  // namespace

std::vector<Vec2> mirror_controls(const std::vector<Vec2>& half) {
  return symmetric(half, [](Vec2 p) { return Vec2{1 - p.x, p.y}; });
}

std::vector<Vec2> rotate_controls(const std::vector<Vec2>& half) {
  return symmetric(half, [](Vec2 p) { return Vec2{1 - p.x, -p.y}; });
}

}  // namespace selfsim::hoist
