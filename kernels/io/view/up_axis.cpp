#include "kernels/io/view/up_axis.h"

#include <cmath>

namespace selfsim::io {

namespace {

// Sums for Pearson's correlation between a level and each coordinate.
struct Sums {
  double n = 0, l = 0, ll = 0, c[3] = {0, 0, 0}, cc[3] = {0, 0, 0}, lc[3] = {0, 0, 0};
  void add(double level, const std::array<double, 3>& p) {
    n += 1;
    l += level;
    ll += level * level;
    for (int a = 0; a < 3; ++a) {
      c[a] += p[a];
      cc[a] += p[a] * p[a];
      lc[a] += level * p[a];
    }
  }
  double correlation(int a) const {
    const double var_l = ll - l * l / n, var_c = cc[a] - c[a] * c[a] / n, cov = lc[a] - l * c[a] / n;
    if (!(var_l > 0) || !(var_c > 0)) return 0;
    const double r = cov / std::sqrt(var_l * var_c);
    return std::isfinite(r) ? r : 0;
  }
};

}  // namespace

int up_axis(const Dataset& d) {
  Sums s;
  if (auto f = d.point_fields.find("level"); f != d.point_fields.end() && f->second.components == 1) {
    for (std::size_t i = 0; i < d.points.size() && i < f->second.values.size(); ++i)
      s.add(f->second.values[i], d.points[i]);
  } else if (auto g = d.cell_fields.find("level"); g != d.cell_fields.end() && g->second.components == 1) {
    for (std::size_t i = 0, begin = 0; i < d.cell_ends.size() && i < g->second.values.size(); begin = d.cell_ends[i++])
      if (d.cell_ends[i] > begin) {
        std::array<double, 3> centre{0, 0, 0};
        for (std::size_t k = begin; k < d.cell_ends[i]; ++k)
          for (int a = 0; a < 3; ++a) centre[a] += d.points.at(d.cell_points[k])[a];
        for (double& x : centre) x /= static_cast<double>(d.cell_ends[i] - begin);
        s.add(g->second.values[i], centre);
      }
  }
  if (s.n < 2) return 1;
  int best = 1;
  double strongest = up_correlation;
  for (int a = 0; a < 3; ++a)
    if (const double r = std::abs(s.correlation(a)); r >= strongest) {
      strongest = r;
      best = a;
    }
  return best;
}

int axis_from_name(const std::string& name) { return name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1; }

}  // namespace selfsim::io
