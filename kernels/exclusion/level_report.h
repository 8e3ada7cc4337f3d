// What one level of an exclusion curve or surface did: how many points it split off (segments split,
// triangle edges split), how many of them could not move, and how long it took.
#pragma once

#include <cstddef>
#include <vector>

namespace selfsim::exclusion {

struct LevelReport {
  std::size_t splits = 0, stuck = 0;
  double seconds = 0;
  double area = -1;  // a surface's area after the level (a curve's report has none)
};

// Points that could not move, over all levels.
inline std::size_t total_stuck(const std::vector<LevelReport>& levels) {
  std::size_t s = 0;
  for (const LevelReport& l : levels) s += l.stuck;
  return s;
}

}  // namespace selfsim::exclusion
