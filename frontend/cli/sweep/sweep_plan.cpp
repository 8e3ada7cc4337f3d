#include "frontend/cli/sweep/sweep_plan.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <set>
#include <string_view>

#include "frontend/lua/parse_text.h"
#include "kernels/base/count_text.h"
#include "kernels/base/error.h"

namespace selfsim::interp {

namespace {

std::string twelve_digits(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.12g", v);
  return buf;
}

// The text of a --set value with its backslash escapes marked: backslash-comma is a comma, backslash-dot a
// dot and two backslashes one backslash, none of which splits a list or makes a range.
struct Marked {
  std::string text;
  std::vector<bool> escaped;  // per character of text

  explicit Marked(const std::string& raw) {
    for (std::size_t i = 0; i < raw.size(); ++i) {
      // Only those three are escapes; any other backslash is itself (a Windows path stays whole).
      const bool esc =
          raw[i] == '\\' && i + 1 < raw.size() && std::string_view(",.\\").find(raw[i + 1]) != std::string_view::npos;
      text += raw[esc ? ++i : i];
      escaped.push_back(esc);
    }
  }
  bool plain(std::size_t i, char c) const { return i < text.size() && text[i] == c && !escaped[i]; }
  // The first unescaped `c` (or "..") at or after `from`.
  std::size_t find(char c, std::size_t from = 0, bool twice = false) const {
    for (std::size_t i = from; i < text.size(); ++i)
      if (plain(i, c) && (!twice || plain(i + 1, c))) return i;
    return std::string::npos;
  }
};

std::vector<std::string> list_values(const std::string& key, const std::string& raw, const Marked& m) {
  std::vector<std::string> values;
  for (std::size_t begin = 0;;) {
    const std::size_t comma = m.find(',', begin);
    values.push_back(m.text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  std::set<std::string> seen;
  for (const std::string& v : values) {
    if (v.empty()) throw Error("--set " + key + "=" + raw + ": an empty value in the list");
    if (!seen.insert(v).second) throw Error("--set " + key + "=" + raw + ": '" + v + "' is listed twice");
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

// A whole number as written ("12", "-3", "1e12", "4.0"): exactly, as a long long when it reads as one,
// else a double that is whole and inside the long long range (every such double is a whole long long).
std::optional<long long> whole_number(const std::string& text) {
  if (const auto w = parse_text<long long>(text)) return w;
  const auto d = parse_text<double>(text);
  if (!d || *d != std::floor(*d) || !(*d >= -0x1p63 && *d < 0x1p63)) return std::nullopt;
  return static_cast<long long>(*d);
}

// A range whose ends and step are whole, counted in integers rather than stepped in doubles: exact where
// doubles cannot tell 2^63 - 8 from 2^63 - 1, never wrapping at the largest integer, and each value
// written whole (1e12 as 1000000000000, which an integer parameter takes; "%.12g" wrote 1e+12).
std::vector<std::string> whole_values(const std::string& set, long long from, long long to, long long step,
                                      const std::string& by) {
  if (step <= 0) throw Error(set + "the step after ':' must be a number > 0, got '" + by + "'");
  if (to < from)
    throw Error(set + "the range runs down; write it from " + std::to_string(to) + " to " + std::to_string(from));
  const unsigned long long span = static_cast<unsigned long long>(to) - static_cast<unsigned long long>(from);
  const unsigned long long steps = span / static_cast<unsigned long long>(step);
  if (steps >= max_sweep_runs)
    throw Error(set + "that is " + count_text(static_cast<double>(steps) + 1) + " values; at most " +
                std::to_string(max_sweep_runs));
  std::vector<std::string> values;
  for (unsigned long long i = 0; i <= steps; ++i)  // from + i * step <= to: no overflow in unsigned
    values.push_back(std::to_string(
        static_cast<long long>(static_cast<unsigned long long>(from) + i * static_cast<unsigned long long>(step))));
  return values;
}

}  // namespace

std::vector<std::string> sweep_values(const std::string& key, const std::string& text) {
  const std::string set = "--set " + key + "=" + text + ": ";
  const Marked m(text);
  const std::size_t dots = m.find('.', 0, true);
  if (dots != std::string::npos && dots > 0) {
    const std::string from = m.text.substr(0, dots);
    const std::size_t colon = m.find(':', dots + 2);
    const std::string to = m.text.substr(dots + 2, colon == std::string::npos ? std::string::npos : colon - dots - 2);
    const std::string by = colon == std::string::npos ? std::string() : m.text.substr(colon + 1);
    const auto a = parse_text<double>(from), b = parse_text<double>(to);
    if (a && b) {
      if (*b < *a) throw Error(set + "the range runs down; write it from " + to + " to " + from);
      const auto wa = whole_number(from), wb = whole_number(to);
      const auto wstep = colon == std::string::npos ? std::optional<long long>(1) : whole_number(by);
      if (colon == std::string::npos && !(wa && wb))
        throw Error(set + "a range of fractions needs a step, e.g. " + from + ".." + to + ":0.1");
      if (wa && wb && wstep) return whole_values(set, *wa, *wb, *wstep, by);
      const auto step = parse_text<double>(by);
      if (!step || !(*step > 0)) throw Error(set + "the step after ':' must be a number > 0, got '" + by + "'");
      // The end counts when the steps reach it to within rounding: 0.3..0.9:0.1 ends at 0.9.
      const double steps = std::floor((*b - *a) / *step * (1 + 1e-12) + 1e-9);
      if (!(steps < max_sweep_runs))
        throw Error(set + "that is " + count_text(steps + 1) + " values; at most " + std::to_string(max_sweep_runs));
      std::vector<std::string> values;
      std::set<std::string> seen;
      for (int i = 0; i <= static_cast<int>(steps); ++i) {
        double v = *a + i * *step;
        if (std::abs(v) < 1e-9 * *step) v = 0;  // -0.3 + 3 * 0.1 is 5.6e-17: the 0 it means
        values.push_back(twelve_digits(v));
        if (!seen.insert(values.back()).second)
          throw Error(set + "the step is too small to tell values apart at 12 digits");
      }
      return values;
    }
  }
  if (m.find(',') != std::string::npos) return list_values(key, text, m);
  return {m.text};
}

std::string escaped_value(const std::string& value) {
  std::string s;
  for (std::size_t i = 0; i < value.size(); ++i) {
    const char c = value[i];
    // A dot only after a dot (1..3 as 1.\.3): plain numbers stay as they read.
    if (c == ',' || c == '\\' || (c == '.' && i > 0 && value[i - 1] == '.')) s += '\\';
    s += c;
  }
  return s;
}

std::string fitting_name(const std::string& prefix, const std::string& core, const std::string& suffix) {
  constexpr std::size_t name_max = 255, mark = 9;  // "~" and 8 hex digits
  if (prefix.size() + core.size() + suffix.size() <= name_max) return prefix + core + suffix;
  std::uint32_t hash = 2166136261u;  // FNV-1a: the same on every machine, so --collect names alike
  for (unsigned char c : core) hash = (hash ^ c) * 16777619u;
  std::size_t keep = name_max - std::min(name_max, prefix.size() + suffix.size() + mark);
  while (keep > 0 && (static_cast<unsigned char>(core[keep]) & 0xC0) == 0x80) --keep;  // not inside a character
  char tail[16];
  std::snprintf(tail, sizeof tail, "~%08x", static_cast<unsigned>(hash));
  return prefix + core.substr(0, keep) + tail + suffix;
}

bool sweep_reserved_name(const std::string& name) {
  for (const char* ours :
       {"sweep.json", "results.csv", "previews", "slurm", "view.py", "selfsim.log", "selfsim.exit", ".", ".."})
    if (name == ours) return true;
  return name.starts_with("sheet_") || name.starts_with("plot_") || name.ends_with("_sweep.pvd") ||
         name.starts_with(".selfsim");
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
