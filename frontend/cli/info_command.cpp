// `selfsim info FILE` and `selfsim info --print FILE`: a geometry file read back, the way a user checks what
// a run wrote (and whether a solid prints).
#include <cstdio>
#include <filesystem>
#include <optional>

#include "frontend/cli/commands.h"
#include "frontend/lua/lua_support.h"
#include "kernels/base/error.h"
#include "kernels/base/lower_case.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/io/dataset/dataset_values.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/read.h"
#include "kernels/io/vdb/vdb_read.h"
#include "kernels/io/view/series_file.h"
#include "kernels/print/print_check.h"

namespace selfsim::interp {

namespace {

// A surface's topology, what a user about to print it wants to know: is it closed and manifold?
void print_surface(const io::Dataset& d) {
  Mesh m;
  try {
    m = io::dataset_mesh(d);
  } catch (const Error& e) {
    std::printf("surface: not a valid mesh (%s)\n", shown_text(e.what(), 300).c_str());
    return;
  }
  const MeshTopology t = mesh_topology(m);
  // A manifold by its connectivity can still pass through itself: a slicer would not print that.
  Progress quiet;
  const std::optional<TrianglePair> crossing = t.manifold() ? first_intersection(m, quiet) : std::nullopt;
  std::printf("triangles: %zu\nsurface: %s%s, %zu component%s, %zu boundary loop%s, Euler characteristic %lld\n",
              t.faces,
              t.closed()     ? "closed manifold"
              : t.manifold() ? "manifold with boundary"
                             : "not manifold",
              crossing ? " that crosses itself" : "", t.components, t.components == 1 ? "" : "s", t.boundary_loops,
              t.boundary_loops == 1 ? "" : "s", t.euler());
  if (!t.manifold()) std::printf("first problem: %s\n", t.first_problem.c_str());
  if (crossing)
    std::printf("first crossing: triangles %u and %u meet near [%.9g, %.9g, %.9g]\n", crossing->first + 1,
                crossing->second + 1, crossing->where.x, crossing->where.y, crossing->where.z);
}

// `selfsim info FILE.vdb`: what each grid's metadata says (no voxel is read).
void print_vdb(const std::string& file) {
  const std::vector<io::VdbGridInfo> grids = io::read_vdb_info(file);
  std::printf("file: %s\ngrids: %zu\n", shown_text(file, 4096).c_str(), grids.size());
  for (const io::VdbGridInfo& g : grids) {
    std::printf("grid: %s\n  class: %s\n  value type: %s\n  voxel size: [%.9g, %.9g, %.9g]\n  active voxels: %llu\n",
                shown_text(g.name, 200).c_str(), g.grid_class.c_str(), shown_text(g.value_type, 100).c_str(),
                g.voxel[0], g.voxel[1], g.voxel[2], static_cast<unsigned long long>(g.active_voxels));
    if (!g.has_bbox) {
      std::printf("  bbox: none (empty grid)\n");
      continue;
    }
    std::printf("  index bbox: [%lld, %lld, %lld] .. [%lld, %lld, %lld]\n", static_cast<long long>(g.index_min[0]),
                static_cast<long long>(g.index_min[1]), static_cast<long long>(g.index_min[2]),
                static_cast<long long>(g.index_max[0]), static_cast<long long>(g.index_max[1]),
                static_cast<long long>(g.index_max[2]));
    std::printf("  world bbox: [%.9g, %.9g, %.9g] .. [%.9g, %.9g, %.9g]\n", g.world_min[0], g.world_min[1],
                g.world_min[2], g.world_max[0], g.world_max[1], g.world_max[2]);
  }
}

// "made by: selfsim 0.1.0 from /r.lua (sha256 a03e42a0e1c1...), --set level=5, seed 0", when recorded.
void print_provenance(const std::filesystem::path& file) {
  const std::optional<io::Provenance> p = io::read_provenance(file);
  if (!p) return;
  std::string sets;
  for (const auto& [k, v] : p->sets) sets += ", --set " + shell_word(k + "=" + v);
  std::printf("made by: selfsim %s from %s (sha256 %s)%s, seed %lld; `selfsim rerun` repeats it\n",
              shown_text(p->version, 40).c_str(), shown_text(p->recipe, 4096).c_str(),
              shown_text(p->sha256.substr(0, 12), 20).c_str(), shown_text(sets, 4096).c_str(), p->seed);
}

}  // namespace

int info_command(const std::string& given) {
  try {
    if (lower_case(std::filesystem::path(given).extension().string()) == ".vdb") {
      print_vdb(given);
      print_provenance(given);
      return 0;
    }
    // A time series: its steps, then the last step (the grown result) as any file.
    std::string file = given;
    if (io::is_series_name(given)) {
      const std::vector<std::filesystem::path> steps = io::read_series_steps(given);
      std::printf("series: %s, %zu step%s, %s ... %s; the last:\n", shown_text(given, 4096).c_str(), steps.size(),
                  steps.size() == 1 ? "" : "s", shown_text(steps.front().string(), 4096).c_str(),
                  shown_text(steps.back().string(), 4096).c_str());
      file = steps.back().string();
    }
    const io::Dataset d = io::read_dataset(file);
    std::array<double, 3> lo{}, hi{};
    for (std::size_t i = 0; i < d.points.size(); ++i)
      for (int k = 0; k < 3; ++k) {
        lo[k] = i == 0 ? d.points[i][k] : std::min(lo[k], d.points[i][k]);
        hi[k] = i == 0 ? d.points[i][k] : std::max(hi[k], d.points[i][k]);
      }
    static const char* const shapes[] = {"polylines", "polygons", "mixed"};
    std::printf("file: %s\npoints: %zu\ncells: %zu %s\n", shown_text(file, 4096).c_str(), d.points.size(),
                d.cell_ends.size(), shapes[static_cast<int>(d.shapes)]);
    if (d.shapes == io::CellShapes::polygons && d.cell_ends.empty())
      std::printf("surface: none (no polygons)\n");
    else if (d.shapes == io::CellShapes::polygons)
      print_surface(d);
    std::printf("bbox: [%.9g, %.9g, %.9g] .. [%.9g, %.9g, %.9g]\n", lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
    for (const auto& [name, f] : d.point_fields)
      std::printf("point field: %s (%d component%s)\n", shown_text(name, 200).c_str(), f.components,
                  f.components == 1 ? "" : "s");
    for (const auto& [name, f] : d.cell_fields)
      std::printf("cell field: %s (%d component%s)\n", shown_text(name, 200).c_str(), f.components,
                  f.components == 1 ? "" : "s");
    print_provenance(file);
    return 0;
  } catch (...) {
    return report_failure("info");
  }
}

int print_info_command(const std::string& file, const print::PrintRules& rules, const PointBudget& budget) {
  try {
    const io::Dataset d = io::read_dataset(file);
    if (d.shapes != io::CellShapes::polygons || d.cell_ends.empty())
      throw Error("it holds " + std::string(d.cell_ends.empty() ? "no cells" : "curves (polylines)") +
                  ", not a solid's surface: make a solid of it first (solid.tube or solid.relief in a recipe)");
    const Mesh m = io::dataset_mesh(d);
    const print::PrintReport r = print::check_print(m, rules, budget, no_progress());
    std::printf("file: %s\n%s\n", shown_text(file, 4096).c_str(), r.summary().c_str());
    for (const print::Problem& p : r.problems)
      std::printf("  - %s: %s\n", print::severity_text(p.severity), p.line().c_str());
    return r.passes() ? 0 : 1;
  } catch (...) {
    return report_failure("info");
  }
}

}  // namespace selfsim::interp
