#include "kernels/geom/field.h"

#include <algorithm>
#include <cmath>

#include "kernels/base/error.h"

namespace selfsim {

std::size_t Field::stored() const {
  const std::size_t n = std::visit([](const auto& v) { return v.size(); }, data);
  return components > 0 ? n / static_cast<std::size_t>(components) : 0;
}

double Field::at(std::size_t i, int c) const {
  const std::size_t k = (uniform ? 0 : i) * static_cast<std::size_t>(components) + static_cast<std::size_t>(c);
  return std::visit([k](const auto& v) { return static_cast<double>(v[k]); }, data);
}

std::size_t Field::bytes() const {
  return std::visit([](const auto& v) { return v.capacity() * sizeof(v[0]); }, data) + name.capacity();
}

Field int_field(std::string name, std::vector<std::int32_t> values, int components) {
  return Field{std::move(name), components, std::move(values)};
}

Field real_field(std::string name, std::vector<double> values, int components) {
  return Field{std::move(name), components, std::move(values)};
}

Field uniform_int(std::string name, std::int32_t value) {
  return Field{std::move(name), 1, std::vector<std::int32_t>{value}, true};
}

const Field* Fields::find(std::string_view name) const {
  for (const Field& f : list)
    if (f.name == name) return &f;
  return nullptr;
}

void Fields::set(Field f) {
  for (Field& g : list)
    if (g.name == f.name) {
      g = std::move(f);
      return;
    }
  list.push_back(std::move(f));
}

void Fields::erase(std::string_view name) {
  std::erase_if(list, [&](const Field& f) { return f.name == name; });
}

std::size_t Fields::bytes() const {
  std::size_t n = 0;
  for (const Field& f : list) n += f.bytes();
  return n;
}

void Fields::check(std::size_t count, const char* element) const {
  for (const Field& f : list) {
    const std::string what = std::string(element) + " field '" + f.name + "'";
    // Names go into XML attributes and file headers: letters, digits and underscores only.
    const bool plain = !f.name.empty() && f.name.size() <= 64 && std::all_of(f.name.begin(), f.name.end(), [](char c) {
      return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    });
    if (!plain) throw Error(what + ": a field name is 1 to 64 letters, digits or underscores");
    if (f.components < 1 || f.components > 3)
      throw Error(what + " has " + std::to_string(f.components) + " components, expected 1 to 3");
    const std::size_t want = f.uniform ? 1 : count;
    const std::size_t n = std::visit([](const auto& v) { return v.size(); }, f.data);
    if (n != want * static_cast<std::size_t>(f.components))
      throw Error(what + " has " + std::to_string(n) + " values, expected " + std::to_string(want) + " × " +
                  std::to_string(f.components));
    if (f.scalar() == Scalar::Float64)
      for (double v : f.reals())
        if (!std::isfinite(v)) throw Error(what + " has a non-finite value");
  }
}

namespace {

bool same_tuple(const Field& a, const Field& b) {
  for (int c = 0; c < a.components; ++c)
    if (a.at(0, c) != b.at(0, c)) return false;
  return true;
}

}  // namespace

Fields join_fields(std::span<const Fields* const> parts, std::span<const std::size_t> counts,
                   std::span<const std::size_t> skip, const Fields& defaults) {
  std::vector<std::string> names;  // every name any part has, in order of first appearance
  for (const Fields* part : parts)
    for (const Field& f : part->list)
      if (std::find(names.begin(), names.end(), f.name) == names.end()) names.push_back(f.name);
  Fields out;
  for (const std::string& name : names) {
    std::vector<const Field*> sources;
    for (const Fields* part : parts) {
      const Field* f = part->find(name);
      if (f == nullptr) f = defaults.find(name);
      const bool fits = f != nullptr && (sources.empty() || (f->components == sources.front()->components &&
                                                             f->scalar() == sources.front()->scalar()));
      if (!fits) {
        sources.clear();
        break;
      }
      sources.push_back(f);
    }
    if (sources.empty()) continue;
    const bool uniform = std::all_of(sources.begin(), sources.end(),
                                     [&](const Field* f) { return f->uniform && same_tuple(*f, *sources.front()); });
    Field joined{name, sources.front()->components, sources.front()->data, uniform};
    if (!uniform)
      std::visit(
          [&](auto& values) {
            values.clear();
            std::size_t total = 0;
            for (std::size_t p = 0; p < sources.size(); ++p) total += counts[p] - skip[p];
            values.reserve(total * static_cast<std::size_t>(joined.components));
            for (std::size_t p = 0; p < sources.size(); ++p)
              for (std::size_t e = skip[p]; e < counts[p]; ++e)
                for (int c = 0; c < joined.components; ++c)
                  values.push_back(static_cast<std::decay_t<decltype(values[0])>>(sources[p]->at(e, c)));
          },
          joined.data);
    out.list.push_back(std::move(joined));
  }
  return out;
}

}  // namespace selfsim
