// L-system expansion speed: selfsim's streaming turtle against a simple build-the-string expansion
// written here as the baseline, on the same grammar and machine, in the same process.
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>
#include <string>

#include "kernels/lsystem/turtle/turtle2d.h"

using namespace selfsim;

namespace {

lsystem::Grammar dragon() { return {.axiom = "FX", .rules = {{'X', "X-YF"}, {'Y', "FX+Y"}}, .angle = 90}; }
lsystem::Grammar koch_snowflake() {
  return {.axiom = "F++F++F", .rules = {{'F', "F-F++F-F"}}, .angle = 60, .shrink = 1.0 / 3};
}

// The baseline: rewrite whole strings level by level, then walk the final string with a turtle.
std::vector<Vec2> string_then_turtle(const lsystem::Grammar& g, int level) {
  std::string s = g.axiom;
  for (int d = 0; d < level; ++d) {
    std::string next;
    for (char c : s) {
      auto it = g.rules.find(c);
      if (it == g.rules.end())
        next += c;
      else
        next += it->second;
    }
    s.swap(next);
  }
  std::vector<Vec2> pts{{0, 0}};
  Vec2 pos{};
  double heading = 0;
  for (char c : s) {
    if (c == 'F') {
      pos += polar(heading);
      pts.push_back(pos);
    } else if (c == '+' || c == '-') {
      heading += (c == '+' ? 1 : -1) * g.angle * M_PI / 180;
    }
  }
  return pts;
}

void streaming(benchmark::State& state, lsystem::Grammar g) {
  const int level = static_cast<int>(state.range(0));
  std::size_t segments = 0;
  for (auto _ : state) {
    Polyline c = lsystem::turtle2d(g, {.level = level}, no_progress());
    segments = c.segments();
    benchmark::DoNotOptimize(c.points.data());
  }
  state.counters["segments/s"] =
      benchmark::Counter(static_cast<double>(segments) * state.iterations(), benchmark::Counter::kIsRate);
}

// Warm: the output array is reused, so this is the kernel's own speed without the operating system's
// first-touch page faults (which bench/peak_memory.sh measures cold, in a fresh process).
void streaming_warm(benchmark::State& state, lsystem::Grammar g) {
  const int level = static_cast<int>(state.range(0));
  Polyline c;
  lsystem::turtle2d_into(g, {.level = level}, no_progress(), c);
  for (auto _ : state) {
    lsystem::turtle2d_into(g, {.level = level}, no_progress(), c);
    benchmark::DoNotOptimize(c.points.data());
  }
  state.counters["segments/s"] =
      benchmark::Counter(static_cast<double>(c.segments()) * state.iterations(), benchmark::Counter::kIsRate);
}

// Thread scaling of the parallel turtle (turtle_split.h): the warm kernel under --threads N (range 1).
void threads(benchmark::State& state, lsystem::Grammar g) {
  const tbb::global_control limit(tbb::global_control::max_allowed_parallelism,
                                  static_cast<std::size_t>(state.range(1)));
  streaming_warm(state, std::move(g));
}

void baseline(benchmark::State& state, lsystem::Grammar g) {
  const int level = static_cast<int>(state.range(0));
  std::size_t segments = 0;
  for (auto _ : state) {
    std::vector<Vec2> pts = string_then_turtle(g, level);
    segments = pts.size() - 1;
    benchmark::DoNotOptimize(pts.data());
  }
  state.counters["segments/s"] =
      benchmark::Counter(static_cast<double>(segments) * state.iterations(), benchmark::Counter::kIsRate);
}

}  // namespace

BENCHMARK_CAPTURE(streaming, dragon, dragon())->Arg(20)->Arg(26)->Unit(benchmark::kMillisecond)->MinTime(4);
BENCHMARK_CAPTURE(streaming_warm, dragon, dragon())->Arg(20)->Arg(26)->Unit(benchmark::kMillisecond)->MinTime(2);
BENCHMARK_CAPTURE(threads, dragon, dragon())
    ->ArgsProduct({{26}, {1, 2, 4, 8, 16}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2)
    ->UseRealTime();
BENCHMARK_CAPTURE(baseline, dragon, dragon())->Arg(20)->Arg(26)->Unit(benchmark::kMillisecond)->MinTime(2);
BENCHMARK_CAPTURE(streaming, koch_snowflake, koch_snowflake())->Arg(11)->Unit(benchmark::kMillisecond)->MinTime(2);
BENCHMARK_CAPTURE(streaming_warm, koch_snowflake, koch_snowflake())->Arg(11)->Unit(benchmark::kMillisecond)->MinTime(2);
BENCHMARK_CAPTURE(baseline, koch_snowflake, koch_snowflake())->Arg(11)->Unit(benchmark::kMillisecond)->MinTime(2);
