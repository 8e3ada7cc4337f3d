#include "kernels/develop/bezier_surface.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <vector>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/develop/level_stack.h"
#include "kernels/geom/all_finite.h"

namespace selfsim::develop {

namespace {

// One level's smoothed curve (§3.1.1) in the polygon's own parameter u ∈ [0, n]: segment j is [j, j+1], its
// midpoint M_j at u = j + ½. The piece around corner V = p_j runs from M_{j−1} (u = j − ½) to M_j (u = j + ½)
// with control points M_{j−1} + k(V − M_{j−1}) and M_j + k(V − M_j); an open curve adds straight pieces from
// its start to M_0 and from M_{n−1} to its end.
class Smoothed {
 public:
  Smoothed(std::span<const Vec2> p, bool closed) : p_(p), n_(p.size() - 1), closed_(closed), k_(p.size(), 2.0 / 3) {
    for (std::size_t j = closed ? 0 : 1; j < n_; ++j) {
      const Vec2 in = p[j] - (j == 0 ? p[n_ - 1] : p[j - 1]), out = p[j + 1] - p[j];
      // Turning angle φ ∈ [0, π]. The cubic closest to a circular arc of angle φ has handles (4/3)·tan(φ/4)·r,
      // r = h/tan(φ/2) for tangent points h from the corner, so k = (4/3)·tan(φ/4)/tan(φ/2), which by the
      // half-angle formula is (2/3)·(1 − tan²(φ/4)): 2/3 when straight, 0 at a full reversal, never NaN.
      const double q = std::tan(std::atan2(std::abs(cross(in, out)), dot(in, out)) / 4);
      k_[j] = 2.0 / 3 * (1 - q * q);
    }
  }

  std::size_t segments() const { return n_; }
  // Bezier pieces: one per corner, plus the two straight end pieces of an open curve.
  std::size_t pieces() const { return closed_ ? n_ : n_ + 1; }

  Vec2 at(double u) const {
    const double n = static_cast<double>(n_);
    if (closed_) u -= n * std::floor(u / n);  // periodic: any u
    // Corner j's piece covers u ∈ [j − ½, j + ½].
    const auto j = static_cast<std::size_t>(std::clamp(std::floor(u + 0.5), 0.0, n));
    if (!closed_ && j == 0) return lerp(p_[0], mid(0), 2 * u);
    if (!closed_ && j == n_) return lerp(mid(n_ - 1), p_[n_], 2 * (u - (n - 0.5)));
    const std::size_t c = j % n_;  // a closed curve's corner n is corner 0
    const double s = u + 0.5 - static_cast<double>(j), r = 1 - s;
    const Vec2 a = mid(c == 0 ? n_ - 1 : c - 1), d = mid(c), v = p_[c];
    const Vec2 b = a + k_[c] * (v - a), e = d + k_[c] * (v - d);
    return r * r * r * a + 3 * r * r * s * b + 3 * r * s * s * e + s * s * s * d;
  }

  // The parameters t = u/n of a row sampling this level: `per_piece` equal steps of each piece's own
  // parameter, so every knot (midpoint, end) is a sample. Open: from t = 0 to 1 inclusive. Closed: from
  // t = 1/(2n) (M_0) once around, short of M_0 again, so the parameters increase past 1.
  std::vector<double> row(int per_piece) const {
    const double n = static_cast<double>(n_), step = 1.0 / per_piece;
    std::vector<double> t;
    t.reserve(pieces() * static_cast<std::size_t>(per_piece) + 1);
    for (std::size_t q = 0; q < pieces(); ++q) {
      const bool end = !closed_ && (q == 0 || q == n_);
      const double start = closed_ ? static_cast<double>(q) + 0.5 : q == 0 ? 0 : static_cast<double>(q) - 0.5;
      for (int k = 0; k < per_piece; ++k) t.push_back((start + (end ? 0.5 : 1.0) * k * step) / n);
    }
    if (!closed_) t.push_back(1);
    return t;
  }

 private:
  Vec2 mid(std::size_t j) const { return 0.5 * (p_[j] + p_[j + 1]); }

  std::span<const Vec2> p_;
  std::size_t n_;
  bool closed_;
  std::vector<double> k_;  // handle fraction at each corner
};

// The mesh's shape, from segment counts and lengths: everything bezier_size needs, in doubles so that an
// absurd request overflows to a number the budget refuses rather than wrapping.
struct Plan {
  bool closed = false;
  std::vector<double> z;          // level heights
  std::vector<double> intervals;  // per level: steps along a row sampling it, resolution·pieces
  std::vector<double> steps;      // per band: row steps m_i from level i to level i+1
  double points = 0, triangles = 0;
};

Plan make_plan(std::span<const Polyline* const> levels, const BezierOptions& opt) {
  opt.validate();
  Plan p;
  p.closed = check_stack(levels);
  p.z = level_heights(levels, opt.height);
  const double extra = p.closed ? 0 : 1;  // an open row's last sample
  for (const Polyline* c : levels) p.intervals.push_back(opt.resolution * (static_cast<double>(c->segments()) + extra));
  p.points = p.intervals[0] + extra;
  for (std::size_t i = 0; i + 1 < levels.size(); ++i) {
    const Polyline& fine = *levels[i + 1];
    const double spacing = fine.length() / static_cast<double>(fine.segments()) / opt.resolution;
    const double m = std::max(2.0, std::ceil((p.z[i] - p.z[i + 1]) / spacing - 1e-9));
    p.steps.push_back(m);
    p.points += m * (p.intervals[i + 1] + extra);
    p.triangles += p.intervals[i] + (2 * m - 1) * p.intervals[i + 1];
  }
  return p;
}

// One row of the mesh: band i at σ ∈ (0, 1] (σ = 0 only for the row at level 0), sampling level `sampled`.
struct Row {
  std::size_t band, sampled;
  double sigma, level;  // level: i + σ, the point field
  std::size_t first;    // index of its first point
};

}  // namespace

void BezierOptions::validate() const {
  check_finite(height, "option 'height'");
  if (!(height > 0)) throw Error("option 'height' must be positive, got " + number_text(height));
  check_range(resolution, 1, 64, "option 'resolution'");
}

double bezier_size(std::span<const Polyline* const> levels, const BezierOptions& opt) {
  const Plan p = make_plan(levels, opt);
  return p.points + p.triangles;
}

BezierCounts bezier_counts(std::span<const Polyline* const> levels, const BezierOptions& opt) {
  const Plan p = make_plan(levels, opt);
  double sides = 0;
  for (double m : p.steps) sides += m;
  return {p.points, p.triangles, p.intervals.front() + p.intervals.back() + (p.closed ? 0 : 2 * sides)};
}

Vec2 smoothed_level_point(const Polyline& level, double t) {
  if (level.paths() != 1 || level.segments() < 1) throw Error("the level must be one path with a segment");
  check_between(t, 0, 1, "t");
  const Smoothed c(level.path(0), closed_path(level.path(0)));
  return c.at(t * static_cast<double>(c.segments()));
}

void zip_rows(std::span<const double> upper, std::uint32_t upper_first, std::span<const double> lower,
              std::uint32_t lower_first, bool closed, std::span<Triangle> out) {
  const std::size_t least = closed ? 3 : 2;
  if (upper.size() < least || lower.size() < least) throw Error("zip_rows: a row is too short");
  // Steps along each row: a closed row's last step returns to its first sample, one period on.
  const std::size_t a_steps = upper.size() - (closed ? 0 : 1), b_steps = lower.size() - (closed ? 0 : 1);
  if (out.size() != a_steps + b_steps) throw Error("zip_rows: the output has the wrong size");
  auto param = [](std::span<const double> row, std::size_t k) { return k < row.size() ? row[k] : row[0] + 1; };
  auto point = [](std::uint32_t first, std::size_t k, std::size_t size) {
    return first + static_cast<std::uint32_t>(k % size);
  };
  std::size_t i = 0, j = 0;
  for (Triangle& f : out) {
    const bool up = j == b_steps || (i < a_steps && param(upper, i + 1) <= param(lower, j + 1));
    const std::uint32_t a = point(upper_first, i, upper.size()), b = point(lower_first, j, lower.size());
    // (upper, lower, next): ∂f/∂s × ∂f/∂t, the way control_mesh's (coarse, fine, next fine) triangles face.
    f = up ? Triangle{a, b, point(upper_first, ++i, upper.size())}
           : Triangle{a, b, point(lower_first, ++j, lower.size())};
  }
}

Mesh bezier_surface(std::span<const Polyline* const> levels, const BezierOptions& opt, Progress& progress) {
  const Plan plan = make_plan(levels, opt);
  check_budget(plan.points + plan.triangles, opt.budget, "the Bezier surface");
  if (plan.points > max_mesh_points)
    throw Error("the Bezier surface would have " + number_text(plan.points) + " points, more than 32-bit indices hold");
  progress.start("developing surface (Bezier)");

  const std::size_t top = levels.size() - 1;
  std::vector<Smoothed> curves;
  std::vector<std::vector<double>> params;  // the row parameters of each level
  for (const Polyline* c : levels) {
    curves.emplace_back(c->path(0), plan.closed);
    params.push_back(curves.back().row(opt.resolution));
  }
  std::vector<Row> rows{{0, 0, 0, 0, 0}};
  for (std::size_t i = 0; i < top; ++i) {
    const auto m = static_cast<std::size_t>(plan.steps[i]);
    for (std::size_t r = 1; r <= m; ++r) {
      const double sigma = static_cast<double>(r) / static_cast<double>(m);
      rows.push_back(
          {i, i + 1, sigma, static_cast<double>(i) + sigma, rows.back().first + params[rows.back().sampled].size()});
    }
  }

  Mesh mesh;
  mesh.points.resize(static_cast<std::size_t>(plan.points));
  mesh.triangles.resize(static_cast<std::size_t>(plan.triangles));
  std::vector<double> point_level(mesh.points.size());
  std::vector<std::int32_t> face_level(mesh.triangles.size());

  // Level l's curve at its height, at parameter t.
  auto lifted = [&](std::size_t l, double t) {
    const Vec2 c = curves[l].at(t * static_cast<double>(curves[l].segments()));
    return Vec3{c.x, c.y, plan.z[l]};
  };
  // f(s, t) in band i: the cubic Hermite curve from level i to level i+1 (tangents per unit σ, see the header).
  auto surface = [&](const Row& row, double t) {
    const std::size_t i = row.band;
    if (row.sigma == 0) return lifted(i, t);
    if (row.sigma == 1) return lifted(i + 1, t);  // exactly on the level's curve and height
    const Vec3 p0 = lifted(i, t), p1 = lifted(i + 1, t);
    const Vec3 d0 = i == 0 ? Vec3{0, 0, (plan.z[1] - plan.z[0]) / 2} : 0.5 * (p1 - p0);
    const Vec3 d1 = i + 1 == top ? Vec3{0, 0, (plan.z[top] - plan.z[top - 1]) / 2} : 0.5 * (lifted(i + 2, t) - p1);
    const double s = row.sigma, s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * d0 + (3 * s2 - 2 * s3) * p1 + (s3 - s2) * d1;
  };

  std::size_t faces = 0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const Row& row = rows[r];
    const std::vector<double>& t = params[row.sampled];
    std::atomic<bool> stop{false};
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, t.size(), std::size_t{1} << 14),
        [&](const tbb::blocked_range<std::size_t>& range) {
          if (stop.load(std::memory_order_relaxed) || progress.cancelled()) {
            stop = true;
            return;
          }
          for (std::size_t k = range.begin(); k < range.end(); ++k) {
            mesh.points[row.first + k] = surface(row, t[k]);
            point_level[row.first + k] = row.level;
          }
        },
        tbb::simple_partitioner());
    if (stop) throw Cancelled();
    if (r > 0) {
      const Row& above = rows[r - 1];
      const std::vector<double>& u = params[above.sampled];
      const std::size_t n = u.size() + t.size() - (plan.closed ? 0 : 2);
      zip_rows(u, static_cast<std::uint32_t>(above.first), t, static_cast<std::uint32_t>(row.first), plan.closed,
               std::span<Triangle>(mesh.triangles).subspan(faces, n));
      std::fill_n(face_level.begin() + static_cast<std::ptrdiff_t>(faces), n, static_cast<std::int32_t>(row.band));
      faces += n;
    }
    progress.step(static_cast<double>(r + 1) / static_cast<double>(rows.size()));
  }
  if (!all_finite<Vec3>(mesh.points))
    throw Error("the Bezier surface has non-finite points (the levels or option 'height' are too large)");
  mesh.point_fields.set(real_field("level", std::move(point_level)));
  mesh.face_fields.set(int_field("level", std::move(face_level)));
  return mesh;
}

}  // namespace selfsim::develop
