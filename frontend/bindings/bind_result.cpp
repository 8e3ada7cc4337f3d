// result(name, value): a number the recipe hands back, recorded for the run (results.json beside its
// outputs, run_command.cpp) and gathered by a sweep into results.csv and its plots (sweep_results.cpp).
#include <cmath>

#include "frontend/bindings/bindings.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "kernels/io/run_results.h"
#include "kernels/io/text/json_text.h"

namespace selfsim::interp {

namespace {

// "recipe.lua:3" from "recipe.lua:3: ".
std::string place(const std::string& where) { return where.substr(0, where.size() - 2); }

// Returns the value, so `local d = result("dimension", fit.dimension)` reads on.
int result(lua_State* L) {
  return call_kernel(L, "result", [&] {
    RunContext& run = RunContext::of(L);
    if (lua_type(L, 1) != LUA_TSTRING)
      throw Error("argument 1 (the result's name) must be a string, got " + describe(L, 1));
    const std::string name = text_value(L, 1, "argument 1 (the result's name)");
    if (const std::string problem = io::result_name_problem(name); !problem.empty())
      throw Error("the result name '" + shown_text(name) + "' " + problem);
    if (lua_gettop(L) > 2)
      throw Error("takes two arguments: result(name, number), got " + std::to_string(lua_gettop(L)) + " arguments");
    if (lua_type(L, 2) != LUA_TNUMBER)
      throw Error("the value of '" + name + "' must be a number, got " + describe(L, 2));
    const double value = lua_tonumber(L, 2);
    if (!std::isfinite(value)) throw Error("the value of '" + name + "' must be finite, got " + describe(L, 2));
    // An integer a double cannot hold exactly (beyond 2^53) would be written as another number.
    if (lua_isinteger(L, 2) &&
        (value >= 9223372036854775808.0 || static_cast<lua_Integer>(value) != lua_tointeger(L, 2)))
      throw Error("the value of '" + name + "', " + describe(L, 2) +
                  ", is a whole number beyond 2^53 that the results table cannot hold exactly: give it as a float");
    // A parameter's name is a column of results.csv already: a result of that name would be a second one.
    if (const auto p = run.param_index.find(name); p != run.param_index.end())
      throw Error("'" + name + "' is the name of a parameter (declared at " + place(run.params[p->second].where) +
                  "): give the result another name");
    const std::string where = recipe_where(L);
    if (run.results.size() >= io::max_results && !run.result_where.contains(name))
      throw Error("a run gives at most " + std::to_string(io::max_results) + " results (each a column of a sweep's " +
                  "results.csv and a plot); '" + name + "' would be one more");
    const auto [at, first] = run.result_where.try_emplace(name, where);
    if (first) {
      run.results.push_back({name, value});
    } else {
      for (const io::RunResult& r : run.results)
        if (r.name == name && !(r.value == value))
          throw Error("'" + name + "' is given again with another value, " + io::json_number(value) + " (first " +
                      io::json_number(r.value) + ", at " + place(at->second) + ")");
    }
    lua_settop(L, 2);
    return 1;
  });
}

}  // namespace

void open_result(lua_State* L) { lua_register(L, "result", result); }

}  // namespace selfsim::interp
