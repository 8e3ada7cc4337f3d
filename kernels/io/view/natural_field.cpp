#include "kernels/io/view/natural_field.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "kernels/base/error.h"

namespace selfsim::io {
namespace {

bool is_class_field(const std::string& name) {
  return name == "tile_class" || name == "surface" || name == "curve" || name == "tile" || name == "color";
}

// Fills min, max and (for integer fields) distinct from values(i), i < count.
template <class Get>
void measure(FieldSummary& s, std::size_t count, Get values, Progress& progress = no_progress()) {
  std::set<int> seen;
  bool first = true;
  for (std::size_t i = 0; i < count; ++i) {
    if ((i & 0xfffff) == 0xfffff && progress.cancelled()) throw Cancelled();
    const double v = values(i);
    if (first || v < s.min) s.min = v;
    if (first || v > s.max) s.max = v;
    first = false;
    if (s.integer && seen.size() <= max_categories) seen.insert(static_cast<int>(v));
  }
  // Values that differ only by rounding (a tube's walls all read as the 1.2 mm cap) are one value: a colour
  // scale spread over 1e-15 would paint the noise.
  if (!first && s.max - s.min <= 1e-9 * std::max(std::abs(s.min), std::abs(s.max))) s.max = s.min;
  s.distinct.assign(seen.begin(), seen.end());
}

void add_fields(std::vector<FieldSummary>& out, const Fields& fields, std::size_t count, bool on_points,
                Progress& progress) {
  for (const Field& f : fields.list) {
    FieldSummary s{f.name, on_points, f.scalar() == Scalar::Int32, f.components, 0, 0, {}};
    if (f.components == 1)
      measure(
          s, f.uniform ? std::min<std::size_t>(count, 1) : count, [&](std::size_t i) { return f.at(i); }, progress);
    out.push_back(std::move(s));
  }
}

void add_values(std::vector<FieldSummary>& out, const std::map<std::string, FieldValues>& fields, bool on_points) {
  for (const auto& entry : fields) {  // not a structured binding: clang 14 cannot capture one in a lambda
    const FieldValues& f = entry.second;
    FieldSummary s{entry.first, on_points, true, f.components, 0, 0, {}};
    s.integer =
        std::all_of(f.values.begin(), f.values.end(), [](double v) { return std::abs(v) < 2e9 && v == std::floor(v); });
    if (f.components == 1) measure(s, f.values.size(), [&](std::size_t i) { return f.values[i]; });
    out.push_back(std::move(s));
  }
}

// The colouring by one field's summary; none for nullptr.
Colouring colouring_of(const FieldSummary* chosen) {
  Colouring c;
  if (!chosen) return c;
  c.field = chosen->name;
  c.on_points = chosen->on_points;
  c.min = chosen->min;
  c.max = chosen->max;
  c.categorical = chosen->integer && is_class_field(chosen->name) && chosen->distinct.size() <= max_categories;
  if (c.categorical) c.categories = chosen->distinct;
  return c;
}

}  // namespace

Colouring natural_colouring(std::span<const FieldSummary> fields) {
  auto pick = [&](const std::string& name, bool must_vary) -> const FieldSummary* {
    // Cell fields first: a face's class or level is what the picture shows.
    for (bool points : {false, true})
      for (const FieldSummary& f : fields)
        if (f.name == name && f.on_points == points && f.components == 1 && (!must_vary || f.max > f.min)) return &f;
    return nullptr;
  };
  const FieldSummary* chosen = nullptr;
  // A print check's copy shows its walls (print_check.h): that is what it was made for.
  // Then a grammar's own colours ('), a plant's branch depth, before the ids and arclength of each branch.
  for (const char* name :
       {"wall", "tile_class", "color", "branch_order", "surface", "curve", "level", "arclength", "t"})
    if ((chosen = pick(name, true))) break;
  if (!chosen)
    for (const FieldSummary& f : fields)
      if (f.components == 1 && f.max > f.min && f.name != "path") {
        chosen = &f;
        break;
      }
  return colouring_of(chosen);
}

Colouring named_colouring(std::span<const FieldSummary> fields, const std::string& name) {
  const FieldSummary* named = nullptr;
  for (bool points : {true, false})
    for (const FieldSummary& f : fields)
      if (!named && f.name == name && f.on_points == points) named = &f;
  if (!named) {
    std::set<std::string> names;
    for (const FieldSummary& f : fields) names.insert(f.name);
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw Error("--field: no field named '" + name + "'" +
                (names.empty() ? std::string("; it holds no fields") : "; it holds " + list));
  }
  if (named->components != 1)
    throw Error("--field: '" + name + "' has " + std::to_string(named->components) +
                " components; a picture is coloured by a field of one");
  return colouring_of(named);
}

std::vector<FieldSummary> summarise(const Fields& points, std::size_t point_count, const Fields& cells,
                                    std::size_t cell_count, Progress& progress) {
  std::vector<FieldSummary> out;
  add_fields(out, points, point_count, true, progress);
  add_fields(out, cells, cell_count, false, progress);
  return out;
}

std::vector<FieldSummary> summarise(const Dataset& d) {
  std::vector<FieldSummary> out;
  add_values(out, d.point_fields, true);
  add_values(out, d.cell_fields, false);
  return out;
}

std::vector<FieldSummary> summarise(const ValueRef& v, Progress& progress) {
  return std::visit(
      [&](const auto* value) {
        using T = std::decay_t<decltype(*value)>;
        if constexpr (std::is_same_v<T, Mesh>) {
          return summarise(value->point_fields, value->points.size(), value->face_fields, value->faces(), progress);
        } else {
          std::vector<FieldSummary> out =
              summarise(value->point_fields, value->points.size(), value->cell_fields, value->paths(), progress);
          if (!value->point_fields.find("arclength")) {
            double longest = 0;
            for (std::size_t p = 0; p < value->paths(); ++p) {
              double length = 0;
              const auto path = value->path(p);
              for (std::size_t i = 1; i < path.size(); ++i) {
                if ((i & 0xfffff) == 0xfffff && progress.cancelled()) throw Cancelled();
                length += norm(path[i] - path[i - 1]);
              }
              longest = std::max(longest, length);
            }
            out.push_back(FieldSummary{"arclength", true, false, 1, 0, longest, {}});
          }
          return out;
        }
      },
      v);
}

namespace {

// c's range and categories widened to those of the same field in every one of `steps` (summarised by
// `summary`), so that the colours mean the same at every step.
template <class Step, class Summary>
void widen(Colouring& c, std::span<const Step> steps, Summary summary) {
  if (c.field.empty()) return;
  std::set<int> categories(c.categories.begin(), c.categories.end());
  for (const Step& step : steps)
    for (const FieldSummary& f : summary(step))
      if (f.name == c.field && f.on_points == c.on_points && f.components == 1) {
        c.min = std::min(c.min, f.min);
        c.max = std::max(c.max, f.max);
        categories.insert(f.distinct.begin(), f.distinct.end());
      }
  if (c.categorical) {
    if (categories.size() > max_categories) c.categorical = false;
    c.categories.assign(categories.begin(), categories.end());
    if (!c.categorical) c.categories.clear();
  }
}

}  // namespace

Colouring series_colouring(std::span<const ValueRef> steps, Progress& progress) {
  if (steps.empty()) return {};
  Colouring c = natural_colouring(summarise(steps.back(), progress));
  widen(c, steps, [&](const ValueRef& v) { return summarise(v, progress); });
  return c;
}

Colouring steps_colouring(std::span<const Dataset> steps, const std::string& name) {
  if (steps.empty()) return {};
  const std::vector<FieldSummary> last = summarise(steps.back());
  if (name.empty()) {
    Colouring c = natural_colouring(last);
    widen(c, steps, [](const Dataset& d) { return summarise(d); });
    return c;
  }
  // --field names a field of the series: the last step that holds it decides (a growth may gain or lose a
  // field on the way; the steps without it are drawn plain). No step holding it: the error lists the
  // fields of every step, not only the last's ("it holds no fields" of a series whose first step held it).
  std::vector<FieldSummary> every;
  for (std::size_t k = steps.size(); k-- > 0;) {
    std::vector<FieldSummary> step = k + 1 == steps.size() ? last : summarise(steps[k]);
    if (std::any_of(step.begin(), step.end(), [&](const FieldSummary& f) { return f.name == name; })) {
      Colouring c = named_colouring(step, name);
      widen(c, steps, [](const Dataset& d) { return summarise(d); });
      return c;
    }
    every.insert(every.end(), std::make_move_iterator(step.begin()), std::make_move_iterator(step.end()));
  }
  return named_colouring(every, name);  // throws: no step holds it
}

Rgb category_colour(int value, std::size_t rank, bool by_value) {
  return class_colour(by_value ? static_cast<std::size_t>(std::abs(static_cast<long long>(value))) : rank);
}

Colouring summaries_colouring(std::span<const std::vector<FieldSummary>> steps) {
  if (steps.empty()) return {};
  Colouring c = natural_colouring(steps.back());
  widen(c, steps, [](const std::vector<FieldSummary>& summary) -> const std::vector<FieldSummary>& { return summary; });
  return c;
}

}  // namespace selfsim::io
