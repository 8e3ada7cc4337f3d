// A closed region of space, the value `volume.box/sphere/mesh` and their union and difference make: where an
// exclusion surface (seed 004 in 3D) grows, and what a .vdb file stores as a level set.
//
// A Volume keeps its description, not a grid, so that each use picks its own resolution: a run resolves the
// region finer than the last radius it reaches (level_set.h), a .vdb file at the voxel size saved. A box, a
// sphere and a mesh have exact boundaries (a sphere's within a quarter voxel, see sphere_mesh); a union or
// difference gets its boundary from OpenVDB's level-set CSG at the voxel size, so it is as fine as the voxels.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/bbox.h"
#include "kernels/geom/mesh.h"
#include "kernels/region/grid_samples.h"

namespace selfsim {

// A union or difference nested deeper than this is refused: freeing a tree releases it one level at a time,
// each on the call stack.
inline constexpr int max_volume_depth = 100000;
// Unions and differences alternating deeper than this are refused: each alternation is converted by a call
// of its own (nested unions, and differences of differences, are flattened and cost none).
inline constexpr int max_conversion_depth = 2000;

struct Volume {
  enum class Kind { box, sphere, mesh, unite, subtract };
  Kind kind = Kind::box;
  Vec3 lo, hi;                                       // box: opposite corners, lo < hi
  Vec3 centre;                                       // sphere
  double radius = 0;                                 // sphere, > 0
  std::shared_ptr<const Mesh> mesh;                  // mesh: closed, not crossing itself, facing outwards
  std::shared_ptr<const GridSamples> samples;        // mesh read from a .vdb: the level set it was meshed from
  std::vector<std::shared_ptr<const Volume>> parts;  // unite: all of them; subtract: the first less the others
  double voxel = 0;                                  // the voxel size given by the recipe; 0: chosen by each use
  BBox3 bounds;                                      // kept when made: a union 20,000 deep is not walked again
  double held_bytes = 0;                             // bytes of the tree (each part as often as it appears)
  int depth = 1;                                     // levels of the tree, at most max_volume_depth
  int conversion_depth = 0;                          // nested calls converting it (unions in unions flattened)

  // Throw Error naming what is wrong ("option 'max' must be above 'min' in every coordinate", "the mesh is not
  // closed: its edge from point 3 to point 7 (in triangle 2) has no other triangle", ...).
  static Volume box(Vec3 lo, Vec3 hi);
  static Volume sphere(Vec3 centre, double radius);
  // Turns an inward-facing mesh outwards (by its signed volume).
  static Volume closed_mesh(Mesh m, Progress& progress);
  static Volume combine(Kind kind, std::vector<std::shared_ptr<const Volume>> parts);

  bool exact() const { return kind != Kind::unite && kind != Kind::subtract; }
  BBox3 bbox() const;
  // Bytes of C++ memory held (meshes included; a part used twice counted twice, to at most 2^62), and the
  // description for tostring: "Volume(box, ...)".
  std::size_t bytes() const;
  std::string summary() const;
  // The voxel size a use without its own choice takes: the given one, or 1/128 of the longest side.
  double default_voxel() const;
};

// The parts a union or a difference combines, with nested unions spliced into a union (a union grown one part
// at a time is a tree as deep as its parts) and each distinct part once (adding a part again adds nothing). A
// difference: its first part (nested differences' first parts followed down), then what is taken away.
// Iterative, so a tree 20,000 deep needs no deep call stack.
std::vector<const Volume*> combined_parts(const Volume& v);

// The distinct boxes, spheres and meshes a volume is made of, each once, whatever the depth.
std::vector<const Volume*> volume_leaves(const Volume& v);

// An icosphere: the icosahedron's faces split 1 -> 4 until no point lies more than `tolerance` inside the
// sphere (at most 7 times, 327,680 triangles), corners on the sphere, facing outwards.
Mesh sphere_mesh(Vec3 centre, double radius, double tolerance);

// Triangles of sphere_mesh for `tolerance`, to predict before building.
double sphere_triangles(double radius, double tolerance);

}  // namespace selfsim
