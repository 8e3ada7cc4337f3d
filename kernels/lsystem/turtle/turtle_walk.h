// The 2D turtle as rewrite() sinks (rewrite.h): headings on a lattice or free, and two walkers. PathTurtle
// draws any grammar into a growing Polyline (branches, moves, several paths); SliceTurtle draws one chunk of
// a split level (turtle_split.h: draws and turns only) straight into its slice of a preallocated array,
// for the parallel turtle. Internal to kernels/lsystem.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <type_traits>
#include <utility>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"
#include "kernels/geom/similarity.h"
#include "kernels/lsystem/compiled_grammar.h"

namespace selfsim::lsystem {

// A heading on the lattice.
struct LatticeHeading {
  const LatticeTable* table;
  int k = 0;

  Vec2 forward() const { return table->step[static_cast<std::size_t>(k)]; }
  void rotate(std::uint8_t s) { k = table->rotate(k, table->turn[s]); }
};

// Heading as an angle, for turns that fit no lattice (irrational fractions of a circle).
struct FreeHeading {
  const Compiled* c;
  double radians;

  Vec2 forward() const { return polar(radians); }
  void rotate(std::uint8_t s) { radians = std::remainder(radians + c->turn[s] * degree, 2 * std::numbers::pi); }
};

// The block of precomputed points for symbol s with `remaining` rewritings left, if there is one.
inline const LatticeBlocks::Block* block_for(const LatticeBlocks* blocks, std::uint8_t s, int remaining) {
  if (blocks == nullptr || remaining != blocks->depth || blocks->block[s] < 0) return nullptr;
  return &blocks->blocks[static_cast<std::size_t>(blocks->block[s])];
}

// Per-point fields of a branched system, for colouring a plant: its branch order and its distance along the
// tree from the start (in unit steps; the caller scales them with the curve).
struct TreeFields {
  std::vector<std::int32_t> branch_order;  // '[' open when the point was drawn
  std::vector<double> root_distance;
};

template <class Heading>
struct PathTurtle {
  struct State {
    Vec2 pos;
    Heading heading;
    double walked;
  };
  const Compiled& c;
  Heading heading;
  const LatticeBlocks* blocks;  // null for free headings
  Polyline& out;
  Progress& reporter;
  double predicted_points;
  TreeFields* tree = nullptr;  // filled when given
  Vec2 pos{};
  bool path_open = false;
  double walked = 0;  // unit steps from the start along the tree
  std::vector<State> saved;

  void add_point(Vec2 p) {
    out.points.push_back(p);
    if (tree != nullptr) {
      tree->branch_order.push_back(static_cast<std::int32_t>(saved.size()));
      tree->root_distance.push_back(walked);
    }
  }

  void progress() { reporter.step(static_cast<double>(out.points.size()) / predicted_points); }

  std::size_t subtree(std::uint8_t s, int remaining) {
    if constexpr (std::is_same_v<Heading, LatticeHeading>) {
      if (const LatticeBlocks::Block* b = block_for(blocks, s, remaining)) {
        const std::vector<Vec2>& pts = b->points[static_cast<std::size_t>(heading.k)];
        if (!pts.empty()) {
          if (!path_open) add_point(pos);
          path_open = true;
          for (const Vec2& p : pts) {
            walked += 1;  // a block is a run of unit steps
            add_point(pos + p);
          }
          pos = out.points.back();
        }
        heading.k = heading.table->rotate(heading.k, b->turn);
        return pts.size() + 1;
      }
    }
    return 0;
  }

  void symbol(std::uint8_t s) {
    switch (c.action[s]) {
      case Action::None:
        break;
      case Action::Draw:
        if (!path_open) {
          add_point(pos);
          path_open = true;
        }
        pos += heading.forward();
        walked += 1;
        add_point(pos);
        break;
      case Action::Move:
        out.close_path();
        path_open = false;
        pos += heading.forward();
        walked += 1;
        break;
      case Action::Turn:
        heading.rotate(s);
        break;
      case Action::Push:
        saved.push_back({pos, heading, walked});
        break;
      case Action::Pop:
        if (saved.empty()) throw Error("option 'axiom'/'rules': ']' without a matching '['");
        out.close_path();
        path_open = false;
        pos = saved.back().pos;
        heading = saved.back().heading;
        walked = saved.back().walked;
        saved.pop_back();
        break;
    }
  }
};

// One chunk of a split level: every drawn point goes through `place` into the slice at `cursor`. Only
// checks cancellation (it runs on worker threads); the calling thread reports progress.
struct SliceTurtle {
  const Compiled& c;
  LatticeHeading heading;
  const LatticeBlocks* blocks;
  Similarity2 place;
  Vec2 pos;
  Vec2* cursor;
  Progress& reporter;

  void progress() {
    if (reporter.cancelled()) throw Cancelled();
  }

  std::size_t subtree(std::uint8_t s, int remaining) {
    const LatticeBlocks::Block* b = block_for(blocks, s, remaining);
    if (b == nullptr) return 0;
    const std::vector<Vec2>& pts = b->points[static_cast<std::size_t>(heading.k)];
    for (const Vec2& p : pts) *cursor++ = place(pos + p);
    if (!pts.empty()) pos = pos + pts.back();
    heading.k = heading.table->rotate(heading.k, b->turn);
    return pts.size() + 1;
  }

  void symbol(std::uint8_t s) {
    if (c.action[s] == Action::Draw) {
      pos += heading.forward();
      *cursor++ = place(pos);
    } else {
      heading.rotate(s);
    }
  }
};

}  // namespace selfsim::lsystem
