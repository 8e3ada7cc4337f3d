#include "kernels/exclusion/query_marks.h"

#include <algorithm>
#include <bit>

namespace selfsim::exclusion {

bool EdgeMarks::first_visit(std::uint32_t a, std::uint32_t b) {
  const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
  if (2 * (used_ + 1) > slots_.size()) grow();
  std::size_t i = (key * 0x9e3779b97f4a7c15ull) >> shift_;
  for (;; i = (i + 1) & (slots_.size() - 1)) {
    Slot& s = slots_[i];
    if (s.query != query_) {
      s = {key, query_};
      ++used_;
      return true;
    }
    if (s.key == key) return false;
  }
}

void EdgeMarks::next_query() {
  used_ = 0;
  if (++query_ == 0) {  // wrapped: forget every old mark
    std::fill(slots_.begin(), slots_.end(), Slot{});
    query_ = 1;
  }
}

void EdgeMarks::grow() {
  std::vector<Slot> old = std::move(slots_);
  slots_.assign(std::max<std::size_t>(1024, 2 * old.size()), Slot{});
  shift_ = 64 - std::countr_zero(slots_.size());
  used_ = 0;
  for (const Slot& s : old)
    if (s.query == query_) first_visit(static_cast<std::uint32_t>(s.key >> 32), static_cast<std::uint32_t>(s.key));
}

void Query::fit(std::size_t triangles, std::size_t boundary, std::size_t points) {
  if (seen.size() == triangles && boundary_seen.size() == boundary && vertex_seen.size() == points) return;
  seen.assign(triangles, 0);
  boundary_seen.assign(boundary, 0);
  vertex_seen.assign(points, 0);
  piece_stamp.assign(points, 0);
  piece_slot.assign(points, 0);
  along.assign(points, 0);
  along_stamp.assign(points, 0);
  stamp = 0;
}

void Query::next() {
  edges.next_query();
  if (++stamp == 0) {  // wrapped: forget every old mark
    std::fill(seen.begin(), seen.end(), 0);
    std::fill(boundary_seen.begin(), boundary_seen.end(), 0);
    std::fill(vertex_seen.begin(), vertex_seen.end(), 0);
    std::fill(piece_stamp.begin(), piece_stamp.end(), 0);
    std::fill(along_stamp.begin(), along_stamp.end(), 0);
    stamp = 1;
  }
  pieces.clear();
}

bool Query::first_visit(std::uint32_t vertex) {
  if (vertex_seen[vertex] == stamp) return false;
  vertex_seen[vertex] = stamp;
  return true;
}

std::array<VertexPieces*, 3> Query::pieces_of(const std::array<std::uint32_t, 3>& corners) {
  for (std::uint32_t v : corners)
    if (piece_stamp[v] != stamp) {
      piece_stamp[v] = stamp;
      piece_slot[v] = static_cast<std::uint32_t>(pieces.size());
      pieces.emplace_back();
    }
  // Taken once the vector has stopped growing.
  return {&pieces[piece_slot[corners[0]]], &pieces[piece_slot[corners[1]]], &pieces[piece_slot[corners[2]]]};
}

}  // namespace selfsim::exclusion
