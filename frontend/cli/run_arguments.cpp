// Parsing `selfsim run` arguments: RECIPE.lua [-o DIR] [--set key=value]... [--max-points N]
// [--max-memory SIZE] [--timeout S] [--seed N] [--threads N] [--no-view] [-q].
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <string_view>

#include "frontend/cli/commands.h"
#include "frontend/cli/sweep/sweep.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/parse_text.h"
#include "kernels/base/count_text.h"
#include "kernels/io/output_file.h"

namespace selfsim::interp {

double number_argument(const std::string& flag, const std::string& text, double lo, double hi) {
  const auto v = parse_text<double>(text);
  if (!v || *v < lo || *v > hi)
    throw UsageError(flag + " expects a number in [" + count_text(lo) + ", " + count_text(hi) + "], got '" + text +
                     "'");
  return *v;
}

// A size in bytes with an optional binary suffix: 512M, 8G, 1T, or plain bytes.
double size_argument(const std::string& flag, const std::string& text) {
  const std::string units = "KMGT";
  const auto u = text.empty() ? std::string::npos
                              : units.find(static_cast<char>(std::toupper(static_cast<unsigned char>(text.back()))));
  const double scale = u == std::string::npos ? 1 : std::ldexp(1.0, 10 * (static_cast<int>(u) + 1));
  const auto v = parse_text<double>(u == std::string::npos ? text : text.substr(0, text.size() - 1));
  if (!v || *v * scale < 16.0 * (1 << 20) || *v * scale > std::ldexp(1.0, 50))
    throw UsageError(flag + " expects a size from 16M to 1024T (bytes, or with a K, M, G or T suffix), got '" + text +
                     "'");
  return *v * scale;
}

const std::vector<std::string>& run_flags() {
  static const std::vector<std::string> flags{"-o",        "--output", "--set",     "--max-points", "--max-memory",
                                              "--timeout", "--seed",   "--threads", "--jobs",       "--no-view",
                                              "-q",        "--quiet",  "--help"};
  return flags;
}

RunConfig parse_run_arguments(const std::vector<std::string>& args) {
  RunConfig c;
  bool have_recipe = false;
  std::size_t recipe_at = 0;  // its index in args
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError(a + " expects a value");
      return args[++i];
    };
    if (a == "-o" || a == "--output") {
      c.out_dir = value();
      if (c.out_dir.empty()) throw UsageError(a + " expects a folder name, got ''");
    } else if (a == "--set") {
      const std::string& kv = value();
      const auto eq = kv.find('=');
      if (eq == std::string::npos || eq == 0) throw UsageError("--set expects key=value, got '" + kv + "'");
      c.sets[kv.substr(0, eq)] = kv.substr(eq + 1);
    } else if (a == "--max-points")
      c.max_points = std::floor(number_argument(a, value(), 1, highest_max_points));
    else if (a == "--max-memory")
      c.max_memory = size_argument(a, value());
    else if (a == "--timeout")
      c.timeout = number_argument(a, value(), 0, 1e9);
    else if (a == "--threads") {
      const std::string& text = value();
      const auto n = parse_text<long long>(text);
      if (!n || *n < 1 || *n > 1024)
        throw UsageError("--threads expects a whole number in [1, 1024], got '" + text + "'");
      c.threads = static_cast<int>(*n);
    } else if (a == "--jobs") {
      const std::string& text = value();
      const auto n = parse_text<long long>(text);
      if (!n || *n < 1 || *n > 1024) throw UsageError("--jobs expects a whole number in [1, 1024], got '" + text + "'");
      c.jobs = static_cast<int>(*n);
    } else if (a == "--seed") {
      const std::string& text = value();
      const auto seed = parse_text<long long>(text);
      if (!seed || *seed < 0) throw UsageError("--seed expects a whole number in [0, 2^63), got '" + text + "'");
      c.seed = *seed;
    } else if (a == "-q" || a == "--quiet")
      c.quiet = true;
    else if (a == "--no-view")
      c.view = false;
    else if (a == "--watch")
      c.watch = true;
    else if (a == "--confined-output")
      // Internal, given by a sweep and the studio to a run whose -o is the folder they made for it: the
      // writer opens that folder refusing a link at its last component too (io::confine_output_root), so a
      // link planted there after they made it is not written through. Process-wide: the child is this run.
      io::confine_output_root();
    else if (a == "--view-folder") {
      c.view_folder = value();
      if (c.view_folder.empty()) throw UsageError("--view-folder expects a folder name, got ''");
    } else if (a == "--no-sheet" || a == "--jobs-file" || a == "--slurm" || a == "--collect") {
      // sweep's own options: say the command that takes them, this one's arguments kept.
      std::vector<std::string> line{"sweep"};
      line.insert(line.end(), args.begin(), args.end());
      throw UsageError(a + " is an option of sweep, not run: " + shell_command(line));
    } else if (!a.empty() && a[0] == '-') {
      const std::string near = suggestion(a, run_flags());
      throw UsageError("unknown option '" + a + "' for run" + (near.empty() ? "" : " (did you mean '" + near + "'?)"));
    } else if (have_recipe)
      throw UsageError("run takes one recipe, got '" + c.recipe.string() + "' and '" + a + "'");
    else {
      c.recipe = a;
      have_recipe = true;
      recipe_at = i;
    }
  }
  if (!have_recipe) throw UsageError("run expects a recipe file");
  if (c.watch && is_sweep(c.sets))
    throw UsageError("--watch re-runs one recipe; a --set with several values (a sweep) cannot be watched");
  // `selfsim run dragon` for dragon.lua: say the command meant.
  std::error_code ec;
  if (c.recipe.extension() != ".lua" && !std::filesystem::exists(std::filesystem::symlink_status(c.recipe, ec))) {
    const std::filesystem::path meant = c.recipe.string() + ".lua";
    if (std::filesystem::is_regular_file(meant, ec)) {
      std::vector<std::string> line{"run"};
      line.insert(line.end(), args.begin(), args.end());
      line[recipe_at + 1] = meant.string();
      throw UsageError("cannot open recipe '" + c.recipe.string() + "': no such file; to run " + meant.string() + ": " +
                       shell_command(line));
    }
  }
  // A file where the output folder should be is the command line's mistake: say so before the recipe runs.
  if (std::filesystem::exists(c.out_dir, ec) && !std::filesystem::is_directory(c.out_dir, ec))
    throw UsageError("-o '" + c.out_dir.string() + "' is a file, not a folder");
  return c;
}

SweepConfig parse_sweep_arguments(const std::vector<std::string>& args) {
  SweepConfig s;
  std::vector<std::string> rest;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--jobs-file" || a == "--slurm") {
      if (i + 1 >= args.size() || args[i + 1].empty()) throw UsageError(a + " expects a file name");
      (a == "--slurm" ? s.slurm : s.jobs_file) = args[++i];
    } else if (a == "--collect") {
      s.collect_only = true;
    } else if (a == "--no-sheet") {
      s.sheet = false;
    } else {
      rest.push_back(a);
    }
  }
  s.run = parse_run_arguments(rest);
  if (s.run.watch) throw UsageError("--watch is for run; a sweep runs once");
  if (!is_sweep(s.run.sets))
    throw UsageError("sweep expects a --set with several values: key=4..10, key=0.3..0.9:0.1 or key=a,b");
  if (s.collect_only && (!s.jobs_file.empty() || !s.slurm.empty()))
    throw UsageError("--collect builds the sheets of a sweep already run; it takes no --jobs-file or --slurm");
  for (const std::string* name : {&s.jobs_file, &s.slurm})
    if (name->find('/') != std::string::npos)
      throw UsageError("the job list and Slurm script go into the output folder: give a file name, got '" + *name +
                       "'");
  return s;
}

}  // namespace selfsim::interp
