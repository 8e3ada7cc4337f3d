#include "kernels/analysis/dataset_diff.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace selfsim::analysis {

namespace {

// All the digits a double needs: two values that differ never print alike.
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

bool close(double a, double b, double tol) {
  if (a == b) return true;  // equal infinities too, whose difference is NaN
  if (std::isnan(a) || std::isnan(b)) return std::isnan(a) && std::isnan(b);
  return std::abs(a - b) <= tol * std::max({1.0, std::abs(a), std::abs(b)});
}

struct Report {
  std::vector<std::string> lines;
  std::size_t max;
  bool full() const { return lines.size() >= max; }
  void add(std::string s) {
    if (!full()) lines.push_back(std::move(s));
  }
};

void compare_fields(const char* kind, const std::map<std::string, io::Field>& a,
                    const std::map<std::string, io::Field>& b, double tol, Report& r) {
  for (const auto& [name, fa] : a) {
    auto it = b.find(name);
    if (it == b.end()) {
      r.add(std::string(kind) + " field '" + name + "' only in the first file");
      continue;
    }
    const io::Field& fb = it->second;
    if (fa.components != fb.components || fa.values.size() != fb.values.size()) {
      r.add(std::string(kind) + " field '" + name + "' has a different size");
      continue;
    }
    for (std::size_t i = 0; i < fa.values.size() && !r.full(); ++i)
      if (!close(fa.values[i], fb.values[i], tol)) {
        r.add(std::string(kind) + " field '" + name + "' differs at tuple " +
              std::to_string(i / static_cast<std::size_t>(fa.components)) + ": " + num(fa.values[i]) + " vs " +
              num(fb.values[i]));
        break;
      }
  }
  for (const auto& [name, fb] : b)
    if (!a.contains(name)) r.add(std::string(kind) + " field '" + name + "' only in the second file");
}

}  // namespace

std::vector<std::string> dataset_diff(const io::Dataset& a, const io::Dataset& b, double tol, std::size_t max_reports) {
  Report r{{}, max_reports};
  if (a.points.size() != b.points.size())
    r.add("point count differs: " + std::to_string(a.points.size()) + " vs " + std::to_string(b.points.size()));
  else
    for (std::size_t i = 0; i < a.points.size() && !r.full(); ++i)
      for (int k = 0; k < 3; ++k)
        if (!close(a.points[i][k], b.points[i][k], tol)) {
          r.add("point " + std::to_string(i) + " differs: (" + num(a.points[i][0]) + ", " + num(a.points[i][1]) + ", " +
                num(a.points[i][2]) + ") vs (" + num(b.points[i][0]) + ", " + num(b.points[i][1]) + ", " +
                num(b.points[i][2]) + ")");
          break;
        }
  if (a.cell_ends != b.cell_ends || a.cell_points != b.cell_points)
    r.add("cells differ: " + std::to_string(a.cell_ends.size()) + " vs " + std::to_string(b.cell_ends.size()) +
          " cells");
  compare_fields("point", a.point_fields, b.point_fields, tol, r);
  compare_fields("cell", a.cell_fields, b.cell_fields, tol, r);
  return r.lines;
}

}  // namespace selfsim::analysis
