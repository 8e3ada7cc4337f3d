// The print check's words: its findings, each a severity, what and where, and the change that fixes it in
// the recipe's own terms with numbers from the report; the one-line summary and a warning's brief line
// (print_check.h). Kept apart from the measuring (print_check.cpp), which only fills the report's numbers.
#include <algorithm>
#include <array>
#include <cmath>

#include "kernels/base/count_text.h"
#include "kernels/geom/point_text.h"
#include "kernels/print/print_check.h"
#include "kernels/print/print_size.h"

namespace selfsim::print {

namespace {

// A factor to scale by, rounded up to a tenth: "2.6x".
std::string times(double k) { return short_number(std::ceil(k * 10 - 1e-9) / 10) + "x"; }

// "<lead>2.6x (solid.size)", or nothing past 10x: a wall or gap of nearly nothing (where parts meet) is
// not fixed by scaling. "or more" when the reading is only a bound.
std::string scale_up(double k, bool resolved, const std::string& lead) {
  if (!(k <= 10)) return "";
  return lead + times(k) + (resolved ? "" : " or more") + " (solid.size)";
}

// A thickness as a recipe writes it: "0.8".
std::string length(double v) { return short_number(v); }

void add_walls(PrintReport& r) {
  const PrintRules& rules = r.rules;
  // A crossing within the rays' first half step is below what the grid resolves: said as "under" its bound.
  const double v = r.resolves(r.wall.value) ? r.wall.value : r.unresolved_bound();
  const std::string value = r.resolves(r.wall.value) ? mm_text(v) : r.unresolved();
  const std::string places = count_text(double(r.wall.places)) + (r.wall.places == 1 ? " place" : " places");
  // Thinner than the nozzle draws nothing there: a printer cannot make it. Between the nozzle and two
  // perimeters it prints, weakly or with gaps.
  add_problem(r, v < rules.nozzle ? Severity::will_fail : Severity::may_fail,
              "walls thinner than " + mm_text(rules.min_wall) + " at " + places + ", the thinnest " + value + " at " +
                  mm_point_text(r.wall.where),
              "thicken to " + mm_text(rules.min_wall) + " (solid.thicken's thickness = " + length(rules.min_wall) +
                  ", solid.tube's min_radius = " + length(rules.min_wall / 2) + ")" +
                  scale_up(rules.min_wall / v, r.resolves(r.wall.value), " or scale up "));
}

void add_gaps(PrintReport& r) {
  const PrintRules& rules = r.rules;
  const double v = r.resolves(r.gap.value) ? r.gap.value : r.unresolved_bound();
  const std::string value = r.resolves(r.gap.value) ? mm_text(v) : r.unresolved();
  const std::string places = count_text(double(r.gap.places)) + (r.gap.places == 1 ? " place" : " places");
  add_problem(r, Severity::may_fail,
              "gaps narrower than " + mm_text(rules.min_gap) + " (they fuse) at " + places + ", the narrowest " +
                  value + " at " + mm_point_text(r.gap.where),
              scale_up(rules.min_gap / v, r.resolves(r.gap.value), "scale up ") +
                  (rules.min_gap / v > 10 ? "" : " or ") + "thinner walls (thickness, radius)");
}

void add_contact(PrintReport& r) {
  const SelfContact& c = r.contact;
  const std::string more = c.capped ? " or more" : "", longer = c.crossings_capped ? " or more" : "";
  if (c.crossing)
    add_problem(r, Severity::will_fail,
                "it crosses itself near " + mm_point_text(c.crossing->where) + " (triangles " +
                    std::to_string(c.crossing->first + 1) + " and " + std::to_string(c.crossing->second + 1) +
                    ", along " + mm_text(c.crossing_length) + longer + ")",
                "method = \"grid\" (solid.thicken, solid.tube) merges it, or a smaller thickness or radius");
  // Separate closed solids overlapping: PrusaSlicer 2.5 slices two overlapping cubes saved as one mesh as
  // their union, but another slicer may not, and the walls between them are measured as one solid's.
  if (c.overlap)
    add_problem(r, Severity::may_fail,
                count_text(double(c.overlap_solids)) + " solids overlap near " + mm_point_text(c.overlap->where) +
                    " (triangles " + std::to_string(c.overlap->first + 1) + " and " +
                    std::to_string(c.overlap->second + 1) + ", along " + mm_text(c.overlap_length) + longer + ")",
                "solid.union{ ... } makes them one solid");
  if (c.crease)
    add_problem(r, Severity::cosmetic,
                "a crease where the surface touches itself near " + mm_point_text(*c.crease) + " (" +
                    count_text(double(c.crease_pairs)) + more + (c.crease_pairs == 1 ? " pair" : " pairs") +
                    " of triangles)",
                "a slicer fuses it");
  if (c.specks > 0)
    add_problem(r, Severity::cosmetic,
                count_text(double(c.specks)) + (c.specks == 1 ? " sealed speck" : " sealed specks") +
                    " smaller than the nozzle's spot (the largest " + mm_text(c.speck_across) + " across, near " +
                    mm_point_text(c.speck_where) + ")",
                c.specks == 1 ? "a slicer fuses or drops it" : "a slicer fuses or drops them");
}

}  // namespace

const char* severity_text(Severity s) {
  switch (s) {
    case Severity::will_fail:
      return "will fail";
    case Severity::may_fail:
      return "may fail";
    case Severity::cosmetic:
      return "cosmetic";
  }
  return "will fail";
}

void add_problem(PrintReport& r, Severity severity, std::string what, std::string fix) {
  Problem p{severity, std::move(what), std::move(fix)};
  // After every problem as serious or more: the most serious first, each kind in the order found.
  const auto at = std::find_if(r.problems.begin(), r.problems.end(),
                               [&](const Problem& q) { return int(q.severity) > int(severity); });
  r.problems.insert(at, p);
  r.findings.clear();
  for (const Problem& q : r.problems)
    if (q.severity != Severity::cosmetic) r.findings.push_back(q.line());
}

void add_findings(PrintReport& r) {
  const PrintRules& rules = r.rules;
  // Under 5 mm is almost always a solid still in its curve's units (a unit box, a radius of 1), not a print:
  // the cause of what else is found (thin walls, a speck of a first layer), said first.
  const double longest = std::max({r.box.size().x, r.box.size().y, r.box.size().z});
  if (longest < 5)
    add_problem(r, Severity::will_fail,
                "it is only " + mm_text(longest) + " across: probably still in model units (sizes are mm)",
                "solid.size(s, 80)");
  if (!r.topology.manifold())
    add_problem(r, Severity::will_fail, "not a 2-manifold: " + r.topology.first_problem,
                "make it on a grid, method = \"grid\" (solid.thicken, solid.tube)");
  // A closed mesh around nothing: flat (every point in one plane) or collapsed to a point or a line.
  const Vec3 size = r.box.size();
  if (!(std::abs(r.volume) > 1e-9 * size.x * size.y * size.z) || !(std::abs(r.volume) > 0))
    add_problem(r, Severity::will_fail, "it encloses no volume (a flat or collapsed mesh)",
                "a solid: solid.thicken of a surface, solid.tube of a curve");
  if (r.inward)
    add_problem(r, Severity::will_fail, "its triangles face inwards (a slicer may print it inside out)",
                "reverse each triangle's corners");
  add_contact(r);
  if (r.wall.measured && r.wall.under > 0 && !r.speck(r.wall)) add_walls(r);
  if (r.gap.measured && r.gap.under > 0 && !r.speck(r.gap)) add_gaps(r);
  if (static_cast<double>(r.triangles) > rules.max_triangles)
    add_problem(r, Severity::may_fail,
                count_text(double(r.triangles)) + " triangles, over the " + count_text(rules.max_triangles) +
                    " a slicer handles well",
                "solid.decimate(s, { triangles = " + short_number(rules.max_triangles, 15) + " })");
  if (rules.bed != Vec3{}) {
    // Any orientation on the bed: the sorted sides must fit the sorted bed.
    std::array<double, 3> part{size.x, size.y, size.z}, bed{rules.bed.x, rules.bed.y, rules.bed.z};
    std::sort(part.begin(), part.end());
    std::sort(bed.begin(), bed.end());
    if (part[0] > bed[0] || part[1] > bed[1] || part[2] > bed[2])
      add_problem(r, Severity::will_fail,
                  "it is " + size_text(size) + ", larger than the bed's " + size_text(rules.bed),
                  "solid.size(s, { fit = {" + short_number(rules.bed.x) + ", " + short_number(rules.bed.y) + ", " +
                      short_number(rules.bed.z) + "} })");
  }
  // Standing on a point or a knife edge. PrusaSlicer 2.5 stopped ("no extrusions in the first layer") on
  // pillars whose first layer was 0.03 to 0.34 mm² (0.4 mm nozzle, 0.2 mm layers; some of 0.22 and 0.28 mm²
  // sliced): under a disc two nozzle widths across (0.5 mm²) the first layer is too small to count on.
  // (Not said of a solid under 5 mm: still in model units, its first layer grows with solid.size.)
  // Resin prints stand on supports (sla): only a printer that lays the first layer on its bed needs one.
  if (r.first_layer < 4 * r.nozzle_spot() && longest >= 5 && r.rules.profile != "sla")
    add_problem(r, Severity::will_fail,
                "it stands on " + area_text(r.first_layer) +
                    ", under a disc two nozzles across: a slicer prints little or nothing in its first layer",
                "lay it on a face, solid.orient(s)");
  if (!r.skipped.empty()) add_problem(r, Severity::may_fail, r.skipped, "");
}

namespace {

// "overhang 3.2 cm² past 45°", or "no overhang past 45°". No advice to turn it: solid.orient may have
// turned it already, and a check cannot tell (docs/print.md says what reduces it).
std::string overhang_fact(const PrintReport& r) {
  const std::string past = " past " + short_number(r.rules.overhang) + "°";
  return r.overhang > 0 ? "overhang " + larger_area_text(r.overhang) + past : "no overhang" + past;
}

std::string tagged(const Problem& p) { return std::string(severity_text(p.severity)) + ": " + p.line(); }

}  // namespace

std::string PrintReport::summary() const {
  const auto at_least = [&](const Spot& s, double cap) {
    // Under the threshold over less than the nozzle's spot: no finding, and said so.
    const std::string speck =
        !this->speck(s) ? ""
        : s.places == 1 ? " on a " + area_text(s.largest_place) + " speck, smaller than the nozzle's spot"
                        : " on " + count_text(double(s.places)) + " specks, each smaller than the nozzle's spot";
    if (!resolves(s.value)) return unresolved() + speck;
    return (s.value >= cap ? ">= " : "") + mm_text(std::min(s.value, cap)) + speck;
  };
  std::string facts = size_text(box.size()) + ", " + count_text(double(triangles)) + " triangles";
  if (wall.measured) facts += ", walls " + at_least(wall, wall_cap) + ", gaps " + at_least(gap, gap_cap);
  if (wall.measured && spacing > std::max(voxel, rules.nozzle) * (1 + 1e-9))
    facts += ", measured every " + mm_text(spacing) + " (the point budget)";
  facts += ", " + overhang_fact(*this);
  std::string cosmetic;
  for (const Problem& p : problems)
    if (p.severity == Severity::cosmetic) cosmetic += "; " + tagged(p);
  if (passes()) return "print check (" + rules.profile + "): passes: closed, " + facts + cosmetic;
  std::string out = "print check (" + rules.profile + "): " + std::to_string(findings.size()) +
                    (findings.size() == 1 ? " problem: " : " problems: ");
  bool first = true;
  for (const Problem& p : problems)
    if (p.severity != Severity::cosmetic) {
      out += (first ? "" : "; ") + tagged(p);
      first = false;
    }
  return out + cosmetic + " (" + facts + ")";
}

std::string brief(const PrintReport& r, std::size_t bytes) {
  std::string all = r.summary();
  if (all.size() <= bytes) return all;
  std::string out = "print check (" + r.rules.profile + "): " + std::to_string(r.findings.size()) +
                    (r.findings.size() == 1 ? " problem: " : " problems: ");
  const std::string more = "; and more: solid.check lists them";
  std::size_t said = 0;
  for (const Problem& p : r.problems) {
    if (p.severity == Severity::cosmetic) continue;
    const std::string line = (said == 0 ? "" : "; ") + tagged(p);
    // Room for this line and for saying there is more (the first is said whatever its length).
    if (said > 0 && out.size() + line.size() + more.size() > bytes) return out + more;
    out += line;
    ++said;
  }
  return out;
}

// The bound said is two voxels, not the first step: the far side is placed by the grid's values at voxel
// corners, and a slab of 0.12 mm crosses within the first step as one of 0.03 mm does; tilted against the
// lattice, slabs of 0.18 mm still did (none of 0.2 mm in 90 random tilts and placements, where the grid
// read 0.2 mm).
std::string PrintReport::unresolved() const {
  return "under " + mm_text(2 * voxel) + " (two of the distance grid's " + mm_text(voxel) +
         " voxels: finer than it resolves)";
}

}  // namespace selfsim::print
