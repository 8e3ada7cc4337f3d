// develop(source, { levels, method, height, smooth, stencil, resolution, thickness, ... }) -> Mesh: seed 002's
// developing surface, by route 1, method "loop" (the control mesh smoothed by Loop subdivision) or route 2 (Bezier arcs
// joined by Hermite curves), optionally thickened. A thin adapter over kernels/develop.
#include "frontend/bindings/bindings.h"
#include "frontend/bindings/print_options.h"
#include "frontend/lua/curve_value.h"
#include "frontend/lua/growth.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "kernels/develop/develop.h"
#include "kernels/develop/rounded_corners.h"
#include "kernels/lsystem/grammar.h"
#include "kernels/lsystem/production_count.h"
#include "kernels/lsystem/turtle/turtle2d.h"

namespace selfsim::interp {

namespace {

// Levels 0..top of a grammar. The whole result is predicted from the production matrix first (every level's
// points, held while the surface is built, and the surface itself: develop.h), so a stack too big, or
// smoothed too often, is refused before any level is drawn.
std::vector<Held<Polyline>> grammar_levels(lua_State* L, const lsystem::Grammar& g, int top,
                                           const develop::DevelopOptions& opt) {
  double points = 0;
  std::vector<double> segments;
  for (int l = 0; l <= top; ++l) {
    const lsystem::LevelCounts counts = lsystem::predict_counts(g, l, RunContext::of(L));
    points += counts.max_points();
    segments.push_back(counts.segments);
  }
  // Open or closed is not known before drawing: the larger (open) count. Route 2's size depends on the
  // levels' segment lengths too: develop_surface predicts it once they are drawn, before building it.
  check_run_budget(
      L, points + (opt.method == develop::Method::loop ? develop::developed_size(segments, false, opt) : 0),
      "levels = " + std::to_string(top) + (opt.smooth > 0 ? ", smooth = " + std::to_string(opt.smooth) : ""));
  std::vector<Held<Polyline>> levels;
  double held = 0;
  for (int l = 0; l <= top; ++l) {
    lsystem::TurtleOptions opt{.level = l, .normalize = true};  // every level on the same unit segment
    levels.push_back(std::make_shared<const Polyline>(with_budget(L, [&](PointBudget b) {
      b.held += held;
      opt.budget = b;
      return lsystem::turtle2d(g, opt, RunContext::of(L));
    })));
    held += static_cast<double>(levels.back()->points.size());
  }
  return levels;
}

int develop(lua_State* L) {
  return call_kernel(L, "develop", [&] {
    if (lua_gettop(L) > 2)
      throw Error("takes a source and a table of options, develop(source, { ... }), got " +
                  std::to_string(lua_gettop(L)) + " arguments");
    Options o(L, 2);
    const Held<lsystem::Grammar> g = test_grammar(L, 1);
    int top = 0;
    if (g) {
      o.require("levels", "the finest level of the stack, e.g. levels = 8 (level 0 is the axiom)");
      top = static_cast<int>(o.integer("levels", 1, 1, lsystem::max_level));
    } else if (lua_type(L, 1) != LUA_TTABLE) {
      throw Error("argument 1 must be a grammar (curves.dragon()) or a list of curves, one per level, got " +
                  describe(L, 1));
    } else if (o.has("levels")) {
      throw Error("option 'levels' is for a grammar: a list of curves is the stack itself, level 0 first");
    }
    develop::DevelopOptions opt;
    opt.method = static_cast<develop::Method>(o.enumeration("method", {"loop", "bezier"}, 0));
    if (o.has("resolution")) opt.resolution = static_cast<int>(o.integer("resolution", 4, 1, 64));
    opt.height = o.number("height", opt.height);
    opt.smooth = static_cast<int>(o.integer("smooth", 0, 0, 12));
    opt.bounded = o.enumeration("stencil", {"loop", "bounded"}, 0) == 1;
    opt.thickness = o.number("thickness", 0);
    opt.thickness_rate = o.number("thickness_rate", 0);
    if (o.has("thickness_rate") && opt.thickness_rate == 0)
      throw Error("option 'thickness_rate' must be in [1e-06, 1], got 0 (leave it out for the curve's own rate)");
    opt.corner_shift = o.number("corner_shift", 0);
    opt.size = o.number("size", 0);
    if (o.has("size") && opt.size == 0)
      throw Error("option 'size' must be a number in [1e-09, 1e+09], got 0 (leave it out to keep the curve's size)");
    opt.size_level = static_cast<int>(o.integer("size_level", -1, -1, lsystem::max_level));
    opt.check = o.boolean("check", true);
    o.finish();

    std::vector<Held<Polyline>> levels;
    if (g) {
      levels = grammar_levels(L, *g, top, opt);
    } else {
      const lua_Integer n = list_length(L, 1, "argument 1 (the levels)");
      for (lua_Integer i = 1; i <= n; ++i) {
        lua_rawgeti(L, 1, i);
        Held<Polyline> c = test_curve(L, -1);
        if (!c)
          throw Error("entry " + std::to_string(i) + " of the levels (level " + std::to_string(i - 1) +
                      ") must be a 2D curve, got " + describe(L, -1));
        levels.push_back(std::move(c));
        lua_pop(L, 1);
      }
    }
    // develop_surface checks the result's predicted size against the budget before building it.
    std::vector<const Polyline*> stack;
    for (const auto& c : levels) stack.push_back(c.get());
    std::vector<std::string> warnings;
    double scale = 1;
    push_geometry(L, with_budget(L, [&](const PointBudget& b) {
                    opt.budget = b;
                    warnings.clear();
                    return develop::develop_surface(stack, opt, RunContext::of(L), &warnings, &scale);
                  }));
    // Its levels: the surfaces of the stack's first levels (two at least), scaled as the whole was, so a
    // growth series does not change size from step to step.
    // The stack's curves: kept for the levels (counted against the budget only when develop drew them: a
    // list of curves is the recipe's own, counted already).
    double kept = 0;
    for (const auto& c : levels) kept += static_cast<double>(c->points.size());
    const double retained = g ? kept : 0;
    opt.scale = opt.size > 0 ? scale : 0;
    attach_growth(L,
                  Growth{1, static_cast<int>(levels.size()) - 1, "level", kept,
                         [levels, opt](int k, const PointBudget& b, Progress& p) {
                           std::vector<const Polyline*> first;
                           for (int l = 0; l <= k; ++l) first.push_back(levels[static_cast<std::size_t>(l)].get());
                           develop::DevelopOptions at = opt;
                           at.budget = b;
                           if (at.size_level > k) at.size_level = -1;  // the factor is given: the level is not measured
                           return GrownValue(develop::develop_surface(first, at, p));
                         }},
                  retained);
    for (const std::string& w : warnings) {
      const std::string message = recipe_where(L) + "develop: " + w;
      lua_warning(L, message.c_str(), 0);
    }
    // A solid given a size in millimetres is meant for printing: the print check says if it is not printable.
    if (opt.size > 0 && opt.thickness > 0 && opt.check)
      warn_unless_printable(L, "develop", test_geometry<Mesh>(L, -1), PrintCheckOption{});
    return 1;
  });
}

}  // namespace

// c:rounded{ samples = 8 } -> Curve: every corner rounded by the arc §1 draws (kernels/develop/rounded_corners.h).
int curve_rounded(lua_State* L) {
  const Held<Polyline> c = geometry_self<Polyline>(L, "rounded");
  return call_kernel(L, "rounded", [&] {
    if (lua_gettop(L) > 2) throw Error("takes a table of options, c:rounded{ samples = 8 }");
    Options o(L, 2);
    develop::RoundOptions opt;
    opt.samples = static_cast<int>(o.integer("samples", opt.samples, 1, 1024));
    o.finish();
    push_geometry(L, with_budget(L, [&](const PointBudget& b) {
                    opt.budget = b;
                    return develop::rounded_corners(*c, opt, RunContext::of(L));
                  }));
    return 1;
  });
}

void open_develop(lua_State* L) { lua_register(L, "develop", develop); }

}  // namespace selfsim::interp
