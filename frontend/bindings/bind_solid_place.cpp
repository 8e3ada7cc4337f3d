// solid.place and solid.orient: a solid put on the printer's bed (issue 40). Thin adapters over
// kernels/print/orient.h and kernels/geom/mesh_transform.h.
#include <cmath>
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
#include "kernels/print/print_size.h"

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
  // The box over the triangles' corners: a point no triangle uses does not hold the solid up.
  const BBox3 box = corner_bbox(placed);
  Vec3 shift = box.empty() ? Vec3{} : print::bed_shift(box);
  if (spot.centre)
    shift += {spot.at.x, spot.at.y, 0};
  else
    shift.x = shift.y = 0;
  for (Vec3& p : placed.points) p += shift;  // a move: no field changes
  if (!placed.finite()) throw Error("option 'at' moves the solid past the largest number");
  // Far out, double precision rounds the points together: a 10 mm tetrahedron at {1e308, 1e308} was
  // 0 x 0 x 10 mm, silently. Its box's sides may change by rounding, a billionth of its size, no more.
  if (!box.empty()) {
    const Vec3 before = box.size(), after = corner_bbox(placed).size();
    const double d = std::abs(after.x - before.x) + std::abs(after.y - before.y) + std::abs(after.z - before.z);
    if (d > 1e-9 * norm(before))
      throw Error("option 'at' = {" + number_text(spot.at.x) + ", " + number_text(spot.at.y) +
                  "} is too far for double precision to keep the solid's size (" + print::size_text(before) +
                  " became " + print::size_text(after) + "): place it nearer the origin");
  }
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

// "standing on 4.2 mm²", with a warning when that is under the first layer's least or its centre is off it.
std::string standing_text(const print::Orientation& r, const print::OrientOptions& opt) {
  const std::string on = "standing on " + area_text(r.first_layer);
  if (r.first_layer < opt.least_first_layer())
    return on + " (under the " + area_text(opt.least_first_layer()) + " a first layer needs)";
  return r.steady ? on : on + " (its centre of mass off it: a brim helps it stay)";
}

// The line solid.orient prints: the pose taken, what it stands on, its overhang.
std::string orient_text(const print::Orientation& r, const print::OrientOptions& opt, const MeshTransform* given) {
  const std::string overhang = overhang_text(r.overhang, opt.overhang, r.overhang_before);
  if (given)
    return "turned " + short_number(given->degrees) + "° about " + point_text(given->axis) + ", " +
           standing_text(r, opt) + ": " + overhang;
  if (opt.least_overhang)
    return std::string(r.kept ? "least overhang as it was" : "to the least overhang") + ", " + standing_text(r, opt) +
           ": " + overhang;
  // It turns only to stand on more than it did (best_orientation).
  if (r.kept) return "left as it was, " + standing_text(r, opt) + ": " + overhang;
  if (r.face >= opt.least_first_layer()) return "on its largest flat face (" + area_text(r.face) + "), " + overhang;
  return "laid across its thinnest side, " + standing_text(r, opt) + ": " + overhang;
}

// solid.orient(mesh, { face = "largest" } | { least = "overhang", overhang = 45 } | { rotate = 90, axis = {1,0,0} },
// nozzle = 0.4)
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
    opt.nozzle = check_between(o.number("nozzle", opt.nozzle), 0.01, 100, "option 'nozzle' (mm)");
    const Spot spot = read_spot(o);
    o.finish();
    given.validate();

    const print::Orientation r = o.has("rotate") ? print::orientation_by(*m, given.map(), opt)
                                                 : print::best_orientation(*m, opt, RunContext::of(L));
    push_on_bed(L, *m, &r.turn, spot);
    if (!RunContext::of(L).config.quiet)
      std::printf("%ssolid.orient: %s\n", recipe_where(L).c_str(),
                  orient_text(r, opt, o.has("rotate") ? &given : nullptr).c_str());
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
