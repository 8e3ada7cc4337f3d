// solid.place and solid.orient: a solid put on the printer's bed (issue 40). Thin adapters over
// kernels/print/orient.h and kernels/geom/mesh_transform.h.
#include <cstdio>

#include "frontend/bindings/bindings.h"
#include "frontend/bindings/transform_options.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/base/check.h"
#include "kernels/geom/point_text.h"
#include "kernels/print/orient.h"
#include "kernels/print/overhang.h"

namespace selfsim::interp {

namespace {

Held<Mesh> solid_argument(lua_State* L, const std::string& call) {
  if (lua_gettop(L) > 2)
    throw Error("takes a mesh and a table of options, " + call + ", got " + std::to_string(lua_gettop(L)) +
                " arguments");
  Held<Mesh> m = test_geometry<Mesh>(L, 1);
  if (!m) throw Error("argument 1 must be a mesh, " + call + ", got " + describe(L, 1));
  return m;
}

// Where the footprint's centre goes: `at = {x, y}` (default the origin), or nowhere with centre = false.
struct Spot {
  bool centre = true;
  Vec2 at{};
};

Spot read_spot(Options& o) {
  Spot s;
  s.centre = o.boolean("centre", true);
  if (const auto at = o.point2("at")) {
    if (!s.centre) throw Error("option 'at' places the footprint's centre: it cannot go with centre = false");
    s.at = *at;
  }
  return s;
}

// m turned by `turn` (none: kept) and put on the bed at the spot, as a new value on the stack.
void push_on_bed(lua_State* L, const Mesh& m, const Affine3* turn, const Spot& spot) {
  check_run_budget(L, budget_size(m), "the placed copy");
  Mesh placed = turn ? transformed(m, *turn, RunContext::of(L)) : m;
  Vec3 shift = print::bed_shift(placed.bbox());
  if (spot.centre)
    shift += {spot.at.x, spot.at.y, 0};
  else
    shift.x = shift.y = 0;
  for (Vec3& p : placed.points) p += shift;  // a move: no field changes
  if (!placed.finite()) throw Error("option 'at' moves the solid past the largest number");
  push_geometry(L, std::move(placed));
}

// solid.place(mesh, { centre = true, at = {x, y} }) -> the mesh with its lowest point at z = 0, centred.
int solid_place(lua_State* L) {
  return call_kernel(L, "solid.place", [&] {
    const Held<Mesh> m = solid_argument(L, "solid.place(mesh)");
    Options o(L, 2);
    const Spot spot = read_spot(o);
    o.finish();
    push_on_bed(L, *m, nullptr, spot);
    return 1;
  });
}

// "overhang 52 mm² past 45° (was 3.1 cm²)", "no overhang past 45° (was none)".
std::string overhang_text(double area, double angle, double before) {
  const std::string past =
      " past " + short_number(angle) + "° (was " + (before > 0 ? larger_area_text(before) : "none") + ")";
  return area > 0 ? "overhang " + larger_area_text(area) + past : "no overhang" + past;
}

// solid.orient(mesh, { face = "largest" } | { least = "overhang", overhang = 45 } | { rotate = 90, axis = {1,0,0} })
int solid_orient(lua_State* L) {
  return call_kernel(L, "solid.orient", [&] {
    const std::string call = "solid.orient(mesh, { face = \"largest\" })";
    const Held<Mesh> m = solid_argument(L, call);
    Options o(L, 2);
    const int ways = o.has("face") + o.has("least") + o.has("rotate");
    if (ways > 1)
      throw Error("give one of face = \"largest\", least = \"overhang\" and rotate = degrees (with axis = {x, y, z})");
    print::OrientOptions opt;
    if (o.has("least")) {
      o.enumeration("least", {"overhang"}, 0);
      opt.least_overhang = true;
    } else {
      o.enumeration("face", {"largest"}, 0);
    }
    MeshTransform given;
    if (o.has("rotate")) read_rotation(L, o, given);
    if (o.has("axis") && !o.has("rotate")) throw Error("option 'axis' is what 'rotate' turns about: give rotate too");
    opt.overhang =
        check_between(o.number("overhang", opt.overhang), 1, 89, "option 'overhang' (degrees from vertical)");
    const Spot spot = read_spot(o);
    o.finish();
    given.validate();

    std::string said;
    Affine3 turn;
    if (o.has("rotate")) {
      turn = given.map();
      print::OverhangOptions along{.angle = opt.overhang};
      const double before = print::overhang_of(*m, along).area;
      // The overhang once turned: measured along the direction the turn takes to +z.
      const Affine3 back = rotation(given.axis / norm(given.axis), -given.degrees);
      along.up = back.linear({0, 0, 1});
      said = "turned " + short_number(given.degrees) + "° about " + point_text(given.axis) + ": " +
             overhang_text(print::overhang_of(*m, along).area, opt.overhang, before);
    } else {
      const print::Orientation r = print::best_orientation(*m, opt, RunContext::of(L));
      turn = r.turn;
      const std::string overhang = overhang_text(r.overhang, opt.overhang, r.overhang_before);
      if (opt.least_overhang)
        said = "to the least overhang, resting on " +
               (r.face > 0 ? "a flat face of " + area_text(r.face) : std::string("an edge or a point")) + ": " +
               overhang;
      else
        said = r.face > 0 ? "on its largest flat face (" + area_text(r.face) + "), " + overhang
                          : "no flat face to lie on, left as it was: " + overhang;
    }
    push_on_bed(L, *m, &turn, spot);
    if (!RunContext::of(L).config.quiet) std::printf("%ssolid.orient: %s\n", recipe_where(L).c_str(), said.c_str());
    return 1;
  });
}

}  // namespace

void add_solid_placing(lua_State* L) {
  lua_pushcfunction(L, solid_place);
  lua_setfield(L, -2, "place");
  lua_pushcfunction(L, solid_orient);
  lua_setfield(L, -2, "orient");
}

}  // namespace selfsim::interp
