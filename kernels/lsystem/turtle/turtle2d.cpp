#include "kernels/lsystem/turtle/turtle2d.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <thread>

#include "kernels/base/budget.h"
#include "kernels/base/check.h"
#include "kernels/base/count_text.h"
#include "kernels/base/error.h"
#include "kernels/base/huge_pages.h"
#include "kernels/geom/all_finite.h"
#include "kernels/geom/similarity.h"
#include "kernels/lsystem/compiled_grammar.h"
#include "kernels/lsystem/production_count.h"
#include "kernels/lsystem/rewrite.h"
#include "kernels/lsystem/turtle/plant.h"
#include "kernels/lsystem/turtle/turtle_split.h"
#include "kernels/lsystem/turtle/turtle_walk.h"

namespace selfsim::lsystem {

namespace {

constexpr double symbols_per_point = 64;

}  // namespace

// Closed when the turtle ends within a tiny fraction of the distance it walked. Normalised open curves do not
// depend on shrink (nor can shrink^level underflow them to a point).
Similarity2 turtle_placement(const Grammar& g, const TurtleOptions& opt, Vec2 end, double steps) {
  const bool closed = norm(end) <= 1e-9 * steps;
  return normalizes(g, opt) && !closed ? Similarity2::to_unit({0, 0}, end)
                                       : Similarity2{{std::pow(g.shrink, opt.level), 0}, {0, 0}};
}

namespace {

Error non_finite(int level) {
  return Error("level " + std::to_string(level) + " has non-finite coordinates (shrink^level overflows)");
}

// One thread, any grammar: draws in unit steps, then places every point.
template <class Heading>
void draw_sequential(const Grammar& g, const TurtleOptions& opt, const Compiled& c, Heading heading,
                     const LatticeBlocks* blocks, const LevelCounts& counts, Polyline& out, Progress& progress) {
  PathTurtle<Heading> turtle{c, heading, blocks, out, progress, counts.max_points()};
  // Branched systems (a plant) also get their branch order and distance from the root: one colour per
  // `level` and an arclength that restarts on every branch say little about a tree. Decided by the grammar,
  // not the level, so every level of a growth carries the same fields.
  TreeFields tree;
  if (branches(g)) {
    tree.branch_order.reserve(out.points.capacity());
    tree.root_distance.reserve(out.points.capacity());
    turtle.tree = &tree;
  }
  rewrite(c, g.axiom, opt.level, turtle);
  out.close_path();
  progress.fraction(1);
  const Similarity2 place = turtle_placement(g, opt, turtle.pos, counts.segments + counts.breaks);
  for (Vec2& p : out.points) p = place(p);
  if (turtle.tree != nullptr && !out.points.empty()) {  // a level that draws nothing has nothing to colour
    const double scale = norm(place.a);                 // unit steps to the curve's own length
    for (double& d : tree.root_distance) d *= scale;
    out.point_fields.set(int_field("branch_order", std::move(tree.branch_order)));
    out.point_fields.set(real_field("root_distance", std::move(tree.root_distance)));
  }
  if (!out.finite()) throw non_finite(opt.level);
}

// Several threads, each drawing its chunks straight into their slices, already placed (the split knows
// where the turtle ends before anything is drawn).
void draw_parallel(const Grammar& g, const TurtleOptions& opt, const Compiled& c, const LatticeTable& table,
                   const TurtleSplit& split, Polyline& out, Progress& progress) {
  const int remaining = opt.level - split.depth;
  const LatticeBlocks blocks(g, c, table, remaining, progress);
  const Similarity2 place = turtle_placement(g, opt, split.end, static_cast<double>(split.points));
  out.points.resize(split.points);
  Vec2* points = out.points.data();
  points[0] = place(Vec2{});
  if (!finite_bits(points[0])) throw non_finite(opt.level);
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<std::size_t> done{0};
  // One chunk per task: the split (not the thread count) decides what each task draws.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, split.chunks.size(), 1), [&](const auto& range) {
    for (std::size_t i = range.begin(); i != range.end(); ++i) {
      const TurtleChunk& k = split.chunks[i];
      SliceTurtle turtle{c,       LatticeHeading{&table, k.heading}, &blocks, place, k.start, points + k.first_point,
                         progress};
      rewrite(c, std::string_view(split.symbols).substr(k.begin, k.end - k.begin), remaining, turtle);
      if (turtle.cursor != points + k.first_point + k.points) throw Error("internal error: a chunk drew a wrong count");
      if (!all_finite(std::span<const Vec2>(points + k.first_point, k.points)))
        throw non_finite(opt.level);  // while the slice is in cache
      const std::size_t total = done += k.points;
      if (std::this_thread::get_id() == caller) progress.fraction(static_cast<double>(total) / split.points);
      if (progress.cancelled()) throw Cancelled();
    }
  });
  out.close_path();
}

}  // namespace

void TurtleOptions::validate() const { check_range(level, 0, max_level, "option 'level'"); }

Polyline turtle2d(const Grammar& g, const TurtleOptions& opt, Progress& progress) {
  Polyline out;
  turtle2d_into(g, opt, progress, out);
  return out;
}

void turtle2d_into(const Grammar& g, const TurtleOptions& opt, Progress& progress, Polyline& out) {
  g.validate();
  opt.validate();
  ProgressStage predicting(progress, 0, 0.01);
  const LevelCounts counts = predict_counts(g, opt.level, predicting);
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
  const double start = start_heading(g, opt);
  if (lattice > 0) {
    const LatticeTable table(c, lattice, start);
    if (const auto split = split_level(g, c, table, opt.level, progress)) {
      draw_parallel(g, opt, c, table, *split, out, progress);
    } else {
      const LatticeBlocks blocks(g, c, table, opt.level, progress);
      draw_sequential(g, opt, c, LatticeHeading{&table}, &blocks, counts, out, progress);
    }
  } else {
    draw_sequential(g, opt, c, FreeHeading{&c, start * degree}, nullptr, counts, out, progress);
  }
}

}  // namespace selfsim::lsystem
