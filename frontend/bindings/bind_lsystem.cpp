// lsystem{ axiom, rules, angle, angles, start_angle, shrink, draw, move } -> grammar with methods
// g:curve{ level, normalize }, g:string(level), g:count(level). A thin adapter over kernels/lsystem.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string_view>

#include "frontend/bindings/bindings.h"
#include "frontend/bindings/lsystem_rules.h"
#include "frontend/bindings/lsystem_value.h"
#include "frontend/lua/curve_value.h"
#include "frontend/lua/growth.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "kernels/base/check.h"
#include "kernels/lsystem/module_checks.h"
#include "kernels/lsystem/module_rewrite.h"
#include "kernels/lsystem/production_count.h"
#include "kernels/lsystem/rewrite.h"
#include "kernels/lsystem/turtle/module_turtle.h"
#include "kernels/lsystem/turtle/turtle2d.h"

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

// The symbols of `among` that g writes without giving them another role (draw, move, a turn of its own), in
// the order first written.
std::string turtle_symbols(const Grammar& g, std::string_view among) {
  std::string found;
  auto see = [&](char c) {
    if (among.find(c) != std::string_view::npos && !g.draws(c) && !g.moves(c) && g.turn_of(c) == 0 &&
        found.find(c) == std::string::npos)
      found += c;
  };
  if (g.modules())  // the modules, not the text: "F(1/2)" holds no roll
    for (const lsystem::Call& c : g.start) see(static_cast<char>(c.symbol));
  else
    for (char c : g.axiom) see(c);
  for (const auto& [symbol, rule] : g.rules)
    for (char c : rule) see(c);
  for (const auto* rules : {&g.productions, &g.decomposition, &g.interpretation})
    for (const lsystem::Production& p : *rules)
      for (const lsystem::Successor& o : p.options)
        for (const lsystem::Call& c : o.modules) see(static_cast<char>(c.symbol));
  return found;
}

// define = { r1 = 0.9, a0 = 45 }: names every expression of the rules and axiom may read.
void read_constants(lua_State* L, Grammar& g) {
  if (lua_type(L, -1) != LUA_TTABLE)
    throw Error("option 'define' must be a table of names and numbers, e.g. { r1 = 0.9 }, got " + describe(L, -1));
  const int n = push_sorted_keys(L, -1);
  if (static_cast<std::size_t>(n) > lsystem::max_constants)
    throw Error("option 'define' holds " + std::to_string(n) + " names, over the limit of " +
                std::to_string(lsystem::max_constants));
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, i);
    const std::string name = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
    const bool word = !name.empty() && !std::isdigit(static_cast<unsigned char>(name[0])) &&
                      std::all_of(name.begin(), name.end(),
                                  [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
    if (!word) throw Error("option 'define' names must be words (letters, digits, _), got " + describe(L, -1));
    lua_rawget(L, -3);
    g.constants.emplace_back(name, finite_number(L, -1, "option 'define' value for '" + name + "'"));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
}

Grammar read_grammar(lua_State* L, int index) {
  Options o(L, index);
  Grammar g;
  o.require("axiom", "the level-0 string, e.g. axiom = \"F\"");
  g.axiom = o.string("axiom", "");
  if (o.push("define") != LUA_TNIL) read_constants(L, g);
  lua_pop(L, 1);
  o.push("rules");
  read_rules(L, lua_gettop(L), g);
  lua_pop(L, 1);
  // Decomposition and interpretation rules make a module grammar of any grammar.
  for (auto [name, rules] :
       {std::pair{"decomposition", &g.decomposition}, std::pair{"interpretation", &g.interpretation}}) {
    o.push(name);
    *rules = read_rule_set(L, lua_gettop(L), g, name);
    lua_pop(L, 1);
  }
  g.max_depth = static_cast<int>(o.integer("max_depth", g.max_depth, 0, lsystem::max_rule_depth));
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
    // An empty list would read as "not given" (the turtle's default): refused, not guessed.
    if (n == 0) throw Error("option 'start_angle' must be a number or a non-empty list of numbers, got {}");
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
  // Context matching skips the turtle's turns: ABOP's, and any symbol given its own angle.
  std::string ignore = g.ignore;
  for (const auto& [symbol, degrees] : g.angles)
    if (ignore.find(symbol) == std::string::npos) ignore += symbol;
  g.ignore = o.string("ignore", ignore);
  g.seed = static_cast<std::uint64_t>(o.integer("seed", RunContext::of(L).config.seed, 0, (1LL << 53)));
  g.dimension = static_cast<int>(o.integer("dimension", 0, 2, 3));  // absent: 0, chosen by the symbols
  if (const std::optional<Vec3> t = o.point3("tropism")) g.tropism = *t;
  // The book's "derivation length": the level drawn when a call gives none.
  g.level = static_cast<int>(o.integer("level", -1, 0, lsystem::max_level));
  o.finish();
  // The byte turtle draws plain grammars in 2D; the module turtle also turns in 3D, keeps widths and
  // colours, and fills polygons.
  if (!g.modules() && (g.dimension == 3 || g.tropism != Vec3{} || !turtle_symbols(g, "&^\\/$!'{}").empty() ||
                       !g.decomposition.empty() || !g.interpretation.empty()))
    to_modules(g);
  g.validate();
  return g;
}

Held<Grammar> self(lua_State* L, const char* method) { return check_self<Grammar>(L, grammar_type, method); }

}  // namespace

Held<Grammar> test_grammar(lua_State* L, int index) { return test_value<Grammar>(L, index, grammar_type); }

namespace {

// The level argument of g:string(n) / g:count(n).
// A whole float (3.0, a level computed as n / 2) is accepted as the integer it is.
int level_argument(lua_State* L, int index, const Grammar& g) {
  if (lua_isnoneornil(L, index) && g.level >= 0) return g.level;  // the grammar's own (derivation length)
  const bool number = lua_type(L, index) == LUA_TNUMBER;
  const double v = number ? lua_tonumber(L, index) : 0;
  if (!lua_isinteger(L, index) && !(number && std::floor(v) == v && std::abs(v) < 1e18))
    throw Error("level must be an integer, got " + describe(L, index));
  const lua_Integer n = lua_isinteger(L, index) ? lua_tointeger(L, index) : static_cast<lua_Integer>(v);
  return static_cast<int>(check_range(n, 0, lsystem::max_level, "level"));
}

// g:curve{ level, normalize } or g:curve(level).
lsystem::TurtleOptions turtle_options(lua_State* L, const char* method, const Grammar& g) {
  lsystem::TurtleOptions opt;
  if (lua_type(L, 2) == LUA_TNUMBER || (lua_isnoneornil(L, 2) && g.level >= 0)) {
    opt.level = level_argument(L, 2, g);
  } else {
    Options o(L, 2);
    if (g.level < 0)
      o.require("level", std::string("the rewriting level: g:") + method + "{ level = 10 } or g:" + method + "(10)");
    opt.level = static_cast<int>(o.integer("level", std::max(g.level, 0), 0, lsystem::max_level));
    if (o.has("normalize")) opt.normalize = o.boolean("normalize", true);  // not given: the grammar decides
    o.finish();
  }
  return opt;
}

// The curve of a grammar at a level: 2D or 3D, by the byte kernel or the module turtle.
GrownValue draw(const Grammar& g, const lsystem::TurtleOptions& opt, Progress& progress) {
  if (!g.modules()) return lsystem::turtle2d(g, opt, progress);
  if (lsystem::draws_in_3d(g)) return lsystem::module_turtle3d(g, opt, progress);
  return lsystem::module_turtle2d(g, opt, progress);
}

int grammar_curve(lua_State* L) {
  const Held<Grammar> held = self(L, "curve");
  const Grammar& g = *held;
  return call_kernel(L, "curve", [&] {
    RunContext& run = RunContext::of(L);
    lsystem::TurtleOptions opt = turtle_options(L, "curve", g);
    GrownValue drawn = with_budget(L, [&](const PointBudget& b) {
      opt.budget = b;
      return draw(g, opt, run);
    });
    if (auto* c = std::get_if<Polyline>(&drawn))
      push_curve(L, std::move(*c));
    else
      push_geometry(L, std::move(std::get<Polyline3>(drawn)));
    // Its levels are the grammar's curves at lower levels, drawn the same way.
    attach_growth(L, Growth{0, opt.level, "level", 0, [held, opt](int k, const PointBudget& b, Progress& p) {
                              lsystem::TurtleOptions at = opt;
                              at.level = k;
                              at.budget = b;
                              return draw(*held, at, p);
                            }});
    return 1;
  });
}

// g:polygons{ level, normalize }: the { . } polygons as a mesh, placed as the 3D curve.
int grammar_polygons(lua_State* L) {
  const Held<Grammar> held = self(L, "polygons");
  const Grammar& g = *held;
  return call_kernel(L, "polygons", [&] {
    if (!g.modules())
      throw Error(
          "this grammar writes no polygons: '{', '.' and '}' make them in a grammar with parameters, "
          "contexts or choices (or write its rules as ABOP strings, rules = { \"F -> ...\" })");
    lsystem::TurtleOptions opt = turtle_options(L, "polygons", g);
    push_geometry(L, with_budget(L, [&](const PointBudget& b) {
                    opt.budget = b;
                    return lsystem::module_polygons(g, opt, RunContext::of(L));
                  }));
    return 1;
  });
}

int grammar_string(lua_State* L) {
  const Held<Grammar> held = self(L, "string");
  const Grammar& g = *held;
  return call_kernel(L, "string", [&] {
    const int level = level_argument(L, 2, g);
    const std::string s = g.modules() ? lsystem::module_string_text(g, level, 1e7, RunContext::of(L))
                                      : lsystem::expand_string(g, level, 1e7);
    lua_pushlstring(L, s.data(), s.size());
    return 1;
  });
}

int grammar_count(lua_State* L) {
  const Held<Grammar> held = self(L, "count");
  const Grammar& g = *held;
  return call_kernel(L, "count", [&] {
    const int level = level_argument(L, 2, g);
    RunContext& run = RunContext::of(L);
    const double n = g.modules() ? lsystem::module_segments(g, level, run.budget().left(), run)
                                 : lsystem::predict_counts(g, level, run).segments;
    if (!std::isfinite(n))
      throw Error("level " + std::to_string(level) + " has more segments than a number can hold (over 1e308)");
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
  const std::size_t rules = g.modules() ? g.productions.size() : g.rules.size();
  lua_pushfstring(L, "Grammar(axiom '%s', %d rules)", g.axiom.c_str(), static_cast<int>(rules));
  return 1;
}

}  // namespace

int push_lsystem(lua_State* L, int index) {
  Grammar g = read_grammar(L, index);
  // A 3D tree drawn by the 2D turtle (dimension = 2) would silently collapse: said once per grammar.
  const std::string ignored = lsystem::draws_in_3d(g) ? "" : turtle_symbols(g, g.modules() ? "&^\\/$" : "&^\\/$!'{}");
  if (!ignored.empty()) {
    std::string list;
    for (char c : ignored) list += std::string(list.empty() ? "'" : ", '") + c + "'";
    const std::string message = recipe_where(L) + "lsystem: the 2D turtle ignores the 3D turtle commands " + list +
                                " (they still take part in rewriting)";
    lua_warning(L, message.c_str(), 0);
  }
  for (const std::string& w : lsystem::context_warnings(g)) {
    const std::string message = recipe_where(L) + "lsystem: " + w;
    lua_warning(L, message.c_str(), 0);
  }
  // A grammar's rules are recipe data held in C++ memory: they count against --max-memory like Lua's
  // own strings, so a recipe cannot hoard gigabytes of grammars.
  std::size_t bytes = sizeof(Grammar) + g.axiom.size() + g.draw.size() + g.move.size();
  for (const auto& [symbol, rule] : g.rules) bytes += rule.size() + 64;
  for (const lsystem::Production& p : g.productions) {
    bytes += sizeof(p) + 2 * p.text.size() + p.where.size();
    for (const lsystem::Successor& o : p.options) bytes += 64 * (o.modules.size() + 1);
  }
  bytes += 64 * g.start.size();
  push_value(L, grammar_type, std::move(g), 0, bytes);
  return 1;
}

namespace {

int make_lsystem(lua_State* L) {
  return call_kernel(L, "lsystem", [&] { return push_lsystem(L, 1); });
}

}  // namespace

void open_lsystem(lua_State* L) {
  register_type<Grammar>(
      L, grammar_type,
      {{"curve", grammar_curve, 1, "one argument: a level, or a table: g:curve{ level = 5, normalize = false }"},
       {"polygons", grammar_polygons, 1,
        "one argument: a level, or a table: g:polygons{ level = 5, normalize = false }"},
       {"string", grammar_string, 1, "one argument: the level, g:string(5)"},
       {"count", grammar_count, 1, "one argument: the level, g:count(5)"}},
      grammar_tostring);
  // lsystem{...} makes a grammar; lsystem.book and lsystem.load read the book's notation and cpfg's files.
  const luaL_Reg functions[] = {{"book", lsystem_book}, {"load", lsystem_load}, {nullptr, nullptr}};
  luaL_newlib(L, functions);
  lua_newtable(L);
  lua_pushcfunction(L, [](lua_State* S) {
    lua_remove(S, 1);  // the lsystem table itself
    return make_lsystem(S);
  });
  lua_setfield(L, -2, "__call");
  lua_setmetatable(L, -2);
  lua_setglobal(L, "lsystem");
}

}  // namespace selfsim::interp
