#include "kernels/geom/mesh_intersections.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/base/huge_pages.h"
#include "kernels/geom/candidate_grid.h"
#include "kernels/geom/triangle_contact.h"

namespace selfsim {

using namespace candidate_grid;

namespace {

// Insertions (triangle, cell) g would make. A sum of whole numbers: the same whatever the threads.
double insertions(const std::vector<Box>& boxes, const Grid& g) {
  return tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, boxes.size(), 1 << 14), 0.0,
      [&](const tbb::blocked_range<std::size_t>& r, double sum) {
        for (std::size_t i = r.begin(); i < r.end(); ++i) sum += double(g.cells(boxes[i]));
        return sum;
      },
      std::plus<>());
}

// Cell sizes: on each axis twice the median triangle's extent along it (from a sample), so a typical
// triangle spans one or two cells an axis, and a mesh of tall thin triangles (a developing surface of a
// large `height`) gets tall thin cells rather than long columns of crowded ones; all doubled while there are
// more than 8 insertions a triangle (a few triangles as large as the mesh would otherwise fill millions of
// cells each). Cells are no smaller than the key allows: three coordinates and the triangle index share 64
// bits. `reach` is the largest box coordinate on each axis.
Grid choose_grid(const std::vector<Box>& boxes, const std::array<float, 3>& reach) {
  const std::size_t f = boxes.size(), samples = std::min<std::size_t>(f, 1 << 16);
  Grid g;
  g.id_bits = std::max(1, bit_width(f - 1));
  const int axis_bits = std::min(21, (64 - g.id_bits) / 3);
  std::array<double, 3> cell{};
  std::vector<float> sizes(samples);
  for (int axis = 0; axis < 3; ++axis) {
    for (std::size_t k = 0; k < samples; ++k) {
      const Box& b = boxes[k * f / samples];
      sizes[k] = b.hi[axis] - b.lo[axis];
    }
    std::nth_element(sizes.begin(), sizes.begin() + samples / 2, sizes.end());
    cell[axis] = std::max(2 * double(sizes[samples / 2]), std::ldexp(2.0, -axis_bits));
  }
  auto with = [&](double scale) {
    for (int axis = 0; axis < 3; ++axis) {
      g.per_unit[axis] = static_cast<float>(1 / (scale * cell[axis]));
      g.last[axis] = (std::uint32_t{1} << axis_bits) - 1;
      g.last[axis] = g.cell(reach[axis], axis);
    }
    return g;
  };
  const double limit = std::min(8.0 * double(f) + 4096, double(std::numeric_limits<std::uint32_t>::max()));
  double scale = 1;
  while (insertions(boxes, with(scale)) > limit && scale * std::min({cell[0], cell[1], cell[2]}) < 2) scale *= 2;
  return g;
}

// A large array, sized to n without a cost per page: 2 MiB pages (first touch is dear on some machines).
// Zero-filled in steps of 2^22, looking for a stop between them: filling gigabytes takes a while.
template <class T>
void size_large(std::vector<T>& v, std::size_t n, Progress& progress) {
  v.reserve(n);
  advise_huge_pages(v);
  while (v.size() < n) {
    if (progress.cancelled()) throw Cancelled();
    v.resize(std::min(n, v.size() + (std::size_t{1} << 22)));
  }
}

// The records of every insertion, sorted by cell (stable, so by triangle within a cell).
std::vector<std::uint64_t> sorted_records(const std::vector<Box>& boxes, const Grid& g, Progress& progress) {
  // Blocks of triangles count their records, then write them from their block's offset.
  constexpr std::size_t block = 1 << 14;
  const std::size_t f = boxes.size(), blocks = (f + block - 1) / block;
  std::vector<std::size_t> start(blocks + 1, 0);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    for (std::size_t i = b * block; i < std::min(f, (b + 1) * block); ++i) start[b + 1] += g.cells(boxes[i]);
  });
  for (std::size_t b = 0; b < blocks; ++b) start[b + 1] += start[b];
  std::vector<std::uint64_t> records, spare;
  size_large(records, start[blocks], progress);
  tbb::parallel_for(std::size_t{0}, blocks, [&](std::size_t b) {
    std::uint64_t* out = records.data() + start[b];
    for (std::size_t i = b * block; i < std::min(f, (b + 1) * block); ++i) {
      const Cell lo = g.low(boxes[i]), hi = g.high(boxes[i]);
      for (std::uint32_t z = lo[2]; z <= hi[2]; ++z)
        for (std::uint32_t y = lo[1]; y <= hi[1]; ++y)
          for (std::uint32_t x = lo[0]; x <= hi[0]; ++x) *out++ = Grid::key({x, y, z}) << g.id_bits | i;
    }
  });
  // Least significant digit first, 11 bits a pass (2048 counters stay in L1). Each pass counts and moves a
  // fixed set of parts in parallel, each part into slots after the earlier parts': stable whatever the threads.
  constexpr int digit = 11;
  constexpr std::uint64_t digit_mask = (1 << digit) - 1;
  constexpr std::size_t parts = 64;
  const std::size_t n = records.size(), part = (n + parts - 1) / parts;
  size_large(spare, n, progress);
  std::vector<std::array<std::size_t, 1 << digit>> slot(parts);
  for (int shift = g.id_bits; shift < g.id_bits + g.key_bits(); shift += digit) {
    if (progress.cancelled()) throw Cancelled();
    tbb::parallel_for(std::size_t{0}, parts, [&](std::size_t p) {
      slot[p].fill(0);
      for (std::size_t k = p * part; k < std::min(n, (p + 1) * part); ++k)
        ++slot[p][(records[k] >> shift) & digit_mask];
    });
    std::size_t sum = 0;
    for (std::size_t d = 0; d <= digit_mask; ++d)
      for (std::size_t p = 0; p < parts; ++p) sum += std::exchange(slot[p][d], sum);
    tbb::parallel_for(std::size_t{0}, parts, [&](std::size_t p) {
      for (std::size_t k = p * part; k < std::min(n, (p + 1) * part); ++k)
        spare[slot[p][(records[k] >> shift) & digit_mask]++] = records[k];
    });
    records.swap(spare);
  }
  return records;
}

// The least pair (first << 32 | second) of triangles that meet, or none.
constexpr std::uint64_t none = std::numeric_limits<std::uint64_t>::max();

// The records in chunks, each starting at the first cell that starts in it; chunks in batches, a step of
// progress each. The threads keep the least pair found so far in one atomic and skip every pair not below
// it: the minimum whatever the order. In a cell, triangles rise, so for each triangle the pairs rise and the
// first pair not below the least ends its row.
std::uint64_t least_pair(const Corners& corners, const std::vector<Box>& boxes, const Grid& grid,
                         const std::vector<std::uint64_t>& records, double eps, Progress& progress) {
  struct Entry {
    Box box;
    Triangle points;
    std::uint32_t id;
    unsigned starts;      // bit a: the box starts in this cell on axis a
    ContactTriangle tri;  // its corners and normal, once per cell rather than once per pair (most pairs are neighbours)
  };
  const std::size_t total = records.size(), chunk = 1 << 13, chunks = (total + chunk - 1) / chunk;
  const std::uint64_t id_mask = (std::uint64_t{1} << grid.id_bits) - 1;
  auto cell_start = [&](std::size_t k) {
    while (k > 0 && k < total && (records[k] >> grid.id_bits) == (records[k - 1] >> grid.id_bits)) ++k;
    return std::min(k, total);
  };
  std::atomic<std::uint64_t> best{none};
  const std::size_t batch = std::max<std::size_t>(chunks / 32, 16);
  for (std::size_t begin = 0; begin < chunks; begin += batch) {
    tbb::parallel_for(begin, std::min(chunks, begin + batch), [&](std::size_t c) {
      std::vector<Entry> in;
      std::uint64_t least = best.load(std::memory_order_relaxed);
      const std::size_t to = cell_start((c + 1) * chunk);
      for (std::size_t k = cell_start(c * chunk); k < to;) {
        const std::uint64_t key = records[k] >> grid.id_bits;
        const Cell here = Grid::cell_of(key);
        least = std::min(least, best.load(std::memory_order_relaxed));
        in.clear();
        for (; k < to && (records[k] >> grid.id_bits) == key; ++k) {
          const auto j = static_cast<std::uint32_t>(records[k] & id_mask);
          const Cell low = grid.low(boxes[j]);
          in.push_back(
              {boxes[j], corners.m.triangles[j], j,
               unsigned(low[0] == here[0]) | unsigned(low[1] == here[1]) << 1 | unsigned(low[2] == here[2]) << 2,
               ContactTriangle(corners(j))});
        }
        for (std::size_t x = 0; x + 1 < in.size(); ++x) {
          const Entry& p = in[x];
          if ((std::uint64_t{p.id} << 32) >= least) break;
          for (std::size_t y = x + 1; y < in.size(); ++y) {
            const Entry& q = in[y];
            // Test a pair once: in the cell at the low corner of the boxes' overlap, where on every axis one
            // of the two starts.
            if ((p.starts | q.starts) != 7 || !overlap(p.box, q.box)) continue;
            const std::uint64_t pair = std::uint64_t{p.id} << 32 | q.id;
            if (pair >= least) break;
            if (!triangles_meet(p.points, q.points, p.tri, q.tri, eps)) continue;
            least = pair;
            break;
          }
        }
      }
      std::uint64_t seen = best.load();
      while (least < seen && !best.compare_exchange_weak(seen, least)) {
      }
    });
    progress.step(0.2 + 0.8 * double(std::min(chunks, begin + batch)) / double(chunks));
  }
  return best.load();
}

}  // namespace

namespace candidate_grid {

Candidates::Candidates(const Mesh& m, const BBox3& bounds, double size, Progress& progress)
    : corners{m, bounds.min, size, 1 / size} {
  const std::size_t f = m.triangles.size();
  // Grown by eps, then by 2^-23 so that rounding to float only ever grows them.
  constexpr double margin = 0x1p-23;
  size_large(boxes, f, progress);
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, f, 1 << 14), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t i = r.begin(); i < r.end(); ++i) {
      const auto c = corners(static_cast<std::uint32_t>(i));
      const Vec3 lo = min_each(min_each(c[0], c[1]), c[2]) - Vec3::all(eps + margin);
      const Vec3 hi = max_each(max_each(c[0], c[1]), c[2]) + Vec3::all(eps + margin);
      boxes[i] = {{float(lo.x), float(lo.y), float(lo.z)}, {float(hi.x), float(hi.y), float(hi.z)}};
    }
  });
  if (progress.cancelled()) throw Cancelled();
  const Vec3 reach = bounds.size() / corners.size + Vec3::all(eps + 2 * margin);
  grid = choose_grid(boxes, {float(reach.x), float(reach.y), float(reach.z)});
  progress.fraction(0.05);
  records = sorted_records(boxes, grid, progress);
  progress.fraction(0.2);
}

// Where triangles i and j meet, in m's coordinates.
TrianglePair Candidates::pair(std::uint32_t i, std::uint32_t j) const {
  const Vec3 where = *triangles_meet(corners.m.triangles[i], corners.m.triangles[j], ContactTriangle(corners(i)),
                                     ContactTriangle(corners(j)), eps);
  return TrianglePair{i, j, corners.origin + where * corners.size};
}

void check_input(const Mesh& m) {
  for (std::size_t i = 0; i < m.points.size(); ++i)
    if (!is_finite(m.points[i])) throw Error("point " + std::to_string(i + 1) + " has non-finite coordinates");
  if (m.triangles.size() > std::numeric_limits<std::uint32_t>::max())
    throw Error("a mesh has at most 4294967295 triangles, got " + std::to_string(m.triangles.size()));
  for (std::size_t f = 0; f < m.triangles.size(); ++f)
    for (std::uint32_t v : m.triangles[f])
      if (v >= m.points.size())
        throw Error("triangle " + std::to_string(f + 1) + " uses point " + std::to_string(std::size_t{v} + 1) +
                    ", but there are " + std::to_string(m.points.size()) + " points");
}

// The mesh's box and its diagonal (1 for a mesh of one point).
double diagonal_of(const Mesh& m, BBox3& bounds) {
  bounds = m.bbox();
  const double diagonal = norm(bounds.size());
  if (!std::isfinite(diagonal)) throw Error("the mesh is too large: its diagonal overflows");
  return diagonal > 0 ? diagonal : 1;
}

}  // namespace candidate_grid

std::optional<TrianglePair> first_intersection(const Mesh& m, Progress& progress) {
  progress.start("intersections");
  check_input(m);
  if (m.triangles.size() < 2) return std::nullopt;
  BBox3 bounds;
  const double size = diagonal_of(m, bounds);
  const Candidates c(m, bounds, size, progress);
  const std::uint64_t pair = least_pair(c.corners, c.boxes, c.grid, c.records, Candidates::eps, progress);
  if (pair == none) return std::nullopt;
  return c.pair(static_cast<std::uint32_t>(pair >> 32), static_cast<std::uint32_t>(pair));
}

}  // namespace selfsim
