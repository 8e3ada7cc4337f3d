// A level of an L-system split into chunks that threads draw independently, each straight into its own
// slice of the vertex array. The production counts give every chunk its first point's index; each
// symbol's net turn and displacement per level (memoised per symbol, remaining level and lattice heading)
// give its start heading and position, so no chunk waits for another and no second pass moves slices into
// place. The split depends only on the grammar and the level, never on the number of threads, so the
// output is byte-identical for any --threads.
// Only for lattice headings (turns are exact integers there; free angles would sum differently in
// different orders) and grammars without branches or moves (a branch's saved state could cross chunks);
// the others are drawn by one thread.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/vec2.h"
#include "kernels/lsystem/compiled_grammar.h"
#include "kernels/lsystem/grammar.h"

namespace selfsim::lsystem {

struct TurtleChunk {
  std::size_t begin = 0, end = 0;  // its symbols: split.symbols[begin, end)
  int heading = 0;                 // lattice heading at its start
  Vec2 start;                      // turtle position at its start (unit steps, before placing)
  std::size_t first_point = 0;     // index of its first drawn point in the vertex array
  std::size_t points = 0;          // points it draws
};

struct TurtleSplit {
  int depth = 0;        // rewritings applied to the axiom to get `symbols`
  std::string symbols;  // the level-`depth` string, rewritten level - depth more times by the chunks
  std::vector<TurtleChunk> chunks;
  Vec2 end;                // the turtle's final position
  std::size_t points = 0;  // points of the whole level: its segments + 1 (the start)
};

// The split of grammar g at `level` on lattice t, or nothing when the level is drawn by one thread: free
// headings, branches or moves, a level too small to be worth it, or memo tables too big.
std::optional<TurtleSplit> split_level(const Grammar& g, const Compiled& c, const LatticeTable& t, int level,
                                       Progress& progress);

}  // namespace selfsim::lsystem
