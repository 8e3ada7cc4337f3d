// The growing exclusion surfaces of one run (seed 004 in 3D): their points and triangles, each level's
// midpoints with the fan of triangles around each, and every triangle of the surfaces and of the region's
// boundary in a grid, so that a move measures only the triangles near it. exclusion_surface.cpp drives it
// level by level; fan_reach.h measures each obstacle.
#pragma once

#include <tbb/enumerable_thread_specific.h>

#include <array>
#include <cstdint>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/exclusion/fan_reach.h"
#include "kernels/exclusion/level_report.h"
#include "kernels/exclusion/query_marks.h"
#include "kernels/geom/box_grid3.h"
#include "kernels/geom/mesh.h"
#include "kernels/region/wall_grid.h"

namespace selfsim::exclusion {

// One midpoint of a level: its vertex, its line, and the fan of new triangles around it.
struct Midpoint {
  std::uint32_t vertex = 0;
  Vec3 d;                               // the line's unit direction (its positive side)
  double h = 0;                         // half its edge's length
  std::array<std::uint32_t, 6> ring{};  // the fan's other corners in order around the point
  std::array<std::uint32_t, 6> fan{};   // the fan's triangles
  int ring_size = 0, fan_size = 0;
  bool closed = false;  // an edge inside a surface: the ring goes all the way round
};

class Surfaces {
 public:
  // `boundary`: the region's closed, outward-oriented boundary; `start`: the surfaces to grow. Reserves
  // room for `points` points and `triangles` triangles.
  Surfaces(const Mesh& boundary, const Mesh& start, double points, double triangles);

  // Splits every triangle 1 -> 4 with the new points on its edges, and lists the midpoints; cells of the
  // neighbour grid sized for radius r.
  void subdivide(int level, double r);
  std::size_t midpoints() const { return mids_.size(); }
  // Moves every midpoint of the level as far as radius r allows, round by round (see order_rounds): the
  // moves of a round are measured in parallel and kept in order, each measured again if an earlier one of
  // its round changed what it measured. The same result for any number of threads, and the same as moving
  // them one after another in that order (speculate = false, for tests).
  void grow(double r, LevelReport& report, Progress& progress, bool speculate = true);
  // Round cells `factor` times a move's usual reach instead of 2 (tests make rounds collide with small ones).
  void set_round_cells(double factor) { round_cells_ = factor; }
  // The moving point's own neighbourhood (exclusion_surface.h, SurfaceOptions): the vertices within
  // `along` radii of it along the mesh's edges, whose pieces already closer than the radius need only keep
  // `close` radii. along = 0: no neighbourhood (the rule before issue 23).
  void set_neighbourhood(double along, double close) { along_ = along, close_ = close; }
  // Walls measured on this distance grid (which must outlive the surfaces) instead of the boundary's
  // triangles (wall_reach.h). Before the first subdivide.
  void set_walls(const WallGrid* walls) { walls_ = walls; }
  Mesh result() const;
  // Each triangle's surface, from 1 (the start's face-connected pieces).
  const std::vector<std::int32_t>& surfaces() const { return surface_; }
  double area() const;

 private:
  // How far mid may move, with q's marks; `looked` grows to cover every box it measured in.
  Reach reach(const Midpoint& mid, double r, Query& q, BBox3& looked) const;
  // The level's order: rounds of midpoints in cells of twice `reach`, cells of one colour (the parities of
  // their coordinates) together, the k-th midpoint (in edge order) of each cell in round k of its colour.
  void order_rounds(double reach);
  // A surface triangle, or a boundary triangle (id with boundary_bit), as an obstacle.
  Obstacle obstacle(std::uint32_t id) const;
  // Marks in q the vertices within `reach` of mid's vertex along the edges of the level's split mesh
  // (Dijkstra).
  void mark_neighbourhood(const Midpoint& mid, double reach, Query& q) const;
  // Each vertex's edges with their lengths as split (surface_neighbourhood.cpp), and whole_, for radius r.
  void link_edges(double r);
  // By surface number: whether every two of its vertices lie within `reach` of each other along the edges
  // (then its neighbourhood is the whole surface, and no move needs to search it).
  std::vector<char> surfaces_within(double reach) const;
  BBox3 triangle_box(std::uint32_t t) const;

  const Mesh& boundary_;
  std::vector<Vec3> points_;
  std::vector<std::int32_t> level_;
  std::vector<Triangle> triangles_;
  std::vector<std::int32_t> surface_;
  std::vector<Midpoint> mids_;
  struct Link {
    std::uint32_t to;
    double length;  // as the level's split left it
  };
  std::vector<std::uint32_t> link_start_;  // each vertex's edges: links_[link_start_[v] ...]
  std::vector<Link> links_;
  std::vector<char> whole_;  // by surface: every two of its vertices lie within the neighbourhood
  BoxGrid3 grid_;
  std::vector<std::uint32_t> order_;  // the midpoints in the order they move
  std::vector<std::size_t> rounds_;   // where each round starts in order_, and the end
  double round_cells_ = 2;
  double along_ = 0, close_ = 0;
  const WallGrid* walls_ = nullptr;
  tbb::enumerable_thread_specific<Query> queries_;
  double far_;  // no point moves farther than this: twice the region's diagonal
};

}  // namespace selfsim::exclusion
