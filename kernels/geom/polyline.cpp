#include "kernels/geom/polyline.h"

#include <algorithm>

#include "kernels/geom/all_finite.h"
#include "kernels/geom/length_fields.h"

namespace selfsim {

template <class V>
PolylineT<V> PolylineT<V>::single(const std::vector<V>& pts) {
  PolylineT c;
  c.points.assign(pts.begin(), pts.end());
  c.close_path();
  return c;
}

template <class V>
std::size_t PolylineT<V>::segments() const {
  std::size_t n = 0;
  for (std::size_t i = 0; i < paths(); ++i) {
    const std::size_t k = path(i).size();
    n += k > 0 ? k - 1 : 0;
  }
  return n;
}

template <class V>
double PolylineT<V>::length() const {
  double total = 0;
  for (std::size_t i = 0; i < paths(); ++i) {
    const auto p = path(i);
    for (std::size_t j = 1; j < p.size(); ++j) total += norm(p[j] - p[j - 1]);
  }
  return total;
}

template <class V>
bool PolylineT<V>::finite() const {
  return all_finite<V>(points);
}

template <class V>
bool PolylineT<V>::paths_consistent() const {
  std::size_t begin = 0;
  for (std::size_t end : path_ends) {
    if (end <= begin) return false;
    begin = end;
  }
  return begin == points.size();
}

template <class V>
void PolylineT<V>::close_path() {
  const std::size_t begin = path_ends.empty() ? 0 : path_ends.back();
  if (points.size() > begin) path_ends.push_back(points.size());
}

template <class V>
std::size_t PolylineT<V>::bytes() const {
  return points.capacity() * sizeof(V) + path_ends.capacity() * sizeof(std::size_t) + point_fields.bytes() +
         cell_fields.bytes();
}

template struct PolylineT<Vec2>;
template struct PolylineT<Vec3>;

Polyline transformed(const Polyline& c, const Similarity2& t) {
  Polyline out = c;
  for (Vec2& p : out.points) p = t(p);
  scale_length_fields(out.point_fields, norm(t.a));
  return out;
}

bool closed_path(std::span<const Vec2> p) {
  if (p.size() < 3) return false;
  BBox2 box;
  for (Vec2 q : p) box.add(q);
  return norm(p.back() - p.front()) <= 1e-9 * std::max(1e-300, norm(box.size()));
}

}  // namespace selfsim
