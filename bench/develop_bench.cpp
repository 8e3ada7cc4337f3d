// Issue 9's developing dragon (level 11, 3 rounds of Loop) stage by stage, and OpenMesh's own Loop
// subdivider (OpenMesh::Subdivider::Uniform::LoopT, the suggestion) on the same control mesh beside
// ours: why selfsim subdivides with its own stencils (point fields, kept corners and the bounded variant
// ride along) and what that costs.
#include <benchmark/benchmark.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <vector>

#include "kernels/develop/control_mesh.h"
#include "kernels/develop/develop.h"
#include "kernels/develop/loop_subdivision.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/lsystem/grammar.h"
#include "kernels/lsystem/turtle/turtle2d.h"

using namespace selfsim;
using namespace selfsim::develop;

namespace {

constexpr int top = 11, rounds = 3;

const std::vector<Polyline>& dragon_levels() {
  static const std::vector<Polyline> levels = [] {
    const lsystem::Grammar dragon{.axiom = "FX", .rules = {{'X', "X-YF"}, {'Y', "FX+Y"}}, .angle = 90};
    std::vector<Polyline> v;
    for (int l = 0; l <= top; ++l) v.push_back(lsystem::turtle2d(dragon, {.level = l}, no_progress()));
    return v;
  }();
  return levels;
}

std::vector<const Polyline*> stack() {
  std::vector<const Polyline*> p;
  for (const Polyline& c : dragon_levels()) p.push_back(&c);
  return p;
}

void faces_rate(benchmark::State& state, std::size_t faces) {
  state.counters["faces/s"] = benchmark::Counter(static_cast<double>(faces) * static_cast<double>(state.iterations()),
                                                 benchmark::Counter::kIsRate);
}

// The whole kernel as `develop` runs it: control mesh, Loop, tile classes, checks, thickening.
void develop_whole(benchmark::State& state) {
  DevelopOptions opt;
  opt.smooth = rounds;
  opt.thickness = 0.03;
  opt.thickness_rate = 0.85;
  std::size_t n = 0;
  for (auto _ : state) n = develop_surface(stack(), opt, no_progress()).faces();
  faces_rate(state, n);
}

void loop_selfsim(benchmark::State& state) {
  const Mesh c = control_mesh(stack(), {}, no_progress());
  std::size_t n = 0;
  for (auto _ : state) n = loop_subdivide(c, {.steps = rounds}, no_progress()).faces();
  faces_rate(state, n);
}

void loop_openmesh(benchmark::State& state) {
  using OM = OpenMesh::TriMesh_ArrayKernelT<>;
  const Mesh c = control_mesh(stack(), {}, no_progress());
  std::size_t n = 0;
  for (auto _ : state) {
    state.PauseTiming();
    OM m;
    std::vector<OM::VertexHandle> v;
    for (const Vec3& p : c.points) v.push_back(m.add_vertex(OM::Point(p.x, p.y, p.z)));
    for (const Triangle& t : c.triangles) m.add_face(v[t[0]], v[t[1]], v[t[2]]);
    state.ResumeTiming();
    OpenMesh::Subdivider::Uniform::LoopT<OM> loop;
    loop.attach(m);
    loop(rounds);
    loop.detach();
    n = m.n_faces();
  }
  faces_rate(state, n);
}

void intersections(benchmark::State& state) {
  const Mesh s = loop_subdivide(control_mesh(stack(), {}, no_progress()), {.steps = rounds}, no_progress());
  for (auto _ : state) benchmark::DoNotOptimize(first_intersection(s, no_progress()));
  faces_rate(state, s.faces());
}

}  // namespace

BENCHMARK(develop_whole)->Unit(benchmark::kMillisecond)->MinTime(2);
BENCHMARK(loop_selfsim)->Unit(benchmark::kMillisecond)->MinTime(2);
BENCHMARK(loop_openmesh)->Unit(benchmark::kMillisecond)->MinTime(2);
BENCHMARK(intersections)->Unit(benchmark::kMillisecond)->MinTime(2);
