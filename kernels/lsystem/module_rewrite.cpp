#include "kernels/lsystem/module_rewrite.h"

#include <array>
#include <utility>
#include <vector>

#include "kernels/geom/budget.h"
#include "kernels/geom/count_text.h"
#include "kernels/geom/error.h"

namespace selfsim::lsystem {

namespace {

constexpr std::size_t check_every = std::size_t{1} << 16;
// rule_parser.cpp's bound on the parameters a rule binds, and the binding's on a grammar's constants.
constexpr std::size_t max_scope = 48 + max_constants;

std::uint64_t mix(std::uint64_t z) {  // the splitmix64 finaliser: every input bit moves every output bit
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The productions that may rewrite each symbol, in the order they are tried: those with a context first,
// then the others, each group in the order written.
struct RuleIndex {
  std::array<std::vector<const Production*>, 256> by_symbol;
  bool context = false;

  explicit RuleIndex(const Grammar& g) {
    for (bool with_context : {true, false})
      for (const Production& p : g.productions)
        if (p.context() == with_context) {
          by_symbol[p.pred.symbol].push_back(&p);
          context = context || with_context;
        }
  }
};

// '%' cuts the rest of its branch (ABOP 1.10): modules written after it are dropped up to the ']' that
// closes the branch it is in.
struct Cut {
  bool active = false;
  int depth = 0;

  // Whether a module of symbol s is kept (and updates the state).
  bool keep(std::uint8_t s) {
    if (!active) {
      if (s != '%') return true;
      active = true;
      depth = 0;
      return false;
    }
    if (s == '[') ++depth;
    if (s == ']' && depth-- == 0) {
      active = false;
      return true;
    }
    return false;
  }
};

void append(ModuleString& out, std::uint8_t s, std::span<const double> args, const std::uint64_t* lineage) {
  out.symbols.push_back(s);
  out.args.insert(out.args.end(), args.begin(), args.end());
  out.arg_end.push_back(static_cast<std::uint32_t>(out.args.size()));
  if (lineage != nullptr) out.lineage.push_back(*lineage);
}

// For each bracket of s, the position of its partner (other modules: unused).
std::vector<std::uint32_t> partners(const ModuleString& s) {
  std::vector<std::uint32_t> partner(s.size(), 0), open;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.symbols[i] == '[') open.push_back(static_cast<std::uint32_t>(i));
    if (s.symbols[i] == ']' && !open.empty()) {
      partner[i] = open.back();
      partner[open.back()] = static_cast<std::uint32_t>(i);
      open.pop_back();
    }
  }
  for (std::uint32_t i : open) partner[i] = static_cast<std::uint32_t>(s.size());  // never closed
  return partner;
}

class Deriver {
 public:
  Deriver(const Grammar& g, const ModuleLimits& limits, Progress& progress)
      : g_(g), index_(g), limits_(limits), progress_(progress), stochastic_(g.stochastic()) {
    for (char c : g.ignore) ignored_[static_cast<std::uint8_t>(c)] = true;
    if (g.constants.size() > max_constants) throw Error("internal error: too many constants");
    for (const auto& [name, value] : g.constants) base_[k_++] = value;
  }

  bool context() const { return index_.context; }

  ModuleString axiom() {
    ModuleString s;
    const std::uint64_t root = mix(g_.seed);
    Cut cut;
    for (const Call& c : g_.start) {
      if (!cut.keep(c.symbol)) continue;
      double args[max_scope];
      for (std::size_t k = 0; k < c.args.size(); ++k)
        args[k] = evaluate(c.args[k], {base_.data(), k_}, c, k, nullptr, 0);
      const std::uint64_t lineage = child_lineage(root, c.salt);
      append(s, c.symbol, {args, c.args.size()}, stochastic_ ? &lineage : nullptr);
    }
    return s;
  }

  // Context-free grammars: depth-first, one evaluated successor per level.
  void depth_first(int level, ModuleSink& sink) {
    std::vector<ModuleString> frames(static_cast<std::size_t>(level) + 1);
    std::vector<std::size_t> pos(frames.size(), 0);
    frames[0] = axiom();
    std::array<double, max_scope> scope = base_;
    Cut cut;
    std::size_t d = 0;
    while (true) {
      ModuleString& f = frames[d];
      if (pos[d] == f.size()) {
        if (d == 0) break;
        --d;
        continue;
      }
      const std::size_t i = pos[d]++;
      if (++work_ >= next_check_) check(frames, pos, d);
      const std::uint8_t s = f.symbols[i];
      if (cut.active && s != '[' && s != ']') continue;  // dropped with the rest of its branch
      if (d < static_cast<std::size_t>(level)) {
        if (const Production* p = match(f, nullptr, i, scope.data())) {
          frames[d + 1].clear();
          apply(*p, f, i, scope.data(), static_cast<int>(d) + 1, frames[d + 1], nullptr);
          pos[++d] = 0;
          continue;
        }
      }
      if (cut.keep(s)) sink.module(s, f.args_of(i));
    }
  }

  // Context-sensitive grammars: each level below the last held whole, the last streamed.
  void level_by_level(int level, ModuleSink& sink) {
    ModuleString cur = axiom(), next, scratch;
    std::array<double, max_scope> scope = base_;
    for (int k = 1; k <= level; ++k) {
      const std::vector<std::uint32_t> partner = partners(cur);
      const bool last = k == level;
      Cut cut;
      ModuleString& out = last ? scratch : next;
      for (std::size_t i = 0; i < cur.size(); ++i) {
        if (++work_ >= next_check_) check_level(k, level, i, cur.size());
        if (last) scratch.clear();
        if (const Production* p = match(cur, &partner, i, scope.data())) {
          apply(*p, cur, i, scope.data(), k, out, last ? nullptr : &cut);
        } else if (last || cut.keep(cur.symbols[i])) {
          append(out, cur.symbols[i], cur.args_of(i), stochastic_ ? &cur.lineage[i] : nullptr);
        }
        if (last)
          for (std::size_t j = 0; j < scratch.size(); ++j)
            if (cut.keep(scratch.symbols[j])) sink.module(scratch.symbols[j], scratch.args_of(j));
      }
      if (!last) {
        if (static_cast<double>(next.size()) > limits_.held)
          throw BudgetError("level " + std::to_string(k) + " of the context-sensitive grammar holds " +
                            count_text(static_cast<double>(next.size())) + " modules, over the limit of " +
                            count_text(limits_.held) + " (--max-points)");
        std::swap(cur, next);
        next.clear();
      }
    }
    if (level == 0)
      for (std::size_t i = 0; i < cur.size(); ++i) sink.module(cur.symbols[i], cur.args_of(i));
  }

 private:
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

  // The first production that rewrites module i of s, with its parameters bound in scope (after the
  // constants, which scope already holds); null if none.
  // `partner` (brackets) is given when productions have contexts.
  const Production* match(const ModuleString& s, const std::vector<std::uint32_t>* partner, std::size_t i,
                          double* scope) const {
    const std::span<const double> args = s.args_of(i);
    double* params = scope + k_;
    for (const Production* p : index_.by_symbol[s.symbols[i]]) {
      if (p->pred.params.size() != args.size()) continue;
      std::size_t slot = 0;
      for (const Pattern& m : p->left) slot += m.params.size();
      std::copy(args.begin(), args.end(), params + slot);
      if (p->context() &&
          !(left_matches(*p, s, *partner, i, params) && right_matches(*p, s, *partner, i, params + slot + args.size())))
        continue;
      if (!p->condition.empty()) {
        double ok = 0;
        try {
          ok = p->condition.eval({scope, k_ + static_cast<std::size_t>(p->slots)});
        } catch (const EvalError& err) {
          throw Error(p->where + " (" + p->text + "): its condition: " + err.what());
        }
        if (ok == 0) continue;
      }
      return p;
    }
    return nullptr;
  }

  bool binds(const Pattern& m, const ModuleString& s, std::size_t j, double* scope) const {
    if (s.symbols[j] != m.symbol) return false;
    const std::span<const double> a = s.args_of(j);
    if (a.size() != m.params.size()) return false;
    std::copy(a.begin(), a.end(), scope);
    return true;
  }

  // The left context, nearest module last: completed branches and the '[' of the module's own branch are
  // skipped (ABOP 1.8), as are ignored symbols.
  bool left_matches(const Production& p, const ModuleString& s, const std::vector<std::uint32_t>& partner,
                    std::size_t i, double* scope) const {
    std::size_t slot = 0;
    for (const Pattern& m : p.left) slot += m.params.size();
    std::size_t j = i;
    for (auto m = p.left.rbegin(); m != p.left.rend(); ++m) {
      while (true) {
        if (j == 0) return false;
        --j;
        const std::uint8_t c = s.symbols[j];
        if (c == ']' && partner[j] < j)
          j = partner[j];
        else if (c != '[' && !ignored_[c])
          break;
      }
      slot -= m->params.size();
      if (!binds(*m, s, j, scope + slot)) return false;
    }
    return true;
  }

  // The right context: a '[' in it enters a branch, a ']' skips to the end of the branch it is in; branches
  // it does not enter are skipped, ignored symbols too, and the end of the module's own branch ends it.
  bool right_matches(const Production& p, const ModuleString& s, const std::vector<std::uint32_t>& partner,
                     std::size_t i, double* scope) const {
    std::size_t j = i;
    const std::size_t n = s.size();
    for (const Pattern& m : p.right) {
      if (m.symbol == ']') {
        int depth = 0;
        for (++j; j < n; ++j) {
          if (s.symbols[j] == '[') ++depth;
          if (s.symbols[j] == ']' && depth-- == 0) break;
        }
        if (j >= n) return false;
        continue;
      }
      while (true) {
        if (++j >= n) return false;
        const std::uint8_t c = s.symbols[j];
        if (c == '[' && m.symbol != '[') {
          j = partner[j];
          if (j >= n) return false;
        } else if (c == ']') {
          return false;
        } else if (!ignored_[c]) {
          break;
        }
      }
      if (!binds(m, s, j, scope)) return false;
      scope += m.params.size();
    }
    return true;
  }

  // Writes p's successor for module i of s (its parameters bound in scope) into out.
  void apply(const Production& p, const ModuleString& s, std::size_t i, const double* scope, int level,
             ModuleString& out, Cut* cut) {
    const Successor* succ = &p.options[0];
    if (p.options.size() > 1)
      succ = &p.options[choose_option(p.options, static_cast<double>(s.lineage[i] >> 11) * 0x1.0p-53)];
    const std::span<const double> bound{scope, k_ + static_cast<std::size_t>(p.slots)};
    double args[max_scope];
    for (const Call& c : succ->modules) {
      if (cut != nullptr && !cut->keep(c.symbol)) continue;
      for (std::size_t k = 0; k < c.args.size(); ++k) args[k] = evaluate(c.args[k], bound, c, k, &p, level);
      const std::uint64_t lineage = stochastic_ ? child_lineage(s.lineage[i], c.salt) : 0;
      append(out, c.symbol, {args, c.args.size()}, stochastic_ ? &lineage : nullptr);
    }
    written_ += succ->modules.size();
  }

  void over_budget() const {
    throw BudgetError("the grammar would rewrite more than " + count_text(limits_.work) +
                      " modules, over the limit (64 x --max-points)");
  }

  void check(const std::vector<ModuleString>& frames, const std::vector<std::size_t>& pos, std::size_t d) {
    next_check_ = work_ + check_every;
    if (static_cast<double>(work_ + written_) > limits_.work) over_budget();
    // Done so far: the finished share of each level's successor, nested.
    double done = 0, scale = 1;
    for (std::size_t k = 0; k <= d && scale > 1e-12; ++k) {
      const double n = static_cast<double>(frames[k].size());
      done += scale * (static_cast<double>(pos[k]) - 1) / n;
      scale /= n;
    }
    progress_.step(done);
  }

  void check_level(int k, int level, std::size_t i, std::size_t n) {
    next_check_ = work_ + check_every;
    if (static_cast<double>(work_ + written_) > limits_.work) over_budget();
    progress_.step((k - 1 + static_cast<double>(i) / static_cast<double>(n)) / level);
  }

  const Grammar& g_;
  RuleIndex index_;
  ModuleLimits limits_;
  Progress& progress_;
  bool stochastic_;
  std::array<bool, 256> ignored_{};
  std::array<double, max_scope> base_{};  // the grammar's constants, then room for a rule's parameters
  std::size_t k_ = 0;                     // how many constants
  std::size_t work_ = 0, written_ = 0, next_check_ = check_every;
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

std::uint64_t child_lineage(std::uint64_t parent, std::uint64_t salt) { return mix(parent ^ mix(salt)); }

std::size_t choose_option(std::span<const Successor> options, double u) {
  double total = 0;
  for (const Successor& o : options) total += o.weight;
  double below = 0;
  for (std::size_t k = 0; k + 1 < options.size(); ++k) {
    below += options[k].weight;
    if (u * total < below) return k;
  }
  // The last option with weight, so rounding never picks a zero-weight one.
  std::size_t k = options.size() - 1;
  while (k > 0 && options[k].weight == 0) --k;
  return k;
}

void rewrite_modules(const Grammar& g, int level, ModuleSink& sink, const ModuleLimits& limits, Progress& progress) {
  g.validate();
  if (!g.modules()) throw Error("internal error: rewrite_modules needs a module grammar");
  Deriver d(g, limits, progress);
  if (d.context())
    d.level_by_level(level, sink);
  else
    d.depth_first(level, sink);
}

std::string module_string_text(const Grammar& g, int level, double max_modules, Progress& progress) {
  TextSink sink;
  sink.max_modules = max_modules;
  sink.level = level;
  rewrite_modules(g, level, sink, ModuleLimits{}, progress);
  return std::move(sink.text);
}

}  // namespace selfsim::lsystem
