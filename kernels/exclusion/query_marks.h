// What one move of the exclusion surface (surface_net.h) has measured already: the triangles, vertices and
// edges it met, marked with the move's number so that nothing is measured twice and nothing needs clearing
// between moves. One per thread.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "kernels/exclusion/fan_reach.h"

namespace selfsim::exclusion {

// The edges (vertex pairs) a query has measured: an open-addressed table whose marks expire with the query.
class EdgeMarks {
 public:
  // True the first time edge a-b (either way round) is seen in this query.
  bool first_visit(std::uint32_t a, std::uint32_t b);
  void next_query();

 private:
  struct Slot {
    std::uint64_t key = 0;
    std::uint32_t query = 0;
  };
  void grow();
  std::vector<Slot> slots_;
  std::uint32_t query_ = 1;
  std::size_t used_ = 0;
  int shift_ = 64;
};

// One move's marks (per thread): which triangles, boundary triangles, vertices and edges it has measured,
// stamped with the move's number, its list of obstacles near, and the sets its obstacles' corners share.
struct Query {
  std::uint32_t stamp = 0;
  std::vector<std::uint32_t> seen, boundary_seen, vertex_seen, piece_stamp, piece_slot;
  std::vector<VertexPieces> pieces;                    // this move's, in piece_slot order
  std::vector<std::pair<double, std::uint32_t>> near;  // box gap, id
  EdgeMarks edges;
  // The moving point's neighbourhood: each vertex's distance from it along the mesh's edges, valid where
  // along_stamp is the move's stamp; and the search's heap.
  std::vector<double> along;
  std::vector<std::uint32_t> along_stamp;
  std::vector<std::pair<double, std::uint32_t>> heap;

  bool within(std::uint32_t vertex, double reach) const {
    return along_stamp[vertex] == stamp && along[vertex] <= reach;
  }

  // Sizes the marks for a level's triangles, boundary triangles and points (clearing them if they change).
  void fit(std::size_t triangles, std::size_t boundary, std::size_t points);
  void next();
  // True the first time a move meets this vertex.
  bool first_visit(std::uint32_t vertex);
  // The shared sets of an obstacle's corners for this move (fan_reach.h), valid until the next call.
  std::array<VertexPieces*, 3> pieces_of(const std::array<std::uint32_t, 3>& corners);
};

}  // namespace selfsim::exclusion
