// The print check: is a solid, in millimetres, something a slicer accepts and a printer can make? It reports
// (print_rules.h gives the thresholds):
//   - whether the mesh is a closed 2-manifold facing outwards (an open surface is refused: thicken it first);
//   - whether it crosses itself, and where, told from creases and sealed specks a slicer fuses
//     (self_contact.h);
//   - the thinnest wall and the narrowest gap between parts, by rays from points on every triangle, inwards
//     to the far side of the wall and outwards to the next part (wall_rays.h): exact rays against the
//     triangles (triangle_bvh.h) by default, or with a voxel on the solid's OpenVDB distance grid, within its
//     interpolation error (WallGrid::error);
//   - what it stands on (first_layer.h) and its overhang (overhang.h);
//   - the triangle count and the bounding box, against the triangle budget and the printer's bed;
//   - a solid under 5 mm across, which is most often one still in its curve's units.
// Thin walls or narrow gaps over less area than the nozzle's spot (a disc of its width), and under a tenth
// of the surface, are no finding: the printer cannot draw anything that small (a mesher's dimple); the
// summary says them apart.
// Each problem is one finding: a severity (will fail, may fail, cosmetic), what it is and where, and the
// change that fixes it in the recipe's own terms, with numbers from the report (print_findings.cpp). The
// walls and gaps are also point and face fields (`wall`, `gap`, mm) so ParaView shows the thin spots, and
// the overhang (overhang.h; not a finding: supports print it) a face field `overhang` (degrees).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/geom/mesh_intersections.h"
#include "kernels/print/print_rules.h"
#include "kernels/print/self_contact.h"

namespace selfsim::print {

// The thinnest (or narrowest) spot found, and how many of the measured places fell under the threshold.
struct Spot {
  double value = 0;  // mm; the cap when nothing was measured below it
  Vec3 where;
  std::size_t under = 0;     // triangles under the threshold
  double area_under = 0;     // mm², of the triangles under the threshold
  std::size_t places = 0;    // the patches they make, joined at shared corners (thin_patches.h)
  double largest_place = 0;  // mm², the largest patch's area
  bool measured = false;     // false when the walls were not measured (see PrintReport::skipped)
};

// How serious a finding is: the slicer refuses it or the print cannot be made (will fail); it prints, but
// likely badly or not as meant (may fail); a slicer fuses or drops it harmlessly (cosmetic: no failure).
enum class Severity { will_fail, may_fail, cosmetic };
const char* severity_text(Severity s);  // "will fail", "may fail", "cosmetic"

struct Problem {
  Severity severity = Severity::will_fail;
  std::string what;  // what and where: "walls thinner than 0.8 mm at 12 places, the thinnest 0.31 mm at (...)"
  std::string fix;   // the change, in the recipe's terms: "thicken to 0.8 mm (thickness = 0.8) or ..."
  std::string line() const { return fix.empty() ? what : what + ": " + fix; }
};

struct PrintReport {
  PrintRules rules;
  std::size_t triangles = 0;
  double area = 0;  // mm², the whole surface's
  BBox3 box;
  MeshTopology topology;
  double volume = 0;                     // mm³ it encloses (negative facing inwards)
  bool inward = false;                   // closed, but facing inwards (negative volume)
  std::optional<TrianglePair> crossing;  // a crossing that counts: contact.crossing, else contact.overlap
  SelfContact contact;                   // crossings, creases and specks (self_contact.h)
  Spot wall, gap;
  double wall_cap = 0, gap_cap = 0;   // walls and gaps at least this wide read as this
  double voxel = 0, error = 0;        // the distance grid's voxel and interpolation error (mm); exact rays: their
                                      // rounding width (1e-10 of the size) and 0
  double spacing = 0;                 // mm: triangles are measured at points about this far apart
  std::string skipped;                // why walls and gaps were not measured (empty when they were)
  double overhang = 0;                // mm² facing down past rules.overhang along +z, off the bed (overhang.h)
  Vec3 overhang_where;                // its largest face's centre
  double first_layer = 0;             // mm² it stands on: its cross-section half a layer up (first_layer.h)
  bool shared = false;                // a kept report handed out again (the bindings set it): nothing measured for it
  std::vector<Problem> problems;      // every finding, cosmetic ones too, the most serious first
  std::vector<std::string> findings;  // the lines of those that fail (will fail, may fail)

  bool passes() const { return findings.empty(); }
  // A disc of the nozzle's width: the least area a thin wall or narrow gap must cover to be a finding.
  double nozzle_spot() const { return 0.25 * 3.14159265358979 * rules.nozzle * rules.nozzle; }
  // Under the threshold only on specks: every place less than the nozzle's spot, and all of them under a
  // tenth of the whole surface (a solid thin all over is no speck, however small).
  bool speck(const Spot& s) const {
    return s.under > 0 && s.largest_place < nozzle_spot() && s.area_under < 0.1 * area;
  }
  // One line: "print check: passes (closed, 120 x 80 x 40 mm, 212,340 triangles, walls >= 0.92 mm, gaps >=
  // 0.41 mm)" or "print check: 2 problems: ...; ...".
  std::string summary() const;
  // A wall or gap crossed within the rays' first step (half a voxel): "under 0.27 mm (two of the
  // distance grid's 0.13 mm voxels: finer than it resolves)": a wall tilted against the lattice reads so up
  // to about 1.4 voxels.
  std::string unresolved() const;
  // Whether a wall or gap reading is one the grid resolves (crossed past the rays' first half step); one
  // it does not is only known to be under unresolved_bound().
  bool resolves(double value) const { return value > 0.25 * voxel; }
  double unresolved_bound() const { return 2 * voxel; }
};

// Checks m (in millimetres) against rules. With `marked`, also returns m with the point and face fields
// `wall` and `gap` (mm) and `overhang` (degrees). Throws Error for a mesh with no triangles or an open one (naming an
// open edge); BudgetError does not escape: a distance grid over the budget leaves the walls unmeasured, which the
// report says (and suggests a larger voxel). Cancelled when progress says stop.
// Fills r.findings from the report's numbers (print_findings.cpp): what check_print ends with.
void add_findings(PrintReport& r);
// Adds a problem (kept in severity order; its line to findings unless cosmetic).
void add_problem(PrintReport& r, Severity severity, std::string what, std::string fix);

// The check's survey besides walls and gaps (print_survey.cpp), called by check_print: self-contact
// (crossings, creases, specks) into r.contact and r.crossing; the overhang into r.overhang, and with
// `marked` (already m, with its wall and gap fields) its fields `overhang` (degrees).
void survey_contact(const Mesh& m, PrintReport& r, Progress& progress);
void add_overhang(const Mesh& m, PrintReport& r, Mesh* marked);

// A solid whose longest side is that of a box the recipe grew it in (a region made by volume.*, whose
// longest side is a whole number of units up to 10), to a thousandth below and a fifth above (a surface
// filling the box, thickened): "probably still in model units" (may fail), once. The run records the boxes
// (print_options.h: note_model_box).
void flag_model_box(PrintReport& r, const std::vector<BBox3>& boxes);

// One line for a warning, under about `bytes`: the summary while it fits, else the problems most serious
// first, each with its fix, while they fit, and how many more solid.check lists.
std::string brief(const PrintReport& r, std::size_t bytes);

PrintReport check_print(const Mesh& m, const PrintRules& rules, const PointBudget& budget, Progress& progress,
                        Mesh* marked = nullptr);

}  // namespace selfsim::print
