#include "kernels/lsystem/turtle.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "kernels/geom/error.h"
#include "kernels/geom/similarity.h"
#include "kernels/lsystem/production_count.h"

namespace selfsim::lsystem {

namespace {

enum class Action : std::uint8_t { None, Draw, Move, Turn, Push, Pop };

constexpr double degree = std::numbers::pi / 180;

// The grammar as flat tables indexed by symbol byte, for the hot loop.
struct Compiled {
  std::array<Action, 256> action{};
  std::array<double, 256> turn{};          // degrees
  std::array<int, 256> rule{};             // index into rules, or -1
  std::vector<std::string> rules;

  explicit Compiled(const Grammar& g) {
    rule.fill(-1);
    for (int s = 0; s < 256; ++s) {
      const char c = static_cast<char>(s);
      turn[s] = g.turn_of(c);
      action[s] = g.draws(c) ? Action::Draw
                  : g.moves(c) ? Action::Move
                  : c == '[' ? Action::Push
                  : c == ']' ? Action::Pop
                  : turn[s] != 0 ? Action::Turn
                                 : Action::None;
    }
    for (const auto& [symbol, replacement] : g.rules) {
      rule[static_cast<unsigned char>(symbol)] = static_cast<int>(rules.size());
      rules.push_back(replacement);
    }
  }

  // Smallest N <= 7200 such that every turn is a whole number of 360/N degree steps, or 0 if none.
  int lattice() const {
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
};

// Direction tables shared by every copy of a heading (the turtle stack copies headings).
struct LatticeTable {
  std::vector<Vec2> step;       // step vector for each of the n lattice directions
  std::array<int, 256> turn{};  // lattice steps turned left by each symbol, in [0, n)
  int n = 1;

  LatticeTable(const Compiled& c, int lattice, double start_deg, double length) : n(lattice) {
    for (int i = 0; i < n; ++i) step.push_back(length * polar(start_deg * degree + 2 * std::numbers::pi * i / n));
    for (int s = 0; s < 256; ++s) {
      const long t = std::lround(c.turn[s] * n / 360) % n;
      turn[s] = static_cast<int>(t < 0 ? t + n : t);  // in [0, n): a turn is one add and one wrap
    }
  }
};

// Heading as a whole number of lattice steps: one table look-up per segment, and no drift from
// accumulating rounded angles however long the curve.
struct LatticeHeading {
  const LatticeTable* table;
  int k = 0;

  Vec2 forward() const { return table->step[static_cast<std::size_t>(k)]; }
  void rotate(std::uint8_t s) {
    k += table->turn[s];
    if (k >= table->n) k -= table->n;
  }
};

// Heading as an angle, for turns that fit no lattice (irrational fractions of a circle).
struct FreeHeading {
  const Compiled* c;
  double radians, length;

  Vec2 forward() const { return length * polar(radians); }
  void rotate(std::uint8_t s) { radians = std::remainder(radians + c->turn[s] * degree, 2 * std::numbers::pi); }
};

struct Frame {
  const std::uint8_t* pos;
  const std::uint8_t* end;
};

const std::uint8_t* bytes(const std::string& s) { return reinterpret_cast<const std::uint8_t*>(s.data()); }

// Expands depth-first into out; returns the turtle's final position.
template <class Heading>
Vec2 run_turtle(const Compiled& c, const std::string& axiom, int level, Heading heading, double predicted_segments,
                Polyline& out, Progress& progress) {
  std::vector<Frame> frames;
  frames.reserve(static_cast<std::size_t>(level) + 1);
  frames.push_back({bytes(axiom), bytes(axiom) + axiom.size()});
  std::vector<std::pair<Vec2, Heading>> saved;
  Vec2 pos{};
  bool path_open = false;
  std::size_t drawn = 0;
  constexpr std::size_t report_every = std::size_t{1} << 20;

  while (!frames.empty()) {
    Frame& f = frames.back();
    if (f.pos == f.end) {
      frames.pop_back();
      continue;
    }
    const std::uint8_t s = *f.pos++;
    const int r = c.rule[s];
    if (r >= 0 && static_cast<int>(frames.size()) <= level) {
      const std::string& rule = c.rules[static_cast<std::size_t>(r)];
      frames.push_back({bytes(rule), bytes(rule) + rule.size()});
      continue;
    }
    switch (c.action[s]) {
      case Action::None: break;
      case Action::Draw:
        if (!path_open) {
          out.points.push_back(pos);
          path_open = true;
        }
        pos += heading.forward();
        out.points.push_back(pos);
        if (++drawn % report_every == 0) progress.step(static_cast<double>(drawn) / predicted_segments);
        break;
      case Action::Move:
        out.close_path();
        path_open = false;
        pos += heading.forward();
        break;
      case Action::Turn: heading.rotate(s); break;
      case Action::Push: saved.emplace_back(pos, heading); break;
      case Action::Pop:
        if (saved.empty()) throw Error("option 'axiom'/'rules': ']' without a matching '['");
        out.close_path();
        path_open = false;
        pos = saved.back().first;
        heading = saved.back().second;
        saved.pop_back();
        break;
    }
  }
  out.close_path();
  return pos;
}

}  // namespace

void CurveOptions::validate() const {
  if (level < 0 || level > max_level)
    throw Error("option 'level' must be an integer in [0, " + std::to_string(max_level) + "], got " +
                std::to_string(level));
}

Polyline curve(const Grammar& g, const CurveOptions& opt, Progress& progress) {
  g.validate();
  opt.validate();
  const LevelCounts counts = predict_counts(g, opt.level);
  if (counts.segments + 1 > opt.max_points)
    throw Error("level " + std::to_string(opt.level) + " would make " + std::to_string(std::llround(counts.segments + 1)) +
                " points, over the limit of " + std::to_string(std::llround(opt.max_points)) +
                " (raise it with --max-points)");

  Polyline out;
  out.level = opt.level;
  out.points.reserve(static_cast<std::size_t>(std::min(counts.max_points(), opt.max_points)));
  progress.start("L-system");

  const Compiled c(g);
  const int lattice = c.lattice();
  const double start = g.start_angle(opt.level);
  const double length = std::pow(g.shrink, opt.level);
  Vec2 end;
  if (lattice > 0) {
    const LatticeTable table(c, lattice, start, length);
    end = run_turtle(c, g.axiom, opt.level, LatticeHeading{&table}, counts.segments, out, progress);
  } else {
    end = run_turtle(c, g.axiom, opt.level, FreeHeading{&c, start * degree, length}, counts.segments, out, progress);
  }
  progress.fraction(1);

  const double extent = std::max(out.bbox().size().x, out.bbox().size().y);
  if (opt.normalize && norm(end) > 1e-9 * extent) {
    const Similarity2 t = Similarity2::to_unit({0, 0}, end);
    for (Vec2& p : out.points) p = t(p);
  }
  if (!out.finite()) throw Error("level " + std::to_string(opt.level) + " has non-finite coordinates (shrink too small?)");
  return out;
}

std::string expand_string(const Grammar& g, int level, double max_symbols) {
  g.validate();
  CurveOptions{.level = level}.validate();
  const double n = predict_counts(g, level).symbols;
  if (n > max_symbols)
    throw Error("level " + std::to_string(level) + " has " + std::to_string(std::llround(n)) +
                " symbols, over the limit of " + std::to_string(std::llround(max_symbols)) + " for a string");
  std::string s = g.axiom;
  for (int d = 0; d < level; ++d) {
    std::string next;
    next.reserve(s.size() * 2);
    for (char c : s) {
      auto it = g.rules.find(c);
      next += it == g.rules.end() ? std::string(1, c) : it->second;
    }
    s = std::move(next);
  }
  return s;
}

}  // namespace selfsim::lsystem
