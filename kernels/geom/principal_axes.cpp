#include "kernels/geom/principal_axes.h"

#include <cmath>

namespace selfsim {

std::vector<Vec3> principal_directions(const Mesh& m) {
  std::vector<double> area(m.faces());
  for (std::size_t i = 0; i < m.faces(); ++i) area[i] = 0.5 * norm(area_normal(m, m.triangles[i]));
  double total = 0;
  Vec3 mean{};
  for (std::size_t i = 0; i < m.faces(); ++i) {
    const Triangle& t = m.triangles[i];
    total += area[i];
    mean = mean + area[i] / 3 * (m.points[t[0]] + m.points[t[1]] + m.points[t[2]]);
  }
  if (!(total > 0)) return {};
  mean = (1 / total) * mean;
  // The surface's own second moment about the mean, exact for each triangle (area A, corners p, q, r taken
  // from the mean): the integral of x x^T over it is A/12 (p p^T + q q^T + r r^T + s s^T), s = p + q + r.
  // Its centre alone would not do: a square cut on one diagonal would lean its axes along that diagonal.
  double c[3][3] = {};
  for (std::size_t i = 0; i < m.faces(); ++i) {
    const Triangle& t = m.triangles[i];
    const Vec3 p = m.points[t[0]] - mean, q = m.points[t[1]] - mean, r = m.points[t[2]] - mean, s = p + q + r;
    for (const Vec3 d : {p, q, r, s}) {
      const double v[3] = {d.x, d.y, d.z};
      for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) c[a][b] += area[i] / 12 * v[a] * v[b];
    }
  }
  double e[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};  // columns: the eigenvectors
  for (int sweep = 0; sweep < 32; ++sweep)
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (!(std::abs(c[p][q]) > 1e-300)) continue;
        const double theta = 0.5 * std::atan2(2 * c[p][q], c[q][q] - c[p][p]);
        const double cs = std::cos(theta), sn = std::sin(theta);
        for (int k = 0; k < 3; ++k) {  // c <- c J
          const double kp = c[k][p], kq = c[k][q];
          c[k][p] = cs * kp - sn * kq, c[k][q] = sn * kp + cs * kq;
        }
        for (int k = 0; k < 3; ++k) {  // c <- J^T c
          const double pk = c[p][k], qk = c[q][k];
          c[p][k] = cs * pk - sn * qk, c[q][k] = sn * pk + cs * qk;
        }
        for (int k = 0; k < 3; ++k) {
          const double kp = e[k][p], kq = e[k][q];
          e[k][p] = cs * kp - sn * kq, e[k][q] = sn * kp + cs * kq;
        }
      }
  std::vector<Vec3> out;
  for (int k = 0; k < 3; ++k) {
    const Vec3 axis{e[0][k], e[1][k], e[2][k]};
    if (!(norm(axis) > 0.5) || !is_finite(axis)) continue;
    out.push_back(normalized(axis));
    out.push_back(-normalized(axis));
  }
  return out;
}

}  // namespace selfsim
