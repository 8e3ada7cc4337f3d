// A sweep's numbers in one table: results.csv in the sweep's folder, one row per run (its swept values, the
// results it gave with result(), its status and folder), and, when one swept key varies and its values are
// numbers, plot_NAME.svg for each result against it. Built from the runs' results.json (kernels/io/
// run_results.h) after a local sweep and by --collect alike (sweep_collect.cpp).
#pragma once

#include <string>
#include <vector>

#include "frontend/cli/sweep/sweep.h"

namespace selfsim::interp {

inline constexpr const char* sweep_results_file = "results.csv";

struct SweepResults {
  std::vector<std::string> written;  // results.csv, then each plot, as names in the output folder
  std::vector<std::string> plots;    // the plots alone, in the order of the results' names
  std::vector<std::string> names;    // every result name the runs gave, in the order first seen
  std::string no_plot;               // why results have no plot ("two keys vary: ..."), else empty
};

// The file a result's plot goes to: "plot_dimension.svg".
std::string plot_name(const std::string& result);

// Writes results.csv and the plots. A run whose results.json cannot be read is a warning and empty cells.
SweepResults write_sweep_results(const SweepConfig& config, const SweepPlan& plan, const std::vector<int>& codes);

}  // namespace selfsim::interp
