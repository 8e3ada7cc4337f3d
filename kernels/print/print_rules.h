// What a printer can make, in millimetres: the thresholds the print check (print_check.h) measures a solid
// against. Named profiles give common defaults; any value may be set on its own.
//   "fdm": a 0.4 mm nozzle, walls of two perimeters (0.8 mm), gaps of a nozzle width (narrower ones fuse);
//   "sla": resin printers' usual limits, walls of 0.4 mm (supported), gaps of 0.5 mm (narrower ones cure
//          shut), a 0.15 mm spot.
// A slicer slows down, and some give up, past a few million triangles: 2 million is the default budget.
// Overhang (45 degrees from vertical) is the same for both: a resin print also needs supports under faces
// tilted past about 45 degrees (its layers peel off the vat's film), and the summary only reports the area.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "kernels/geom/vec3.h"

namespace selfsim::print {

struct PrintRules {
  std::string profile = "fdm";
  double nozzle = 0.4;         // mm: the smallest feature the printer draws
  double min_wall = 0.8;       // mm: thinner walls are findings
  double min_gap = 0.4;        // mm: narrower gaps between parts fuse
  double max_triangles = 2e6;  // more is a finding (decimate)
  double overhang = 45;        // degrees from vertical: faces tilted down past it need support (overhang.h)
  Vec3 bed{};                  // mm: the build volume; zero: not checked
  double voxel = 0;            // mm: walls and gaps on a distance grid of this voxel; 0: exact rays, no grid

  // Throws Error naming the option ("option 'min_wall' must be a number in [0.01, 100] (mm), got 0").
  void validate() const;
  bool operator==(const PrintRules&) const = default;
  // The profile's defaults; throws Error listing the profiles for an unknown name.
  static PrintRules named(std::string_view profile);
  static std::vector<std::string> profiles();
};

}  // namespace selfsim::print
