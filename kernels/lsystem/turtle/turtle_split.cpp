#include "kernels/lsystem/turtle/turtle_split.h"

#include <algorithm>
#include <array>

#include "kernels/lsystem/production_count.h"
#include "kernels/lsystem/rewrite.h"

namespace selfsim::lsystem {

namespace {

constexpr double max_split_symbols = 1 << 16;  // the split string stays small
constexpr double min_split_symbols = 64;       // fewer subtrees would balance badly
constexpr double min_split_points = 1 << 16;   // smaller levels take less than a thread costs to start
// Fixed, never derived from the thread count: the output must not depend on it.
constexpr double chunk_count = 512;
constexpr double max_memo_steps = 1 << 26;  // building the displacement memo stays cheap next to drawing

// What a symbol becomes after r rewritings, for every start heading.
struct Effect {
  double segments = 0;
  int turn = 0;            // lattice steps turned
  std::vector<Vec2> move;  // [start heading] -> displacement
};

}  // namespace

std::optional<TurtleSplit> split_level(const Grammar& g, const Compiled& c, const LatticeTable& t, int level,
                                       Progress& progress) {
  std::array<bool, 256> used{};  // symbols of the axiom and the rules
  for (unsigned char s : g.axiom) used[s] = true;
  for (const auto& [symbol, rule] : g.rules) {
    used[static_cast<unsigned char>(symbol)] = true;
    for (unsigned char s : rule) used[s] = true;
  }
  for (int s = 0; s < 256; ++s) {
    const Action a = c.action[static_cast<std::size_t>(s)];
    if (used[static_cast<std::size_t>(s)] && (a == Action::Move || a == Action::Push || a == Action::Pop))
      return std::nullopt;
  }

  // The deepest level-d string small enough to hold: its symbols are the subtrees.
  SymbolWeights length = symbol_weights(g, Weight::Symbols);
  auto axiom_length = [&] {
    double n = 0;
    for (unsigned char s : g.axiom) n += length[s];
    return n;
  };
  int depth = 0;
  for (int d = 1; d <= level; ++d) {
    rewrite_weights(g, length);
    if (axiom_length() > max_split_symbols) break;
    depth = d;
  }
  const int remaining = level - depth;
  double memo_steps = 0;  // per level: each rule's symbols for every heading, and a copy of every effect
  for (const std::string& r : c.rules) memo_steps += static_cast<double>(r.size());
  memo_steps += static_cast<double>(std::count(used.begin(), used.end(), true));
  if (static_cast<double>(remaining) * memo_steps * t.n > max_memo_steps) return std::nullopt;

  TurtleSplit split;
  split.depth = depth;
  // An axiom longer than the limit is split as it is (depth 0): it is already in memory.
  split.symbols = depth == 0 ? g.axiom : expand_string(g, depth, max_split_symbols);
  if (static_cast<double>(split.symbols.size()) < min_split_symbols) return std::nullopt;

  // Effects after 0 rewritings, then one more level at a time up to `remaining`.
  const std::size_t n = static_cast<std::size_t>(t.n);
  std::array<Effect, 256> now;
  for (int s = 0; s < 256; ++s) {
    if (!used[static_cast<std::size_t>(s)]) continue;
    Effect& e = now[static_cast<std::size_t>(s)];
    const Action a = c.action[static_cast<std::size_t>(s)];
    e.segments = a == Action::Draw ? 1 : 0;
    e.turn = a == Action::Turn ? t.turn[static_cast<std::size_t>(s)] : 0;
    e.move.assign(n, Vec2{});
    if (a == Action::Draw) e.move = t.step;
  }
  for (int r = 1; r <= remaining; ++r) {
    if (progress.cancelled()) throw Cancelled();
    std::array<Effect, 256> next = now;
    for (int s = 0; s < 256; ++s) {
      const int rule = c.rule[static_cast<std::size_t>(s)];
      if (rule < 0 || !used[static_cast<std::size_t>(s)]) continue;
      Effect& e = next[static_cast<std::size_t>(s)];
      e.segments = 0;
      e.turn = 0;
      for (unsigned char x : c.rules[static_cast<std::size_t>(rule)]) {
        e.segments += now[x].segments;
        e.turn = t.rotate(e.turn, now[x].turn);
      }
      for (std::size_t h = 0; h < n; ++h) {
        Vec2 sum{};
        int k = static_cast<int>(h);
        for (unsigned char x : c.rules[static_cast<std::size_t>(rule)]) {
          sum += now[x].move[static_cast<std::size_t>(k)];
          k = t.rotate(k, now[x].turn);
        }
        e.move[h] = sum;
      }
    }
    now = std::move(next);
  }

  double segments = 0;
  for (unsigned char x : split.symbols) segments += now[x].segments;
  if (segments < min_split_points) return std::nullopt;

  // Chunks of about equal numbers of points, in order.
  const double target = segments / chunk_count;
  int heading = 0;
  Vec2 pos{};
  std::size_t point = 1;  // point 0 is the start, (0, 0)
  for (std::size_t i = 0; i < split.symbols.size(); ++i) {
    const Effect& e = now[static_cast<unsigned char>(split.symbols[i])];
    if (split.chunks.empty() || static_cast<double>(split.chunks.back().points) >= target) {
      if (!split.chunks.empty()) split.chunks.back().end = i;
      split.chunks.push_back({i, i, heading, pos, point, 0});
    }
    split.chunks.back().points += static_cast<std::size_t>(e.segments);
    point += static_cast<std::size_t>(e.segments);
    pos += e.move[static_cast<std::size_t>(heading)];
    heading = t.rotate(heading, e.turn);
  }
  split.chunks.back().end = split.symbols.size();
  split.end = pos;
  split.points = point;
  return split;
}

}  // namespace selfsim::lsystem
