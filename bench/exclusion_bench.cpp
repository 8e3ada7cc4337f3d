// Issue 10's exclusion curve (Figure 3's conditions: unit square, diagonal start, radius 0.1, factor 0.8),
// grid neighbour queries against measuring every segment for every split (brute force, the original
// program's O(N²) scan). The two give bit-identical curves (a unit test checks it); this shows the cost.
#include <benchmark/benchmark.h>

#include "kernels/exclusion/exclusion_curve.h"

using namespace selfsim;

namespace {

void figure3(benchmark::State& state, bool brute_force) {
  const Region square({{{0, 0}, {1, 0}, {1, 1}, {0, 1}}});
  const Polyline start = Polyline::single({{0, 0}, {1, 1}});
  exclusion::CurveOptions o;
  o.levels = static_cast<int>(state.range(0));
  o.brute_force = brute_force;
  for (auto _ : state) benchmark::DoNotOptimize(exclusion::exclusion_curve(square, start, o, no_progress()));
  state.counters["segments"] = static_cast<double>(1 << o.levels);
}

void BM_ExclusionGrid(benchmark::State& state) { figure3(state, false); }
void BM_ExclusionBruteForce(benchmark::State& state) { figure3(state, true); }

}  // namespace

BENCHMARK(BM_ExclusionGrid)->Arg(12)->Arg(14)->Arg(16)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExclusionBruteForce)->Arg(12)->Arg(14)->Unit(benchmark::kMillisecond)->Iterations(1);
