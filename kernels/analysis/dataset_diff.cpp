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

// Where values differ: how many elements, the first, and the largest difference.
struct Differences {
  std::size_t count = 0, first = 0, largest_at = 0;
  double largest = -1;
  void add(std::size_t element, double difference) {
    if (count == 0) first = element;
    if (count == 0 || element != last) ++count;
    if (!(difference <= largest)) largest = difference, largest_at = element;  // NaN counts as largest
    last = element;
  }
  // "3 of 40 points, the largest difference 0.25 at point 7" (1-based, as c:point(i) counts).
  std::string summary(std::size_t total, const char* element) const {
    std::string s = std::to_string(count) + " of " + std::to_string(total) + " " + element + "s";
    if (count > 1)
      s += ", the largest difference " + num(largest) + " at " + element + " " + std::to_string(largest_at + 1);
    return s;
  }

 private:
  std::size_t last = 0;
};

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
    Differences d;
    const std::size_t k = static_cast<std::size_t>(fa.components);
    for (std::size_t i = 0; i < fa.values.size(); ++i)
      if (!close(fa.values[i], fb.values[i], tol)) d.add(i / k, std::abs(fa.values[i] - fb.values[i]));
    if (d.count > 0) {
      const std::size_t first = d.first * k;
      std::string values;
      for (std::size_t c = 0; c < k; ++c)
        values += (c ? ", " : "") + num(fa.values[first + c]) + " vs " + num(fb.values[first + c]);
      r.add(std::string(kind) + " field '" + name + "' differs at " + d.summary(fa.values.size() / k, "tuple") +
            "; the first, tuple " + std::to_string(d.first + 1) + ": " + values);
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

// "(0, 1, 2)", at most 8 ids shown: point ids as the file stores them (0-based, as ParaView shows them).
std::string ids_text(const std::vector<std::size_t>& ids) {
  std::string s = "(";
  for (std::size_t k = 0; k < ids.size() && k < 8; ++k) s += (k ? ", " : "") + std::to_string(ids[k]);
  return s + (ids.size() > 8 ? ", ... " + std::to_string(ids.size()) + " in all)" : ")");
}

}  // namespace

std::vector<std::string> dataset_diff(const io::Dataset& a, const io::Dataset& b, double tol, std::size_t max_reports) {
  Report r{{}, max_reports};
  if (a.points.size() != b.points.size()) {
    r.add("point count differs: " + std::to_string(a.points.size()) + " vs " + std::to_string(b.points.size()));
  } else {
    Differences d;
    for (std::size_t i = 0; i < a.points.size(); ++i)
      for (int k = 0; k < 3; ++k)
        if (!close(a.points[i][k], b.points[i][k], tol)) d.add(i, std::abs(a.points[i][k] - b.points[i][k]));
    if (d.count > 0) {
      const auto& p = a.points[d.first];
      const auto& q = b.points[d.first];
      r.add("points differ at " + d.summary(a.points.size(), "point") + "; the first, point " +
            std::to_string(d.first + 1) + ": (" + num(p[0]) + ", " + num(p[1]) + ", " + num(p[2]) + ") vs (" +
            num(q[0]) + ", " + num(q[1]) + ", " + num(q[2]) + ")");
    }
  }
  if (a.cell_ends.size() != b.cell_ends.size())
    r.add("cell count differs: " + std::to_string(a.cell_ends.size()) + " vs " + std::to_string(b.cell_ends.size()));
  else if (a.shapes != b.shapes)
    r.add("cell kinds differ (polylines, polygons or mixed)");
  else
    for (std::size_t i = 0; i < a.cell_ends.size(); ++i)
      if (cell_of(a, i) != cell_of(b, i)) {
        r.add("cell " + std::to_string(i + 1) + " differs: points " + ids_text(cell_of(a, i)) + " vs " +
              ids_text(cell_of(b, i)));
        break;
      }
  compare_fields("point", a.point_fields, b.point_fields, tol, r);
  compare_fields("cell", a.cell_fields, b.cell_fields, tol, r);
  return r.lines;
}

}  // namespace selfsim::analysis
