#include "frontend/bindings/style_reader.h"

#include "kernels/base/lower_case.h"
#include "kernels/io/text/colour.h"

namespace selfsim::interp {

namespace {

std::string colour(lua_State* L, const std::string& what) {
  const std::string expected = " must be a CSS colour name, #rgb, #rrggbb or 'none'";
  if (lua_type(L, -1) != LUA_TSTRING) throw Error(what + expected + ", got " + describe(L, -1));
  const std::string value = text_value(L, -1, what);
  if (lower_case(value) == "none") return "none";
  if (io::is_colour(value)) return value;
  if (const std::string near = suggestion(lower_case(value), io::colour_names()); !near.empty())
    throw Error(what + ": unknown colour '" + shown_text(value) + "' (did you mean '" + near + "'?)");
  throw Error(what + expected + ", got '" + shown_text(value) + "'");
}

// The value at key read by `one` from the top of the stack, or, when palette is allowed, each entry of a
// list of such values.
template <class T, class Read>
std::vector<T> one_or_list(lua_State* L, Options& o, const char* key, bool palette, Read one) {
  std::vector<T> out;
  const std::string what = std::string("option '") + key + "'";
  const int type = o.push(key);
  if (type == LUA_TTABLE && palette) {
    const lua_Integer n = list_length(L, -1, what);
    if (n == 0) throw Error(what + " is an empty list (give one value, or a list of values cycled over the curves)");
    check_run_budget(L, static_cast<double>(n), what);
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, -1, i);
      out.push_back(one(what + " entry " + std::to_string(i)));
      lua_pop(L, 1);
    }
  } else if (type == LUA_TTABLE) {
    throw Error(what + " must be one value here (a list of values, a palette, is for save())");
  } else if (type != LUA_TNIL) {
    out.push_back(one(what));
  }
  lua_pop(L, 1);
  return out;
}

}  // namespace

StyleOptions read_style(lua_State* L, Options& o, bool palette) {
  StyleOptions s;
  s.stroke = one_or_list<std::string>(L, o, "stroke", palette, [&](const std::string& w) { return colour(L, w); });
  s.stroke_width =
      one_or_list<double>(L, o, "stroke_width", palette, [&](const std::string& w) { return finite_number(L, -1, w); });
  s.fill = one_or_list<std::string>(L, o, "fill", palette, [&](const std::string& w) { return colour(L, w); });
  return s;
}

}  // namespace selfsim::interp
