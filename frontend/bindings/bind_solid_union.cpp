// solid.union and solid.difference: one solid from several (issue 40). Thin adapters over
// kernels/print/solid_union.h:
//   solid.union{ a, b, ..., voxel = 0.1 }        every point of any of them
//   solid.difference(a, b)                        a less b
//   solid.difference(a, { b, c, voxel = 0.1 })    a less b and c
// Each says how it went ("exact (2 disjoint solids)", "on a 0.1 mm grid (solids 1 and 2 meet)") unless quiet,
// and its result is checked like any solid (check = false skips it).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "frontend/bindings/bindings.h"
#include "frontend/bindings/print_options.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/base/check.h"
#include "kernels/print/solid_union.h"

namespace selfsim::interp {

namespace {

// The solids listed at table `index` (keys 1..n; `what` names them in messages) and its options.
struct Listed {
  std::vector<Held<Mesh>> held;
  std::vector<const Mesh*> solids;
  print::UnionOptions opt;
  PrintCheckOption check;
};

Listed read_list(lua_State* L, int index, const std::string& what, const std::string& call) {
  if (lua_type(L, index) != LUA_TTABLE)
    throw Error("expected a list of solids, " + call + ", got " + describe(L, index));
  Listed out;
  // Entries 1..n, beside named options (list_length would refuse those); a key past n is unknown to finish().
  const auto n = static_cast<lua_Integer>(lua_rawlen(L, index));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, index, i);
    Held<Mesh> m = test_geometry<Mesh>(L, -1);
    if (!m) throw Error(what + " " + std::to_string(i) + " must be a mesh (a solid), got " + describe(L, -1));
    lua_pop(L, 1);
    out.solids.push_back(m.get());
    out.held.push_back(std::move(m));
  }
  Options o(L, index);
  o.positional(n);
  out.opt.voxel = o.has("voxel") ? o.number("voxel", 0) : 0;
  if (o.has("voxel") && (!(out.opt.voxel > 0) || !std::isfinite(out.opt.voxel)))
    throw Error("option 'voxel' must be a positive length (mm), got " + number_text(out.opt.voxel));
  out.check = read_print_check(o);
  o.finish();
  return out;
}

void finish(lua_State* L, const char* fn, print::UnionResult r, const PrintCheckOption& check) {
  if (!RunContext::of(L).config.quiet) std::printf("%s%s: %s\n", recipe_where(L).c_str(), fn, r.how.c_str());
  push_geometry(L, std::move(r.solid));
  warn_unless_printable(L, fn, test_geometry<Mesh>(L, -1), check);
}

int solid_union(lua_State* L) {
  return call_kernel(L, "solid.union", [&] {
    const std::string call = "solid.union{ a, b, ... }";
    if (lua_gettop(L) != 1)
      throw Error("takes one list of solids, " + call + ", got " + std::to_string(lua_gettop(L)) + " arguments");
    Listed l = read_list(L, 1, "solid", call);
    if (l.solids.size() < 2)
      throw Error("takes at least two solids, " + call + ", got " + std::to_string(l.solids.size()));
    // The work copies turned outwards, a pair's test or the result: the grid predicts its own (volume_boundary).
    check_run_budget(L, print::union_work_size(l.solids), "the union's copies of its solids");
    print::UnionResult r = with_budget(L, [&](const PointBudget& b) {
      l.opt.budget = b;
      return print::solid_union(l.solids, l.opt, RunContext::of(L));
    });
    finish(L, "solid.union", std::move(r), l.check);
    return 1;
  });
}

int solid_difference(lua_State* L) {
  return call_kernel(L, "solid.difference", [&] {
    const std::string call = "solid.difference(a, b) or solid.difference(a, { b, c })";
    if (lua_gettop(L) != 2)
      throw Error("takes a solid and what to cut from it, " + call + ", got " + std::to_string(lua_gettop(L)) +
                  " arguments");
    const Held<Mesh> from = test_geometry<Mesh>(L, 1);
    if (!from) throw Error("argument 1 must be a mesh (a solid), " + call + ", got " + describe(L, 1));
    Listed cuts;
    if (Held<Mesh> one = test_geometry<Mesh>(L, 2)) {
      cuts.solids.push_back(one.get());
      cuts.held.push_back(std::move(one));
    } else {
      cuts = read_list(L, 2, "cut", call);
      if (cuts.solids.empty()) throw Error("argument 2 lists no solid to cut away, " + call);
    }
    std::vector<const Mesh*> all{from.get()};
    all.insert(all.end(), cuts.solids.begin(), cuts.solids.end());
    check_run_budget(L, print::union_work_size(all), "the difference's copies of its solids");
    print::UnionResult r = with_budget(L, [&](const PointBudget& b) {
      cuts.opt.budget = b;
      return print::solid_difference(*from, cuts.solids, cuts.opt, RunContext::of(L));
    });
    finish(L, "solid.difference", std::move(r), cuts.check);
    return 1;
  });
}

}  // namespace

void add_solid_union(lua_State* L) {
  lua_pushcfunction(L, solid_union);
  lua_setfield(L, -2, "union");
  lua_pushcfunction(L, solid_difference);
  lua_setfield(L, -2, "difference");
}

}  // namespace selfsim::interp
