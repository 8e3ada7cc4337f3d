// Sizes of an L-system level predicted from its production matrix before anything is expanded, so that a
// request too big for memory is refused at once. Counts are doubles: exact below 2^53, and still ordered
// correctly (or infinite) far beyond that.
#pragma once

#include <array>

#include "kernels/base/progress.h"
#include "kernels/lsystem/grammar.h"

namespace selfsim::lsystem {

struct LevelCounts {
  double symbols = 0;    // length of the level's string
  double segments = 0;   // drawn segments
  double breaks = 0;     // places a new path may begin (']' and move symbols)
  double max_depth = 0;  // most branches open at once ('[' not yet closed): the turtle's saved states

  // Upper bound on points: each path has one more point than segments.
  double max_points() const { return segments + breaks + 1; }
};

// Counts for grammar g at `level` (>= 0). Costs level x grammar size; checks cancellation once per level.
LevelCounts predict_counts(const Grammar& g, int level, Progress& progress = no_progress());

// Per-symbol weights indexed by symbol byte, and one rewriting step of them: after it, w[s] is the sum of
// the old weights over s's replacement (symbols without a rule keep theirs).
using SymbolWeights = std::array<double, 256>;
void rewrite_weights(const Grammar& g, SymbolWeights& w);

// Each single symbol's own weight before any rewriting: 1 for every symbol, or 1 for those that draw.
// rewrite_weights then gives what each symbol becomes after one more step. Indexed by symbol byte.
enum class Weight { Symbols, Segments };
SymbolWeights symbol_weights(const Grammar& g, Weight weight);

}  // namespace selfsim::lsystem
