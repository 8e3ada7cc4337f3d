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

void compare_fields(const char* kind, const std::map<std::string, io::FieldValues>& a,
                    const std::map<std::string, io::FieldValues>& b, double tol, Report& r) {
  for (const auto& [name, fa] : a) {
    auto it = b.find(name);
    if (it == b.end()) {
      r.add(std::string(kind) + " field '" + name + "' only in the first file");
      continue;
    }
    const io::FieldValues& fb = it->second;
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

// The point ids of cell i.
std::vector<std::size_t> cell_of(const io::Dataset& d, std::size_t i) {
  const std::size_t begin = i == 0 ? 0 : d.cell_ends[i - 1];
  return {d.cell_points.begin() + static_cast<std::ptrdiff_t>(begin),
          d.cell_points.begin() + static_cast<std::ptrdiff_t>(d.cell_ends[i])};
}

// "(0, 1, 2)", at most 8 ids shown.
std::string ids_text(const std::vector<std::size_t>& ids) {
  std::string s = "(";
  for (std::size_t k = 0; k < ids.size() && k < 8; ++k) s += (k ? ", " : "") + std::to_string(ids[k]);
  return s + (ids.size() > 8 ? ", ... " + std::to_string(ids.size()) + " in all)" : ")");
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
  if (a.cell_ends.size() != b.cell_ends.size())
    r.add("cell count differs: " + std::to_string(a.cell_ends.size()) + " vs " + std::to_string(b.cell_ends.size()));
  else if (a.shapes != b.shapes)
    r.add("cell kinds differ (polylines, polygons or mixed)");
  else
    for (std::size_t i = 0; i < a.cell_ends.size(); ++i)
      if (cell_of(a, i) != cell_of(b, i)) {
        r.add("cell " + std::to_string(i) + " differs: points " + ids_text(cell_of(a, i)) + " vs " +
              ids_text(cell_of(b, i)));
        break;
      }
  compare_fields("point", a.point_fields, b.point_fields, tol, r);
  compare_fields("cell", a.cell_fields, b.cell_fields, tol, r);
  return r.lines;
}

}  // namespace selfsim::analysis
