#include "kernels/hoist/multiply.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cmath>
#include <string>
#include <utility>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/base/huge_pages.h"

namespace selfsim::hoist {

namespace {

// C's `t`, or its arclength fraction when it has none.
std::vector<double> parameter_of(const Polyline& c) {
  const auto pts = c.path(0);
  std::vector<double> t(pts.size());
  if (const Field* f = c.point_fields.find("t"); f != nullptr && f->components == 1) {
    for (std::size_t i = 0; i < t.size(); ++i) t[i] = f->at(i);
    return t;
  }
  double s = 0;
  for (std::size_t i = 1; i < pts.size(); ++i) t[i] = s += norm(pts[i] - pts[i - 1]);
  for (double& v : t) v /= s;
  return t;
}

}  // namespace

void MultiplyOptions::validate() const { check_between(multiplicity, 1, 1e6, "multiplicity"); }

double copies(double multiplicity) { return std::ceil(multiplicity - 1e-12); }

double multiplied_points(std::size_t c_points, double multiplicity) {
  return multiplicity * static_cast<double>(c_points - 1) + 1;
}

Polyline multiply(const Polyline& c, const MultiplyOptions& opt, Progress& progress) {
  opt.validate();
  if (c.paths() != 1 || c.points.size() < 2)
    throw Error("the curve to multiply must be a single path of 2 or more points");
  const auto pts = c.path(0);
  if (norm(pts.front()) > 1e-9 || norm(pts.back() - Vec2{1, 0}) > 1e-9)
    throw Error("the curve to multiply must run from (0,0) to (1,0)");
  const double m = opt.multiplicity;
  const double n_copies = copies(m);
  const double length = c.length();
  if (!(length > 0)) throw Error("the curve to multiply has no length");
  const std::vector<double> t = parameter_of(c);

  const std::size_t n = pts.size();
  const double whole = std::floor(m + 1e-12);  // copies taken whole; a last one only in part
  const auto whole_copies = static_cast<std::size_t>(whole);
  auto copy_map = [&](std::size_t i) {
    const SegmentTransform tr =
        opt.transforms.empty() ? SegmentTransform::Identity : opt.transforms[i % opt.transforms.size()];
    return std::pair{Similarity2{{1, 0}, {static_cast<double>(i), 0}}.after(unit_map(tr)), walks_backwards(tr)};
  };

  // The partial copy first (walked until its arclength reaches the fraction m − ⌊m⌋ of C's), since its
  // end decides the similarity that puts the whole result back onto (0,0)–(1,0).
  std::vector<Vec2> tail;
  std::vector<double> tail_t;
  if (n_copies > whole) {
    const auto [map, back] = copy_map(whole_copies);
    const double cut = (m - whole) * length;
    double walked = 0;
    for (std::size_t k = 1; k < n; ++k) {
      const std::size_t j = back ? n - 1 - k : k;     // the point reached
      const std::size_t from = back ? j + 1 : j - 1;  // the point left
      const double tj = back ? 1 - t[j] : t[j];
      const double step = norm(pts[j] - pts[from]);
      if (walked + step >= cut) {  // the cut falls on this segment: end there
        const double w = step > 0 ? (cut - walked) / step : 1;
        const double tf = back ? 1 - t[from] : t[from];
        tail.push_back(map(lerp(pts[from], pts[j], w)));
        tail_t.push_back(whole + tf + w * (tj - tf));
        break;
      }
      walked += step;
      tail.push_back(map(pts[j]));
      tail_t.push_back(whole + tj);
    }
  }
  // t runs from 0 to 1 over the copies: (copy + C's t) / span. The cut falls at a fraction of C's
  // arclength, where C's own t (a spline's parameter) may be more or less than that fraction, so the span
  // is the t reached at the cut, not m: dividing by m gave values past 1.
  const double span = tail_t.empty() ? m : tail_t.back();
  for (double& v : tail_t) v /= span;
  // Back onto (0,0)–(1,0): by 1/m for whole m (exactly), by the similarity taking the end to (1,0) otherwise.
  const Vec2 end = tail.empty() ? Vec2{m, 0} : tail.back();
  // Scaling back an end that lies almost where the curve starts would blow the curve up by as much.
  if (!(norm(end) > 1e-6 * m))
    throw Error(std::string("the multiplied curve ends ") +
                (norm(end) > 0 ? "within a millionth of its size of" : "at") +
                " its start: it cannot be scaled back onto (0,0)-(1,0) (try another multiplicity)");
  const Vec2 a = Vec2{1, 0} / end;

  // The whole copies, point k of the result from copy (k − 1)/(n − 1): every point has its own place, so
  // threads fill fixed chunks (and first-touch their own pages, which on a fresh array costs more than the
  // arithmetic). The bytes do not depend on the thread count.
  const std::size_t body = 1 + whole_copies * (n - 1), total = body + tail.size();
  // The exact count, before the result is allocated (the partial copy above is at most C's size).
  check_budget(static_cast<double>(whole_copies) * static_cast<double>(n - 1) + 1 + static_cast<double>(tail.size()),
               opt.budget, "multiplicity " + number_text(m));
  Polyline out;
  out.points.resize(total);
  advise_huge_pages(out.points);
  std::vector<double> out_t;
  out_t.reserve(total);
  advise_huge_pages(out_t);
  // std::vector zero-fills as it grows: in steps, so a stop is seen during a fill of gigabytes too.
  while (out_t.size() < total) {
    if (progress.cancelled()) throw Cancelled();
    out_t.resize(std::min(total, out_t.size() + (std::size_t{1} << 22)));
  }
  std::vector<std::pair<Similarity2, bool>> maps(whole_copies);
  for (std::size_t i = 0; i < whole_copies; ++i) maps[i] = copy_map(i);
  out.points[0] = {0, 0};
  out_t[0] = 0;
  std::atomic<bool> stop{false};
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(1, body, std::size_t{1} << 14),
      [&](const tbb::blocked_range<std::size_t>& r) {
        if (stop.load(std::memory_order_relaxed) || progress.cancelled()) {
          stop = true;
          return;
        }
        for (std::size_t k = r.begin(); k < r.end(); ++k) {
          const std::size_t i = (k - 1) / (n - 1), step = (k - 1) % (n - 1) + 1;
          const auto& [map, back] = maps[i];
          const std::size_t j = back ? n - 1 - step : step;
          out.points[k] = a * map(pts[j]);
          out_t[k] = (static_cast<double>(i) + (back ? 1 - t[j] : t[j])) / span;
        }
      },
      tbb::simple_partitioner());
  if (stop) throw Cancelled();
  for (std::size_t k = 0; k < tail.size(); ++k) {
    out.points[body + k] = a * tail[k];
    out_t[body + k] = tail_t[k];
  }
  out.points.back() = {1, 0};
  out.close_path();
  for (const Field& f : c.point_fields.list)
    if (f.uniform && f.name != "t") out.point_fields.set(f);
  out.point_fields.set(real_field("t", std::move(out_t)));
  out.cell_fields = c.cell_fields;
  return out;
}

}  // namespace selfsim::hoist
