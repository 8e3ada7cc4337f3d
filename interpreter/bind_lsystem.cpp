// lsystem{ axiom, rules, angle, angles, start_angle, shrink, draw, move } -> grammar with methods
// g:curve{ level, normalize }, g:string(level), g:count(level). A thin adapter over kernels/lsystem.
#include <cmath>
#include <string_view>

#include "interpreter/bindings.h"
#include "interpreter/curve_value.h"
#include "interpreter/growth.h"
#include "interpreter/lua_support.h"
#include "interpreter/options_reader.h"
#include "interpreter/run_context.h"
#include "kernels/geom/check.h"
#include "kernels/lsystem/production_count.h"
#include "kernels/lsystem/rewrite.h"
#include "kernels/lsystem/turtle2d.h"

namespace selfsim::interp {

namespace {

using lsystem::Grammar;
constexpr const char* grammar_type = "selfsim.Grammar";

char symbol_key(lua_State* L, int index, const char* table) {
  if (lua_type(L, index) != LUA_TSTRING || lua_rawlen(L, index) != 1 || lua_tostring(L, index)[0] == '\0')
    throw Error(std::string("option '") + table + "' keys must be single symbols, got " + describe(L, index));
  return lua_tostring(L, index)[0];
}

// Calls f(symbol) for each key of the table on top of the stack, in sorted order (so the first bad one
// reported is the same every run), with the value on top.
template <class F>
void each_symbol(lua_State* L, const char* table, F&& f) {
  if (lua_type(L, -1) != LUA_TTABLE)
    throw Error(std::string("option '") + table + "' must be a table, got " + describe(L, -1));
  const int n = push_sorted_keys(L, -1);
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, i);
    const char s = symbol_key(L, -1, table);
    lua_rawget(L, -3);
    f(s);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
}

Grammar read_grammar(lua_State* L, int index) {
  Options o(L, index);
  Grammar g;
  o.require("axiom", "the level-0 string, e.g. axiom = \"F\"");
  g.axiom = o.string("axiom", "");
  if (o.push("rules") != LUA_TNIL) {
    each_symbol(L, "rules",
                [&](char s) { g.rules[s] = text_value(L, -1, std::string("option 'rules': rule for '") + s + "'"); });
  }
  lua_pop(L, 1);
  g.angle = o.number("angle", g.angle);
  if (o.push("angles") != LUA_TNIL)
    each_symbol(L, "angles", [&](char s) {
      g.angles[s] = finite_number(L, -1, std::string("option 'angles' value for '") + s + "'");
    });
  lua_pop(L, 1);
  const int t = o.push("start_angle");
  if (t == LUA_TTABLE) {
    g.start_angles.clear();
    const lua_Integer n = list_length(L, -1, "option 'start_angle'");
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, -1, i);
      const double a = finite_number(L, -1, "option 'start_angle' entry " + std::to_string(i));
      lua_pop(L, 1);
      g.start_angles.push_back(a);
    }
  } else if (t != LUA_TNIL) {
    g.start_angles = {finite_number(L, -1, "option 'start_angle'")};
  }
  lua_pop(L, 1);
  g.shrink = o.number("shrink", g.shrink);
  g.draw = o.string("draw", g.draw);
  g.move = o.string("move", g.move);
  o.finish();
  g.validate();
  return g;
}

Held<Grammar> self(lua_State* L, const char* method) { return check_self<Grammar>(L, grammar_type, method); }

}  // namespace

Held<Grammar> test_grammar(lua_State* L, int index) { return test_value<Grammar>(L, index, grammar_type); }

namespace {

// The level argument of g:string(n) / g:count(n).
// A whole float (3.0, a level computed as n / 2) is accepted as the integer it is.
int level_argument(lua_State* L, int index) {
  const bool number = lua_type(L, index) == LUA_TNUMBER;
  const double v = number ? lua_tonumber(L, index) : 0;
  if (!lua_isinteger(L, index) && !(number && std::floor(v) == v && std::abs(v) < 1e18))
    throw Error("level must be an integer, got " + describe(L, index));
  const lua_Integer n = lua_isinteger(L, index) ? lua_tointeger(L, index) : static_cast<lua_Integer>(v);
  return static_cast<int>(check_range(n, 0, lsystem::max_level, "level"));
}

int grammar_curve(lua_State* L) {
  const Held<Grammar> held = self(L, "curve");
  const Grammar& g = *held;
  return call_kernel(L, "curve", [&] {
    RunContext& run = RunContext::of(L);
    lsystem::TurtleOptions opt;
    if (lua_type(L, 2) == LUA_TNUMBER) {
      opt.level = level_argument(L, 2);
    } else {
      Options o(L, 2);
      o.require("level", "the rewriting level: g:curve{ level = 10 } or g:curve(10)");
      opt.level = static_cast<int>(o.integer("level", 0, 0, lsystem::max_level));
      opt.normalize = o.boolean("normalize", opt.normalize);
      o.finish();
    }
    push_curve(L, with_budget(L, [&](const PointBudget& b) {
                 opt.budget = b;
                 return lsystem::turtle2d(g, opt, run);
               }));
    // Its levels are the grammar's curves at lower levels, drawn the same way.
    attach_growth(L, Growth{0, opt.level, "level", 0, [held, opt](int k, const PointBudget& b, Progress& p) {
                              lsystem::TurtleOptions at = opt;
                              at.level = k;
                              at.budget = b;
                              return GrownValue(lsystem::turtle2d(*held, at, p));
                            }});
    return 1;
  });
}

int grammar_string(lua_State* L) {
  const Held<Grammar> held = self(L, "string");
  const Grammar& g = *held;
  return call_kernel(L, "string", [&] {
    const std::string s = lsystem::expand_string(g, level_argument(L, 2), 1e7);
    lua_pushlstring(L, s.data(), s.size());
    return 1;
  });
}

int grammar_count(lua_State* L) {
  const Held<Grammar> held = self(L, "count");
  const Grammar& g = *held;
  return call_kernel(L, "count", [&] {
    const double n = lsystem::predict_counts(g, level_argument(L, 2), RunContext::of(L)).segments;
    if (n < 9e15)
      lua_pushinteger(L, static_cast<lua_Integer>(n));
    else
      lua_pushnumber(L, n);
    return 1;
  });
}

int grammar_tostring(lua_State* L) {
  const Held<Grammar> held = self(L, "tostring");
  const Grammar& g = *held;
  lua_pushfstring(L, "Grammar(axiom '%s', %d rules)", g.axiom.c_str(), static_cast<int>(g.rules.size()));
  return 1;
}

// ABOP's 3D turtle commands that the 2D turtle neither draws nor turns by, in the order first written: a
// 3D tree read by the 2D turtle would silently collapse, so the recipe is told once per grammar.
std::string ignored_3d_symbols(const Grammar& g) {
  std::string found;
  auto scan = [&](const std::string& text) {
    for (char c : text)
      if (std::string_view("&^\\/!{}'").find(c) != std::string_view::npos && !g.draws(c) && !g.moves(c) &&
          g.turn_of(c) == 0 && found.find(c) == std::string::npos)
        found += c;
  };
  scan(g.axiom);
  for (const auto& [symbol, rule] : g.rules) scan(rule);
  return found;
}

int make_lsystem(lua_State* L) {
  return call_kernel(L, "lsystem", [&] {
    Grammar g = read_grammar(L, 1);
    if (const std::string ignored = ignored_3d_symbols(g); !ignored.empty()) {
      std::string list;
      for (char c : ignored) list += std::string(list.empty() ? "'" : ", '") + c + "'";
      const std::string message = recipe_where(L) + "lsystem: the 2D turtle ignores the 3D turtle commands " + list +
                                  " (they still take part in rewriting)";
      lua_warning(L, message.c_str(), 0);
    }
    // A grammar's rules are recipe data held in C++ memory: they count against --max-memory like Lua's
    // own strings, so a recipe cannot hoard gigabytes of grammars.
    std::size_t bytes = sizeof(Grammar) + g.axiom.size() + g.draw.size() + g.move.size();
    for (const auto& [symbol, rule] : g.rules) bytes += rule.size() + 64;
    push_value(L, grammar_type, std::move(g), 0, bytes);
    return 1;
  });
}

}  // namespace

void open_lsystem(lua_State* L) {
  static const luaL_Reg methods[] = {
      {"curve", grammar_curve}, {"string", grammar_string}, {"count", grammar_count}, {nullptr, nullptr}};
  register_type<Grammar>(L, grammar_type, methods, grammar_tostring);
  lua_register(L, "lsystem", make_lsystem);
}

}  // namespace selfsim::interp
