// Seed 000's ITERATE at issue 8's size (multiplicity 5, 4 generations, about a million points), stage by
// stage: sampling the spline, MULTIPLY and HOIST of the last generation, and the whole iteration.
#include <benchmark/benchmark.h>

#include "kernels/hoist/hoist.h"
#include "kernels/hoist/iterate.h"
#include "kernels/hoist/multiply.h"
#include "kernels/hoist/spline.h"

using namespace selfsim;
using namespace selfsim::hoist;

namespace {

const SplineOptions base_options{.points = {{0, 0}, {0.2, 0.3}, {0.45, -0.25}, {0.7, 0.35}, {1, 0}}, .flatness = 5e-7};
const IterateOptions iterate_options{.multiplicity = 5,
                                     .generations = 4,
                                     .boundary = Boundary::Rotate,
                                     .transforms = {SegmentTransform::Identity, SegmentTransform::HalfTurn}};

void points_rate(benchmark::State& state, std::size_t points) {
  state.counters["points/s"] = benchmark::Counter(static_cast<double>(points) * static_cast<double>(state.iterations()),
                                                  benchmark::Counter::kIsRate);
}

void sampling(benchmark::State& state) {
  std::size_t n = 0;
  for (auto _ : state) n = sample_spline(base_options, no_progress()).points.size();
  points_rate(state, n);
}

// The last generation's MULTIPLY: generation 3 (8,026 · 25 points) into a million.
void multiplying(benchmark::State& state) {
  const Polyline p = sample_spline(base_options, no_progress());
  IterateOptions three = iterate_options;
  three.generations = 3;
  const Polyline c = iterate(p, three, no_progress());
  std::size_t n = 0;
  for (auto _ : state) n = multiply(c, {5, iterate_options.transforms, {}}, no_progress()).points.size();
  points_rate(state, n);
}

// The last generation's HOIST of those million points onto P.
void hoisting(benchmark::State& state) {
  const Polyline p = sample_spline(base_options, no_progress());
  IterateOptions three = iterate_options;
  three.generations = 3;
  const Polyline q = multiply(iterate(p, three, no_progress()), {5, iterate_options.transforms, {}}, no_progress());
  const BaseCurve base(p);
  std::size_t n = 0;
  for (auto _ : state) n = hoist_onto(q, base, Boundary::Rotate, no_progress()).points.size();
  points_rate(state, n);
}

void iterating(benchmark::State& state) {
  const Polyline p = sample_spline(base_options, no_progress());
  std::size_t n = 0;
  for (auto _ : state) n = iterate(p, iterate_options, no_progress()).points.size();
  points_rate(state, n);
}

}  // namespace

BENCHMARK(sampling)->Unit(benchmark::kMillisecond);
BENCHMARK(multiplying)->Unit(benchmark::kMillisecond);
BENCHMARK(hoisting)->Unit(benchmark::kMillisecond);
BENCHMARK(iterating)->Unit(benchmark::kMillisecond);
