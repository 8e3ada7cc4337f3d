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
  r.overhang = o.number("overhang", r.overhang);
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
// by a new value is never mistaken for it; the dead entries go when a report is kept. A report keeps its
// solid's `wall` and `gap` fields (point and face: about as much memory as the solid itself) when the run
// could afford them, so solid.check after a warning or a save marks the solid without measuring it again.
struct PrintReports {
  struct Entry {
    std::weak_ptr<const Mesh> mesh;
    print::PrintReport report;
    std::shared_ptr<const std::pair<Fields, Fields>> marks;  // point and face fields; null when not kept
    double bytes = 0;                                        // the marks' memory, held against --max-memory
  };
  std::vector<Entry> entries;
  std::vector<BBox3> model_boxes;  // boxes the recipe grew things in (note_model_box)

  const Entry* find(const Held<Mesh>& m, const print::PrintRules& rules) const {
    for (const Entry& e : entries)
      if (e.report.rules == rules && !e.mesh.expired() && e.mesh.lock() == m) return &e;
    return nullptr;
  }
  // Keeps r (and marks, whose `bytes` the caller holds) for m; the dead values' entries go, their marks'
  // memory released.
  void keep(lua_State* L, const Held<Mesh>& m, const print::PrintReport& r,
            std::shared_ptr<const std::pair<Fields, Fields>> marks = nullptr, double bytes = 0) {
    double released = 0;
    std::erase_if(entries, [&](const Entry& e) {
      if (e.mesh.expired()) released += e.bytes;
      return e.mesh.expired();
    });
    if (released > 0) hold_memory(L, -released);
    entries.push_back({m, r, std::move(marks), bytes});
  }
};

namespace {

PrintReports& reports_of(lua_State* L) {
  RunContext& run = RunContext::of(L);
  if (!run.print_reports) run.print_reports = std::make_shared<PrintReports>();
  return *run.print_reports;
}

}  // namespace

void note_model_box(lua_State* L, const BBox3& box) {
  std::vector<BBox3>& boxes = reports_of(L).model_boxes;
  if (boxes.size() < 64) boxes.push_back(box);  // the first few: recipes grow in one or two
}

print::PrintReport check_print_in_run(lua_State* L, const Held<Mesh>& m, const print::PrintRules& rules, Mesh* marked) {
  PrintReports& reports = reports_of(L);
  if (const PrintReports::Entry* e = reports.find(m, rules)) {
    if (marked == nullptr || e->marks) {
      print::PrintReport r = e->report;
      r.shared = true;
      if (marked != nullptr) {
        *marked = *m;
        marked->point_fields = e->marks->first;
        marked->face_fields = e->marks->second;
        print::add_overhang(*m, r, marked);
      }
      return r;
    }
  }
  // Marked always when the run can hold a copy of the solid beside the check, so that a later solid.check
  // shares this check; its fields are kept with the report.
  Mesh own;
  Mesh* mark = marked;
  if (mark == nullptr && with_budget(L, [&](const PointBudget& b) { return b.left() > 4 * budget_size(*m); }))
    mark = &own;
  print::PrintReport r =
      with_budget(L, [&](const PointBudget& b) { return print::check_print(*m, rules, b, RunContext::of(L), mark); });
  print::flag_model_box(r, reports.model_boxes);
  // The wall and gap fields (the overhang is made again in an instant), held against --max-memory: kept
  // only when they fit.
  std::shared_ptr<std::pair<Fields, Fields>> marks;
  double bytes = 0;
  if (mark != nullptr && mark->point_fields.find("wall") != nullptr) {
    marks = mark == &own
                ? std::make_shared<std::pair<Fields, Fields>>(std::move(own.point_fields), std::move(own.face_fields))
                : std::make_shared<std::pair<Fields, Fields>>(mark->point_fields, mark->face_fields);
    marks->first.erase("overhang");
    marks->second.erase("overhang");
    bytes = static_cast<double>(marks->first.bytes() + marks->second.bytes());
    try {
      hold_memory(L, bytes);
    } catch (const Error&) {
      marks = nullptr;
      bytes = 0;
    }
  }
  reports.keep(L, m, r, std::move(marks), bytes);
  return r;
}

void keep_print_report(lua_State* L, const Held<Mesh>& m, const print::PrintReport& r) { reports_of(L).keep(L, m, r); }

void warn_unless_printable(lua_State* L, const char* fn, const Held<Mesh>& m, const PrintCheckOption& check) {
  if (!check.on) return;
  const print::PrintReport r = check_print_in_run(L, m, check.rules);
  if (r.passes()) return;
  // Warnings are cut at 500 bytes: the problems most serious first, with their fixes, while they fit.
  const std::string where = recipe_where(L) + fn + ": ", skip = " (check = false to skip)";
  const std::size_t room = 490 > where.size() + skip.size() ? 490 - where.size() - skip.size() : 100;
  const std::string message = where + print::brief(r, room) + skip;
  lua_warning(L, message.c_str(), 0);
}

void warn_unless_printable_solid(lua_State* L, const char* fn, const Held<Mesh>& m, const PrintCheckOption& check) {
  if (check.on && mesh_topology(*m, RunContext::of(L)).closed()) warn_unless_printable(L, fn, m, check);
}

std::string print_summary(lua_State* L, const Held<Mesh>& m) {
  if (const PrintReports::Entry* e = reports_of(L).find(m, print::PrintRules{})) return e->report.summary();
  const MeshTopology t = mesh_topology(*m, RunContext::of(L));
  if (t.boundary_edges > 0)
    return "print check: an open surface (" + std::to_string(t.boundary_edges) +
           " boundary edges), not a solid: thicken it to print (solid.thicken)";
  return check_print_in_run(L, m, print::PrintRules{}).summary();
}

void push_print_report(lua_State* L, const print::PrintReport& r) {
  lua_createtable(L, 0, 16);
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
  // Every finding, cosmetic ones too, the most serious first: { severity, what, fix }.
  lua_createtable(L, static_cast<int>(r.problems.size()), 0);
  for (std::size_t i = 0; i < r.problems.size(); ++i) {
    const print::Problem& p = r.problems[i];
    lua_createtable(L, 0, 3);
    lua_pushstring(L, print::severity_text(p.severity));
    lua_setfield(L, -2, "severity");
    lua_pushstring(L, p.what.c_str());
    lua_setfield(L, -2, "what");
    lua_pushstring(L, p.fix.c_str());
    lua_setfield(L, -2, "fix");
    lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
  }
  lua_setfield(L, -2, "problems");
  lua_pushinteger(L, static_cast<lua_Integer>(r.triangles));
  lua_setfield(L, -2, "triangles");
  push_point(L, r.box.size());
  lua_setfield(L, -2, "size");
  lua_pushboolean(L, r.topology.closed() && !r.inward);
  lua_setfield(L, -2, "closed");
  lua_pushboolean(L, r.crossing.has_value());
  lua_setfield(L, -2, "crossing");
  lua_pushinteger(L, static_cast<lua_Integer>(r.contact.crease_pairs));
  lua_setfield(L, -2, "creases");
  lua_pushinteger(L, static_cast<lua_Integer>(r.contact.specks));
  lua_setfield(L, -2, "specks");
  lua_pushnumber(L, r.overhang);
  lua_setfield(L, -2, "overhang");
  lua_pushnumber(L, r.first_layer);
  lua_setfield(L, -2, "first_layer");
  lua_pushboolean(L, r.shared);
  lua_setfield(L, -2, "reused");
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
    lua_pushinteger(L, static_cast<lua_Integer>(r.wall.places));
    lua_setfield(L, -2, "thin");
    lua_pushinteger(L, static_cast<lua_Integer>(r.gap.places));
    lua_setfield(L, -2, "narrow");
  }
}

}  // namespace selfsim::interp
