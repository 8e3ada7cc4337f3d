#include "kernels/geom/curve_join.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "kernels/base/error.h"

namespace selfsim {

namespace {

// Appends pts to out in chunks, checking for a stop between them: a join copies up to the whole budget.
template <class V>
void append(PointArray<V>& out, std::span<const V> pts, Progress& progress) {
  constexpr std::size_t chunk = std::size_t{1} << 20;
  for (std::size_t i = 0; i < pts.size(); i += chunk) {
    if (progress.cancelled()) throw Cancelled();
    const auto part = pts.subspan(i, std::min(chunk, pts.size() - i));
    out.insert(out.end(), part.begin(), part.end());
  }
}

// A path's end meets the next path's start when they agree to rounding: within a billionth of the
// parts' whole extent (not of the coordinates' size, which would swallow real gaps far from the origin).
template <class V>
bool meets(const V& a, const V& b, double extent) {
  return norm(a - b) <= 1e-9 * extent;
}

template <class V>
std::size_t total_points(std::span<const PolylineT<V>* const> parts) {
  std::size_t n = 0;
  for (const PolylineT<V>* p : parts) n += p->points.size();
  return n;
}

}  // namespace

template <class V>
PolylineT<V> group(std::span<const PolylineT<V>* const> members, std::span<const Fields> overrides,
                   const Fields& cell_defaults, Progress& progress) {
  if (members.empty()) throw Error("a group needs at least one curve");
  if (!overrides.empty() && overrides.size() != members.size())
    throw Error("a group's overrides must be one per member");  // a caller's mistake, not a recipe's
  PolylineT<V> out;
  out.points.reserve(total_points(members));
  std::vector<Fields> cells(members.size());  // each member's cell fields with its overrides
  std::vector<const Fields*> point_fields, cell_fields;
  std::vector<std::size_t> points, paths, zero(members.size(), 0);
  std::vector<std::int32_t> member_of_path;
  for (std::size_t m = 0; m < members.size(); ++m) {
    const PolylineT<V>& c = *members[m];
    if (c.paths() == 0) throw Error("member " + std::to_string(m + 1) + " of the group is empty");
    const std::size_t offset = out.points.size();
    append<V>(out.points, c.points, progress);
    for (std::size_t end : c.path_ends) out.path_ends.push_back(offset + end);
    member_of_path.insert(member_of_path.end(), c.paths(), static_cast<std::int32_t>(m + 1));
    cells[m] = c.cell_fields;
    if (!overrides.empty())
      for (const Field& f : overrides[m].list) cells[m].set(f);
    point_fields.push_back(&c.point_fields);
    cell_fields.push_back(&cells[m]);
    points.push_back(c.points.size());
    paths.push_back(c.paths());
  }
  out.point_fields = join_fields(point_fields, points, zero, {});
  out.cell_fields = join_fields(cell_fields, paths, zero, cell_defaults);
  out.cell_fields.erase("path");
  out.cell_fields.set(int_field("curve", std::move(member_of_path)));
  return out;
}

template <class V>
PolylineT<V> concat(std::span<const PolylineT<V>* const> parts, Progress& progress) {
  if (parts.empty()) throw Error("concat needs at least one curve");
  PolylineT<V> out;
  out.points.reserve(total_points(parts));
  BBox<V> box = parts.front()->bbox();
  for (const PolylineT<V>* c : parts) box.add(c->bbox());
  const double diagonal = norm(box.size());
  const double extent = std::isfinite(diagonal) ? diagonal : 0;  // an overflowing extent: exact meeting only
  std::vector<const Fields*> point_fields;
  std::vector<std::size_t> points, skip;
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const PolylineT<V>& c = *parts[p];
    if (c.paths() != 1)
      throw Error("argument " + std::to_string(p + 1) + " has " + std::to_string(c.paths()) +
                  " paths; concat joins single paths (group{} keeps several paths in one value)");
    const std::size_t first = !out.points.empty() && meets(out.points.back(), c.points.front(), extent) ? 1 : 0;
    append<V>(out.points, std::span<const V>(c.points).subspan(first), progress);
    point_fields.push_back(&c.point_fields);
    points.push_back(c.points.size());
    skip.push_back(first);
  }
  out.close_path();
  out.point_fields = join_fields(point_fields, points, skip, {});
  out.point_fields.erase("arclength");
  // One path: a cell field survives only where every part holds the same value.
  for (const Field& f : parts.front()->cell_fields.list) {
    const bool agreed = std::all_of(parts.begin(), parts.end(), [&](const PolylineT<V>* c) {
      const Field* g = c->cell_fields.find(f.name);
      if (g == nullptr || g->components != f.components || g->scalar() != f.scalar()) return false;
      for (int k = 0; k < f.components; ++k)
        if (g->at(0, k) != f.at(0, k)) return false;
      return true;
    });
    if (agreed) {
      Field one{f.name, f.components, f.data, true};
      std::visit([&](auto& v) { v.resize(static_cast<std::size_t>(f.components)); }, one.data);
      out.cell_fields.set(std::move(one));
    }
  }
  return out;
}

namespace {

// The tuples of f in reverse order (a uniform field is its own reverse).
Field reversed_field(const Field& f) {
  Field out = f;
  if (!f.uniform)
    std::visit(
        [&](auto& v) {
          const std::size_t k = static_cast<std::size_t>(f.components);
          const std::size_t n = v.size() / k;
          for (std::size_t i = 0; i < n / 2; ++i)
            std::swap_ranges(v.begin() + static_cast<std::ptrdiff_t>(i * k),
                             v.begin() + static_cast<std::ptrdiff_t>((i + 1) * k),
                             v.begin() + static_cast<std::ptrdiff_t>((n - 1 - i) * k));
        },
        out.data);
  return out;
}

}  // namespace

template <class V>
PolylineT<V> reversed(const PolylineT<V>& c) {
  PolylineT<V> out;
  out.points.assign(c.points.rbegin(), c.points.rend());
  std::size_t end = 0;
  for (std::size_t i = c.paths(); i-- > 0;) {
    end += c.path(i).size();
    out.path_ends.push_back(end);
  }
  for (const Field& f : c.point_fields.list)
    if (f.name != "arclength") out.point_fields.list.push_back(reversed_field(f));
  for (const Field& f : c.cell_fields.list) out.cell_fields.list.push_back(reversed_field(f));
  return out;
}

template Polyline group<Vec2>(std::span<const Polyline* const>, std::span<const Fields>, const Fields&, Progress&);
template Polyline3 group<Vec3>(std::span<const Polyline3* const>, std::span<const Fields>, const Fields&, Progress&);
template Polyline concat<Vec2>(std::span<const Polyline* const>, Progress&);
template Polyline3 concat<Vec3>(std::span<const Polyline3* const>, Progress&);
template Polyline reversed<Vec2>(const Polyline&);
template Polyline3 reversed<Vec3>(const Polyline3&);

}  // namespace selfsim
