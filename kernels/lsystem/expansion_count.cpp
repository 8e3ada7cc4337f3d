#include "kernels/lsystem/expansion_count.h"

#include <algorithm>
#include <cstring>

namespace selfsim::lsystem {

namespace {

constexpr std::size_t poll_every = 4096;                // modules visited between two polls for a stop
constexpr std::size_t max_memo = std::size_t{1} << 16;  // entries kept before the memo starts again

// Thrown inside a count past its caps, with what was counted so far.
struct Over {
  double modules, steps;
};

template <class T>
void append_bytes(std::string& key, const T& value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  key.append(bytes, sizeof(T));
}

}  // namespace

ExpansionCount::ExpansionCount(const RuleIndex& rules, int max_depth, RuleScope& scope,
                               const std::array<bool, 256>& steps, Progress& progress)
    : rules_(rules),
      max_depth_(max_depth),
      scope_(scope),
      steps_(steps),
      progress_(progress),
      values_(static_cast<std::size_t>(std::max(max_depth, 0)) + 1) {
  // bound_ after d more levels of rewriting: a module no rule rewrites stays one (also when its rules'
  // conditions fail), else the largest sum over any successor of its symbols' bounds one level less deep.
  bound_.fill(1);
  for (int d = 0; d < max_depth_; ++d) {
    if (progress_.cancelled()) throw Cancelled();
    std::array<double, 256> next;
    next.fill(1);
    for (int s = 0; s < 256; ++s)
      for (const Production* p : rules_.by_symbol[s])
        for (const Successor& o : p->options) {
          double sum = 0;
          for (const Call& c : o.modules) sum += bound_[c.symbol];
          next[s] = std::max(next[s], sum);
        }
    bound_ = next;
  }
  for (int s = 0; s < 256; ++s)
    for (const Production* p : rules_.by_symbol[s]) by_lineage_ = by_lineage_ || p->options.size() > 1;
}

ExpansionSize ExpansionCount::count(std::uint8_t symbol, std::span<const double> args, std::uint64_t lineage, int level,
                                    double max_modules, double max_steps) {
  level_ = level;
  max_modules_ = max_modules;
  max_steps_ = max_steps;
  ExpansionSize out;
  if (max_depth_ > 0 && !rules_.empty_for(symbol)) out.rule = scope_.match(rules_, symbol, args, level);
  try {
    const Size s = visit(symbol, args, lineage, 0);
    out.modules = s.modules;
    out.steps = s.steps;
  } catch (const Over& o) {
    out.modules = o.modules;
    out.steps = o.steps;
    out.over = true;
  }
  return out;
}

ExpansionCount::Size ExpansionCount::visit(std::uint8_t symbol, std::span<const double> args, std::uint64_t lineage,
                                           int depth) {
  if (depth >= max_depth_ || rules_.empty_for(symbol)) return leaf(symbol);
  if (++visits_ >= next_poll_) {
    next_poll_ = visits_ + poll_every;
    if (progress_.cancelled()) throw Cancelled();
  }
  std::string key;
  key.push_back(static_cast<char>(symbol));
  key.push_back(static_cast<char>(depth));
  if (by_lineage_) append_bytes(key, lineage);
  for (double a : args) append_bytes(key, a);
  if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
  const Production* p = scope_.match(rules_, symbol, args, level_);
  if (p == nullptr) return leaf(symbol);
  const Successor& succ = scope_.chosen(*p, lineage);
  std::vector<double>& values = values_[static_cast<std::size_t>(depth)];
  scope_.evaluate_successor(*p, succ, level_, values);
  Size total{0, 0};
  std::size_t v = 0;
  for (const Call& c : succ.modules) {
    const Size part = visit(c.symbol, {values.data() + v, c.args.size()}, scope_.child(lineage, c), depth + 1);
    total.modules += part.modules;
    total.steps += part.steps;
    // A part past a cap makes the whole past it: stop here, not after counting the rest.
    if (total.modules > max_modules_ || total.steps > max_steps_) throw Over{total.modules, total.steps};
    v += c.args.size();
  }
  if (memo_.size() >= max_memo) memo_.clear();
  memo_.emplace(std::move(key), total);
  return total;
}

}  // namespace selfsim::lsystem
