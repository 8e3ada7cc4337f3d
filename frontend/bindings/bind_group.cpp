// group{ a, b, { c, stroke = "red" } }, concat(a, b, ...) and c:reverse(): curves joined into one value, or
// walked backwards. A thin adapter over kernels/geom/curve_join.h.
#include <algorithm>
#include <variant>

#include "frontend/bindings/bindings.h"
#include "frontend/bindings/style_reader.h"
#include "frontend/lua/curve_value.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "kernels/base/check.h"
#include "kernels/geom/curve_join.h"
#include "kernels/io/save.h"
#include "kernels/io/text/colour.h"

namespace selfsim::interp {

namespace {

using AnyCurve = std::variant<Held<Polyline>, Held<Polyline3>>;

std::optional<AnyCurve> test_any_curve(lua_State* L, int index) {
  if (Held<Polyline> c = test_curve(L, index)) return c;
  if (Held<Polyline3> c = test_geometry<Polyline3>(L, index)) return c;
  return std::nullopt;
}

Field uniform_real(const char* name, std::vector<double> tuple) {
  const int components = static_cast<int>(tuple.size());
  return Field{name, components, std::move(tuple), true};
}

Field rgb_field(const char* name, const std::string& colour) {
  if (colour == "none") return uniform_real(name, {-1, -1, -1});
  const io::Rgb c = *io::colour_rgb(colour);  // read_style accepted only colours
  return uniform_real(name, {c[0], c[1], c[2]});
}

// A member's SVG style as the cell fields the writer reads (kernels/io/svg/curve_style.h).
Fields style_fields(const StyleOptions& s) {
  Fields f;
  if (!s.stroke.empty()) f.set(rgb_field("color", s.stroke[0]));
  if (!s.stroke_width.empty()) {
    if (!(s.stroke_width[0] > 0 && s.stroke_width[0] < 1e6))
      throw Error("option 'stroke_width' must be a positive number below 1000000, got " +
                  number_text(s.stroke_width[0]));
    f.set(uniform_real("width", {s.stroke_width[0]}));
  }
  if (!s.fill.empty()) f.set(rgb_field("fill", s.fill[0]));
  return f;
}

// What members without a style of their own are drawn with: save()'s defaults.
Fields style_defaults() {
  const io::SaveOptions d;
  Fields f;
  f.set(rgb_field("color", d.stroke[0]));
  f.set(uniform_real("width", {d.stroke_width[0]}));
  f.set(rgb_field("fill", "none"));
  return f;
}

struct Members {
  std::vector<AnyCurve> curves;
  std::vector<Fields> styles;
};

// Entry i (on top of the stack): a curve, or { curve, stroke = ..., stroke_width = ..., fill = ... }. The
// list is at `list`, with n entries; `into` names it in messages.
void read_member(lua_State* L, lua_Integer i, Members& m, int list, lua_Integer n, const std::string& into) {
  const std::string what = "member " + std::to_string(i) + " of the group";
  if (auto c = test_any_curve(L, -1)) {
    m.curves.push_back(*c);
    m.styles.emplace_back();
    return;
  }
  if (lua_type(L, -1) == LUA_TTABLE) {
    lua_rawgeti(L, -1, 1);
    auto c = test_any_curve(L, -1);
    lua_pop(L, 1);
    if (c) {
      try {
        Options o(L, -1);
        o.positional(1);
        const StyleOptions style = read_style(L, o, false);
        o.finish();
        m.styles.push_back(style_fields(style));
      } catch (const Error& e) {
        throw Error(what + ": " + e.what());
      }
      m.curves.push_back(*c);
      return;
    }
  }
  // The last entry, a table of named entries after a value: the second result of a call, spread.
  if (i == n && i > 1) {
    lua_rawgeti(L, list, i - 1);
    const std::string advice = spread_report_advice(L, -2, -1, into);
    lua_pop(L, 1);
    if (!advice.empty()) throw Error("member " + std::to_string(i) + " is a table " + advice);
  }
  throw Error(what + " must be a curve, or { curve, stroke = ..., stroke_width = ..., fill = ... }, got " +
              describe(L, -1));
}

template <class V>
PolylineT<V> group_of(const Members& m, Progress& progress) {
  const Fields defaults = style_defaults();
  std::vector<const PolylineT<V>*> curves;
  for (std::size_t i = 0; i < m.curves.size(); ++i) {
    const std::string what = "member " + std::to_string(i + 1) + " of the group";
    const auto* held = std::get_if<Held<PolylineT<V>>>(&m.curves[i]);
    if (held == nullptr)
      throw Error(what + " is a " + (sizeof(V) == sizeof(Vec2) ? "3D" : "2D") +
                  " curve and member 1 is not: a group is all 2D or all 3D");
    // A field of a style's name but another shape (from a loaded file) would silently drop every member's
    // style of that name when the fields are joined.
    for (const Field& d : defaults.list) {
      const bool styled =
          std::any_of(m.styles.begin(), m.styles.end(), [&](const Fields& s) { return s.find(d.name) != nullptr; });
      const Field* f = (*held)->cell_fields.find(d.name);
      if (styled && f != nullptr && m.styles[i].find(d.name) == nullptr &&
          (f->components != d.components || f->scalar() != d.scalar()))
        throw Error(what + " has a cell field '" + d.name + "' that is not a style (" + std::to_string(d.components) +
                    " float components): give the member its own, { curve, " +
                    (d.name == "color"   ? "stroke"
                     : d.name == "width" ? "stroke_width"
                                         : "fill") +
                    " = ... }");
    }
    curves.push_back(held->get());
  }
  return group<V>(curves, m.styles, defaults, progress);
}

}  // namespace

void push_group(lua_State* L, int index, const char* into) {
  index = lua_absindex(L, index);
  if (lua_type(L, index) != LUA_TTABLE) throw Error("expected a list of curves, got " + describe(L, index));
  const lua_Integer n =
      list_length(L, index, "a group", " (style a member as { curve, stroke = ... }, or give save() a palette)");
  if (n == 0) throw Error("a group needs at least one curve");
  check_run_budget(L, static_cast<double>(n), "group");
  Members m;
  double points = 0;
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, index, i);
    read_member(L, i, m, index, n, into);
    lua_pop(L, 1);
    points += std::visit([](const auto& c) { return static_cast<double>(c->points.size()); }, m.curves.back());
  }
  check_run_budget(L, points, "group");
  RunContext& run = RunContext::of(L);
  if (std::holds_alternative<Held<Polyline>>(m.curves.front()))
    push_geometry(L, group_of<Vec2>(m, run));
  else
    push_geometry(L, group_of<Vec3>(m, run));
}

namespace {

int make_group(lua_State* L) {
  return call_kernel(L, "group", [&] {
    if (lua_gettop(L) != 1)
      throw Error("takes one list of curves, group{ a, b, ... }, got " + std::to_string(lua_gettop(L)) + " arguments");
    push_group(L, 1);
    return 1;
  });
}

template <class V>
int push_concat(lua_State* L, const std::vector<Held<PolylineT<V>>>& held) {
  std::vector<const PolylineT<V>*> parts;
  double points = 0;
  for (const auto& h : held) {
    parts.push_back(h.get());
    points += static_cast<double>(h->points.size());
  }
  check_run_budget(L, points, "concat");
  PolylineT<V> joined = concat<V>(parts, RunContext::of(L));
  if (joined.points.size() < 2) throw Error("the joined curve has a single point (a curve needs at least 2)");
  push_geometry(L, std::move(joined));
  return 1;
}

// concat(a, b, ...): 2D curves (or tables of {x, y}) or 3D curves, each a single path.
int make_concat(lua_State* L) {
  return call_kernel(L, "concat", [&] {
    const int n = lua_gettop(L);
    if (n == 0) throw Error("needs at least one curve");
    if (test_geometry<Polyline3>(L, 1)) {
      std::vector<Held<Polyline3>> held;
      for (int i = 1; i <= n; ++i) {
        held.push_back(test_geometry<Polyline3>(L, i));
        if (!held.back()) throw Error("argument " + std::to_string(i) + " must be a 3D curve, as argument 1 is");
      }
      return push_concat<Vec3>(L, held);
    }
    std::vector<Held<Polyline>> held;
    for (int i = 1; i <= n; ++i) {
      if (i == n && i > 1)
        if (const std::string advice = spread_report_advice(L, i, i - 1, "concat(...)"); !advice.empty())
          throw Error("argument " + std::to_string(i) + " is a table " + advice);
      held.push_back(held_curve(L, i, "argument " + std::to_string(i)));
    }
    return push_concat<Vec2>(L, held);
  });
}

}  // namespace

template <class V>
int curve_reverse(lua_State* L) {
  const Held<PolylineT<V>> c = geometry_self<PolylineT<V>>(L, "reverse");
  return call_kernel(L, "reverse", [&] {
    check_run_budget(L, static_cast<double>(c->points.size()), "reverse");
    push_geometry(L, reversed(*c));
    return 1;
  });
}
template int curve_reverse<Vec2>(lua_State*);
template int curve_reverse<Vec3>(lua_State*);

void open_group(lua_State* L) {
  lua_register(L, "group", make_group);
  lua_register(L, "concat", make_concat);
}

}  // namespace selfsim::interp
