// A solid on the printer's bed: turned to lie on its largest flat face or to the least overhang
// (solid.orient), then put on z = 0 (solid.place).
//
// A pose is named by the direction `up` (a unit vector in the solid's own frame) that will point up; the
// solid rests on the plane that bounds it from below across `up`. Its flat face there is the area of its
// triangles lying in that plane (within `tolerance`, facing down within 2 degrees): several separate faces
// (a table's four feet) add up. Only a plane that bounds the solid counts, so a face it can really stand on.
// Only the points the triangles use count (a stray point below a solid does not hold it up).
//
// What a pose stands on must be enough for a first layer: the check's threshold (print_findings.cpp), a
// disc two nozzle widths across (pi nozzle², 0.503 mm² for a 0.4 mm nozzle), measured as the cross-section
// half a layer up (first_layer.h, layer = nozzle / 2). The largest flat face is taken only when it is at
// least that large; otherwise the pose is kept (a sliver facet is no better than the pose it came in).
//
// Candidates, for a cost bounded on any mesh (O(faces) once, then O(points) per candidate): the faces'
// normals are gathered on a cube map of 6 x 64 x 64 cells (about 1.4 degrees each), area and mean normal per
// cell. The largest flat face is looked for under the 48 cells of most area (a cell's area bounds the face
// its direction can hold, so the search stops at a cell smaller than the best face found). The least
// overhang is estimated from the cells alone for those directions, 1,000 directions spread evenly over the
// sphere (a Fibonacci lattice, about 6.5 degrees apart) and the six axes; the best 8, the 8 largest flat
// faces of at least the threshold and the pose as it came are measured exactly (overhang.h, first_layer.h).
// Poses whose first layer is under the threshold are not taken, unless none reaches it (then the pose with
// the largest first layer); of the rest the least overhang wins. Overhangs within a thousandth of the
// surface's area count as equal: then the larger first layer wins, then the lower solid, then the smaller
// turn from the pose it came in. So the result never has more overhang than the pose as it came (beyond
// that thousandth) when that pose stood on enough.
#pragma once

#include "kernels/base/progress.h"
#include "kernels/geom/bbox.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/mesh_transform.h"

namespace selfsim::print {

struct OrientOptions {
  bool least_overhang = false;  // false: the largest flat face
  double overhang = 45;         // degrees from vertical (print_rules.h)
  double nozzle = 0.4;          // mm: sets the least first layer (and its height, half a nozzle)

  // mm²: what a pose must stand on, a disc two nozzle widths across (print_findings.cpp's threshold).
  double least_first_layer() const;
};

struct Orientation {
  Vec3 up{0, 0, 1};            // the direction, in the solid's frame, that the turn points up
  Affine3 turn;                // the least rotation taking `up` to +z
  double face = 0;             // mm²: the flat face it rests on (0: it stands on an edge or a point)
  double overhang = 0;         // mm² past the angle, so turned
  double overhang_before = 0;  // mm² past the angle, as it came
  double first_layer = 0;      // mm² it stands on, so turned (first_layer.h)
  bool steady = false;         // its centre of mass over its footprint (footing.h)
  bool kept = false;           // the pose as it came (no turn)
};

// The best pose of m for opt. Looks for a stop once per candidate pass.
Orientation best_orientation(const Mesh& m, const OrientOptions& opt, Progress& progress = no_progress());

// m turned by the rotation `turn` (solid.orient{ rotate }), measured as best_orientation measures a pose.
// A translation in `turn` is ignored (the solid is placed afterwards).
Orientation orientation_by(const Mesh& m, const Affine3& turn, const OrientOptions& opt);

// The least rotation taking the unit vector `up` to +z (half a turn about x for -z).
Affine3 turn_up(Vec3 up);

// The area of m's faces lying on the plane that bounds it from below across the unit vector `up`.
double resting_area(const Mesh& m, Vec3 up);

// The shift that puts a solid of bounding box `box` on the bed: its lowest point at z = 0 and its footprint
// (the box's x and y) centred on x = y = 0, where slicers centre a part anyway.
Vec3 bed_shift(const BBox3& box);

}  // namespace selfsim::print
