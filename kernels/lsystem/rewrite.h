// Rewriting apart from drawing (seed 002 §1): the symbols of an L-system level streamed depth-first to a
// sink, with a stack of rule positions (one frame per level) and never the level's string. The 2D turtle
// is one sink; a 3D turtle and stochastic or parametric rules will be others.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "kernels/lsystem/compiled_grammar.h"
#include "kernels/lsystem/grammar.h"

namespace selfsim::lsystem {

// Units of work between two calls of sink.progress(): a symbol read, or what subtree() reports.
inline constexpr std::size_t rewrite_check_every = std::size_t{1} << 20;

// Rewrites `start` `level` times depth-first, feeding the resulting symbols to `sink` in order. A Sink has
//   std::size_t subtree(std::uint8_t s, int remaining);  // offered before s (which has a rule) is expanded
//       with `remaining` > 0 rewritings left: the units of work done if the sink produced s's whole
//       expansion itself (a precomputed block), or 0 to have it expanded
//   void symbol(std::uint8_t s);                         // one symbol of the level's string
//   void progress();                                     // every rewrite_check_every units of work
// Counting symbols read, not only symbols produced, keeps a grammar that rewrites much and draws little
// stoppable too.
template <class Sink>
void rewrite(const Compiled& c, std::string_view start, int level, Sink& sink) {
  struct Frame {
    const std::uint8_t* pos;
    const std::uint8_t* end;
  };
  auto bytes = [](std::string_view s) { return reinterpret_cast<const std::uint8_t*>(s.data()); };
  std::vector<Frame> frames;
  frames.reserve(static_cast<std::size_t>(level) + 1);  // never reallocated: references stay valid
  frames.push_back({bytes(start), bytes(start) + start.size()});
  std::size_t work = 0, next_check = rewrite_check_every;
  while (!frames.empty()) {
    Frame& f = frames.back();
    if (f.pos == f.end) {
      frames.pop_back();
      continue;
    }
    if (++work >= next_check) {
      sink.progress();
      next_check = work + rewrite_check_every;
    }
    const std::uint8_t s = *f.pos++;
    const int r = c.rule[s];
    const int remaining = level - (static_cast<int>(frames.size()) - 1);
    if (r >= 0 && remaining > 0) {
      if (const std::size_t done = sink.subtree(s, remaining)) {
        work += done;
        continue;
      }
      const std::string& rule = c.rules[static_cast<std::size_t>(r)];
      frames.push_back({bytes(rule), bytes(rule) + rule.size()});
      continue;
    }
    sink.symbol(s);
  }
}

// The string of level `level`, for small levels; refuses one predicted longer than max_symbols.
std::string expand_string(const Grammar& g, int level, double max_symbols);

}  // namespace selfsim::lsystem
