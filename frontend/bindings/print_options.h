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

// Options profile ("fdm", "sla"), nozzle, min_wall, min_gap, triangles, bed and voxel, as PrintRules.
print::PrintRules read_print_rules(Options& o);

// A solid-making function's `check`: true (the default, the fdm profile), false, or a profile's name.
struct PrintCheckOption {
  bool on = true;
  print::PrintRules rules;
};
PrintCheckOption read_print_check(Options& o);

// check_print with the run's budget and progress. A value's report is kept while the value lives (values
// never change), so checking it again with the same rules costs nothing; with `marked` the check runs (the
// fields need it) and its report is kept for m and for `marked_value`, the marked copy once it is a value.
print::PrintReport check_print_in_run(lua_State* L, const Held<Mesh>& m, const print::PrintRules& rules,
                                      Mesh* marked = nullptr);
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

// Pushes the report as a table: passes, summary, findings (a list), triangles, size {x, y, z}, thinnest_wall
// and narrowest_gap (mm; nil when not measured), thin and narrow (counts), closed, crossing.
void push_print_report(lua_State* L, const print::PrintReport& r);

}  // namespace selfsim::interp
