// Writing speed: dragon level 22 (4,194,305 points) saved as .vtp and .svg, reported as MB/s of file.
#include <benchmark/benchmark.h>

#include <filesystem>

#include "kernels/io/save.h"
#include "kernels/lsystem/turtle/turtle2d.h"

using namespace selfsim;

namespace {

void save_dragon(benchmark::State& state, std::string ext) {
  const lsystem::Grammar g{.axiom = "FX", .rules = {{'X', "X-YF"}, {'Y', "FX+Y"}}, .angle = 90};
  const Polyline c = lsystem::turtle2d(g, {.level = static_cast<int>(state.range(0))}, no_progress());
  const auto file = std::filesystem::temp_directory_path() / ("selfsim_bench" + ext);
  double bytes = 0;
  for (auto _ : state) {
    io::save(&c, file, {}, no_progress());
    bytes = static_cast<double>(std::filesystem::file_size(file));
  }
  std::filesystem::remove(file);
  state.counters["MB/s"] = benchmark::Counter(bytes * state.iterations() / 1e6, benchmark::Counter::kIsRate);
  state.counters["MB"] = bytes / 1e6;
}

}  // namespace

BENCHMARK_CAPTURE(save_dragon, vtp, ".vtp")->Arg(22)->Unit(benchmark::kMillisecond)->MinTime(2)->UseRealTime();
BENCHMARK_CAPTURE(save_dragon, svg, ".svg")->Arg(22)->Unit(benchmark::kMillisecond)->MinTime(2)->UseRealTime();
