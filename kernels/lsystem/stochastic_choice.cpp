#include "kernels/lsystem/stochastic_choice.h"

#include <algorithm>

namespace selfsim::lsystem {

namespace {

std::uint64_t mix(std::uint64_t z) {  // the splitmix64 finaliser: every input bit moves every output bit
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

std::uint64_t root_lineage(std::uint64_t seed) { return mix(seed); }

std::uint64_t child_lineage(std::uint64_t parent, std::uint64_t salt) { return mix(parent ^ mix(salt)); }

std::size_t choose_option(std::span<const Successor> options, double u) {
  // Weights taken relative to the largest, so that neither 1e308 + 1e308 overflows nor subnormal ones
  // lose their ratio.
  double largest = 0;
  for (const Successor& o : options) largest = std::max(largest, o.weight);
  double total = 0;
  for (const Successor& o : options) total += o.weight / largest;
  double below = 0;
  for (std::size_t k = 0; k + 1 < options.size(); ++k) {
    below += options[k].weight / largest;
    if (u * total < below) return k;
  }
  // The last option with weight, so rounding never picks a zero-weight one.
  std::size_t k = options.size() - 1;
  while (k > 0 && options[k].weight == 0) --k;
  return k;
}

}  // namespace selfsim::lsystem
