#include "kernels/exclusion/wall_reach.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace selfsim::exclusion {

namespace {

using Corners = std::array<Vec3, 3>;

// A lower bound of the least interpolated clearance over the fan's triangles with the point at p, refined
// where it falls below what a step of `wanted` needs, or half the room the triangles' centroids show beyond
// r, whichever is less (where the walls are near, no bound proves more; where they are far, a coarse one
// does). Parts are measured a generation at a time, so one grid accessor serves each generation.
double least_clearance(const FanMove& f, Vec3 p, const WallGrid& walls, double r, double wanted) {
  std::vector<Corners> parts, next;
  const std::size_t n = f.ring.size(), triangles = f.closed ? n : n - 1;
  for (std::size_t i = 0; i < triangles; ++i) parts.push_back({f.ring[i], f.ring[(i + 1) % n], p});
  std::vector<Vec3> centroids;
  std::vector<double> clear;
  double least = unbounded, enough = unbounded;
  for (int depth = 0; !parts.empty(); ++depth) {
    centroids.clear();
    for (const Corners& c : parts) centroids.push_back((1.0 / 3) * (c[0] + c[1] + c[2]));
    clear.resize(parts.size());
    walls.clearances(centroids, clear);
    if (depth == 0) {
      const double room = *std::min_element(clear.begin(), clear.end()) - r;
      enough = r + std::min(WallGrid::slope * wanted, 0.5 * room);
    }
    next.clear();
    for (std::size_t k = 0; k < parts.size(); ++k) {
      const Corners& c = parts[k];
      const Vec3 g = centroids[k];
      const double far = std::max({norm(c[0] - g), norm(c[1] - g), norm(c[2] - g)});
      const double bound = clear[k] - WallGrid::slope * far;
      if (bound >= enough || clear[k] <= r || depth == max_wall_depth) {
        least = std::min(least, bound);
        continue;
      }
      const Vec3 m01 = 0.5 * (c[0] + c[1]), m12 = 0.5 * (c[1] + c[2]), m20 = 0.5 * (c[2] + c[0]);
      for (const Corners& s :
           {Corners{c[0], m01, m20}, Corners{m01, c[1], m12}, Corners{m20, m12, c[2]}, Corners{m01, m12, m20}})
        next.push_back(s);
    }
    parts.swap(next);
  }
  return least;
}

// How far the point may go from m along `dir` (a unit vector) before `limit`, the reach already found (finite).
double side_reach(const FanMove& f, Vec3 dir, const WallGrid& walls, double r, double h, double limit) {
  constexpr int most_steps = 64;
  double t = 0;
  for (int step = 0; step < most_steps && t < limit; ++step) {
    const double wanted = limit - t;
    const double safe = (least_clearance(f, f.m + t * dir, walls, r, wanted) - r) / WallGrid::slope;
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
