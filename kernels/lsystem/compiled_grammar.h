// The grammar compiled for the turtle's hot loop: flat tables indexed by symbol byte, the heading
// lattice, and precomputed blocks of points for the last levels of rewriting.
#pragma once

#include <array>
#include <cstdint>
#include <numbers>
#include <string>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/vec2.h"
#include "kernels/lsystem/grammar.h"

namespace selfsim::lsystem {

enum class Action : std::uint8_t { None, Draw, Move, Turn, Push, Pop };

constexpr double degree = std::numbers::pi / 180;

// The grammar as flat tables indexed by symbol byte.
struct Compiled {
  std::array<Action, 256> action{};
  std::array<double, 256> turn{};  // degrees in (-360, 360), positive = left
  std::array<int, 256> rule{};     // index into rules, or -1
  std::vector<std::string> rules;

  explicit Compiled(const Grammar& g);
  // Smallest N <= 7200 such that every turn is a whole number of 360/N degree steps, or 0 if none.
  int lattice() const;
};

// Headings on a lattice of n directions: one table look-up per segment, and no drift from accumulating
// rounded angles however long the curve.
struct LatticeTable {
  std::vector<Vec2> step;       // unit step vector for each of the n directions
  std::array<int, 256> turn{};  // lattice steps turned left by each symbol, in [0, n)
  int n = 1;

  LatticeTable(const Compiled& c, int lattice, double start_degrees);
  int rotate(int k, int by) const { return k + by >= n ? k + by - n : k + by; }
};

// The points drawn by a symbol rewritten `depth` more times, for every start heading: the last levels of
// expansion become copies of these blocks instead of thousands of tiny rule frames.
struct LatticeBlocks {
  struct Block {
    std::vector<std::vector<Vec2>> points;  // [start heading] -> drawn points relative to the start
    int turn = 0;                           // lattice steps the whole expansion turns
  };
  int depth = 0;                 // remaining rewriting depth at which blocks replace frames (0: none)
  std::array<int, 256> block{};  // index into blocks, or -1 (no rule, or branches/moves inside)
  std::vector<Block> blocks;

  LatticeBlocks(const Grammar& g, const Compiled& c, const LatticeTable& t, int level, Progress& progress);
};

}  // namespace selfsim::lsystem
