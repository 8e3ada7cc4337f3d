#include "interpreter/sweep_plan.h"

#include <cmath>
#include <cstdio>
#include <set>

#include "interpreter/parse_text.h"
#include "kernels/geom/count_text.h"
#include "kernels/geom/error.h"

namespace selfsim::interp {

namespace {

std::string twelve_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

std::vector<std::string> list_values(const std::string& key, const std::string& text) {
  std::vector<std::string> values(1);
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == ',') {
      values.back() += ',';
      ++i;
    } else if (text[i] == ',') {
      values.emplace_back();
    } else {
      values.back() += text[i];
    }
  }
  std::set<std::string> seen;
  for (const std::string& v : values) {
    if (v.empty()) throw Error("--set " + key + "=" + text + ": an empty value in the list");
    if (!seen.insert(v).second) throw Error("--set " + key + "=" + text + ": '" + v + "' is listed twice");
  }
  return values;
}

// A sanitised piece of a folder name: letters, digits and . _ + - kept, anything else '_'.
std::string folder_piece(const std::string& text) {
  std::string s;
  for (unsigned char c : text)
    s += std::isalnum(c) || c == '.' || c == '_' || c == '+' || c == '-' ? static_cast<char>(c) : '_';
  return s;
}

}  // namespace

std::vector<std::string> sweep_values(const std::string& key, const std::string& text) {
  const std::string set = "--set " + key + "=" + text + ": ";
  const std::size_t dots = text.find("..");
  if (dots != std::string::npos && dots > 0) {
    const std::string from = text.substr(0, dots);
    std::string to = text.substr(dots + 2), by;
    if (const std::size_t colon = to.find(':'); colon != std::string::npos) {
      by = to.substr(colon + 1);
      to = to.substr(0, colon);
    }
    const auto a = parse_text<double>(from), b = parse_text<double>(to);
    if (a && b) {
      if (*b < *a) throw Error(set + "the range runs down; write it from " + to + " to " + from);
      if (by.empty()) {
        const auto wa = parse_text<long long>(from), wb = parse_text<long long>(to);
        if (!wa || !wb) throw Error(set + "a range of fractions needs a step, e.g. " + from + ".." + to + ":0.1");
        if (static_cast<double>(*wb - *wa) >= max_sweep_runs)
          throw Error(set + "that is " + count_text(static_cast<double>(*wb - *wa) + 1) + " values; at most " +
                      std::to_string(max_sweep_runs));
        std::vector<std::string> values;
        for (long long v = *wa; v <= *wb; ++v) values.push_back(std::to_string(v));
        return values;
      }
      const auto step = parse_text<double>(by);
      if (!step || !(*step > 0)) throw Error(set + "the step after ':' must be a number > 0, got '" + by + "'");
      // The end counts when the steps reach it to within rounding: 0.3..0.9:0.1 ends at 0.9.
      const double steps = std::floor((*b - *a) / *step * (1 + 1e-12) + 1e-9);
      if (!(steps < max_sweep_runs))
        throw Error(set + "that is " + count_text(steps + 1) + " values; at most " + std::to_string(max_sweep_runs));
      std::vector<std::string> values;
      std::set<std::string> seen;
      for (int i = 0; i <= static_cast<int>(steps); ++i) {
        values.push_back(twelve_digits(*a + i * *step));
        if (!seen.insert(values.back()).second)
          throw Error(set + "the step is too small to tell values apart at 12 digits");
      }
      return values;
    }
  }
  if (text.find(',') != std::string::npos) return list_values(key, text);
  return {text};
}

bool is_sweep(const std::map<std::string, std::string>& sets) {
  for (const auto& [key, text] : sets)
    if (sweep_values(key, text).size() > 1) return true;
  return false;
}

SweepPlan plan_sweep(const std::map<std::string, std::string>& sets) {
  SweepPlan plan;
  std::vector<std::pair<std::string, std::vector<std::string>>> axes;
  double total = 1;
  for (const auto& [key, text] : sets) {
    axes.emplace_back(key, sweep_values(key, text));
    total *= static_cast<double>(axes.back().second.size());
    if (axes.back().second.size() > 1) plan.keys.push_back(key);
  }
  if (total > max_sweep_runs)
    throw Error("the sweep has " + count_text(total) + " runs (the product of its --set lists); at most " +
                std::to_string(max_sweep_runs));
  std::vector<std::size_t> at(axes.size(), 0);
  std::set<std::string> folders;
  for (std::size_t n = 0; n < static_cast<std::size_t>(total); ++n) {
    SweepRun run;
    for (std::size_t k = 0; k < axes.size(); ++k) {
      const std::string& value = axes[k].second[at[k]];
      run.sets[axes[k].first] = value;
      if (axes[k].second.size() == 1) continue;
      run.folder += (run.folder.empty() ? "" : ",") + folder_piece(axes[k].first) + "=" + folder_piece(value);
      run.caption += (run.caption.empty() ? "" : ", ") + axes[k].first + "=" + value;
    }
    if (run.folder.size() > 200)
      throw Error("the folder name of run " + std::to_string(n + 1) + " would be " + std::to_string(run.folder.size()) +
                  " characters; at most 200 (shorter values or names)");
    if (!folders.insert(run.folder).second)
      throw Error("two runs would share the folder '" + run.folder +
                  "': their values differ only in characters a folder name cannot keep");
    plan.runs.push_back(std::move(run));
    for (std::size_t k = axes.size(); k-- > 0;) {  // the last key varies fastest
      if (++at[k] < axes[k].second.size()) break;
      at[k] = 0;
    }
  }
  return plan;
}

}  // namespace selfsim::interp
