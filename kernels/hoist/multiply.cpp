#include "kernels/hoist/multiply.h"

#include <cmath>
#include <string>

#include "kernels/geom/check.h"
#include "kernels/geom/error.h"

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
  return copies(multiplicity) * static_cast<double>(c_points - 1) + 2;  // + 1, and + 1 for a partial copy's cut
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
  check_budget(multiplied_points(pts.size(), m), opt.budget, "multiplicity " + number_text(m));
  const double length = c.length();
  if (!(length > 0)) throw Error("the curve to multiply has no length");
  const std::vector<double> t = parameter_of(c);

  Polyline out;
  std::vector<double> out_t;
  out.points.reserve(static_cast<std::size_t>(multiplied_points(pts.size(), m)));
  out_t.reserve(out.points.capacity());
  out.points.push_back({0, 0});
  out_t.push_back(0);
  const double whole = std::floor(m + 1e-12);  // copies taken whole; a last one only in part
  const double cut = (m - whole) * length;     // arclength of the partial copy (0 when m is whole)
  for (std::size_t i = 0; static_cast<double>(i) < n_copies; ++i) {
    if (progress.cancelled()) throw Cancelled();  // once per copy: a copy is at most the budget
    const SegmentTransform tr =
        opt.transforms.empty() ? SegmentTransform::Identity : opt.transforms[i % opt.transforms.size()];
    const Similarity2 map = Similarity2{{1, 0}, {static_cast<double>(i), 0}}.after(unit_map(tr));
    const bool back = walks_backwards(tr);
    const bool partial = static_cast<double>(i) >= whole;
    double walked = 0;
    for (std::size_t k = 1; k < pts.size(); ++k) {
      const std::size_t j = back ? pts.size() - 1 - k : k;  // the point reached
      const std::size_t from = back ? j + 1 : j - 1;        // the point left
      const double tj = back ? 1 - t[j] : t[j];
      if (partial) {
        const double step = norm(pts[j] - pts[from]);
        if (walked + step >= cut) {  // the cut falls on this segment: end there
          const double w = step > 0 ? (cut - walked) / step : 1;
          const double tf = back ? 1 - t[from] : t[from];
          out.points.push_back(map(lerp(pts[from], pts[j], w)));
          out_t.push_back((static_cast<double>(i) + tf + w * (tj - tf)) / m);
          break;
        }
        walked += step;
      }
      out.points.push_back(map(pts[j]));
      out_t.push_back((static_cast<double>(i) + tj) / m);
    }
  }
  // Back onto (0,0)–(1,0): by 1/m for whole m (exactly), by the similarity taking the end to (1,0) otherwise.
  const Vec2 end = m == whole ? Vec2{m, 0} : out.points.back();
  if (!(norm(end) > 1e-12 * m))
    throw Error("the multiplied curve ends where it starts: it cannot be scaled back to (1,0)");
  const Vec2 a = Vec2{1, 0} / end;
  for (Vec2& p : out.points) p = a * p;
  out.points.back() = {1, 0};
  out.close_path();
  for (const Field& f : c.point_fields.list)
    if (f.uniform && f.name != "t") out.point_fields.set(f);
  out.point_fields.set(real_field("t", std::move(out_t)));
  out.cell_fields = c.cell_fields;
  return out;
}

}  // namespace selfsim::hoist
