#include "frontend/cli/sweep/sweep_results.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include "frontend/lua/lua_support.h"
#include "frontend/lua/parse_text.h"
#include "kernels/io/csv_file.h"
#include "kernels/io/output_file.h"
#include "kernels/io/read_error.h"
#include "kernels/io/run_results.h"
#include "kernels/io/view/result_plot.h"

namespace selfsim::interp {

namespace {

// The table's own columns, after the keys and results: "status" and "folder", unless a key or a result
// has that name; then an underscore goes in front until it is a name of its own.
std::string own_column(std::string name, const std::vector<std::string>& taken) {
  while (std::find(taken.begin(), taken.end(), name) != taken.end()) name = "_" + name;
  return name;
}

// The swept key's value of each run as a number, when one key varies and every value is one.
std::optional<std::vector<double>> plot_xs(const SweepPlan& plan, std::string& why_not) {
  if (plan.keys.size() != 1) {
    std::string keys;
    for (const std::string& k : plan.keys) keys += (keys.empty() ? "" : ", ") + k;
    why_not = std::to_string(plan.keys.size()) + " keys vary (" + keys + "): a plot needs one";
    return std::nullopt;
  }
  std::vector<double> xs;
  for (const SweepRun& run : plan.runs) {
    const std::optional<double> x = parse_text<double>(run.sets.at(plan.keys[0]));
    if (!x) {
      why_not = "'" + plan.keys[0] + "' is not a number in every run ('" + run.sets.at(plan.keys[0]) + "')";
      return std::nullopt;
    }
    xs.push_back(*x);
  }
  return xs;
}

}  // namespace

std::string plot_name(const std::string& result) { return fitting_name("plot_", result, ".svg"); }

SweepResults write_sweep_results(const SweepConfig& c, const SweepPlan& plan, const std::vector<int>& codes) {
  const std::filesystem::path& out = c.run.out_dir;
  const std::size_t n = plan.runs.size();
  SweepResults r;
  // Each run's results by name; the names in the order first seen, over the runs in order.
  std::vector<std::map<std::string, double>> values(n);
  std::set<std::string> seen;  // r.names as a set: a search of the list for each result was quadratic
  for (std::size_t i = 0; i < n; ++i) {
    if (codes[i] != 0) continue;  // a failed run's results (if any) are not the run's: its cells stay empty
    try {
      const std::filesystem::path folder = out / plan.runs[i].folder;
      const auto given = io::read_results(folder);
      if (!given) continue;
      // result() refuses a parameter's name, so a result named like a swept key was written by hand (or by
      // another recipe): a second column of that name would be read as the key by whoever reads the table.
      for (const io::RunResult& one : *given)
        if (std::find(plan.keys.begin(), plan.keys.end(), one.name) != plan.keys.end())
          throw Error(io::cannot_read(folder / io::results_file,
                                      "it gives a result named '" + one.name + "', as the swept key"));
      for (const io::RunResult& one : *given) {
        if (seen.insert(one.name).second) r.names.push_back(one.name);
        values[i][one.name] = one.value;
      }
    } catch (const Error& e) {
      std::fprintf(stderr, "selfsim: warning: %s: its cells in results.csv are empty\n", e.what());
    }
  }

  std::vector<std::string> taken = plan.keys;
  taken.insert(taken.end(), r.names.begin(), r.names.end());
  io::CsvRows rows(1);
  for (const std::string& name : taken) rows[0].emplace_back(name);
  rows[0].emplace_back(own_column("status", taken));
  rows[0].emplace_back(own_column("folder", taken));
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<io::CsvCell> row;
    for (const std::string& key : plan.keys) row.emplace_back(plan.runs[i].sets.at(key));
    for (const std::string& name : r.names) {
      const auto v = values[i].find(name);
      if (v != values[i].end())
        row.emplace_back(v->second);
      else
        row.emplace_back(std::string());
    }
    row.emplace_back(std::string(codes[i] == 0 ? "ok" : codes[i] < 0 ? "not run" : "failed"));
    row.emplace_back(plan.runs[i].folder);
    rows.push_back(std::move(row));
  }
  io::save_csv(out, sweep_results_file, rows);
  r.written.push_back(sweep_results_file);
  // An earlier sweep's plots in this folder are of its results, not these: the plots below are all there are.
  io::remove_files(out, "",
                   [](const std::string& name) { return name.starts_with("plot_") && name.ends_with(".svg"); });

  if (r.names.empty()) return r;
  const std::optional<std::vector<double>> xs = plot_xs(plan, r.no_plot);
  if (!xs) return r;
  const std::string recipe = c.run.recipe.filename().string();
  for (const std::string& name : r.names) {
    std::vector<io::PlotPoint> points;
    for (std::size_t i = 0; i < n; ++i)
      if (const auto v = values[i].find(name); v != values[i].end()) points.push_back({(*xs)[i], v->second});
    io::PlotLabels labels;
    labels.title = name + " against " + plan.keys[0];
    labels.note = recipe + ": " + std::to_string(points.size()) + " of " + std::to_string(n) + " runs";
    labels.x = plan.keys[0];
    labels.y = name;
    const std::string file = plot_name(name);
    io::write_whole(out, file, io::result_plot_svg(labels, std::move(points)));
    r.written.push_back(file);
    r.plots.push_back(file);
  }
  return r;
}

}  // namespace selfsim::interp
