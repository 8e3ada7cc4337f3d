// The print check's words: its findings, each a line naming where the problem is, and the one-line summary
// (print_check.h). Kept apart from the measuring (print_check.cpp), which only fills the report's numbers.
#include <algorithm>
#include <array>

#include "kernels/base/count_text.h"
#include "kernels/geom/point_text.h"
#include "kernels/print/print_check.h"
#include "kernels/print/print_size.h"

namespace selfsim::print {

void add_findings(PrintReport& r) {
  const PrintRules& rules = r.rules;
  if (!r.topology.manifold()) r.findings.push_back("not a 2-manifold: " + r.topology.first_problem);
  if (r.inward) r.findings.push_back("its triangles face inwards (a slicer may print it inside out)");
  if (r.crossing)
    r.findings.push_back("it crosses itself near " + mm_point_text(r.crossing->where) + " (triangles " +
                         std::to_string(r.crossing->first + 1) + " and " + std::to_string(r.crossing->second + 1) +
                         ")");
  const auto places = [](std::size_t n) { return count_text(double(n)) + (n == 1 ? " place" : " places"); };
  // A crossing within the rays' first half step is below what the grid resolves: said as "under" its bound.
  const auto measured = [&](double v) { return r.resolves(v) ? mm_text(v) : r.unresolved(); };
  if (r.wall.measured && r.wall.under > 0 && !r.speck(r.wall))
    r.findings.push_back("walls thinner than " + mm_text(rules.min_wall) + " at " + places(r.wall.under) +
                         ", the thinnest " + measured(r.wall.value) + " at " + mm_point_text(r.wall.where));
  if (r.gap.measured && r.gap.under > 0 && !r.speck(r.gap))
    r.findings.push_back("gaps narrower than " + mm_text(rules.min_gap) + " (they fuse) at " + places(r.gap.under) +
                         ", the narrowest " + measured(r.gap.value) + " at " + mm_point_text(r.gap.where));
  if (static_cast<double>(r.triangles) > rules.max_triangles)
    r.findings.push_back(count_text(double(r.triangles)) + " triangles, over the " + count_text(rules.max_triangles) +
                         " a slicer handles well (decimate it)");
  const Vec3 size = r.box.size();
  if (rules.bed != Vec3{}) {
    // Any orientation on the bed: the sorted sides must fit the sorted bed.
    std::array<double, 3> part{size.x, size.y, size.z}, bed{rules.bed.x, rules.bed.y, rules.bed.z};
    std::sort(part.begin(), part.end());
    std::sort(bed.begin(), bed.end());
    if (part[0] > bed[0] || part[1] > bed[1] || part[2] > bed[2])
      r.findings.push_back("it is " + size_text(size) + ", larger than the bed's " + size_text(rules.bed));
  }
  const double longest = std::max({size.x, size.y, size.z});
  // Under 5 mm is almost always a solid still in its curve's units (a unit box, a radius of 1), not a print.
  if (longest < 5)
    r.findings.push_back("it is only " + mm_text(longest) +
                         " across: probably still in model units (sizes are mm): solid.size(s, 80)");
  if (!r.skipped.empty()) r.findings.push_back(r.skipped);
}

std::string PrintReport::summary() const {
  const auto at_least = [&](const Spot& s, double cap) {
    // Under the threshold over less than the nozzle's spot: no finding, and said so.
    const std::string speck =
        this->speck(s) ? " on a " + area_text(s.area_under) + " speck, smaller than the nozzle's spot" : "";
    if (!resolves(s.value)) return unresolved() + speck;
    return (s.value >= cap ? ">= " : "") + mm_text(std::min(s.value, cap)) + speck;
  };
  std::string facts = size_text(box.size()) + ", " + count_text(double(triangles)) + " triangles";
  if (wall.measured) facts += ", walls " + at_least(wall, wall_cap) + ", gaps " + at_least(gap, gap_cap);
  if (wall.measured && spacing > std::max(voxel, rules.nozzle) * (1 + 1e-9))
    facts += ", measured every " + mm_text(spacing) + " (the point budget)";
  if (passes()) return "print check (" + rules.profile + "): passes: closed, " + facts;
  std::string out = "print check (" + rules.profile + "): " + std::to_string(findings.size()) +
                    (findings.size() == 1 ? " problem: " : " problems: ");
  for (std::size_t i = 0; i < findings.size(); ++i) out += (i == 0 ? "" : "; ") + findings[i];
  return out + " (" + facts + ")";
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
