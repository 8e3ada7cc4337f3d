#include "kernels/exclusion/original_chains.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>

#include "kernels/base/error.h"
#include "kernels/exclusion/chain_order.h"
#include "kernels/exclusion/start_check.h"

namespace selfsim::exclusion::original {

Chains::Chains(const Region& region, const Polyline& start, double scale, bool brute_force, double points)
    : brute_force_(brute_force) {
  const auto room = static_cast<std::size_t>(points) + region.edges();
  at_.reserve(room);
  next_.reserve(room);
  level_.reserve(room);
  auto add_chain = [&](std::span<const Vec2> p, bool loop, int level) {
    const auto first = static_cast<std::uint32_t>(at_.size());
    const auto n = static_cast<std::uint32_t>(p.size());
    for (std::uint32_t k = 0; k < n; ++k) {
      at_.push_back(scale * p[k]);
      next_.push_back(k + 1 < n ? first + k + 1 : loop ? first : no_vertex);
      level_.push_back(level);
    }
    return first;
  };
  for (const std::vector<Vec2>& ring : region.rings()) add_chain(ring, true, -1);
  boundary_ = at_.size();
  for (std::size_t i = 0; i < start.paths(); ++i) {
    const auto p = start.path(i);
    const bool loop = exact_loop(p);  // as check_start reads it
    first_.push_back(add_chain(loop ? p.first(p.size() - 1) : p, loop, 0));
    closed_.push_back(loop);
  }
  out_.assign(at_.size(), no_vertex);
}

std::vector<std::uint32_t> Chains::chain(std::size_t i) const { return chain_vertices(first_[i], next_, no_vertex); }

void Chains::renumber() {
  std::vector<std::uint32_t> order(boundary_);  // old numbers in their new order
  for (std::uint32_t v = 0; v < boundary_; ++v) order[v] = v;
  append_chains(order, first_, next_, no_vertex);
  permute(at_, order);
  permute(next_, order);
  permute(level_, order);
  relink(next_, order, no_vertex);
}

std::uint32_t Chains::add_segment(Vec2 p, Vec2 q) {
  const auto id = static_cast<std::uint32_t>(from_.size());
  from_.push_back(p);
  to_.push_back(q);
  alive_.push_back(1);
  seen_.push_back(0);
  if (grid_.covers(p) && grid_.covers(q))
    grid_.add_segment(id, p, q);
  else
    outside_segments_.push_back(id);
  return id;
}

void Chains::list_vertex(std::uint32_t v) {
  if (grid_.covers(at_[v]))
    grid_.add_vertex(v, at_[v]);
  else
    outside_vertices_.push_back(v);
}

void Chains::begin_level(double r) {
  if (brute_force_) return;
  renumber();
  BBox2 bounds;
  double length = 0, segments = 0, shortest = std::numeric_limits<double>::infinity();
  for (std::uint32_t v = 0; v < at_.size(); ++v) {
    bounds.add(at_[v]);
    if (next_[v] == no_vertex) continue;
    const double l = norm(at_[next_[v]] - at_[v]);
    shortest = std::min(shortest, l);
    if (v >= boundary_) length += l, ++segments;
  }
  // A split's halves are at least h = half its segment long (the point moves along the bisector).
  shortest_ = 0.49 * shortest;
  size_ = std::max(largest_coordinate(bounds), std::max(bounds.size().x, bounds.size().y));
  // Cells of the radius or twice the mean segment, whichever is larger (measured fastest in Figure 3's
  // conditions among 1 to 4 times either, for factors 0.3 to 0.95).
  const double mean = segments > 0 ? length / segments : 0;
  grid_.reset(bounds, std::max({r, 2 * mean, 1e-6 * size_}));
  from_.clear();
  to_.clear();
  alive_.clear();
  seen_.clear();
  walks_ = 0;
  outside_vertices_.clear();
  outside_segments_.clear();
  for (std::uint32_t v = 0; v < at_.size(); ++v) {
    list_vertex(v);
    out_[v] = next_[v] == no_vertex ? no_vertex : add_segment(at_[v], at_[next_[v]]);
  }
  grid_.pack(alive_);
}

// His loop: every vertex of every chain but a, vertex-tested unless it is b, and its segment tested.
void Chains::limits_brute(const Frame& f, std::uint32_t a, std::uint32_t b, Limits& l) const {
  for (std::uint32_t v = 0; v < at_.size(); ++v) {
    if (v == a) continue;
    if (v != b) vertex_test(f, at_[v], l);
    if (next_[v] != no_vertex) segment_test(f, at_[v], at_[next_[v]], l);
  }
}

double Chains::split(std::uint32_t a, double r, int level) {
  const std::uint32_t b = next_[a];
  const Frame f(at_[a], at_[b], r);
  Limits l;
  if (brute_force_)
    limits_brute(f, a, b, l);
  else
    limits_grid(f, a, b, l);
  const double t = l.chosen();
  if (!(std::abs(t) < unbounded))
    throw Error("the original rule found nothing to stop a point on one side at level " + std::to_string(level) +
                " (the curve has left the region)");
  const auto p = static_cast<std::uint32_t>(at_.size());
  at_.push_back(f.at(t));
  level_.push_back(level);
  next_.push_back(b);
  next_[a] = p;
  out_.push_back(no_vertex);
  if (!brute_force_) {
    alive_[out_[a]] = 0;
    out_[a] = add_segment(at_[a], at_[p]);
    out_[p] = add_segment(at_[p], at_[b]);
    list_vertex(p);
    // Packed again once a fifth as much has been added (a few times a level), dropping dead segments.
    if (grid_.added() > std::max<std::size_t>(4096, grid_.packed() / 5)) grid_.pack(alive_);
  }
  return t;
}

Polyline Chains::result(const Polyline& start, double scale) const {
  Polyline out;
  std::vector<std::int32_t> level, curve;
  for (std::size_t i = 0; i < curves(); ++i) {
    std::vector<std::uint32_t> c = chain(i);
    if (closed_[i]) c.push_back(c.front());
    const auto given = start.path(i);
    std::size_t k = 0;
    for (std::uint32_t v : c) {
      out.points.push_back(level_[v] == 0 ? given[k++] : (1 / scale) * at_[v]);
      level.push_back(level_[v]);
    }
    out.close_path();
    curve.push_back(static_cast<std::int32_t>(i + 1));
  }
  out.point_fields.set(int_field("level", std::move(level)));
  out.cell_fields.set(int_field("curve", std::move(curve)));
  return out;
}

}  // namespace selfsim::exclusion::original
