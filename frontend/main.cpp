// The `selfsim` executable: dispatches to run / diff / info / preview.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "frontend/cli/commands.h"
#include "frontend/cli/info_arguments.h"
#include "frontend/cli/sweep/sweep.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/parse_text.h"
#include "kernels/base/budget.h"
#include "kernels/geom/point_text.h"
#include "kernels/print/print_rules.h"

namespace {

const char* const help = R"(selfsim — fractal geometry from Lua recipes

usage:
  selfsim run RECIPE.lua [options]   run a recipe; outputs go to the output folder
      -o, --output DIR      output folder (default: out)
      --set KEY=VALUE       override param(KEY, default) in the recipe (repeatable)
      --max-points N        points (and mesh faces) all of the run's values may hold together
                            (default 268435456)
      --max-memory SIZE     memory for the recipe's Lua strings and tables, e.g. 2G
                            (default: a quarter of this machine's memory)
      --timeout S           stop the run after S seconds (default: none); the run exits 1
      --seed N              seed for math.random (default 0): same seed, same files
      -h, --help            this text
      --threads N           threads for parallel kernels (default: all cores); the files are
                            byte-identical for any N
      --jobs N              a sweep's runs at a time (default: one per core)
      --no-view             do not write view.py, the ParaView view of the run's VTK outputs
                            (written whenever the run saved a .vtp, .vtu, .pvd or .vtp.series)
      -q, --quiet           print nothing but errors
  A sweep: a --set with several values runs the recipe once per value, and several such --set once per
  combination, each into its own folder of the output folder named by its values (out/level=4,mode=clamp),
  with a contact sheet of each result (sheet_NAME.svg), a ParaView series of each VTK file, and
  results.csv: a row per run of its values and the numbers its recipe gave with result(NAME, number)
  (plot_NAME.svg of each against the swept number when one number varies):
      --set level=4..10     whole numbers 4 to 10        --set factor=0.3..0.9:0.1   a range with a step
      --set mode=clamp,rotate  a list ("\," for a comma inside a value)
  selfsim sweep RECIPE.lua --set ... [run options] [--jobs-file F] [--slurm F] [--collect] [--no-sheet]
                             as run with a sweep; --jobs-file writes the runs as a job list for GNU
                             parallel (into the output folder) instead of running them, --slurm a Slurm
                             job-array script and its collect job; --collect builds the sheets and
                             series once they have run; --no-sheet skips the sheets and previews
  selfsim params RECIPE.lua [--set KEY=VALUE]...
                             the recipe's parameters as JSON: name, type, default, min, max, step,
                             choices, doc. The recipe runs only up to its first heavy step (nothing
                             is built or written); "complete" says whether it reached its end
  selfsim studio RECIPE.lua [--port N] [run options]
                             a page on http://127.0.0.1:N/ (default 8765; 0: any free port) with a
                             control per param(), the outputs drawn, re-running as a control moves or
                             the recipe is saved; outputs in the output folder, as run writes them
  selfsim rerun FILE [-o DIR] run again the recipe FILE records it was made by (every file a run saves
                             records its recipe, --set values and seed), into DIR (default: a new
                             folder ./rerun), and say whether FILE comes out the same byte for byte.
                             Exit 0 same, 1 different or failed, 2 error
  selfsim diff A B [--tol T] compare two geometry files (.vtp .vtu .svg .stl .3mf .obj .ply) point by point,
                             cell by cell and field by field; T is relative (default 1e-9).
                             Exit 0 same, 1 different, 2 error
  selfsim info FILE          points, cells, bounding box and fields of a geometry file, and for a
                             surface whether it is a closed manifold; for a .vdb, each grid's name,
                             class, value type, voxel size, active voxels and bounding boxes; for a
                             .pvd or .vtp.series, its steps and then the last one
  selfsim info --print FILE [--profile fdm|sla] [--voxel MM] [--max-points N] [--timeout S]
                             the print check of a closed solid in millimetres (.stl .3mf .obj .ply
                             .vtp): closed, crossing, thinnest wall, narrowest gap, what it stands
                             on, overhang, triangles, size; each problem with its severity and fix.
                             --voxel: walls and gaps on a distance grid of this voxel (default none:
                             exact rays against the triangles; at most half the profile's least wall
                             and gap); --max-points: the budget, --timeout (also for info FILE) as
                             for run. Exit 0 passes, 1 with its findings or past --timeout, 2 error,
                             130 interrupted (Ctrl-C: one line, no report)
  selfsim preview FILE... [-o DIR] [-q] [--field NAME] [--up x|y|z] [--steps] [--timeout S]
                             [--max-memory SIZE] [--max-points N] [--as NAME FILE]...
                             a PNG picture of each file (.vtp .vtu .svg .stl .obj .ply .3mf, .vdb as
                             its surface, .pvd/.vtp.series as its last step): NAME.png beside it, or in
                             DIR. Flat drawings from above; 3D upright (+y, or the axis a level field
                             grew along), a front and an oblique view, lit; widths as tubes. Coloured by
                             the field a ParaView view uses, or --field NAME; an SVG in its own colours.
                             A series in one camera and one colour range over its steps; --steps also
                             writes NAME.steps.png (every step) and NAME.apng (an animation).
                             Needs an X display; without one it starts Xvfb (apt-get install xvfb).
                             Exit 1 when a file could not be drawn (the others still are).
                             --timeout, --max-memory and --max-points (a .vdb's tiles) as for run;
                             --as NAME FILE writes FILE's PNG
                             as DIR/NAME (folders made inside DIR, never through a link)
  selfsim --help | --version

exit codes: 0 success, 1 recipe error, 2 usage error, 130 interrupted
)";

// `selfsim run ... --help`: prints the help when any argument asks for it.
bool asks_help(const std::vector<std::string>& args) {
  for (const std::string& a : args)
    if (a == "--help" || a == "-h") {
      std::fputs(help, stdout);
      return true;
    }
  return false;
}

int usage_error(const std::string& message) {
  std::fprintf(stderr, "selfsim: %s (see selfsim --help)\n", message.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace selfsim::interp;
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty()) throw UsageError("expected a command: run, sweep, studio, params, rerun, diff, info or preview");
    const std::string command = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (command == "--help" || command == "-h" || command == "help") {
      std::fputs(help, stdout);
      return 0;
    }
    if (command == "--version") {
      std::printf("selfsim %s\n", SELFSIM_VERSION);
      return 0;
    }
    if (command == "run") {
      if (asks_help(rest)) return 0;
      return run_command(parse_run_arguments(rest));
    }
    if (command == "sweep") {
      if (asks_help(rest)) return 0;
      return sweep_command(parse_sweep_arguments(rest));
    }
    if (command == "studio") {
      if (asks_help(rest)) return 0;
      int port = 8765;
      std::vector<std::string> run_args;
      for (std::size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == "--port") {
          if (i + 1 >= rest.size()) throw UsageError("--port expects a number");
          port = static_cast<int>(number_argument("--port", rest[++i], 0, 65535));
        } else {
          run_args.push_back(rest[i]);
        }
      }
      RunConfig config = parse_run_arguments(run_args);
      if (config.watch) throw UsageError("the studio watches the recipe itself: no --watch");
      if (is_sweep(config.sets)) throw UsageError("the studio runs one value at a time: give each --set one value");
      return studio_command(config, port);
    }
    if (command == "rerun") {
      std::string file, out;
      for (std::size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == "-o" || rest[i] == "--output") {
          if (i + 1 >= rest.size() || rest[i + 1].empty()) throw UsageError(rest[i] + " expects a folder");
          out = rest[++i];
        } else if (!file.empty()) {
          throw UsageError("rerun expects one file, got '" + file + "' and '" + rest[i] + "'");
        } else {
          file = rest[i];
        }
      }
      if (file.empty()) throw UsageError("rerun expects a file that selfsim wrote");
      return rerun_command(file, out);
    }
    if (command == "params") {
      for (const std::string& a : rest)
        if (a == "-o" || a == "--output" || a == "--jobs" || a == "--watch" || a == "--view-folder")
          throw UsageError("params builds and writes nothing: " + a + " is for run");
      RunConfig config = parse_run_arguments(rest);
      config.params_only = true;
      config.quiet = true;
      config.view = false;
      if (config.timeout == 0) config.timeout = 30;  // a recipe whose Lua loops before its first kernel
      return run_command(config);
    }
    if (command == "info") {
      if (asks_help(rest)) return 0;
      return info_command(parse_info_arguments(rest));
    }
    if (command == "preview") {
      if (asks_help(rest)) return 0;
      return preview_command(parse_preview_arguments(rest));
    }
    if (command == "diff") {
      std::vector<std::string> files;
      double tol = 1e-9;
      for (std::size_t i = 0; i < rest.size(); ++i) {
        if (rest[i] == "--tol") {
          if (i + 1 >= rest.size()) throw UsageError("--tol expects a value");
          tol = number_argument("--tol", rest[++i], 0, 1e300);
        } else {
          files.push_back(rest[i]);
        }
      }
      if (files.size() != 2) throw UsageError("diff expects two files");
      return diff_command(files[0], files[1], tol);
    }
    // A recipe given without `run` (selfsim dragon.lua, or selfsim dragon for dragon.lua): the command meant.
    std::error_code ec;
    const bool lua = command.size() > 4 && command.compare(command.size() - 4, 4, ".lua") == 0;
    if (lua || (!command.empty() && command[0] != '-' && std::filesystem::is_regular_file(command + ".lua", ec))) {
      std::vector<std::string> line{"run", lua ? command : command + ".lua"};
      line.insert(line.end(), rest.begin(), rest.end());
      throw UsageError("unknown command '" + command + "'; to run a recipe: " + shell_command(line));
    }
    const std::string near = suggestion(
        command, {"run", "sweep", "studio", "params", "rerun", "diff", "info", "preview", "--help", "--version"});
    throw UsageError("unknown command '" + command + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
  } catch (const UsageError& e) {
    return usage_error(e.what());
  } catch (const std::exception& e) {  // a filesystem error, out of memory: one line, never an abort
    std::fprintf(stderr, "selfsim: %s\n", e.what());
    return 2;
  }
}
