#include "kernels/exclusion/wall_reach.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace selfsim::exclusion {

namespace {

// A part of a fan triangle: its corners, and the weight the moving point has at each (a point of the part
// moves at most the largest of them times as far as the moving point does).
struct Part {
  std::array<Vec3, 3> at;
  std::array<double, 3> weight;
};

// How far the point may step from p while every point of the fan, of moving weight c, keeps an interpolated
// clearance of `r + margin·c` (negative when a part already has less). Each part's clearance is bounded
// below by its centroid's less slope times its farthest corner; the part may step (bound − keep) / (slope·c)
// with c and keep its largest weight's. A part that allows less than `wanted` is split 1 -> 4 while its
// bound's slack (slope times its size) is more than half its room beyond keep, down to max_wall_depth.
// Parts are measured a generation at a time, so one grid accessor serves each generation.
double safe_step(const FanMove& f, Vec3 p, const WallGrid& walls, double r, double margin, double wanted) {
  std::vector<Part> parts, next;
  const std::size_t n = f.ring.size(), triangles = f.closed ? n : n - 1;
  for (std::size_t i = 0; i < triangles; ++i) parts.push_back({{f.ring[i], f.ring[(i + 1) % n], p}, {0, 0, 1}});
  std::vector<Vec3> centroids;
  std::vector<double> clear;
  double step = unbounded;
  for (int depth = 0; !parts.empty(); ++depth) {
    centroids.clear();
    for (const Part& q : parts) centroids.push_back((1.0 / 3) * (q.at[0] + q.at[1] + q.at[2]));
    clear.resize(parts.size());
    walls.clearances(centroids, clear);
    next.clear();
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const Part& q = parts[k];
      const Vec3 g = centroids[k];
      const double far = std::max({norm(q.at[0] - g), norm(q.at[1] - g), norm(q.at[2] - g)});
      const double c = std::max({q.weight[0], q.weight[1], q.weight[2]}), keep = r + margin * c;
      const double slack = WallGrid::slope * far, room = clear[k] - keep;
      const double allows = c > 0 ? (room - slack) / (WallGrid::slope * c) : room - slack >= 0 ? unbounded : -1;
      if (allows >= wanted || slack <= 0.5 * room || room <= 0 || depth == max_wall_depth) {
        step = std::min(step, allows);
        continue;
      }
      auto mid = [&](int i, int j) { return std::pair{0.5 * (q.at[i] + q.at[j]), 0.5 * (q.weight[i] + q.weight[j])}; };
      const auto [m01, w01] = mid(0, 1);
      const auto [m12, w12] = mid(1, 2);
      const auto [m20, w20] = mid(2, 0);
      next.push_back({{q.at[0], m01, m20}, {q.weight[0], w01, w20}});
      next.push_back({{m01, q.at[1], m12}, {w01, q.weight[1], w12}});
      next.push_back({{m20, m12, q.at[2]}, {w20, w12, q.weight[2]}});
      next.push_back({{m01, m12, m20}, {w01, w12, w20}});
    }
    parts.swap(next);
  }
  return step;
}

// How far the point may go from m along `dir` (a unit vector) before `limit`, the reach already found (finite).
// A move the walls stop is stopped where the moving point keeps r plus a quarter of its half edge, not r: a
// point left exactly at r would leave its neighbours' fans, which share it as a static corner, no room for
// any bound to prove (each loses slope times its parts' size), and so no move at all. A fan already nearer
// than that margin may still move while it keeps r.
double side_reach(const FanMove& f, Vec3 dir, const WallGrid& walls, double r, double h, double limit) {
  constexpr int most_steps = 256;
  double t = 0, margin = 0.25 * h;
  for (int step = 0; step < most_steps && t < limit; ++step) {
    const double wanted = limit - t;
    double safe = safe_step(f, f.m + t * dir, walls, r, margin, wanted);
    if (step == 0 && safe < 0 && margin > 0) safe = safe_step(f, f.m, walls, r, margin = 0, wanted);
    if (safe >= wanted) return limit;
    if (!(safe > 1e-2 * h)) return t;
    t += safe;
  }
  return std::min(t, limit);
}

}  // namespace

void limit_by_walls(const FanMove& f, const WallGrid& walls, double r, double h, double far, Reach& reach) {
  reach.positive = std::min(reach.positive, far), reach.negative = std::min(reach.negative, far);
  reach.positive = side_reach(f, f.d, walls, r, h, reach.positive);
  reach.negative = side_reach(f, -f.d, walls, r, h, reach.negative);
}

}  // namespace selfsim::exclusion
