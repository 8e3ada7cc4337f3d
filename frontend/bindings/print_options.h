// The print check as the bindings use it (issue 25): reading a printer's rules from options, running the
// check within the run's budget, warning when a solid-making function's result fails it, and the report as
// a Lua table. solid.* (bind_solid.cpp), develop{ size } and save() of a print format share it.
#pragma once

#include <lua.hpp>
#include <string>

#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "kernels/geom/mesh.h"
#include "kernels/print/print_check.h"

namespace selfsim::interp {

// Options profile ("fdm", "sla"), nozzle, min_wall, min_gap, triangles, overhang, bed and voxel, as PrintRules.
print::PrintRules read_print_rules(Options& o);

// A solid-making function's `check`: true (the default, the fdm profile), false, or a profile's name.
struct PrintCheckOption {
  bool on = true;
  print::PrintRules rules;
};
PrintCheckOption read_print_check(Options& o);

// check_print with the run's budget and progress. A value's report is kept while the value lives (values
// never change), so checking it again with the same rules costs nothing: the solid-making function's
// warning, save()'s summary and solid.check share one check (the report's `shared` says it was kept). The
// check marks a copy whenever the run can hold one (four times the solid's points left in the budget) and
// keeps its fields, so a later `marked` is made from them; otherwise `marked` measures again. A new check
// is also compared with the boxes the recipe grew things in (note_model_box, flag_model_box).
print::PrintReport check_print_in_run(lua_State* L, const Held<Mesh>& m, const print::PrintRules& rules,
                                      Mesh* marked = nullptr);
// Records a box the recipe grew something in (a volume.* region): a solid of its size is probably still in
// model units (print_check.h: flag_model_box).
void note_model_box(lua_State* L, const BBox3& box);

// Keeps r as the report of `m` (a marked copy pushed after its check).
void keep_print_report(lua_State* L, const Held<Mesh>& m, const print::PrintReport& r);

// With check.on, checks m and warns (one line, naming the recipe line and fn) when it fails.
void warn_unless_printable(lua_State* L, const char* fn, const Held<Mesh>& m, const PrintCheckOption& check);

// The same for a function whose result may be an open surface on its way to a solid (solid.smooth,
// solid.decimate): an open mesh is not checked.
void warn_unless_printable_solid(lua_State* L, const char* fn, const Held<Mesh>& m, const PrintCheckOption& check);

// The line save() prints under a print format's file: the check's summary (fdm), or that the mesh is an
// open surface and not a solid.
std::string print_summary(lua_State* L, const Held<Mesh>& m);

// Pushes the report as a table: passes, summary, findings (a list of the failing ones' lines), problems (a
// list of { severity = "will fail" | "may fail" | "cosmetic", what, fix }, cosmetic ones too), triangles,
// size {x, y, z}, thinnest_wall and narrowest_gap (mm; nil when not measured), thin and narrow (counts),
// closed, crossing, creases and specks (counts), overhang (mm²), reused (this call measured nothing).
void push_print_report(lua_State* L, const print::PrintReport& r);

}  // namespace selfsim::interp
