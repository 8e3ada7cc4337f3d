#include "frontend/lua/growth.h"

#include "frontend/lua/lua_support.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/base/check.h"

namespace selfsim::interp {

namespace {

Box* geometry_box(lua_State* L, int index) {
  for (const char* type : {ValueType<Polyline>::name, ValueType<Polyline3>::name, ValueType<Mesh>::name})
    if (auto* box = static_cast<Box*>(luaL_testudata(L, index, type))) return box;
  return nullptr;
}

// The growth of the value at index; Error when it is not a value, or has none.
std::shared_ptr<const Growth> growth_of(lua_State* L, int index, const char* method) {
  Box* box = geometry_box(L, index);
  if (box == nullptr)
    throw Error(std::string("expected a curve or mesh before ':' (write value:") + method + "(...)), got " +
                describe(L, index));
  const LiveValue* v = RunContext::of(L).values.find(box->id);
  if (v == nullptr) throw Error("the value was used after it was freed (kept alive by a finalizer)");
  if (!v->growth)
    throw Error(
        "this value has no levels: they come with the values of g:curve{}, substitute{}, hoist.iterate, develop, "
        "exclusion.curve and exclusion.surface (a transformed, joined or loaded value has none)");
  return std::static_pointer_cast<const Growth>(v->growth);
}

// Pushes the value at level k of the value at `self` (which is its last level), with the levels up to k.
void push_level(lua_State* L, int self, const std::shared_ptr<const Growth>& g, int k) {
  if (k == g->last) {
    lua_pushvalue(L, self);
    return;
  }
  RunContext& run = RunContext::of(L);
  GrownValue v = with_budget(L, [&](const PointBudget& b) { return g->at(k, b, run); });
  std::visit([&](auto& value) { push_geometry(L, std::move(value)); }, v);
  attach_growth(L, Growth{g->first, k, g->unit, g->kept, g->at}, g->kept);
}

int level_number(lua_State* L, int index, const Growth& g) {
  if (!lua_isinteger(L, index))
    throw Error(g.unit + " must be an integer in [" + std::to_string(g.first) + ", " + std::to_string(g.last) +
                "], got " + describe(L, index));
  return static_cast<int>(check_range(lua_tointeger(L, index), g.first, g.last, g.unit.c_str()));
}

}  // namespace

void attach_growth(lua_State* L, Growth growth, double retained) {
  Box* box = geometry_box(L, -1);
  RunContext& run = RunContext::of(L);
  LiveValue* v = box ? run.values.find(box->id) : nullptr;
  if (v == nullptr) return;
  if (retained > 0) check_run_budget(L, retained, "keeping its levels");
  v = run.values.find(box->id);  // a collection may have run
  if (v == nullptr) return;
  v->growth = std::make_shared<const Growth>(std::move(growth));
  v->points += retained;
  if (v->held) run.held_points += retained;
}

bool has_growth(lua_State* L, int index) {
  Box* box = geometry_box(L, index);
  const LiveValue* v = box ? RunContext::of(L).values.find(box->id) : nullptr;
  return v != nullptr && v->growth != nullptr;
}

void push_levels(lua_State* L, int index) {
  index = lua_absindex(L, index);
  const std::shared_ptr<const Growth> g = growth_of(L, index, "levels");
  lua_createtable(L, g->last - g->first + 1, 1);
  lua_createtable(L, g->last - g->first + 1, 0);
  for (int k = g->first; k <= g->last; ++k) {
    lua_pushinteger(L, k);
    lua_rawseti(L, -2, k - g->first + 1);
  }
  lua_setfield(L, -2, "times");
  for (int k = g->first; k <= g->last; ++k) {
    push_level(L, index, g, k);
    lua_rawseti(L, -2, k - g->first + 1);
  }
}

int value_levels(lua_State* L) {
  return call_kernel(L, "levels", [&] {
    if (lua_gettop(L) > 1) throw Error("takes no arguments: v:levels() (one level: v:level(k))");
    push_levels(L, 1);
    return 1;
  });
}

int value_level(lua_State* L) {
  return call_kernel(L, "level", [&] {
    if (lua_gettop(L) != 2) throw Error("takes one level number: v:level(3)");
    const std::shared_ptr<const Growth> g = growth_of(L, 1, "level");
    push_level(L, 1, g, level_number(L, 2, *g));
    return 1;
  });
}

}  // namespace selfsim::interp
