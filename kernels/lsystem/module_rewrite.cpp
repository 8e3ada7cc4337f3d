#include "kernels/lsystem/module_rewrite.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

#include "kernels/geom/budget.h"
#include "kernels/geom/count_text.h"
#include "kernels/geom/error.h"
#include "kernels/lsystem/context_match.h"
#include "kernels/lsystem/cut.h"
#include "kernels/lsystem/derivation_frame.h"
#include "kernels/lsystem/rule_index.h"

namespace selfsim::lsystem {

namespace {

constexpr std::size_t check_every = std::size_t{1} << 16;
// rule_parser.cpp's bound on the parameters a rule binds, and the binding's on a grammar's constants.
constexpr std::size_t max_scope = 48 + max_constants;

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
        stochastic_(g.stochastic()),
        values_(static_cast<std::size_t>(g.max_depth) + 2) {
    for (char c : g.ignore) ignored_[static_cast<std::uint8_t>(c)] = true;
    if (g.constants.size() > max_constants) throw Error("internal error: too many constants");
    for (const auto& [name, value] : g.constants) scope_[k_++] = value;
  }

  bool context() const { return index_.context; }

  ModuleString axiom() {
    ModuleString s;
    const std::uint64_t root = root_lineage(g_.seed);
    Cut cut;
    for (const Call& c : g_.start) {
      double args[max_scope];
      for (std::size_t k = 0; k < c.args.size(); ++k)
        args[k] = evaluate(c.args[k], {scope_.data(), k_}, c, k, nullptr, 0);
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
        if (const Production* p = match(index_, s, run.args_of(i))) {
          const std::uint64_t lineage = f.lineage(i, stochastic_);
          if (d + 1 == static_cast<std::size_t>(level) && decompose_.total == 0) {
            emit_successor(*p, lineage, level, cut, sink);  // the last level: never held
            continue;
          }
          DerivationFrame& next = frames[++d];
          pos[d] = 0;
          if (decompose_.total == 0) {  // the successor read in place, with its evaluated parameters
            const Successor& succ = chosen(*p, lineage);
            evaluate_successor(*p, succ, static_cast<int>(d), next.values);
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
        if (const Production* p = match(index_, cur, &near, i))
          apply(*p, lineage_of(cur, i), k, out, streamed ? nullptr : &cut);
        else if (streamed || cut.keep(cur.symbols[i]))
          out.push(cur.symbols[i], cur.args_of(i), stochastic_ ? &cur.lineage[i] : nullptr);
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
  // A written module's lineage: hashed only when a choice will read it.
  std::uint64_t child(std::uint64_t parent, const Call& c) const {
    return stochastic_ ? child_lineage(parent, c.salt) : 0;
  }

  double evaluate(const Expression& e, std::span<const double> scope, const Call& c, std::size_t k, const Production* p,
                  int level) const {
    try {
      return e.eval(scope);
    } catch (const EvalError& err) {
      const std::string where = p == nullptr ? "option 'axiom'" : p->where + " (" + p->text + ")";
      throw Error(where + (p == nullptr ? "" : " deriving level " + std::to_string(level)) + ": parameter " +
                  std::to_string(k + 1) + " of " + module_text(c.symbol, {}) + ": " + err.what());
    }
  }

  // The first production of `index` that rewrites module i of s, its parameters bound in scope_ (after the
  // constants, which scope_ always holds); null if none. `near` is given when productions have contexts.
  const Production* match(const RuleIndex& index, const ModuleString& s, const Neighbours* near, std::size_t i) {
    const std::span<const double> args = s.args_of(i);
    double* params = scope_.data() + k_;
    for (const Production* p : index.by_symbol[s.symbols[i]]) {
      if (p->pred.params.size() != args.size()) continue;
      std::size_t slot = 0;
      for (const Pattern& m : p->left) slot += m.params.size();
      std::copy(args.begin(), args.end(), params + slot);
      if (p->context() && !(left_context(*p, s, *near, i, params) &&
                            right_context(*p, s, *near, i, ignored_, params + slot + args.size())))
        continue;
      if (holds(*p)) return p;
    }
    return nullptr;
  }

  // The first context-free production of `index` for a module given by its symbol and parameters.
  const Production* match(const RuleIndex& index, std::uint8_t symbol, std::span<const double> args) {
    for (const Production* p : index.by_symbol[symbol]) {
      if (p->pred.params.size() != args.size()) continue;
      std::copy(args.begin(), args.end(), scope_.data() + k_);
      if (holds(*p)) return p;
    }
    return nullptr;
  }

  bool holds(const Production& p) const {
    if (p.condition.empty()) return true;
    try {
      return p.condition.eval({scope_.data(), k_ + static_cast<std::size_t>(p.slots)}) != 0;
    } catch (const EvalError& err) {
      throw Error(p.where + " (" + p.text + "): its condition: " + err.what());
    }
  }

  // The successor p chooses for a module of this lineage (its parameters bound in scope_).
  const Successor& chosen(const Production& p, std::uint64_t lineage) const {
    if (p.options.size() == 1) return p.options[0];
    return p.options[choose_option(p.options, choice_point(lineage))];
  }

  // Evaluates the successor's parameters into `values` (the modules' parameters, in order), before any
  // of them is written: writing may decompose, which binds scope_ again.
  void evaluate_successor(const Production& p, const Successor& succ, int level, std::vector<double>& values) const {
    const std::span<const double> bound{scope_.data(), k_ + static_cast<std::size_t>(p.slots)};
    values.clear();
    for (const Call& c : succ.modules)
      for (std::size_t k = 0; k < c.args.size(); ++k) values.push_back(evaluate(c.args[k], bound, c, k, &p, level));
  }

  // Writes p's successor for a module of this lineage (its parameters bound in scope_) into out.
  void apply(const Production& p, std::uint64_t lineage, int level, ModuleString& out, Cut* cut) {
    const Successor& succ = chosen(p, lineage);
    std::vector<double>& values = values_[0];
    evaluate_successor(p, succ, level, values);
    std::size_t v = 0;
    for (const Call& c : succ.modules) {
      write(out, c.symbol, {values.data() + v, c.args.size()}, child(lineage, c), level, 0, cut);
      v += c.args.size();
    }
    count(succ.modules.size());
  }

  // Feeds p's successor for a module of this lineage straight to the sink, as the last level's frame would.
  void emit_successor(const Production& p, std::uint64_t lineage, int level, Cut& cut, ModuleSink& sink) {
    const Successor& succ = chosen(p, lineage);
    std::vector<double>& values = values_[0];
    evaluate_successor(p, succ, level, values);
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
      if (const Production* p = match(decompose_, symbol, args)) {
        const Successor& succ = chosen(*p, lineage);
        std::vector<double>& values = values_[static_cast<std::size_t>(depth) + 1];
        evaluate_successor(*p, succ, level, values);
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
    out.push(symbol, args, stochastic_ ? &lineage : nullptr);
  }

  // Feeds a module of the level to the sink, replaced first by its interpretation (recursively, to
  // g.max_depth levels) when drawing and an interpretation rule matches it.
  void emit(std::uint8_t symbol, std::span<const double> args, std::uint64_t lineage, int level, int depth,
            ModuleSink& sink) {
    if (interpreting_ && depth < g_.max_depth && !interpret_.empty_for(symbol)) {
      if (const Production* p = match(interpret_, symbol, args)) {
        const Successor& succ = chosen(*p, lineage);
        std::vector<double>& values = values_[static_cast<std::size_t>(depth) + 1];
        evaluate_successor(*p, succ, level, values);
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

  // Counts modules written; a decomposition or interpretation that keeps writing is stopped here.
  void count(std::size_t n) {
    written_ += n;
    if (written_ < next_written_) return;
    next_written_ = written_ + check_every;
    if (static_cast<double>(work_ + written_) > limits_.work) over_budget();
    if (progress_.cancelled()) throw Cancelled();
  }

  void over_budget() const {
    throw BudgetError("the grammar would rewrite more than " + count_text(limits_.work) +
                      " modules, over the limit (64 x --max-points)");
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
  bool stochastic_;
  std::array<bool, 256> ignored_{};
  std::vector<std::vector<double>> values_;  // evaluated successor parameters, one list per depth
  std::array<double, max_scope> scope_{};    // the grammar's constants, then the parameters a rule binds
  std::size_t k_ = 0;                        // how many constants
  bool interpreting_ = false;
  std::array<bool, 256> passes_{};  // see interpret()
  std::array<bool, 256> final_{};   // the same on the last level, where productions no longer apply
  std::size_t work_ = 0, written_ = 0, next_check_ = check_every, next_written_ = check_every;
};

struct TextSink : ModuleSink {
  std::string text;
  double max_modules;
  double count = 0;
  int level;
  void module(std::uint8_t s, std::span<const double> args) override {
    text += module_text(s, args);
    // Parameters print up to 24 bytes each: the text is bounded too, not only the count.
    if (++count > max_modules || static_cast<double>(text.size()) > 8 * max_modules)
      throw Error("level " + std::to_string(level) + " has more than " + count_text(max_modules) + " modules (or " +
                  count_text(8 * max_modules) + " bytes of text), over the limit for a string");
  }
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

std::string module_string_text(const Grammar& g, int level, double max_modules, Progress& progress) {
  TextSink sink;
  sink.max_modules = max_modules;
  sink.level = level;
  // A string is small: its derivation may hold and do no more than its text could be.
  rewrite_modules(g, level, sink, {.work = 64 * max_modules, .held = max_modules}, progress);
  return std::move(sink.text);
}

}  // namespace selfsim::lsystem
