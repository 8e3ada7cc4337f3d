#include "kernels/lsystem/turtle.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <type_traits>

#include "kernels/geom/budget.h"
#include "kernels/geom/check.h"
#include "kernels/geom/count_text.h"
#include "kernels/geom/error.h"
#include "kernels/geom/huge_pages.h"
#include "kernels/geom/similarity.h"
#include "kernels/lsystem/compiled_grammar.h"
#include "kernels/lsystem/production_count.h"

namespace selfsim::lsystem {

namespace {

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

struct Frame {
  const std::uint8_t* pos;
  const std::uint8_t* end;
};

constexpr double symbols_per_point = 64;

const std::uint8_t* bytes(const std::string& s) { return reinterpret_cast<const std::uint8_t*>(s.data()); }

// Expands depth-first into out and returns the turtle's final position. With lattice headings, a symbol
// reaching the blocks' depth is drawn by copying its precomputed block.
template <class Heading>
Vec2 run_turtle(const Compiled& c, const std::string& axiom, int level, Heading heading, const LatticeBlocks* blocks,
                double predicted_segments, Polyline& out, Progress& progress) {
  std::vector<Frame> frames;
  frames.reserve(static_cast<std::size_t>(level) + 1);
  frames.push_back({bytes(axiom), bytes(axiom) + axiom.size()});
  std::vector<std::pair<Vec2, Heading>> saved;
  Vec2 pos{};
  bool path_open = false;
  // Progress and cancellation once per 2^20 units of work: a symbol read, or a point copied from a block.
  // Counting symbols, not points, keeps a grammar that rewrites much and draws little stoppable too.
  constexpr std::size_t check_every = std::size_t{1} << 20;
  std::size_t work = 0, next_check = check_every;
  const int block_level = blocks ? level - blocks->depth : -1;  // rewritings done when blocks take over

  while (!frames.empty()) {
    Frame& f = frames.back();
    if (f.pos == f.end) {
      frames.pop_back();
      continue;
    }
    if (++work >= next_check) {
      progress.step(static_cast<double>(out.points.size()) / predicted_segments);
      next_check = work + check_every;
    }
    const std::uint8_t s = *f.pos++;
    const int r = c.rule[s];
    const int done = static_cast<int>(frames.size()) - 1;
    if (r >= 0 && done < level) {
      if constexpr (std::is_same_v<Heading, LatticeHeading>) {
        if (done == block_level && blocks->block[s] >= 0) {
          const LatticeBlocks::Block& b = blocks->blocks[static_cast<std::size_t>(blocks->block[s])];
          const std::vector<Vec2>& pts = b.points[static_cast<std::size_t>(heading.k)];
          if (!pts.empty()) {
            if (!path_open) out.points.push_back(pos);
            path_open = true;
            for (const Vec2& p : pts) out.points.push_back(pos + p);
            pos = out.points.back();
          }
          heading.k = heading.table->rotate(heading.k, b.turn);
          work += pts.size();
          continue;
        }
      }
      const std::string& rule = c.rules[static_cast<std::size_t>(r)];
      frames.push_back({bytes(rule), bytes(rule) + rule.size()});
      continue;
    }
    switch (c.action[s]) {
      case Action::None:
        break;
      case Action::Draw:
        if (!path_open) {
          out.points.push_back(pos);
          path_open = true;
        }
        pos += heading.forward();
        out.points.push_back(pos);
        break;
      case Action::Move:
        out.close_path();
        path_open = false;
        pos += heading.forward();
        break;
      case Action::Turn:
        heading.rotate(s);
        break;
      case Action::Push:
        saved.emplace_back(pos, heading);
        break;
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

void CurveOptions::validate() const { check_range(level, 0, max_level, "option 'level'"); }

Polyline curve(const Grammar& g, const CurveOptions& opt, Progress& progress) {
  Polyline out;
  curve_into(g, opt, progress, out);
  return out;
}

void curve_into(const Grammar& g, const CurveOptions& opt, Progress& progress, Polyline& out) {
  g.validate();
  opt.validate();
  const LevelCounts counts = predict_counts(g, opt.level, progress);
  const std::string what = "level " + std::to_string(opt.level);
  check_budget(counts.max_points(), opt.budget, what);  // every path break adds a point
  // Each branch left open keeps a saved turtle state (32 bytes, two points' worth) until it closes.
  if (counts.max_depth > 0)
    check_budget(counts.max_points() + 2 * counts.max_depth, opt.budget,
                 what + ", with " + count_text(counts.max_depth) + " branches open at once,");
  // Symbols that draw nothing still cost time: refuse levels that would rewrite far more than they draw.
  if (counts.symbols > symbols_per_point * opt.budget.left())
    throw BudgetError(what + " would rewrite " + count_text(counts.symbols) + " symbols, over the limit of " +
                      count_text(symbols_per_point * opt.budget.left()) + " (" +
                      std::to_string(static_cast<int>(symbols_per_point)) + " x --max-points)");

  out.points.clear();
  out.path_ends.clear();
  out.point_fields = {};
  out.cell_fields = {};
  out.point_fields.set(uniform_int("level", opt.level));
  out.points.reserve(static_cast<std::size_t>(counts.max_points()));  // within the budget: checked above
  advise_huge_pages(out.points);
  progress.start("L-system");

  const Compiled c(g);
  const int lattice = c.lattice();
  const double start = g.start_angle(opt.level);
  Vec2 end;  // the turtle walks unit steps; the step length shrink^level is applied below
  if (lattice > 0) {
    const LatticeTable table(c, lattice, start);
    const LatticeBlocks blocks(g, c, table, opt.level, progress);
    end = run_turtle(c, g.axiom, opt.level, LatticeHeading{&table}, &blocks, counts.segments, out, progress);
  } else {
    end = run_turtle(c, g.axiom, opt.level, FreeHeading{&c, start * degree}, nullptr, counts.segments, out, progress);
  }
  progress.fraction(1);

  // Closed when the turtle ends within a tiny fraction of the distance it walked. Open curves are
  // normalised, so shrink never matters to them (nor can shrink^level underflow them to a point).
  const bool closed = norm(end) <= 1e-9 * (counts.segments + counts.breaks);
  const Similarity2 place = opt.normalize && !closed ? Similarity2::to_unit({0, 0}, end)
                                                     : Similarity2{{std::pow(g.shrink, opt.level), 0}, {0, 0}};
  bool finite = true;
  for (Vec2& p : out.points) {
    p = place(p);
    finite &= is_finite(p);
  }
  if (!finite)
    throw Error("level " + std::to_string(opt.level) + " has non-finite coordinates (shrink^level overflows)");
}

std::string expand_string(const Grammar& g, int level, double max_symbols) {
  g.validate();
  CurveOptions{.level = level}.validate();
  const double n = predict_counts(g, level).symbols;
  if (n > max_symbols)
    throw Error("level " + std::to_string(level) + " has " + count_text(n) + " symbols, over the limit of " +
                count_text(max_symbols) + " for a string");
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
