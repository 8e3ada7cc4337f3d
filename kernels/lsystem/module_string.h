// A level of a parametric L-system held in memory (ABOP 1.10): symbols, their parameters and, for
// stochastic choice, each module's lineage. Parallel arrays rather than a vector of small objects, so a
// million modules are four allocations, not a million.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace selfsim::lsystem {

struct ModuleString {
  std::vector<std::uint8_t> symbols;
  std::vector<std::uint32_t> arg_end;  // module i's parameters are args[arg_begin(i), arg_end[i])
  std::vector<double> args;
  std::vector<std::uint64_t> lineage;  // kept only when the grammar is stochastic (else empty)

  std::size_t size() const { return symbols.size(); }
  std::size_t arg_begin(std::size_t i) const { return i == 0 ? 0 : arg_end[i - 1]; }
  std::span<const double> args_of(std::size_t i) const {
    return {args.data() + arg_begin(i), args.data() + arg_end[i]};
  }
  // Appends a module (its lineage too when given).
  void push(std::uint8_t s, std::span<const double> a, const std::uint64_t* l = nullptr) {
    symbols.push_back(s);
    for (double x : a) args.push_back(x);  // most modules have 0 or 1: cheaper than a range insert
    arg_end.push_back(static_cast<std::uint32_t>(args.size()));
    if (l != nullptr) lineage.push_back(*l);
  }
  void clear() {
    symbols.clear();
    arg_end.clear();
    args.clear();
    lineage.clear();
  }
  // Bytes held per module with n parameters, for budgets.
  static constexpr double bytes_per_module(double params) { return 1 + 4 + 8 + 8 * params; }
};

// Modules [begin, end) of arrays laid out as ModuleString's: a run of a level, or a successor's modules
// with their evaluated parameters.
struct ModuleRun {
  const std::uint8_t* symbols;
  const std::uint32_t* arg_end;
  const double* args;
  std::size_t begin, end;

  std::span<const double> args_of(std::size_t i) const {
    return {args + (i == 0 ? 0 : arg_end[i - 1]), args + arg_end[i]};
  }
};

inline ModuleRun run_of(const ModuleString& s, std::size_t begin, std::size_t end) {
  return {s.symbols.data(), s.arg_end.data(), s.args.data(), begin, end};
}

// Appends a run to `out` (no lineage): a short one module by module, a long one in three block copies.
inline void push_run(ModuleString& out, const ModuleRun& r) {
  if (r.end <= r.begin + 8) {
    for (std::size_t i = r.begin; i < r.end; ++i) out.push(r.symbols[i], r.args_of(i));
    return;
  }
  const std::uint32_t first = r.begin == 0 ? 0 : r.arg_end[r.begin - 1], last = r.arg_end[r.end - 1];
  const auto base = static_cast<std::uint32_t>(out.args.size());
  out.symbols.insert(out.symbols.end(), r.symbols + r.begin, r.symbols + r.end);
  out.args.insert(out.args.end(), r.args + first, r.args + last);
  for (std::size_t i = r.begin; i < r.end; ++i) out.arg_end.push_back(base + (r.arg_end[i] - first));
}

// "A(1.5,2)": a module as ABOP writes it, parameters in the shortest form that reads back exactly.
std::string module_text(std::uint8_t symbol, std::span<const double> args);

}  // namespace selfsim::lsystem
