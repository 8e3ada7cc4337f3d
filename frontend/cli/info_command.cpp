// `selfsim info FILE` and `selfsim info --print FILE`: a geometry file read back, the way a user checks what
// a run wrote (and whether a solid prints). Stopped as a run is (Ctrl-C, SIGTERM, --timeout): the kernels'
// Progress is a RunContext, and a Watchdog ends what does not check it (a long read).
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>

#include "frontend/cli/commands.h"
#include "frontend/cli/info_arguments.h"
#include "frontend/lua/lua_support.h"
#include "frontend/process/watchdog.h"
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

extern "C" void on_info_signal(int) { interrupted.store(true); }

// A surface's topology, what a user about to print it wants to know: is it closed and manifold? Measured
// before anything is printed, so that a stop leaves no report half written.
std::string surface_text(const io::Dataset& d, Progress& progress) {
  Mesh m;
  try {
    m = io::dataset_mesh(d);
  } catch (const Error& e) {
    return "surface: not a valid mesh (" + shown_text(e.what(), 300) + ")\n";
  }
  const MeshTopology t = mesh_topology(m, progress);
  // A manifold by its connectivity can still pass through itself: a slicer would not print that.
  const std::optional<TrianglePair> crossing = t.manifold() ? first_intersection(m, progress) : std::nullopt;
  char line[512];
  std::snprintf(line, sizeof line,
                "triangles: %zu\nsurface: %s%s, %zu component%s, %zu boundary loop%s, Euler characteristic %lld\n",
                t.faces,
                t.closed()     ? "closed manifold"
                : t.manifold() ? "manifold with boundary"
                               : "not manifold",
                crossing ? " that crosses itself" : "", t.components, t.components == 1 ? "" : "s", t.boundary_loops,
                t.boundary_loops == 1 ? "" : "s", t.euler());
  std::string text = line;
  if (!t.manifold()) text += "first problem: " + t.first_problem + "\n";
  if (crossing) {
    std::snprintf(line, sizeof line, "first crossing: triangles %u and %u meet near [%.9g, %.9g, %.9g]\n",
                  crossing->first + 1, crossing->second + 1, crossing->where.x, crossing->where.y, crossing->where.z);
    text += line;
  }
  return text;
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

// `selfsim info FILE`; throws.
int describe(const std::string& given, RunContext& progress) {
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
  std::string surface;
  if (d.shapes == io::CellShapes::polygons && d.cell_ends.empty())
    surface = "surface: none (no polygons)\n";
  else if (d.shapes == io::CellShapes::polygons)
    surface = surface_text(d, progress);
  progress.finish_bar();  // the bar a long check drew on a terminal ends before the report
  std::printf("file: %s\npoints: %zu\ncells: %zu %s\n", shown_text(file, 4096).c_str(), d.points.size(),
              d.cell_ends.size(), shapes[static_cast<int>(d.shapes)]);
  std::fputs(surface.c_str(), stdout);
  std::printf("bbox: [%.9g, %.9g, %.9g] .. [%.9g, %.9g, %.9g]\n", lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
  for (const auto& [name, f] : d.point_fields)
    std::printf("point field: %s (%d component%s)\n", shown_text(name, 200).c_str(), f.components,
                f.components == 1 ? "" : "s");
  for (const auto& [name, f] : d.cell_fields)
    std::printf("cell field: %s (%d component%s)\n", shown_text(name, 200).c_str(), f.components,
                f.components == 1 ? "" : "s");
  print_provenance(file);
  return 0;
}

// `selfsim info --print FILE`; throws. The report is printed only once the check is whole.
int check(const InfoArguments& a, RunContext& progress) {
  const std::string& file = a.file;
  const io::Dataset d = io::read_dataset(file);
  if (d.shapes != io::CellShapes::polygons || d.cell_ends.empty())
    throw Error("it holds " + std::string(d.cell_ends.empty() ? "no cells" : "curves (polylines)") +
                ", not a solid's surface: make a solid of it first (solid.tube or solid.relief in a recipe)");
  const Mesh m = io::dataset_mesh(d);
  const print::PrintReport r = print::check_print(m, a.rules, a.budget, progress);
  progress.finish_bar();  // the bar a long check drew on a terminal ends before the report
  std::printf("file: %s\n%s\n", shown_text(file, 4096).c_str(), r.summary().c_str());
  for (const print::Problem& p : r.problems)
    std::printf("  - %s: %s\n", print::severity_text(p.severity), p.line().c_str());
  return r.passes() ? 0 : 1;
}

}  // namespace

int info_command(const InfoArguments& a) {
  RunConfig config;
  config.timeout = a.timeout;
  RunContext run(config);  // cancelled() on a stop signal or past --timeout, as in a run; a bar on a terminal
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on_info_signal);
  const Watchdog watchdog(run, "selfsim info");
  try {
    const int code = a.print ? check(a, run) : describe(a.file, run);
    run.reported = true;
    return code;
  } catch (const Cancelled&) {
    run.finish_bar();
    run.reported = true;  // before the line: the watchdog adds none
    const std::string reason = run.stop_reason();
    std::fprintf(stderr, "selfsim info: %s\n", reason.empty() ? "cancelled" : reason.c_str());
    return interrupted.load() ? 130 : 1;
  } catch (...) {
    run.finish_bar();
    run.reported = true;
    return report_failure("info");
  }
}

}  // namespace selfsim::interp
