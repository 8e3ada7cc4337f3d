// Wall thickness and gap width at points of a closed solid's surface, measured on its signed distance
// (the print check, print_check.h). From a surface point p with outward normal n:
//   wall: march inwards along −n until the distance says "outside" again: the far side of the wall;
//   gap:  march outwards along +n until it says "inside" again: another part of the solid (or another
//         stretch of the same part) across a gap.
// Each crossing is placed by linear interpolation between the two samples around it, and counts only through
// a surface that faces the ray's start (keep_facing in wall_rays.cpp: not the far flank of a groove). A march that
// finds no crossing within its cap reads as the cap: the wall (or gap) is at least that. Thick bodies do not read as
// thin near their convex edges: a ray from near an edge runs beside the other face without crossing it. The distance
// function is passed in (an OpenVDB grid in the check, an exact one in the tests).
#pragma once

#include <functional>
#include <span>

#include "kernels/base/progress.h"
#include "kernels/geom/vec3.h"

namespace selfsim::print {

// Fills `out` with the signed distance at each point, positive inside the solid. Called from several
// threads at once.
using Clearance = std::function<void(std::span<const Vec3> points, std::span<double> out)>;

struct RayLimits {
  double step = 0;      // between samples along a ray, > 0
  double wall_cap = 0;  // the longest wall measured
  double gap_cap = 0;   // the widest gap measured
  // A crossing counts when the surface crossed is within acos(facing) of facing the ray. Gaps are stricter:
  // at the narrowest spot between two parts (or two stretches of one) the surfaces face each other exactly,
  // while the bottom of a V-shaped crease (a folded sheet's inner side) fills without joining anything new.
  double wall_facing = 0.7;  // 45 degrees: a wedge sharper than 90 degrees is thin near its edge
  double gap_facing = 0.94;  // 20 degrees: a crease's groove narrower than 40 degrees still counts
};

// wall[i] and gap[i] for the ray pair from points[i] along unit normals[i] (a zero normal reads as both
// caps: no direction to measure). Looks for a stop once per chunk of points.
void measure_rays(std::span<const Vec3> points, std::span<const Vec3> normals, const Clearance& clearance,
                  const RayLimits& limits, std::span<double> wall, std::span<double> gap, Progress& progress);

}  // namespace selfsim::print
