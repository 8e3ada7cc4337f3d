// Every pair of triangles that meet, up to a limit, and the same sorted into kinds (mesh_intersections.h):
// the print check's survey of self-contact (kernels/print/self_contact.h). The grid of candidates is
// first_intersection's (candidate_grid.h).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "kernels/geom/candidate_grid.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/geom/triangle_contact.h"

namespace selfsim {

using namespace candidate_grid;

namespace {

using Kind = std::function<int(std::uint32_t, std::uint32_t)>;

// The least `limit` of `pairs` (first << 32 | second), sorted.
void keep_least(std::vector<std::uint64_t>& pairs, std::size_t limit) {
  std::sort(pairs.begin(), pairs.end());
  if (pairs.size() > limit) pairs.resize(limit);
}

// Every pair that meets, by kind (none: all of kind 0), in the chunks of whole batches while some kind has
// fewer than `limit` (each kind then keeps its least `limit`): which pairs does not depend on the threads,
// as the batches are fixed.
std::vector<std::vector<TrianglePair>> gather_pairs(const Candidates& c, std::size_t limit, int kinds, const Kind* kind,
                                                    Progress& progress) {
  const Grid& grid = c.grid;
  const std::vector<std::uint64_t>& records = c.records;
  const std::size_t total = records.size(), chunk = 1 << 13, chunks = (total + chunk - 1) / chunk;
  const std::uint64_t id_mask = (std::uint64_t{1} << grid.id_bits) - 1;
  auto cell_start = [&](std::size_t k) {
    while (k > 0 && k < total && (records[k] >> grid.id_bits) == (records[k - 1] >> grid.id_bits)) ++k;
    return std::min(k, total);
  };
  const auto full = [&](const std::vector<std::vector<std::uint64_t>>& by_kind) {
    return std::all_of(by_kind.begin(), by_kind.end(), [&](const auto& v) { return v.size() >= limit; });
  };
  std::vector<std::vector<std::vector<std::uint64_t>>> found(chunks);
  std::vector<std::vector<std::uint64_t>> pairs(kinds);
  const std::size_t batch = std::max<std::size_t>(chunks / 32, 16);
  for (std::size_t begin = 0; begin < chunks && !full(pairs); begin += batch) {
    const std::size_t end = std::min(chunks, begin + batch);
    tbb::parallel_for(begin, end, [&](std::size_t k0) {
      struct Entry {
        std::uint32_t id;
        unsigned starts;  // bit a: the box starts in this cell on axis a
        ContactTriangle tri;
      };
      std::vector<Entry> in;
      std::vector<std::vector<std::uint64_t>>& out = found[k0];
      out.resize(kinds);
      const std::size_t to = cell_start((k0 + 1) * chunk);
      for (std::size_t k = cell_start(k0 * chunk); k < to && !full(out);) {
        const std::uint64_t key = records[k] >> grid.id_bits;
        const Cell here = Grid::cell_of(key);
        in.clear();
        for (; k < to && (records[k] >> grid.id_bits) == key; ++k) {
          const auto j = static_cast<std::uint32_t>(records[k] & id_mask);
          const Cell low = grid.low(c.boxes[j]);
          in.push_back(
              {j, unsigned(low[0] == here[0]) | unsigned(low[1] == here[1]) << 1 | unsigned(low[2] == here[2]) << 2,
               ContactTriangle(c.corners(j))});
        }
        for (std::size_t x = 0; x + 1 < in.size(); ++x)
          for (std::size_t y = x + 1; y < in.size(); ++y) {
            const Entry& p = in[x];
            const Entry& q = in[y];
            // Once a pair: in the cell at the low corner of the boxes' overlap.
            if ((p.starts | q.starts) != 7 || !overlap(c.boxes[p.id], c.boxes[q.id])) continue;
            if (!triangles_meet(c.corners.m.triangles[p.id], c.corners.m.triangles[q.id], p.tri, q.tri,
                                Candidates::eps))
              continue;
            const int k_of = kind != nullptr ? (*kind)(p.id, q.id) : 0;
            if (k_of < 0 || k_of >= kinds || out[k_of].size() >= limit) continue;
            out[k_of].push_back(std::uint64_t{p.id} << 32 | q.id);
          }
      }
    });
    for (std::size_t k = begin; k < end; ++k) {
      for (int i = 0; i < kinds; ++i) pairs[i].insert(pairs[i].end(), found[k][i].begin(), found[k][i].end());
      std::vector<std::vector<std::uint64_t>>().swap(found[k]);
    }
    for (auto& p : pairs) keep_least(p, limit);  // memory bounded by `limit` a kind, whatever the batches find
    progress.step(0.2 + 0.8 * double(end) / double(chunks));
  }
  std::vector<std::vector<TrianglePair>> out(kinds);
  for (int i = 0; i < kinds; ++i) {
    out[i].reserve(pairs[i].size());
    for (std::uint64_t p : pairs[i]) out[i].push_back(c.pair(std::uint32_t(p >> 32), std::uint32_t(p)));
  }
  return out;
}

std::vector<std::vector<TrianglePair>> search(const Mesh& m, std::size_t limit, int kinds, const Kind* kind,
                                              Progress& progress) {
  progress.start("intersections");
  check_input(m);
  if (m.triangles.size() < 2 || limit == 0 || kinds <= 0)
    return std::vector<std::vector<TrianglePair>>(std::max(kinds, 0));
  BBox3 bounds;
  const double size = diagonal_of(m, bounds);
  const Candidates c(m, bounds, size, progress);
  return gather_pairs(c, limit, kinds, kind, progress);
}

}  // namespace

std::vector<TrianglePair> intersecting_pairs(const Mesh& m, std::size_t limit, Progress& progress) {
  return std::move(search(m, limit, 1, nullptr, progress)[0]);
}

std::vector<std::vector<TrianglePair>> classified_pairs(const Mesh& m, std::size_t limit, int kinds, const Kind& kind,
                                                        Progress& progress) {
  return search(m, limit, kinds, &kind, progress);
}

}  // namespace selfsim
