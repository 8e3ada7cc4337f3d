// The `selfsim` subcommands. Each returns the process exit code: 0 success, 1 recipe error (or, for diff,
// files that differ), 2 usage error.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "frontend/cli/shell_quote.h"  // shell_word, shell_command
#include "frontend/lua/run_context.h"
#include "kernels/base/budget.h"
#include "kernels/print/print_rules.h"

namespace selfsim::interp {

// A mistake on the command line; main prints it with a pointer to --help and exits 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

int run_command(const RunConfig& config);

// The parameters a recipe declares, read as `selfsim params` reads them (run_command.cpp): the recipe runs
// up to its first heavy step. Throws Error with the recipe's error line when it fails before that.
struct ParamsRead {
  std::vector<ParamSpec> specs;
  std::string stopped_at;  // "recipe.lua:7" where it stopped, or empty when it ran to its end
};
ParamsRead read_params(const RunConfig& config);
// `selfsim studio RECIPE [--port N]` (studio_command.cpp): until Ctrl-C, then 130. Throws UsageError.
int studio_command(const RunConfig& config, int port);
// `selfsim run --watch` (watch_command.cpp).
int watch_command(const RunConfig& config);
int diff_command(const std::string& a, const std::string& b, double tol);  // diff_command.cpp
// Called inside a catch (command_failure.cpp): prints "selfsim COMMAND: what" whatever was thrown (an Error,
// std::bad_alloc, a filesystem error), on one line, and returns exit status 2.
int report_failure(const char* command);
// `selfsim rerun FILE [-o DIR]`: the run FILE records, again, into DIR (default: a new ./rerun folder); exit 0
// when FILE comes out byte for byte the same, 1 when it differs or the run fails. Throws UsageError.
int rerun_command(const std::string& file, const std::string& out);

// `selfsim preview FILE... [-o DIR] [-q] [--field NAME] [--up x|y|z] [--steps] [--timeout S] [--max-memory SIZE]
// [--as NAME FILE]...`.
struct PreviewConfig {
  std::vector<std::string> files;
  std::string out_dir;             // empty: each PNG beside its input
  std::vector<std::string> names;  // per file, the PNG's name inside out_dir ("" for NAME.png); --as
  bool quiet = false;
  double timeout = 0;                      // seconds for all the previews, 0 = none (as run's --timeout)
  double max_memory = 0;                   // bytes the previews may add, 0 = none (as run's --max-memory)
  double max_points = default_max_points;  // a .vdb's tiles weighed against it (as run's --max-points)
  std::string field;                       // --field: colour by it (empty: the natural field)
  int up = -1;                             // --up: 0, 1, 2 for x, y, z; -1: each file's own (up_axis.h)
  bool steps = false;                      // --steps: also NAME.steps.png and NAME.apng of each series
};
// Throws UsageError.
PreviewConfig parse_preview_arguments(const std::vector<std::string>& args);
// 0 when every file was drawn; 1 when one could not be read or drawn (one line each), or there is no display.
int preview_command(const PreviewConfig& config);

// A flag's value as a finite number in [lo, hi]; throws UsageError naming the flag.
double number_argument(const std::string& flag, const std::string& text, double lo, double hi);
// A flag's value as a size in bytes (512M, 8G, or plain bytes) from 16M to 1024T; throws UsageError.
double size_argument(const std::string& flag, const std::string& text);

// Parses the arguments after `selfsim run`. Throws UsageError.
RunConfig parse_run_arguments(const std::vector<std::string>& args);

}  // namespace selfsim::interp
