#include "kernels/lsystem/module_rewrite.h"

#include <algorithm>
#include <array>
#include <limits>
#include <utility>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/count_text.h"
#include "kernels/base/error.h"
#include "kernels/lsystem/context_match.h"
#include "kernels/lsystem/cut.h"
#include "kernels/lsystem/derivation_frame.h"
#include "kernels/lsystem/expansion_count.h"
#include "kernels/lsystem/polled_growth.h"
#include "kernels/lsystem/rule_index.h"
#include "kernels/lsystem/rule_scope.h"

namespace selfsim::lsystem {

namespace {

constexpr std::size_t check_every = std::size_t{1} << 16;
// A decomposition or interpretation bounded by this many modules (expansion_count.h) is not counted before
// it is written: it cannot take the budget by surprise, and counting it would cost as much as writing it.
constexpr double small_expansion = 4096;

// The memory a level takes, in budget points (16 bytes): what its arrays have reserved.
double held_points(const ModuleString& s) {
  return (static_cast<double>(s.symbols.capacity()) + 4.0 * static_cast<double>(s.arg_end.capacity()) +
          8.0 * static_cast<double>(s.args.capacity() + s.lineage.capacity())) /
         16;
}

class Deriver {
 public:
  Deriver(const Grammar& g, const ModuleLimits& limits, Progress& progress)
      : g_(g),
        index_(g.productions),
        decompose_(g.decomposition),
        interpret_(g.interpretation),
        limits_(limits),
        progress_(progress),
        rules_(g),
        stochastic_(g.stochastic()),
        decomposed_(decompose_, g.max_depth, rules_, limits.steps, progress),
        interpreted_(interpret_, g.max_depth, rules_, limits.steps, progress),
        values_(static_cast<std::size_t>(g.max_depth) + 2) {
    for (char c : g.ignore) ignored_[static_cast<std::uint8_t>(c)] = true;
  }

  bool context() const { return index_.context; }

  ModuleString axiom() {
    ModuleString s;
    const std::uint64_t root = root_lineage(g_.seed);
    Cut cut;
    for (const Call& c : g_.start) {
      double args[max_scope];
      for (std::size_t k = 0; k < c.args.size(); ++k)
        args[k] = rules_.evaluate(c.args[k], rules_.constants(), c, k, nullptr, 0);
      write(s, c.symbol, {args, c.args.size()}, child_lineage(root, c.salt), 0, 0, &cut);
    }
    return s;
  }

  // Context-free grammars: depth-first, one evaluated successor per level.
  void depth_first(int level, ModuleSink& sink) {
    std::vector<DerivationFrame> frames(static_cast<std::size_t>(level) + 1);
    std::vector<std::size_t> pos(frames.size(), 0);
    frames[0].held = axiom();
    frames[0].hold();
    Cut cut;
    std::size_t d = 0;
    while (true) {
      const DerivationFrame& f = frames[d];
      const ModuleRun& run = f.run;
      if (pos[d] == run.end) {
        if (d == 0) break;
        --d;
        continue;
      }
      const std::size_t i = pos[d]++;
      if (++work_ >= next_check_) check(frames, pos, d);
      const std::uint8_t s = run.symbols[i];
      if (cut.active && s != '[' && s != ']') continue;  // dropped with the rest of its branch
      const std::array<bool, 256>& passes = d == static_cast<std::size_t>(level) ? final_ : passes_;
      if (passes[s] && !cut.active) {
        pos[d] = emit_run(run, i, sink, passes);
        work_ += pos[d] - i - 1;
        continue;
      }
      if (d < static_cast<std::size_t>(level)) {
        if (const Production* p = rules_.match(index_, s, run.args_of(i), static_cast<int>(d) + 1)) {
          const std::uint64_t lineage = f.lineage(i, stochastic_);
          if (d + 1 == static_cast<std::size_t>(level) && decompose_.total == 0) {
            emit_successor(*p, lineage, level, cut, sink);  // the last level: never held
            continue;
          }
          DerivationFrame& next = frames[++d];
          pos[d] = 0;
          if (decompose_.total == 0) {  // the successor read in place, with its evaluated parameters
            const Successor& succ = rules_.chosen(*p, lineage);
            rules_.evaluate_successor(*p, succ, static_cast<int>(d), next.values);
            next.view(succ, lineage);
            count(succ.modules.size());
          } else {
            next.held.clear();
            apply(*p, lineage, static_cast<int>(d), next.held, nullptr);
            next.hold();
          }
          continue;
        }
      }
      if (cut.keep(s)) emit(s, run.args_of(i), f.lineage(i, stochastic_), level, 0, sink);
    }
  }

  // Context-sensitive grammars: each level below the last held whole, the last streamed.
  void level_by_level(int level, ModuleSink& sink) {
    ModuleString cur = axiom(), next, last;
    for (int k = 1; k <= level; ++k) {
      const Neighbours near = level_neighbours(cur, ignored_);
      const bool streamed = k == level;
      Cut cut;
      for (std::size_t i = 0; i < cur.size(); ++i) {
        if (++work_ >= next_check_) check_level(k, level, i, cur, next);
        ModuleString& out = streamed ? last : next;
        if (streamed) last.clear();
        if (const Production* p = match(cur, near, i, k))
          apply(*p, lineage_of(cur, i), k, out, streamed ? nullptr : &cut);
        else if (streamed || cut.keep(cur.symbols[i]))
          push(out, cur.symbols[i], cur.args_of(i), stochastic_ ? &cur.lineage[i] : nullptr);
        if (streamed)
          for (std::size_t j = 0; j < last.size(); ++j)
            if (cut.keep(last.symbols[j])) emit(last.symbols[j], last.args_of(j), lineage_of(last, j), level, 0, sink);
      }
      if (!streamed) {
        check_held(k, cur, next);
        std::swap(cur, next);
        next.clear();
      }
    }
    if (level == 0)
      for (std::size_t i = 0; i < cur.size(); ++i) emit(cur.symbols[i], cur.args_of(i), lineage_of(cur, i), 0, 0, sink);
  }

  void interpret(bool on) {
    interpreting_ = on;
    // The symbols that reach the sink as they are, wherever they are met: no production, no interpretation
    // when drawing, and not the cut; on the last level, any without interpretation but the cut.
    for (int c = 0; c < 256; ++c) {
      final_[c] = c != '%' && (!interpreting_ || interpret_.empty_for(static_cast<std::uint8_t>(c)));
      passes_[c] = final_[c] && index_.empty_for(static_cast<std::uint8_t>(c));
    }
  }

 private:
  std::uint64_t lineage_of(const ModuleString& s, std::size_t i) const { return stochastic_ ? s.lineage[i] : 0; }
  std::uint64_t child(std::uint64_t parent, const Call& c) const { return rules_.child(parent, c); }

  // The first production of index_ that rewrites module i of s (deriving level `level`), its parameters
  // bound in the scope (after the constants); null if none.
  const Production* match(const ModuleString& s, const Neighbours& near, std::size_t i, int level) {
    const std::span<const double> args = s.args_of(i);
    double* params = rules_.params();
    for (const Production* p : index_.by_symbol[s.symbols[i]]) {
      if (p->pred.params.size() != args.size()) continue;
      std::size_t slot = 0;
      for (const Pattern& m : p->left) slot += m.params.size();
      std::copy(args.begin(), args.end(), params + slot);
      if (p->context() && !(left_context(*p, s, near, i, params) &&
                            right_context(*p, s, near, i, ignored_, params + slot + args.size())))
        continue;
      if (rules_.holds(*p, args, level)) return p;
    }
    return nullptr;
  }

  // Writes p's successor for a module of this lineage (its parameters bound) into out.
  void apply(const Production& p, std::uint64_t lineage, int level, ModuleString& out, Cut* cut) {
    const Successor& succ = rules_.chosen(p, lineage);
    std::vector<double>& values = values_[0];
    rules_.evaluate_successor(p, succ, level, values);
    std::size_t v = 0;
    for (const Call& c : succ.modules) {
      write(out, c.symbol, {values.data() + v, c.args.size()}, child(lineage, c), level, 0, cut);
      v += c.args.size();
    }
    count(succ.modules.size());
  }

  // Feeds p's successor for a module of this lineage straight to the sink, as the last level's frame would.
  void emit_successor(const Production& p, std::uint64_t lineage, int level, Cut& cut, ModuleSink& sink) {
    const Successor& succ = rules_.chosen(p, lineage);
    std::vector<double>& values = values_[0];
    rules_.evaluate_successor(p, succ, level, values);
    const ModuleRun run{succ.symbols.data(), succ.arg_end.data(), values.data(), 0, succ.symbols.size()};
    for (std::size_t i = 0; i < run.end;) {
      const std::uint8_t s = run.symbols[i];
      if (final_[s] && !cut.active) {
        i = emit_run(run, i, sink, final_);
        continue;
      }
      if (!(cut.active && s != '[' && s != ']') && cut.keep(s))
        emit(s, run.args_of(i), child(lineage, succ.modules[i]), level, 0, sink);
      ++i;
    }
    work_ += run.end;  // read, as from a frame (the loop checks the total)
    count(run.end);
  }

  // Feeds the run of modules from i on that go to the sink as they are (`passes`: passes_ or final_) in one
  // call; returns where the run ends.
  std::size_t emit_run(ModuleRun run, std::size_t i, ModuleSink& sink, const std::array<bool, 256>& passes) {
    std::size_t j = i + 1;
    while (j < run.end && passes[run.symbols[j]]) ++j;
    run.begin = i;
    run.end = j;
    sink.modules(run);
    return j;
  }

  // Appends a module to out, replaced first by its decomposition (recursively, to g.max_depth levels)
  // when a decomposition rule matches it.
  void write(ModuleString& out, std::uint8_t symbol, std::span<const double> args, std::uint64_t lineage, int level,
             int depth, Cut* cut) {
    if (depth < g_.max_depth && !decompose_.empty_for(symbol)) {
      if (depth == 0) predict_decomposition(out, symbol, args, lineage, level);
      if (const Production* p = rules_.match(decompose_, symbol, args, level)) {
        const Successor& succ = rules_.chosen(*p, lineage);
        std::vector<double>& values = values_[static_cast<std::size_t>(depth) + 1];
        rules_.evaluate_successor(*p, succ, level, values);
        std::size_t v = 0;
        for (const Call& c : succ.modules) {
          write(out, c.symbol, {values.data() + v, c.args.size()}, child(lineage, c), level, depth + 1, cut);
          v += c.args.size();
        }
        count(succ.modules.size());
        return;
      }
    }
    if (cut != nullptr && !cut->keep(symbol)) return;
    if (out.size() % 1024 == 0 && held_points(out) > limits_.held)
      throw BudgetError("level " + std::to_string(level) + ": one successor's decomposition would take more than " +
                        count_text(limits_.held) + " points' worth of memory, over the limit");
    push(out, symbol, args, stochastic_ ? &lineage : nullptr);
  }

  // Feeds a module of the level to the sink, replaced first by its interpretation (recursively, to
  // g.max_depth levels) when drawing and an interpretation rule matches it.
  void emit(std::uint8_t symbol, std::span<const double> args, std::uint64_t lineage, int level, int depth,
            ModuleSink& sink) {
    if (interpreting_ && depth < g_.max_depth && !interpret_.empty_for(symbol)) {
      if (depth == 0) predict_interpretation(symbol, args, lineage, level);
      if (const Production* p = rules_.match(interpret_, symbol, args, level)) {
        const Successor& succ = rules_.chosen(*p, lineage);
        std::vector<double>& values = values_[static_cast<std::size_t>(depth) + 1];
        rules_.evaluate_successor(*p, succ, level, values);
        std::size_t v = 0;
        for (const Call& c : succ.modules) {
          emit(c.symbol, {values.data() + v, c.args.size()}, child(lineage, c), level, depth + 1, sink);
          v += c.args.size();
        }
        count(succ.modules.size());
        return;
      }
    }
    sink.module(symbol, args);
  }

  // Appends a module to a held string, growing it in pieces that look for a stop (polled_growth.h).
  void push(ModuleString& out, std::uint8_t symbol, std::span<const double> args, const std::uint64_t* lineage) {
    if (out.symbols.size() == out.symbols.capacity() || out.args.size() + args.size() > out.args.capacity())
      make_room(out, args.size(), lineage != nullptr, progress_);
    out.push(symbol, args, lineage);
  }

  // Counts modules written; a decomposition or interpretation that keeps writing is stopped here.
  void count(std::size_t n) {
    written_ += n;
    if (written_ < next_written_) return;
    next_written_ = written_ + check_every;
    if (static_cast<double>(work_ + written_) > limits_.work) over_budget();
    if (progress_.cancelled()) throw Cancelled();
  }

  void over_budget(const std::string& what = "the grammar") const {
    throw BudgetError(what + " would rewrite more than " + count_text(limits_.work) +
                      " modules, over the limit (64 x --max-points)");
  }

  double work_left() const { return limits_.work - static_cast<double>(work_ + written_); }

  static std::string through(const ExpansionSize& size, int level) {
    const std::string rule = size.rule == nullptr ? "" : " through " + size.rule->where + " (" + size.rule->text + ")";
    return "level " + std::to_string(level) + rule;
  }

  // Counts the interpretation of a module before it is drawn: refused when it would pass the work limit or,
  // with the modules drawn through interpretations before it, the point budget.
  void predict_interpretation(std::uint8_t symbol, std::span<const double> args, std::uint64_t lineage, int level) {
    if (!interpreted_.may_exceed(symbol, small_expansion)) return;
    const double inf = std::numeric_limits<double>::infinity();
    const double steps_left = limits_.points ? limits_.points->left() - predicted_steps_ : inf;
    const ExpansionSize size = interpreted_.count(symbol, args, lineage, level, work_left(), steps_left);
    if (limits_.points && size.steps > steps_left) {
      const PointBudget& b = *limits_.points;
      if (!size.over) check_budget(predicted_steps_ + size.steps, b, through(size, level));
      throw BudgetError(through(size, level) + " would make more than " + count_text(b.left()) +
                        " points, over the limit of " + count_text(b.limit) +
                        (b.held > 0 ? " with " + count_text(b.held) + " held by the recipe's other values" : "") +
                        " (raise it with --max-points)");
    }
    if (size.modules > work_left()) over_budget(through(size, level));
    predicted_steps_ += size.steps;
  }

  // Counts the decomposition of a module before it is written into `out`: refused when it would pass the
  // work limit, or make `out` hold more than the memory limit.
  void predict_decomposition(const ModuleString& out, std::uint8_t symbol, std::span<const double> args,
                             std::uint64_t lineage, int level) {
    if (!decomposed_.may_exceed(symbol, small_expansion)) return;
    // Each module held takes at least bytes_per_module(0) bytes; budget points are 16.
    const double held_left = (limits_.held - held_points(out)) * 16 / ModuleString::bytes_per_module(0);
    const double inf = std::numeric_limits<double>::infinity();
    const ExpansionSize size = decomposed_.count(symbol, args, lineage, level, std::min(work_left(), held_left), inf);
    if (size.modules > held_left)
      throw BudgetError(through(size, level) + ": one successor's decomposition would take more than " +
                        count_text(limits_.held) + " points' worth of memory, over the limit");
    if (size.modules > work_left()) over_budget(through(size, level));
  }

  void check(const std::vector<DerivationFrame>& frames, const std::vector<std::size_t>& pos, std::size_t d) {
    next_check_ = work_ + check_every;
    if (static_cast<double>(work_ + written_) > limits_.work) over_budget();
    // Done so far: the finished share of each level's successor, nested.
    double done = 0, scale = 1;
    for (std::size_t k = 0; k <= d && scale > 1e-12; ++k) {
      const double n = static_cast<double>(frames[k].run.end);
      done += scale * (static_cast<double>(pos[k]) - 1) / n;
      scale /= n;
    }
    progress_.step(done);
  }

  void check_level(int k, int level, std::size_t i, const ModuleString& cur, const ModuleString& next) {
    next_check_ = work_ + check_every;
    if (static_cast<double>(work_ + written_) > limits_.work) over_budget();
    check_held(k, cur, next);
    progress_.step((k - 1 + static_cast<double>(i) / static_cast<double>(cur.size())) / level);
  }

  // The two levels a context-sensitive grammar holds (and their neighbours), in budget points.
  void check_held(int k, const ModuleString& cur, const ModuleString& next) const {
    const double points = held_points(cur) + held_points(next) + 8.0 * static_cast<double>(cur.size()) / 16;
    if (points > limits_.held)
      throw BudgetError("level " + std::to_string(k) + " of the context-sensitive grammar would hold " +
                        count_text(static_cast<double>(next.size())) + " modules and more, over the limit of " +
                        count_text(limits_.held) + " points' worth of memory (raise --max-points)");
  }

  const Grammar& g_;
  RuleIndex index_, decompose_, interpret_;
  ModuleLimits limits_;
  Progress& progress_;
  RuleScope rules_;  // the scope every expression is evaluated in
  bool stochastic_;
  ExpansionCount decomposed_, interpreted_;
  double predicted_steps_ = 0;  // points counted by predict_interpretation, drawn or to be
  std::array<bool, 256> ignored_{};
  std::vector<std::vector<double>> values_;  // evaluated successor parameters, one list per depth
  bool interpreting_ = false;
  std::array<bool, 256> passes_{};  // see interpret()
  std::array<bool, 256> final_{};   // the same on the last level, where productions no longer apply
  std::size_t work_ = 0, written_ = 0, next_check_ = check_every, next_written_ = check_every;
};

}  // namespace

void rewrite_modules(const Grammar& g, int level, ModuleSink& sink, const ModuleLimits& limits, Progress& progress,
                     bool interpret) {
  g.validate();
  if (!g.modules()) throw Error("internal error: rewrite_modules needs a module grammar");
  Deriver d(g, limits, progress);
  d.interpret(interpret);
  if (d.context())
    d.level_by_level(level, sink);
  else
    d.depth_first(level, sink);
}

}  // namespace selfsim::lsystem
