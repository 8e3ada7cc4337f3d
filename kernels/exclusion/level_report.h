// What one level of an exclusion curve or surface did: how many points it split off (segments split,
// triangle edges split), how many of them could not move, and how long it took.
#pragma once

#include <cstddef>

namespace selfsim::exclusion {

struct LevelReport {
  std::size_t splits = 0, stuck = 0;
  double seconds = 0;
};

}  // namespace selfsim::exclusion
