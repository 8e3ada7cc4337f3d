#include "kernels/lsystem/compiled_grammar.h"

#include <algorithm>
#include <cmath>

#include "kernels/lsystem/production_count.h"

namespace selfsim::lsystem {

Compiled::Compiled(const Grammar& g) {
  rule.fill(-1);
  for (int s = 0; s < 256; ++s) {
    const char c = static_cast<char>(s);
    // Reduced exactly (fmod is exact): a turn of 1e20 degrees is the turn it really is, not a rounding of it.
    turn[s] = std::fmod(g.turn_of(c), 360.0);
    action[s] = g.draws(c)     ? Action::Draw
                : g.moves(c)   ? Action::Move
                : c == '['     ? Action::Push
                : c == ']'     ? Action::Pop
                : turn[s] != 0 ? Action::Turn
                               : Action::None;
  }
  for (const auto& [symbol, replacement] : g.rules) {
    rule[static_cast<unsigned char>(symbol)] = static_cast<int>(rules.size());
    rules.push_back(replacement);
  }
}

int Compiled::lattice() const {
  for (int n = 1; n <= 7200; ++n) {
    bool all = true;
    for (int s = 0; s < 256 && all; ++s) {
      const double k = turn[s] * n / 360;
      all = std::abs(k - std::round(k)) < 1e-9;
    }
    if (all) return n;
  }
  return 0;
}

LatticeTable::LatticeTable(const Compiled& c, int lattice, double start_degrees) : n(lattice) {
  const double start = std::fmod(start_degrees, 360.0) * degree;
  for (int i = 0; i < n; ++i) step.push_back(polar(start + 2 * std::numbers::pi * i / n));
  for (int s = 0; s < 256; ++s) {
    const long t = std::lround(c.turn[s] * n / 360) % n;
    turn[s] = static_cast<int>(t < 0 ? t + n : t);
  }
}

namespace {

// Blocks stay small enough to live in cache and to cost little to build.
constexpr double max_block_points = 1024;
constexpr double max_block_symbols = 16384;
constexpr double max_table_bytes = 16 << 20;
// Building a block walks its symbols once per heading: 7200 headings of long rules must stay cheap too.
constexpr double max_build_steps = 1 << 25;

// Symbols of `s` rewritten d times, appended to out.
void expand(const Compiled& c, unsigned char s, int d, std::string& out) {
  if (d == 0 || c.rule[s] < 0) {
    out += static_cast<char>(s);
    return;
  }
  for (char t : c.rules[static_cast<std::size_t>(c.rule[s])]) expand(c, static_cast<unsigned char>(t), d - 1, out);
}

}  // namespace

LatticeBlocks::LatticeBlocks(const Grammar& g, const Compiled& c, const LatticeTable& t, int level,
                             Progress& progress) {
  block.fill(-1);
  // The deepest d whose blocks all fit the limits.
  SymbolWeights w = symbol_weights(g, Weight::Segments), symbols = symbol_weights(g, Weight::Symbols);
  for (int d = 1; d <= level; ++d) {
    rewrite_weights(g, w);
    rewrite_weights(g, symbols);
    double biggest = 0, longest = 0, bytes = 0, steps = 0;
    for (int s = 0; s < 256; ++s)
      if (c.rule[s] >= 0) {
        biggest = std::max(biggest, w[s]);
        longest = std::max(longest, symbols[s]);
        bytes += w[s] * t.n * sizeof(Vec2);
        steps += symbols[s] * t.n;
      }
    if (biggest > max_block_points || longest > max_block_symbols || bytes > max_table_bytes || steps > max_build_steps)
      break;
    depth = d;
  }
  if (depth == 0) return;
  for (int s = 0; s < 256; ++s) {
    if (c.rule[s] < 0) continue;
    std::string symbols;
    expand(c, static_cast<unsigned char>(s), depth, symbols);
    const bool plain = std::none_of(symbols.begin(), symbols.end(), [&](char x) {
      const Action a = c.action[static_cast<unsigned char>(x)];
      return a == Action::Move || a == Action::Push || a == Action::Pop;
    });
    if (!plain) continue;
    Block b;
    for (int h = 0; h < t.n; ++h) {
      if (h % 64 == 0 && progress.cancelled()) throw Cancelled();
      std::vector<Vec2> pts;
      Vec2 pos{};
      int k = h;
      for (char x : symbols) {
        const auto u = static_cast<unsigned char>(x);
        if (c.action[u] == Action::Draw) {
          pos += t.step[static_cast<std::size_t>(k)];
          pts.push_back(pos);
        } else {
          k = t.rotate(k, t.turn[u]);
        }
      }
      b.turn = (k - h + t.n) % t.n;
      b.points.push_back(std::move(pts));
    }
    block[s] = static_cast<int>(blocks.size());
    blocks.push_back(std::move(b));
  }
}

}  // namespace selfsim::lsystem
