// The turtle for module grammars (module_rewrite.h), in 2D or 3D: the byte turtle's symbols with ABOP's
// parameters (ABOP 1.5, 1.10). F(len), G(len) and f(len) step len (1 without); +(a) and -(a) turn a degrees
// left or right (the grammar's angle without), a symbol of `angles` given a parameter turns that many
// degrees its way; in 3D also & ^ (pitch down, up), \ / (roll left, right), $ (roll until the left
// vector is horizontal) and tropism (turtle_frame3.h). '!(w)' sets the line width and '!' lowers it by 1
// (not below 0), '\''(i) sets the colour index and '\'' raises it by 1: each becomes a point field (`width`,
// in the curve's units, and `color`) when the grammar writes its symbol (a segment's is its end point's).
// '{' starts a polygon, '}' ends it: its corners are where the turtle starts it, every step's end inside it
// and every '.'; steps inside it draw no line.
#pragma once

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"
#include "kernels/geom/polyline.h"
#include "kernels/lsystem/grammar.h"
#include "kernels/lsystem/turtle/plant.h"
#include "kernels/lsystem/turtle/turtle2d.h"

namespace selfsim::lsystem {

// The curve of module grammar g at opt.level, placed as turtle2d() places curves (plant.h; in 3D, when
// normalised, an open curve's start onto (0,0,0) and end onto (1,0,0), turned the least way). A plant in
// 3D starts at the origin with heading H = +y, left L = -x and up U = +z (turtle_frame3.h), so a grammar
// kept in the plane of H and L draws what the 2D turtle draws, seen from +z with y up.
// A branched grammar's curve carries `branch_order` and `root_distance`, as turtle2d's.
Polyline module_turtle2d(const Grammar& g, const TurtleOptions& opt, Progress& progress);
Polyline3 module_turtle3d(const Grammar& g, const TurtleOptions& opt, Progress& progress);
// The level's polygons, triangulated, placed as its 3D curve; face fields `polygon` (which one) and
// `color` (the colour index when it was closed).
Mesh module_polygons(const Grammar& g, const TurtleOptions& opt, Progress& progress);

// The segments (drawing modules) of level `level`, counted by deriving it (a module grammar's length
// cannot be predicted); refuses past modules_per_point x max_points modules of work.
double module_segments(const Grammar& g, int level, double max_points, Progress& progress);

}  // namespace selfsim::lsystem
