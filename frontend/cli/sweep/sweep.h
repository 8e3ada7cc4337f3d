// Sweeps: one `selfsim run` per combination of --set values, here N at a time (sweep_command.cpp), or as a
// job list for GNU parallel or a Slurm job array (sweep_jobs.cpp); then the contact sheets and ParaView
// series over the runs (sweep_collect.cpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "frontend/cli/sweep/sweep_plan.h"
#include "frontend/lua/run_context.h"

namespace selfsim::interp {

struct SweepConfig {
  RunConfig run;              // the recipe, output folder, --set values (lists and ranges) and limits of each run
  std::string jobs_file;      // write the runs as a job list for GNU parallel instead of running them
  std::string slurm;          // write a Slurm job-array script instead of running them
  bool collect_only = false;  // the runs are done (by parallel or Slurm): build the sheets and series
  bool sheet = true;          // contact sheets (and the previews they need)
};

// Parses the arguments after `selfsim sweep`: those of run, and --jobs-file F, --slurm F, --collect,
// --no-sheet. Throws UsageError.
SweepConfig parse_sweep_arguments(const std::vector<std::string>& args);

int sweep_command(const SweepConfig& config);

// Reads the recipe's parameters (as `selfsim params` does) and checks the sweep's values against their
// ranges and choices before any run starts. Throws Error naming the --set and what was expected.
void check_sweep_params(const RunConfig& run, const SweepPlan& plan);

// The arguments of one run's `selfsim run` (after the program's name), writing into `dir`, with `threads`
// (0: the run's default) and every other limit of `run`.
std::vector<std::string> run_arguments(const RunConfig& run, const SweepRun& one, const std::filesystem::path& dir,
                                       int threads);

// Refuses, before anything starts, a link or a file where one of the sweep's folders goes, and a job list
// or Slurm script named like a file of the sweep's own. Throws UsageError.
void check_sweep_folders(const SweepConfig& config, const SweepPlan& plan);

// Refuses (UsageError), before anything is written, a job list or Slurm script that no shell could read
// line by line as written: a path, name or --set value holding a line break (shell_quote.h).
void check_job_lists(const SweepConfig& config, const SweepPlan& plan, const std::string& exe);

// Writes the job list and/or the Slurm scripts into the output folder and says how to run them: every
// path, value and name in them quoted for the shell by shell_quote.h's one rule.
int write_job_lists(const SweepConfig& config, const SweepPlan& plan, const std::string& exe);

// Each run's exit code as its folder's selfsim.exit records it; -1 where there is none.
std::vector<int> read_exit_codes(const std::filesystem::path& out, const SweepPlan& plan);

// results.csv and its plots (sweep_results.h), the contact sheets and ParaView series of the runs that
// succeeded, and the sweep's summary line. Returns
// the exit code: 0 when every run succeeded, 1 when one failed or did not run.
int collect_sweep(const SweepConfig& config, const SweepPlan& plan, const std::vector<int>& codes);

}  // namespace selfsim::interp
