// substitute{ path, generator, levels, transforms } -> Curve. A thin adapter over kernels/substitute.
#include "frontend/bindings/bindings.h"
#include "frontend/lua/curve_value.h"
#include "frontend/lua/growth.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "kernels/substitute/substitute.h"

namespace selfsim::interp {

namespace {

using substitute::SegmentTransform;

const std::vector<std::string> transform_names{"identity", "reflect_segment", "reflect_bisector", "half_turn"};

std::vector<SegmentTransform> read_transforms(lua_State* L) {
  std::vector<SegmentTransform> out;
  if (lua_type(L, -1) != LUA_TTABLE) throw Error("option 'transforms' must be a list of names, got " + describe(L, -1));
  const lua_Integer n = list_length(L, -1, "option 'transforms'");
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, i);
    const std::string name =
        lua_type(L, -1) == LUA_TSTRING ? shown_text(text_value(L, -1, "option 'transforms'")) : describe(L, -1);
    lua_pop(L, 1);
    out.push_back(static_cast<SegmentTransform>(
        enum_index(name, transform_names, "transform", " (entry " + std::to_string(i) + ")")));
  }
  return out;
}

int make_substitute(lua_State* L) {
  return call_kernel(L, "substitute", [&] {
    RunContext& run = RunContext::of(L);
    Options o(L, 1);
    o.require("path", "the curve whose segments are replaced: a curve or a table of {x, y}");
    o.require("generator", "the path that replaces each segment, from (0,0) to (1,0)");
    o.require("levels", "how many times to substitute, e.g. levels = 4");
    const Polyline path = o.curve("path");
    const Polyline generator = o.curve("generator");
    substitute::SubstituteOptions opt;
    opt.levels = static_cast<int>(o.integer("levels", 1, 0, 64));
    if (o.push("transforms") != LUA_TNIL) opt.transforms = read_transforms(L);
    lua_pop(L, 1);
    o.finish();
    push_curve(L, with_budget(L, [&](const PointBudget& b) {
                 opt.budget = b;
                 return substitute::substitute(path, generator, opt, run);
               }));
    // Its levels: the same substitution done fewer times.
    auto inputs = std::make_shared<const std::pair<Polyline, Polyline>>(path, generator);
    const double kept = static_cast<double>(path.points.size() + generator.points.size());
    attach_growth(L,
                  Growth{0, opt.levels, "level", kept,
                         [inputs, opt](int k, const PointBudget& b, Progress& p) {
                           substitute::SubstituteOptions at = opt;
                           at.levels = k;
                           at.budget = b;
                           return GrownValue(substitute::substitute(inputs->first, inputs->second, at, p));
                         }},
                  kept);
    return 1;
  });
}

}  // namespace

void open_substitute(lua_State* L) { lua_register(L, "substitute", make_substitute); }

}  // namespace selfsim::interp
