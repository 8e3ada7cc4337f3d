#include "kernels/geom/polyline.h"

namespace selfsim {

Polyline Polyline::single(std::vector<Vec2> pts, int level) {
  Polyline c;
  c.points = std::move(pts);
  c.level = level;
  c.close_path();
  return c;
}

std::size_t Polyline::segments() const {
  std::size_t n = 0;
  for (std::size_t i = 0; i < paths(); ++i) {
    const std::size_t k = path(i).size();
    n += k > 0 ? k - 1 : 0;
  }
  return n;
}

double Polyline::length() const {
  double total = 0;
  for (std::size_t i = 0; i < paths(); ++i) {
    const auto p = path(i);
    for (std::size_t j = 1; j < p.size(); ++j) total += norm(p[j] - p[j - 1]);
  }
  return total;
}

bool Polyline::finite() const {
  // No early exit, so the loop stays branch-free: x - x is 0 for a finite x and NaN otherwise.
  bool ok = true;
  for (const Vec2& p : points) ok &= (p.x - p.x == 0) & (p.y - p.y == 0);
  return ok;
}

void Polyline::close_path() {
  const std::size_t begin = path_ends.empty() ? 0 : path_ends.back();
  if (points.size() > begin) path_ends.push_back(points.size());
}

Polyline transformed(const Polyline& c, const Similarity2& t) {
  Polyline out = c;
  for (Vec2& p : out.points) p = t(p);
  return out;
}

}  // namespace selfsim
