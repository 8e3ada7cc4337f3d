#include "frontend/bindings/print_options.h"

#include "frontend/lua/lua_support.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/value_types.h"
#include "kernels/geom/mesh_check.h"

namespace selfsim::interp {

print::PrintRules read_print_rules(Options& o) {
  print::PrintRules r = print::PrintRules::named(
      print::PrintRules::profiles()[o.enumeration("profile", print::PrintRules::profiles(), 0)]);
  r.nozzle = o.number("nozzle", r.nozzle);
  r.min_wall = o.number("min_wall", r.min_wall);
  r.min_gap = o.number("min_gap", r.min_gap);
  r.max_triangles = o.number("triangles", r.max_triangles);
  if (const auto bed = o.point3("bed")) r.bed = *bed;
  r.voxel = o.number("voxel", r.voxel);
  r.validate();
  return r;
}

PrintCheckOption read_print_check(Options& o) {
  PrintCheckOption c;
  const int type = o.push("check");
  if (type == LUA_TBOOLEAN) {
    c.on = o.boolean("check", true);
  } else if (type == LUA_TSTRING) {
    c.rules = print::PrintRules::named(
        print::PrintRules::profiles()[o.enumeration("check", print::PrintRules::profiles(), 0)]);
  } else if (type != LUA_TNIL) {
    throw Error("option 'check' must be true, false or a printer profile ('fdm', 'sla')");
  }
  return c;
}

// Reports by value. A value that has died no longer matches (its weak pointer expired), so an address reused
// by a new value is never mistaken for it; the dead entries go when a report is kept.
struct PrintReports {
  struct Entry {
    std::weak_ptr<const Mesh> mesh;
    print::PrintReport report;
  };
  std::vector<Entry> entries;

  const print::PrintReport* find(const Held<Mesh>& m, const print::PrintRules& rules) const {
    for (const Entry& e : entries)
      if (e.report.rules == rules && !e.mesh.expired() && e.mesh.lock() == m) return &e.report;
    return nullptr;
  }
  void keep(const Held<Mesh>& m, const print::PrintReport& r) {
    std::erase_if(entries, [](const Entry& e) { return e.mesh.expired(); });
    entries.push_back({m, r});
  }
};

namespace {

PrintReports& reports_of(lua_State* L) {
  RunContext& run = RunContext::of(L);
  if (!run.print_reports) run.print_reports = std::make_shared<PrintReports>();
  return *run.print_reports;
}

}  // namespace

print::PrintReport check_print_in_run(lua_State* L, const Held<Mesh>& m, const print::PrintRules& rules, Mesh* marked) {
  PrintReports& reports = reports_of(L);
  if (marked == nullptr)
    if (const print::PrintReport* r = reports.find(m, rules)) return *r;
  print::PrintReport r =
      with_budget(L, [&](const PointBudget& b) { return print::check_print(*m, rules, b, RunContext::of(L), marked); });
  reports.keep(m, r);
  return r;
}

void keep_print_report(lua_State* L, const Held<Mesh>& m, const print::PrintReport& r) { reports_of(L).keep(m, r); }

void warn_unless_printable(lua_State* L, const char* fn, const Held<Mesh>& m, const PrintCheckOption& check) {
  if (!check.on) return;
  const print::PrintReport r = check_print_in_run(L, m, check.rules);
  if (r.passes()) return;
  const std::string message = recipe_where(L) + fn + ": " + r.summary() + " (check = false to skip)";
  lua_warning(L, message.c_str(), 0);
}

void warn_unless_printable_solid(lua_State* L, const char* fn, const Held<Mesh>& m, const PrintCheckOption& check) {
  if (check.on && mesh_topology(*m, RunContext::of(L)).closed()) warn_unless_printable(L, fn, m, check);
}

std::string print_summary(lua_State* L, const Held<Mesh>& m) {
  if (const print::PrintReport* r = reports_of(L).find(m, print::PrintRules{})) return r->summary();
  const MeshTopology t = mesh_topology(*m, RunContext::of(L));
  if (t.boundary_edges > 0)
    return "print check: an open surface (" + std::to_string(t.boundary_edges) +
           " boundary edges), not a solid: thicken it to print (solid.thicken)";
  return check_print_in_run(L, m, print::PrintRules{}).summary();
}

void push_print_report(lua_State* L, const print::PrintReport& r) {
  lua_createtable(L, 0, 12);
  lua_pushboolean(L, r.passes());
  lua_setfield(L, -2, "passes");
  lua_pushstring(L, r.summary().c_str());
  lua_setfield(L, -2, "summary");
  lua_createtable(L, static_cast<int>(r.findings.size()), 0);
  for (std::size_t i = 0; i < r.findings.size(); ++i) {
    lua_pushstring(L, r.findings[i].c_str());
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "findings");
  lua_pushinteger(L, static_cast<lua_Integer>(r.triangles));
  lua_setfield(L, -2, "triangles");
  push_point(L, r.box.size());
  lua_setfield(L, -2, "size");
  lua_pushboolean(L, r.topology.closed() && !r.inward);
  lua_setfield(L, -2, "closed");
  lua_pushboolean(L, r.crossing.has_value());
  lua_setfield(L, -2, "crossing");
  if (r.wall.measured) {
    // A reading finer than the grid resolves is given as the bound it is under, with `*_resolved` false:
    // the rays' first-step number means nothing (0.03 mm for a 0.12 mm slab).
    const auto push_reading = [&](const print::Spot& s, double cap, const char* name, const char* resolved) {
      lua_pushnumber(L, r.resolves(s.value) ? std::min(s.value, cap) : r.unresolved_bound());
      lua_setfield(L, -2, name);
      lua_pushboolean(L, r.resolves(s.value));
      lua_setfield(L, -2, resolved);
    };
    push_reading(r.wall, r.wall_cap, "thinnest_wall", "wall_resolved");
    push_reading(r.gap, r.gap_cap, "narrowest_gap", "gap_resolved");
    lua_pushinteger(L, static_cast<lua_Integer>(r.wall.under));
    lua_setfield(L, -2, "thin");
    lua_pushinteger(L, static_cast<lua_Integer>(r.gap.under));
    lua_setfield(L, -2, "narrow");
  }
}

}  // namespace selfsim::interp
