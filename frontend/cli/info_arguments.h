// `selfsim info`'s command line: FILE, or --print FILE with its print flags, and --timeout for both.
#pragma once

#include <string>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/print/print_rules.h"

namespace selfsim::interp {

struct InfoArguments {
  std::string file;
  bool print = false;       // --print: the print check of a solid
  print::PrintRules rules;  // --profile's rules, with --voxel
  PointBudget budget;       // --max-points
  double timeout = 0;       // --timeout: seconds, 0 = none (as run's)
};

// The flags may come before or after the file, in any order. Throws UsageError naming an unknown flag.
InfoArguments parse_info_arguments(const std::vector<std::string>& args);

// `selfsim info` as parsed: Ctrl-C, SIGTERM and SIGHUP end it with one line "selfsim info: interrupted" and exit
// 130, --timeout with "selfsim info: stopped: --timeout of S s reached" and exit 1; no report is printed then.
int info_command(const InfoArguments& a);

}  // namespace selfsim::interp
