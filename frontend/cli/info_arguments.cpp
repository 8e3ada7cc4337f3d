// Parses `selfsim info [--print] FILE [--profile fdm|sla] [--voxel MM] [--max-points N] [--timeout S]`.
#include "frontend/cli/info_arguments.h"

#include <algorithm>
#include <cmath>

#include "frontend/cli/commands.h"
#include "frontend/lua/parse_text.h"
#include "kernels/geom/point_text.h"

namespace selfsim::interp {

namespace {

const char* const print_flags = "--profile fdm|sla, --voxel MM, --max-points N, --timeout S";

// A word that is a flag rather than a file (a file named "-x" is given as ./-x).
bool flag_like(const std::string& a) { return a.size() > 1 && a[0] == '-'; }

}  // namespace

InfoArguments parse_info_arguments(const std::vector<std::string>& args) {
  InfoArguments a;
  std::string profile, voxel_text, print_flag, unknown;
  int files = 0;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    const bool has_value = i + 1 < args.size();
    if (arg == "--print") {
      a.print = true;
    } else if (arg == "--profile") {
      if (!has_value) throw UsageError("--profile expects fdm or sla");
      profile = args[++i];
    } else if (arg == "--voxel") {
      if (!has_value) throw UsageError("--voxel expects a size in mm");
      print_flag = arg;
      voxel_text = args[++i];
    } else if (arg == "--max-points") {
      if (!has_value) throw UsageError("--max-points expects a number");
      print_flag = arg;
      a.budget.limit = std::floor(number_argument(arg, args[++i], 1, highest_max_points));
    } else if (arg == "--timeout") {
      if (!has_value) throw UsageError("--timeout expects seconds");
      a.timeout = number_argument(arg, args[++i], 0, 1e9);  // as run's --timeout (run_arguments.cpp)
    } else if (flag_like(arg)) {
      if (unknown.empty()) unknown = arg;  // named once --print is known, which may come later
    } else {
      a.file = arg;
      ++files;
    }
  }
  if (!unknown.empty())
    throw UsageError("unknown option '" + unknown + "' for " +
                     (a.print ? std::string("info --print; it takes ") + print_flags
                              : std::string("info; it takes --timeout S, and --print with ") + print_flags));
  if (!profile.empty() && !a.print) throw UsageError("--profile is for info --print FILE");
  if (!print_flag.empty() && !a.print) throw UsageError(print_flag + " is for info --print FILE");
  if (files != 1)
    throw UsageError(a.print ? "info --print expects one file (and optionally --profile fdm|sla), got " +
                                   std::to_string(files)
                             : "info expects one file, got " + std::to_string(files));
  if (!a.print) return a;
  if (profile.empty()) profile = "fdm";
  if (profile != "fdm" && profile != "sla") throw UsageError("--profile expects fdm or sla, got '" + profile + "'");
  a.rules = print::PrintRules::named(profile);
  // The voxel's range as solid.check's option takes it, named as the flag.
  if (!voxel_text.empty()) {
    const double most = std::min(a.rules.min_wall, a.rules.min_gap) / 2;
    const auto v = parse_text<double>(voxel_text);
    if (!v || !(*v >= 1e-3 && *v <= most))
      throw UsageError("--voxel expects a size in mm from 0.001 to " + mm_text(most) + " (half the " + profile +
                       " profile's least wall or gap), got '" + voxel_text + "'");
    a.rules.voxel = *v;
  }
  return a;
}

}  // namespace selfsim::interp
