// Overhang: the part of a solid's surface that faces down more steeply than a printer builds without
// support. A face's overhang angle is how far its outward normal tilts from horizontal towards straight
// down: 0 for a vertical wall (and for any face looking up), 90 for a flat ceiling. FDM printers bridge
// up to about 45 degrees (print_rules.h: `overhang`); past it a slicer adds supports. Faces that lie on the
// bed (every corner within `on_bed` of the lowest corner along `up`) rest on it and overhang nothing, so a
// cube has no overhang and a mushroom's cap has its whole underside. Only the triangles' corners count:
// a point no triangle uses (a stray point in a loaded file) does not lift the bed below the solid.
#pragma once

#include <vector>

#include "kernels/geom/mesh.h"
#include "kernels/geom/vec3.h"

namespace selfsim::print {

struct OverhangOptions {
  double angle = 45;     // degrees from vertical: faces tilted down past it overhang
  double on_bed = 0.01;  // mm: faces this near the lowest point rest on the bed
  Vec3 up{0, 0, 1};      // the build direction (a unit vector); the bed is the lowest plane across it
};

struct Overhang {
  double area = 0;            // mm² of the faces tilted down past the angle, off the bed
  Vec3 where;                 // the centroid of the largest such face (where to look), or the origin when none
  std::vector<double> angle;  // per face, degrees (0 on the bed); empty unless asked for
};

// The overhang of m along opt.up. With per_face, also every face's angle (for a field).
Overhang overhang_of(const Mesh& m, const OverhangOptions& opt, bool per_face = false);

}  // namespace selfsim::print
