// exclusion.curve{ region, start, radius, factor, levels, order, scan, exclusion } -> Curve, report: seed
// 004's exclusion-radius curve (kernels/exclusion). The region is a closed curve: polygon{...}, or a curve
// of several closed paths (group{...}) whose first is the outer ring and the others holes. The start is a
// curve whose paths are the start curves. The report says how many points could not move, level by level.
// A thin adapter.
#include <string>

#include "frontend/bindings/bindings.h"
#include "frontend/bindings/level_reports.h"
#include "frontend/lua/curve_value.h"
#include "frontend/lua/growth.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "kernels/base/check.h"
#include "kernels/exclusion/curve_at_level.h"
#include "kernels/exclusion/discs.h"
#include "kernels/exclusion/exclusion_curve.h"

namespace selfsim::interp {

namespace {

// A region's rings are closed curves (each path ends at its first point, as polygon{} makes them): an open
// polyline is refused rather than closed silently with an edge the recipe never drew.
Region region_of(const Polyline& c) {
  std::vector<std::vector<Vec2>> rings;
  for (std::size_t i = 0; i < c.paths(); ++i) {
    auto path = c.path(i);
    // A ring walked by a turtle or a substitution ends a rounding error from its start (the Koch
    // snowflake): closed, by the rule the writers and develop use, and that last point dropped.
    if (path.size() > 3 && path.front() != path.back() && closed_path(path))
      path = path.first(path.size() - 1);
    else if (path.size() > 1 && path.front() != path.back())
      throw Error("option 'region': " + (c.paths() > 1 ? "path " + std::to_string(i + 1) : std::string("the curve")) +
                  " is open (it ends at {" + number_text(path.back().x) + ", " + number_text(path.back().y) +
                  "}, not at its first point): a region is closed; write polygon { ... }, which closes itself");
    rings.emplace_back(path.begin(), path.end());
  }
  try {
    return Region(std::move(rings));
  } catch (const BudgetError&) {
    throw;
  } catch (const Error& e) {
    throw Error(std::string("option 'region': ") + e.what());
  }
}

// { stuck = n, levels = { { splits = , stuck = , seconds = }, ... } }
void push_report(lua_State* L, const exclusion::CurveResult& r) {
  lua_createtable(L, 0, 2);
  lua_pushinteger(L, static_cast<lua_Integer>(r.stuck()));
  lua_setfield(L, -2, "stuck");
  push_level_reports(L, r.levels, "splits");
  lua_setfield(L, -2, "levels");
}

int exclusion_curve(lua_State* L) {
  return call_kernel(L, "exclusion.curve", [&] {
    if (lua_gettop(L) != 1 || !lua_istable(L, 1))
      throw Error("takes one table of options, exclusion.curve{ region = ..., start = ..., radius = ... }");
    Options o(L, 1);
    o.require("region", "the region to fill, e.g. region = polygon { {0,0}, {1,0}, {1,1}, {0,1} }");
    o.require("start", "the start curve, e.g. start = polyline { {0,0}, {1,1} }");
    o.require("radius", "the first level's exclusion radius, e.g. radius = 0.1");
    o.require("levels", "how many times every segment is split, e.g. levels = 10");
    const Polyline region_curve = o.curve("region");
    const Polyline start = o.curve("start");
    exclusion::CurveOptions opt;
    opt.radius = o.number("radius", opt.radius);
    opt.factor = o.number("factor", opt.factor);
    opt.levels = static_cast<int>(o.integer("levels", 1, 0, 40));
    opt.order = static_cast<exclusion::Order>(o.enumeration("order", {"breadth", "depth"}, 0));
    if (opt.order == exclusion::Order::depth && o.has("scan"))
      throw Error("option 'scan' applies to order = \"breadth\" only (depth first always goes forward)");
    opt.scan = static_cast<exclusion::Scan>(o.enumeration("scan", {"alternate", "forward"}, 0));
    opt.exclusion = static_cast<exclusion::Mode>(o.enumeration("exclusion", {"exact", "vertex", "original"}, 0));
    if (opt.exclusion == exclusion::Mode::original && opt.order == exclusion::Order::depth)
      throw Error(
          "option 'exclusion' = \"original\" splits level by level, as Bowyer's program does: leave out "
          "order = \"depth\"");
    o.finish();
    opt.validate();
    const Region region = region_of(region_curve);
    exclusion::CurveResult r = with_budget(L, [&](const PointBudget& b) {
      opt.budget = b;
      return exclusion::exclusion_curve(region, start, opt, RunContext::of(L));
    });
    push_curve(L, std::move(r.curve));
    // Its levels: its points up to each level (placed points never move).
    const Held<Polyline> grown = test_curve(L, -1);
    attach_growth(
        L, Growth{0, opt.levels, "level", budget_size(*grown), [grown](int k, const PointBudget& b, Progress& p) {
                    Polyline c = exclusion::curve_at_level(*grown, k, p);
                    check_budget(budget_size(c), b, "level " + std::to_string(k));
                    return GrownValue(std::move(c));
                  }});
    push_report(L, r);
    return 2;
  });
}

// exclusion.discs(curve, { radius, factor, level, samples }) -> Curve: Figure 4's exclusion discs.
int exclusion_discs(lua_State* L) {
  return call_kernel(L, "exclusion.discs", [&] {
    const Held<Polyline> c = held_curve(L, 1, "argument 1 (an exclusion curve)");
    Options o(L, 2);
    o.require("radius", "the curve's first exclusion radius, e.g. radius = 0.1");
    exclusion::DiscOptions opt;
    opt.radius = o.number("radius", opt.radius);
    opt.factor = o.number("factor", opt.factor);
    opt.level = static_cast<int>(o.integer("level", opt.level, 1, 40));
    opt.samples = static_cast<int>(o.integer("samples", opt.samples, 3, 4096));
    o.finish();
    push_curve(L, with_budget(L, [&](const PointBudget& b) {
                 opt.budget = b;
                 return exclusion::exclusion_discs(*c, opt, RunContext::of(L));
               }));
    return 1;
  });
}

}  // namespace

void open_exclusion(lua_State* L) {
  const luaL_Reg functions[] = {
      {"curve", exclusion_curve}, {"discs", exclusion_discs}, {"surface", exclusion_surface}, {nullptr, nullptr}};
  luaL_newlib(L, functions);
  lua_setglobal(L, "exclusion");
}

}  // namespace selfsim::interp
