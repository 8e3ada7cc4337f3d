// Growing a vector of gigabytes copies it for seconds (and touches every page of the new one): longer
// than --timeout allows between two looks for a stop. These grow it in pieces, looking between them.
// Internal to kernels/lsystem.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/lsystem/module_string.h"

namespace selfsim::lsystem {

// Elements copied between two looks for a stop (16 MB of points).
constexpr std::size_t growth_piece = std::size_t{1} << 20;

// Makes room in v (a std::vector, or one with its own allocator) for `need` elements in all: twice its size (at least
// 1024), but no more than `cap` (the most the caller's budget lets it hold) unless `need` is more. Throws Cancelled
// when progress says so.
template <class Vector>
void grow_polled(Vector& v, std::size_t need, std::size_t cap, Progress& progress) {
  if (need <= v.capacity()) return;
  const std::size_t want = std::max(need, std::min(std::max<std::size_t>(1024, 2 * v.size()), cap));
  if (v.size() <= growth_piece) {
    v.reserve(want);
    return;
  }
  Vector bigger;
  bigger.reserve(want);
  for (std::size_t i = 0; i < v.size(); i += growth_piece) {
    if (progress.cancelled()) throw Cancelled();
    const auto from = v.begin() + static_cast<std::ptrdiff_t>(i);
    bigger.insert(bigger.end(), from, from + static_cast<std::ptrdiff_t>(std::min(growth_piece, v.size() - i)));
  }
  v.swap(bigger);
}

// Room in s for one more module with `args` parameters (and a lineage when it keeps them).
inline void make_room(ModuleString& s, std::size_t args, bool lineage, Progress& progress) {
  const std::size_t most = static_cast<std::size_t>(-1) / 2;
  grow_polled(s.symbols, s.symbols.size() + 1, most, progress);
  grow_polled(s.arg_end, s.symbols.capacity(), most, progress);
  grow_polled(s.args, s.args.size() + args, most, progress);
  if (lineage) grow_polled(s.lineage, s.symbols.capacity(), most, progress);
}

// Calls f(begin, end) over [0, n) in pieces, looking for a stop between them.
template <class F>
void in_pieces(std::size_t n, Progress& progress, F f) {
  for (std::size_t i = 0; i < n; i += growth_piece) {
    if (progress.cancelled()) throw Cancelled();
    f(i, std::min(n, i + growth_piece));
  }
}

}  // namespace selfsim::lsystem
