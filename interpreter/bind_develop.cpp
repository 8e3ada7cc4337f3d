// develop(source, { levels, height, smooth }) -> Mesh: seed 002's developing surface by route 1, the control
// mesh smoothed by Loop subdivision. A thin adapter over kernels/develop.
#include "interpreter/bindings.h"
#include "interpreter/curve_value.h"
#include "interpreter/lua_support.h"
#include "interpreter/options_reader.h"
#include "interpreter/run_context.h"
#include "kernels/develop/develop.h"
#include "kernels/lsystem/grammar.h"
#include "kernels/lsystem/production_count.h"
#include "kernels/lsystem/turtle2d.h"

namespace selfsim::interp {

namespace {

// Levels 0..top of a grammar. The whole surface is predicted from the production matrix first (every level's
// points, held while the mesh is built, the mesh's points, and a triangle per coarse and per fine segment),
// so a stack too big is refused before any level is drawn.
std::vector<Held<Polyline>> grammar_levels(lua_State* L, const lsystem::Grammar& g, int top) {
  double points = 0, faces = 0, previous = 0;
  for (int l = 0; l <= top; ++l) {
    const lsystem::LevelCounts counts = lsystem::predict_counts(g, l, RunContext::of(L));
    points += counts.max_points();
    if (l > 0) faces += previous + counts.segments;
    previous = counts.segments;
  }
  check_run_budget(L, 2 * points + faces, "levels = " + std::to_string(top));
  std::vector<Held<Polyline>> levels;
  double held = 0;
  for (int l = 0; l <= top; ++l) {
    lsystem::TurtleOptions opt{.level = l};
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
    Options o(L, 2);
    const Held<lsystem::Grammar> g = test_grammar(L, 1);
    int top = 0;
    if (g) {
      o.require("levels", "the finest level of the stack, e.g. levels = 8 (level 0 is the axiom)");
      top = static_cast<int>(o.integer("levels", 1, 1, lsystem::max_level));
    } else if (lua_type(L, 1) != LUA_TTABLE) {
      throw Error("argument 1 must be a grammar (curves.dragon()) or a list of curves, one per level, got " +
                  describe(L, 1));
    }
    develop::DevelopOptions opt;
    opt.height = o.number("height", opt.height);
    opt.smooth = static_cast<int>(o.integer("smooth", 0, 0, 12));
    opt.thickness = o.number("thickness", 0);
    opt.thickness_rate = o.number("thickness_rate", 0);
    opt.corner_shift = o.number("corner_shift", 0);
    opt.size = o.number("size", 0);
    opt.size_level = static_cast<int>(o.integer("size_level", -1, -1, lsystem::max_level));
    o.finish();

    std::vector<Held<Polyline>> levels;
    if (g) {
      levels = grammar_levels(L, *g, top);
    } else {
      const lua_Integer n = list_length(L, 1, "argument 1 (the levels)");
      for (lua_Integer i = 1; i <= n; ++i) {
        lua_rawgeti(L, 1, i);
        Held<Polyline> c = test_curve(L, -1);
        if (!c)
          throw Error("entry " + std::to_string(i) + " of the levels (level " + std::to_string(i - 1) +
                      ") must be a curve, got " + describe(L, -1));
        levels.push_back(std::move(c));
        lua_pop(L, 1);
      }
    }
    // The mesh has every level's points and, per tile, as many triangles as the tile's coarse and fine
    // segments together; the levels made here are held while it is built.
    std::vector<const Polyline*> stack;
    double points = 0, faces = 0;
    for (std::size_t l = 0; l < levels.size(); ++l) {
      stack.push_back(levels[l].get());
      points += static_cast<double>(levels[l]->points.size());
      if (l + 1 < levels.size()) faces += static_cast<double>(levels[l]->segments() + levels[l + 1]->segments());
    }
    check_run_budget(L, (g ? 2 : 1) * points + faces, "develop");
    push_geometry(L, with_budget(L, [&](const PointBudget& b) {
                    opt.budget = b;
                    return develop::develop_surface(stack, opt, RunContext::of(L));
                  }));
    return 1;
  });
}

}  // namespace

void open_develop(lua_State* L) { lua_register(L, "develop", develop); }

}  // namespace selfsim::interp
