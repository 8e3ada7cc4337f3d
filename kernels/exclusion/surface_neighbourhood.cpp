// The moving point's own neighbourhood under the neighbourhood rule (exclusion_surface.h): the vertices
// within a reach of it along the edges of the mesh as the level's split left it. Measured on the split mesh,
// so the same for every move of the level whatever the order of moves.
#include <algorithm>
#include <cmath>
#include <functional>

#include "kernels/exclusion/surface_net.h"

namespace selfsim::exclusion {

namespace {

// Dijkstra from `start` along each vertex's edges (links[first[v]] ... links[first[v + 1]]), out to `reach`:
// `distance(v)` is v's best distance so far (infinite when none), `improve(v, d)` records a better one, and
// `settle(d)` sees each vertex's final distance once, nearest first.
template <class Links, class Distance, class Improve, class Settle>
void walk_edges(const std::vector<std::uint32_t>& first, const Links& links, std::uint32_t start, double reach,
                std::vector<std::pair<double, std::uint32_t>>& heap, Distance distance, Improve improve,
                Settle settle) {
  const auto later = std::greater<std::pair<double, std::uint32_t>>();
  improve(start, 0.0);
  heap.assign(1, {0.0, start});
  while (!heap.empty()) {
    std::pop_heap(heap.begin(), heap.end(), later);
    const auto [dv, v] = heap.back();
    heap.pop_back();
    if (dv > distance(v)) continue;  // reached again by a shorter path
    settle(dv);
    for (std::uint32_t i = first[v]; i < first[v + 1]; ++i) {
      const auto [w, length] = links[i];
      const double dw = dv + length;
      if (dw > reach || dw >= distance(w)) continue;
      improve(w, dw);
      heap.push_back({dw, w});
      std::push_heap(heap.begin(), heap.end(), later);
    }
  }
}

}  // namespace

void Surfaces::link_edges(double r) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;
  ends.reserve(6 * triangles_.size());
  for (const Triangle& t : triangles_)
    for (int k = 0; k < 3; ++k) ends.push_back({t[k], t[(k + 1) % 3]}), ends.push_back({t[(k + 1) % 3], t[k]});
  std::sort(ends.begin(), ends.end());
  ends.erase(std::unique(ends.begin(), ends.end()), ends.end());
  link_start_.assign(points_.size() + 1, 0);
  for (const auto& e : ends) ++link_start_[e.first + 1];
  for (std::size_t v = 0; v < points_.size(); ++v) link_start_[v + 1] += link_start_[v];
  links_.clear();
  for (const auto& [a, b] : ends) links_.push_back({b, norm(points_[b] - points_[a])});
  whole_ = surfaces_within(along_ * r);
}

std::vector<char> Surfaces::surfaces_within(double reach) const {
  // From one vertex of each surface, the farthest any of its vertices lies along the edges: no two of its
  // vertices are farther apart than twice that.
  std::vector<double> along(points_.size(), unbounded);
  std::vector<std::pair<double, std::uint32_t>> heap;
  std::vector<double> farthest;
  std::vector<std::int32_t> surface_of(points_.size(), 0);
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    for (std::uint32_t v : triangles_[t]) surface_of[v] = surface_[t];
  for (std::uint32_t start = 0; start < points_.size(); ++start) {
    const auto s = static_cast<std::size_t>(surface_of[start]);
    if (s == 0 || (s < farthest.size() && farthest[s] >= 0)) continue;  // not a surface's, or done
    if (farthest.size() <= s) farthest.resize(s + 1, -1);
    double far = 0;
    walk_edges(
        link_start_, links_, start, unbounded, heap, [&](std::uint32_t v) { return along[v]; },
        [&](std::uint32_t v, double d) { along[v] = d; }, [&](double d) { far = std::max(far, d); });
    farthest[s] = far;
  }
  std::vector<char> whole(farthest.size(), 0);
  for (std::size_t s = 0; s < farthest.size(); ++s) whole[s] = farthest[s] >= 0 && 2 * farthest[s] <= reach;
  return whole;
}

void Surfaces::mark_neighbourhood(const Midpoint& mid, double reach, Query& q) const {
  walk_edges(
      link_start_, links_, mid.vertex, reach, q.heap,
      [&](std::uint32_t v) { return q.along_stamp[v] == q.stamp ? q.along[v] : unbounded; },
      [&](std::uint32_t v, double d) { q.along[v] = d, q.along_stamp[v] = q.stamp; }, [](double) {});
}

}  // namespace selfsim::exclusion
