// A sweep's runs from its --set values: `level=4..10`, `factor=0.3..0.9:0.1` and `mode=clamp,rotate` each
// give a list of values, several --set make their product, and each run gets a folder named by its values
// ("factor=0.3,level=4"). Pure: the sweep command (sweep_command.cpp) runs what this plans.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace selfsim::interp {

// At most this many runs in one sweep: a typo like 1..1e9 is refused before anything starts.
inline constexpr std::size_t max_sweep_runs = 10000;

// The values one --set gives: "4..10" (whole numbers, step 1), "0.3..0.9:0.1" (a range with a step; the
// end is included when the steps reach it to within rounding), "a,b,c" (a list) or one plain value. A
// backslash takes the next character as it is: "\," is a comma inside a value, "1\.\.3" the text 1..3. A range whose
// ends and step are whole ("0..4e12:1e12") is counted in integers and its values written whole; other range values
// are written to 12 significant digits, so 0.1 * 3 reads "0.3". Throws Error naming the key: a range that runs down or
// has no whole-number ends without a step, a step that is not > 0, an empty or repeated list item, more than
// max_sweep_runs values.
std::vector<std::string> sweep_values(const std::string& key, const std::string& text);

// A value written so that sweep_values reads it back as that one value (for a run's own --set).
std::string escaped_value(const std::string& value);

// A file name prefix + core + suffix (a sweep's "sheet_" + "dragon" + ".svg") that always fits a folder's
// 255-byte limit: as it is when it fits, else `core` cut at a character boundary and "~" and 8 hex digits of
// a hash of the whole core put after it, so that two long names stay apart. For every name a sweep derives
// from a run's output (sheets, series, previews): an output may use the whole 255 bytes itself.
std::string fitting_name(const std::string& prefix, const std::string& core, const std::string& suffix);

// Whether `name` (a file name in a sweep's output folder) is one a sweep writes or keeps for itself, now or
// later (by --collect): sweep.json, results.csv, previews, slurm, view.py, selfsim.log, selfsim.exit, and any
// sheet_*, plot_*, *_sweep.pvd or .selfsim* name. A job list or Slurm script given such a name would be overwritten by,
// or overwrite, the sweep's own (the run folders and jobs.txt depend on the plan: check_sweep_folders adds them).
bool sweep_reserved_name(const std::string& name);

// Whether any --set gives more than one value (the run is a sweep).
bool is_sweep(const std::map<std::string, std::string>& sets);

struct SweepRun {
  std::map<std::string, std::string> sets;  // every --set key with this run's value
  std::string folder;                       // "level=4,mode=clamp": only the keys that vary, in key order
  std::string caption;                      // "level=4, mode=clamp"
};

struct SweepPlan {
  std::vector<std::string> keys;  // the keys that vary, in order
  std::vector<SweepRun> runs;     // the product, the last key varying fastest
};

// The runs of a sweep. Throws Error for more than max_sweep_runs runs, or two runs whose folder names
// would be the same (values that differ only in characters a folder name cannot keep: "a b" and "a_b").
SweepPlan plan_sweep(const std::map<std::string, std::string>& sets);

}  // namespace selfsim::interp
