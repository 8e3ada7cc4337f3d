// Sizes of an L-system level predicted from its production matrix before anything is expanded, so that a
// request too big for memory is refused at once. Counts are doubles: exact below 2^53, and still ordered
// correctly (or infinite) far beyond that.
#pragma once

#include <array>

#include "kernels/lsystem/grammar.h"

namespace selfsim::lsystem {

struct LevelCounts {
  double symbols = 0;   // length of the level's string
  double segments = 0;  // drawn segments
  double breaks = 0;    // places a new path may begin (']' and move symbols)

  // Upper bound on points: each path has one more point than segments.
  double max_points() const { return segments + breaks + 1; }
};

// Counts for grammar g at `level` (>= 0).
LevelCounts predict_counts(const Grammar& g, int level);

// What each single symbol becomes after `depth` rewriting steps: its number of symbols, or of drawn
// segments. Indexed by symbol byte.
enum class Weight { Symbols, Segments };
std::array<double, 256> per_symbol_counts(const Grammar& g, int depth, Weight weight);

}  // namespace selfsim::lsystem
