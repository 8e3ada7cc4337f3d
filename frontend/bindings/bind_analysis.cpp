// dimension(curve, { method, from, to }) -> table: a curve's fractal dimension (kernels/analysis), by the
// length scaling of seed 004 (method = "length", the default: the curve's `level` field gives its levels)
// or by box counting (method = "box"). A thin adapter.
#include <algorithm>
#include <cmath>

#include "frontend/bindings/bindings.h"
#include "frontend/lua/curve_value.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "kernels/analysis/dimension.h"
#include "kernels/base/check.h"

namespace selfsim::interp {

namespace {

void set_number(lua_State* L, const char* key, double v) {
  lua_pushnumber(L, v);
  lua_setfield(L, -2, key);
}

// { method, dimension, slope, intercept, error, points = { { step, x, y }, ... } }
void push_dimension(lua_State* L, const char* method, const analysis::Dimension& d) {
  lua_createtable(L, 0, 6);
  lua_pushstring(L, method);
  lua_setfield(L, -2, "method");
  set_number(L, "dimension", d.dimension);
  set_number(L, "slope", d.fit.slope);
  set_number(L, "intercept", d.fit.intercept);
  if (d.fit.has_error) set_number(L, "error", d.fit.error);  // absent from two points: undefined
  lua_createtable(L, static_cast<int>(d.steps.size()), 0);
  for (std::size_t i = 0; i < d.steps.size(); ++i) {
    lua_createtable(L, 0, 3);
    lua_pushinteger(L, d.steps[i]);
    lua_setfield(L, -2, "step");
    set_number(L, "x", d.fit.x[i]);
    set_number(L, "y", d.fit.y[i]);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "points");
}

// The default last box step: boxes no smaller than the curve's mean segment, at most 2^11 a side. An extent
// or length that overflows gives no ratio (the kernel then refuses the extent): the step after `from`.
int default_last_box(const Polyline& c, int from) {
  const double side = std::max(c.bbox().size().x, c.bbox().size().y);
  const double mean = c.segments() > 0 ? c.length() / static_cast<double>(c.segments()) : side;
  const double ratio = side / mean;
  const double steps = mean > 0 && std::isfinite(ratio) ? std::floor(std::log2(ratio)) : 11;
  if (!std::isfinite(side)) return std::min(from + 1, 11);
  return static_cast<int>(std::min(std::max(steps, from + 1.0), 11.0));
}

// Length scaling reads `level` as exclusion.curve writes it: the level each point was made at, from 0 at the
// start. L-system curves carry a `level` too, of another meaning (the level the whole curve was drawn at):
// the kernel would find no start and say only that level 0 has no length, so such a curve is named here.
void check_point_levels(const Polyline& c) {
  const Field* field = c.point_fields.find("level");
  if (field == nullptr || c.points.empty()) return;  // the kernel names a missing field
  double lo = field->at(0), hi = lo;
  for (std::size_t i = 1; i < field->stored(); ++i) {
    lo = std::min(lo, field->at(i));
    hi = std::max(hi, field->at(i));
  }
  if (!(lo > 0)) return;
  const std::string found =
      lo == hi ? "is " + number_text(lo) + " at every point (as an L-system curve's is: the level it was drawn at)"
               : "runs from " + number_text(lo) + " to " + number_text(hi) + " with no point at level 0";
  throw Error(
      "length scaling needs exclusion.curve's point field 'level' (the level each point was made at, 0 for the "
      "start); this curve's 'level' " +
      found + ": use method = \"box\"");
}

int dimension(lua_State* L) {
  return call_kernel(L, "dimension", [&] {
    const Held<Polyline> c = held_curve(L, 1, "argument 1 (the curve)");
    Options o(L, 2);
    const int method = o.enumeration("method", {"length", "box"}, 0);
    const int from = static_cast<int>(o.integer("from", method == 0 ? 0 : 1, 0, method == 0 ? 40 : 11));
    const int to = static_cast<int>(
        o.integer("to", method == 0 ? -1 : default_last_box(*c, from), method == 0 ? -1 : 0, method == 0 ? 40 : 11));
    o.finish();
    if (method == 0) {
      check_point_levels(*c);
      push_dimension(L, "length", analysis::length_scaling(*c, from, to));
    } else {
      push_dimension(L, "box", analysis::box_counting(*c, from, to, RunContext::of(L)));
    }
    return 1;
  });
}

}  // namespace

void open_analysis(lua_State* L) { lua_register(L, "dimension", dimension); }

}  // namespace selfsim::interp
