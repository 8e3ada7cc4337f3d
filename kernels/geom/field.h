// Named fields: arrays of int32 or float64 tuples (1 to 3 components) on the points or cells of a value.
// A kernel attaches what it knows (level, arclength, path, parent, generation, curve, tile_class,
// thickness, ...) and every writer writes whatever is there under its name, so a new field needs no
// writer change. A uniform field stores one tuple for all points or cells (a curve's level): no memory
// in proportion to the curve for a constant.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "kernels/base/progress.h"

namespace selfsim {

enum class Scalar { Int32, Float64 };

struct Field {
  std::string name;
  int components = 1;                                                 // 1, 2 or 3
  std::variant<std::vector<std::int32_t>, std::vector<double>> data;  // tuple after tuple
  bool uniform = false;                                               // one tuple stands for every element

  Scalar scalar() const { return data.index() == 0 ? Scalar::Int32 : Scalar::Float64; }
  // Number of tuples stored (1 for a uniform field).
  std::size_t stored() const;
  // Component c of tuple i of a field on `count` elements, as a double.
  double at(std::size_t i, int c = 0) const;
  std::span<const std::int32_t> ints() const { return std::get<0>(data); }
  std::span<const double> reals() const { return std::get<1>(data); }
  std::size_t bytes() const;
};

Field int_field(std::string name, std::vector<std::int32_t> values, int components = 1);
Field real_field(std::string name, std::vector<double> values, int components = 1);
// One value for every element.
Field uniform_int(std::string name, std::int32_t value);

// The fields on one kind of element (points, or cells), in the order they were attached.
struct Fields {
  std::vector<Field> list;

  const Field* find(std::string_view name) const;
  // Attaches f, replacing a field of the same name.
  void set(Field f);
  // Removes the field of that name, if there is one.
  void erase(std::string_view name);
  bool empty() const { return list.empty(); }
  std::size_t bytes() const;
  // Throws Error naming the first field (on `element`s: "point", "cell") with a bad name, component count
  // or size for `count` elements, or a non-finite value.
  void check(std::size_t count, const char* element) const;
};

// The fields of elements joined from several parts, part p contributing its elements [skip[p], counts[p]) in
// order. A field is kept when every part has it, or `defaults` holds one for the parts that lack it, with one
// type and component count throughout; it stays uniform when every part's tuple is the same single one.
Fields join_fields(std::span<const Fields* const> parts, std::span<const std::size_t> counts,
                   std::span<const std::size_t> skip, const Fields& defaults);

// The fields of elements picked from others: element k of the result takes the tuples of element source[k]
// (a simplified curve's kept points, a thickened mesh's two sheets); uniform fields stay as they are. Looks
// for a stop every 2^20 elements.
template <class Index>
Fields picked_fields(const Fields& fields, std::span<const Index> source, Progress& progress = no_progress()) {
  Fields out;
  for (const Field& f : fields.list) {
    if (f.uniform) {
      out.list.push_back(f);
      continue;
    }
    Field g{f.name, f.components, {}, false};
    std::visit(
        [&](const auto& values) {
          const auto k = static_cast<std::size_t>(f.components);
          std::remove_cvref_t<decltype(values)> picked;
          picked.reserve(source.size() * k);
          for (std::size_t j = 0; j < source.size(); ++j) {
            if ((j & 0xfffff) == 0xfffff && progress.cancelled()) throw Cancelled();
            const Index s = source[j];
            picked.insert(picked.end(), values.begin() + static_cast<std::ptrdiff_t>(s * k),
                          values.begin() + static_cast<std::ptrdiff_t>((s + 1) * k));
          }
          g.data = std::move(picked);
        },
        f.data);
    out.list.push_back(std::move(g));
  }
  return out;
}

}  // namespace selfsim
