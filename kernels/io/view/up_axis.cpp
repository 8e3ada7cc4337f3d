#include "kernels/io/view/up_axis.h"

#include <cmath>
#include <filesystem>
#include <type_traits>
#include <variant>

#include "kernels/base/lower_case.h"
#include "kernels/geom/mesh.h"

namespace selfsim::io {

namespace {

// Sums for Pearson's correlation between a level and each coordinate, each taken relative to the first
// sample: sums of squares at a distance from the origin (a stack at z = 1e9) lose the spread to rounding.
struct Sums {
  double n = 0, l = 0, ll = 0, c[3] = {0, 0, 0}, cc[3] = {0, 0, 0}, lc[3] = {0, 0, 0};
  double level0 = 0;
  std::array<double, 3> p0{};
  void add(double level_at, const std::array<double, 3>& p_at) {
    if (n == 0) level0 = level_at, p0 = p_at;
    const double level = level_at - level0;
    const std::array<double, 3> p{p_at[0] - p0[0], p_at[1] - p0[1], p_at[2] - p0[2]};
    n += 1;
    l += level;
    ll += level * level;
    for (int a = 0; a < 3; ++a) {
      c[a] += p[a];
      cc[a] += p[a] * p[a];
      lc[a] += level * p[a];
    }
  }
  // The axis the level follows most, at least up_correlation; else y.
  int axis() const {
    if (n < 2) return 1;
    int best = 1;
    double strongest = up_correlation;
    for (int a = 0; a < 3; ++a)
      if (const double r = std::abs(correlation(a)); r >= strongest) {
        strongest = r;
        best = a;
      }
    return best;
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
  return s.axis();
}

int up_axis(const Dataset& d, const std::string& file) {
  const std::string ext = lower_case(std::filesystem::path(file).extension().string());
  const bool checked = d.point_fields.contains("wall") || d.cell_fields.contains("wall");
  return ext == ".3mf" || ext == ".stl" || checked ? 2 : up_axis(d);
}

int up_axis(const ValueRef& v) {
  Sums s;
  std::visit(
      [&](const auto* value) {
        using T = std::decay_t<decltype(*value)>;
        if constexpr (!std::is_same_v<T, Polyline>) {
          auto at = [&](std::size_t i) {
            const Vec3& p = value->points[i];
            return std::array<double, 3>{p.x, p.y, p.z};
          };
          if (const Field* f = value->point_fields.find("level"); f != nullptr && f->components == 1) {
            for (std::size_t i = 0; i < value->points.size(); ++i) s.add(f->at(i), at(i));
          } else if constexpr (std::is_same_v<T, Mesh>) {
            if (const Field* g = value->face_fields.find("level"); g != nullptr && g->components == 1)
              for (std::size_t i = 0; i < value->triangles.size(); ++i) {
                std::array<double, 3> centre{0, 0, 0};
                for (std::size_t k = 0; k < 3; ++k)
                  for (int a = 0; a < 3; ++a) centre[a] += at(value->triangles[i][k])[a] / 3;
                s.add(g->at(i), centre);
              }
          }
        }
      },
      v);
  return s.axis();
}

int axis_from_name(const std::string& name) { return name == "x" ? 0 : name == "y" ? 1 : name == "z" ? 2 : -1; }

}  // namespace selfsim::io
