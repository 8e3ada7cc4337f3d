// Renumbering the vertices of linked chains (curve_net.cpp's curves, original_chains.cpp's chains) so that
// each chain's vertices are consecutive in memory: both keep parallel arrays indexed by vertex and links
// (next, prev) holding vertex numbers, and renumber them the same way.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace selfsim::exclusion {

// The vertices of the chain that starts at `first`, following `next` until `none` or back at `first`.
inline std::vector<std::uint32_t> chain_vertices(std::uint32_t first, const std::vector<std::uint32_t>& next,
                                                 std::uint32_t none) {
  std::vector<std::uint32_t> c;
  std::uint32_t v = first;
  do {
    c.push_back(v);
    v = next[v];
  } while (v != none && v != first);
  return c;
}

// Appends every chain's vertices to `order` (old numbers in their new order), chain after chain, and sets
// first[i] to where chain i now begins.
inline void append_chains(std::vector<std::uint32_t>& order, std::vector<std::uint32_t>& first,
                          const std::vector<std::uint32_t>& next, std::uint32_t none) {
  for (std::uint32_t& f : first) {
    const std::vector<std::uint32_t> c = chain_vertices(f, next, none);
    f = static_cast<std::uint32_t>(order.size());
    order.insert(order.end(), c.begin(), c.end());
  }
}

// Reorders values so that entry k holds old entry order[k]: in place, through a copy, so that the vector
// keeps the capacity reserved for the whole run.
template <class T>
void permute(std::vector<T>& values, std::span<const std::uint32_t> order) {
  const std::vector<T> old = values;
  for (std::size_t k = 0; k < order.size(); ++k) values[k] = old[order[k]];
}

// Links to old vertex numbers made links to the new ones (order[k]: the old number of new vertex k); the
// value `none` stays as it is.
inline void relink(std::vector<std::uint32_t>& links, std::span<const std::uint32_t> order, std::uint32_t none) {
  std::vector<std::uint32_t> to(links.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) to[order[k]] = k;
  for (std::uint32_t& x : links)
    if (x != none) x = to[x];
}

}  // namespace selfsim::exclusion
