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

#include <cstdint>
#include <functional>
#include <span>

#include "kernels/base/progress.h"
#include "kernels/geom/triangle_bvh.h"
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

// The same readings by exact rays against the triangles themselves (the check's way unless a voxel is asked
// for): no grid, no step, no interpolation error. Along each ray the solid's winding number is counted, +1
// through a triangle facing the ray, -1 through one facing away (the parts of a solid that overlap are one
// solid, as the grid's union made them): the wall ends where it falls from 1 to 0, the far side of the wall;
// the gap where it first rises above 0, another part. The crossing counts when its triangle faces as
// `limits` says (the far flank of a groove does not), else the reading is the cap. Crossings at the same
// distance (a shared edge or vertex, which every triangle there reports) count once, and a ray that only
// grazes an edge between a face it would enter and one it would leave crosses nothing.
struct ExactRays {
  const TriangleBvh* bvh = nullptr;
  std::span<const std::uint32_t> faces;  // the triangle each point lies on: its own crossing is not counted
  double tmin = 0;         // mm, a rounding's width: crossings closer together are one, none nearer counts
  double orientation = 1;  // -1 when the triangles' winding faces inwards (the points' normals face out)
  // Per point, whether it may lie inside another part of the solid (a speck through a wall, parts that
  // cross: the caller knows which shells overlap); empty for none. Such a point, where it reads less than
  // a cap, is tested by a ray `far` long (past the solid's box): where the winding number beyond its face is
  // over 0 it is no surface of the solid and reads as both caps, as the grid's union has no surface there.
  std::span<const char> may_be_buried;
  double far = 0;
};
void measure_rays_exact(std::span<const Vec3> points, std::span<const Vec3> normals, const ExactRays& how,
                        const RayLimits& limits, std::span<double> wall, std::span<double> gap, Progress& progress);

}  // namespace selfsim::print
