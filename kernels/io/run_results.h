// A run's named results (result("dimension", d) in a recipe): the numbers a sweep gathers into one table,
// results.csv, and plots. A run that gave any writes them as results.json in its output folder, beside its
// outputs, with the run's provenance; a sweep reads each run's back. Names are kept plain (a letter or '_',
// then letters, digits, '_', '-', '.', at most 64 bytes) because each becomes a CSV column's header and a
// plot's file name (plot_NAME.svg) as it is.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace selfsim::io {

struct RunResult {
  std::string name;
  double value = 0;  // finite
};

// The file a run writes its results into, inside its output folder.
inline constexpr const char* results_file = "results.json";

inline constexpr std::size_t max_result_name = 64;
// The most results one run may give: each is a column of the sweep's results.csv and a plot of its own, so
// that thousands are a table nobody reads and minutes of writing plots (200,000 took 4.5 minutes).
inline constexpr std::size_t max_results = 1000;

// Empty when `name` is a result name; else what is wrong with it ("is empty", "holds ' ' (a result name is
// ...)"), for a message that names the name first.
std::string result_name_problem(const std::string& name);

// results.json's text: {"results": {NAME: NUMBER, ...}, "provenance": PROVENANCE} (the provenance record
// as provenance_json writes it, naming results.json), the names in the order the recipe gave them and each
// number in the shortest form that reads back to the same double. Throws Error for a bad name or a value
// that is not finite (checked before anything is written).
std::string results_json(const std::vector<RunResult>& results, const std::string& provenance);

// Parses results_json's text strictly: the names checked as above and given once, each number finite and
// in JSON's form, the provenance a record parse_provenance reads. Throws Error naming what was expected.
std::vector<RunResult> parse_results(const std::string& text);

// The results recorded in `folder`'s results.json; nullopt when there is none (a run that gave no result,
// or did not run). Throws Error ("cannot read 'FILE': ...") when the file is there but cannot be read or
// parsed, or is not a regular file.
std::optional<std::vector<RunResult>> read_results(const std::filesystem::path& folder);

}  // namespace selfsim::io
