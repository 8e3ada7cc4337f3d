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

// "A(1.5,2)": a module as ABOP writes it, parameters in the shortest form that reads back exactly.
std::string module_text(std::uint8_t symbol, std::span<const double> args);

}  // namespace selfsim::lsystem
