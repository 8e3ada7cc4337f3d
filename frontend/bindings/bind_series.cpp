// save(list or value, "growth.pvd" | "growth.vtp.series"): a ParaView time series (kernels/io/view/series_file.h).
#include <algorithm>
#include <cstdio>
#include <string_view>
#include <vector>

#include "frontend/bindings/save_support.h"
#include "frontend/lua/growth.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/io/view/series_file.h"

namespace selfsim::interp {

// save(list or value, "growth.pvd" or "growth.vtp.series", opts?): a ParaView time series, one step per
// entry of the list (times from its `times`, else 0, 1, ...); a value that grew by levels saves its levels.
int save_series(lua_State* L) {
  RunContext& run = RunContext::of(L);
  const std::string name = text_value(L, 2, "argument 2 (the file name)");
  if (has_growth(L, 1)) {  // a value that grew: its levels
    push_levels(L, 1);
    lua_replace(L, 1);
  } else if (test_any(L, 1)) {  // any other value: a series of one step
    lua_createtable(L, 1, 0);
    lua_pushvalue(L, 1);
    lua_rawseti(L, -2, 1);
    lua_replace(L, 1);
  }
  if (lua_type(L, 1) != LUA_TTABLE)
    throw Error("a series holds a list of curves or meshes (v:levels(), or { a, b, c }), got " + describe(L, 1));
  // The list's entries; its one named key may be `times`.
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, 1));
  lua_pushnil(L);
  while (lua_next(L, 1) != 0) {
    lua_pop(L, 1);
    const bool listed = lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 && lua_tointeger(L, -1) <= n;
    if (!listed && !(lua_type(L, -1) == LUA_TSTRING && std::string_view(lua_tostring(L, -1)) == "times"))
      throw Error("a series is a list of curves or meshes with an optional 'times', got the key " + describe(L, -1));
  }
  if (n < 1) throw Error("a series needs at least one curve or mesh");
  std::vector<AnyValue> held;
  std::vector<io::SeriesStep> steps;
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, 1, i);
    std::optional<AnyValue> v = test_any(L, -1);
    if (!v)
      throw Error("entry " + std::to_string(i) + " of the series must be a curve or mesh, got " + describe(L, -1));
    lua_pop(L, 1);
    steps.push_back({v->ref(), static_cast<double>(i - 1)});
    held.push_back(std::move(*v));
  }
  if (lua_getfield(L, 1, "times") != LUA_TNIL) {
    if (!lua_istable(L, -1))
      throw Error("the series' 'times' must be a list of " + std::to_string(n) + " numbers, one per entry, got " +
                  describe(L, -1) + " (not a list)");
    const lua_Integer count = list_length(L, -1, "the series' 'times'");
    if (count != n)
      throw Error("the series' 'times' must be a list of " + std::to_string(n) + " numbers, one per entry, got " +
                  std::to_string(count));
    for (lua_Integer i = 1; i <= n; ++i) {
      lua_rawgeti(L, -1, i);
      steps[static_cast<std::size_t>(i - 1)].time = finite_number(L, -1, "entry " + std::to_string(i) + " of 'times'");
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
  io::SaveOptions opt = read_save_options(L, 3, *io::find_format(io::series_step_extension(name)));
  check_not_saved(L, name);
  // A curve that draws nothing at a level (a plant's axiom "X" at level 0) has no file to be: the series
  // starts at its first level that has one, each step keeping its time.
  std::erase_if(steps, [](const io::SeriesStep& s) {
    return std::visit([](const auto* v) { return v->points.empty(); }, s.value);
  });
  if (steps.empty()) throw Error("every entry of the series is empty: there is nothing to draw");
  const std::vector<std::string> step_names = io::series_step_names(name, steps.size());
  for (const std::string& step : step_names) {
    try {
      check_not_saved(L, step);
    } catch (const Error& e) {
      throw Error("'" + shown_text(name) + "' would write its steps into the folder of '" + shown_text(step) +
                  "' (a .pvd and a .vtp.series of one name share it): " + e.what());
    }
  }
  opt.budget = run_budget(L);
  opt.provenance = run_provenance(L, name);
  const io::SeriesFiles written = io::save_series(steps, run.config.out_dir, name, opt, run);
  for (const std::string& step : step_names) record_saved(L, step);
  record_saved(L, name);
  std::vector<io::ValueRef> refs;
  for (const io::SeriesStep& s : steps) refs.push_back(s.value);
  record_view(L, name, role_of(refs.back()), refs, true);
  if (!run.config.quiet)
    std::printf("wrote %s (%zu step%s, %s%s%s; %zu points in the last)\n", shown_text(written.series, 4096).c_str(),
                steps.size(), steps.size() == 1 ? "" : "s", shown_text(written.steps.front(), 4096).c_str(),
                steps.size() == 1 ? "" : " ... ",
                steps.size() == 1 ? "" : shown_text(written.steps.back(), 4096).c_str(),
                std::visit([](const auto* v) { return v->points.size(); }, steps.back().value));
  return 0;
}

}  // namespace selfsim::interp
