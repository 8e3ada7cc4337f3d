// A bounding volume hierarchy over a mesh's triangles, for short rays that must find every triangle they
// cross, exactly (to rounding): the print check's walls and gaps (wall_rays.h). Boxes split at the median of
// their triangles' centres along their longest side, down to leaves of at most four triangles; nodes and
// triangles in flat arrays, each node's second child an offset from itself, so subtrees built apart (in
// parallel) are joined by copying. (Tried and left: halving a Morton order of the centres built in half the
// time and made the print check's rays five times slower; boxes in floats saved nothing.)
//
// A ray crossing a shared edge or vertex is reported by every triangle there (the barycentric test admits a
// rounding's width outside each triangle): a caller counting crossings merges those at the same distance
// (wall_rays.cpp), where a test that admitted none would let the ray slip through between them.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"

namespace selfsim {

class TriangleBvh {
 public:
  // One crossing: the ray's parameter there, the triangle, and the cosine between the triangle's outward
  // normal (by its winding) and the ray: negative where the ray enters the solid, positive where it leaves.
  struct Hit {
    double t;
    std::uint32_t face;
    double facing;
    std::uint32_t ray = 0;  // which of the rays crossed it (crossings of several rays at once)
  };

  // Budget points (16 bytes each) that building and holding the hierarchy of `triangles` takes at most.
  static double size(std::size_t triangles);

  // Over m's triangles (degenerate ones, with no area, are left out: no ray crosses them). Copies what it
  // needs: m may go. Cancelled when progress says stop.
  TriangleBvh(const Mesh& m, Progress& progress);

  // Appends to `hits` every triangle that origin + t·dir crosses for tmin < t <= tmax (dir a unit vector; tmin
  // may be negative: a line through origin, both ways), in no particular order. Safe to call from several
  // threads at once.
  void crossings(Vec3 origin, Vec3 dir, double tmin, double tmax, std::vector<Hit>& hits) const;
  // The same for several rays of one direction (the points of one triangle along its normal), each hit
  // tagged with its ray's index in `origins`: one search of the tree for them all, as one thick ray. Stops,
  // returning false, once its work (boxes looked at and crossings found) passes `most`: a caller that needs
  // only the first few crossings of rays through many triangles asks again over shorter stretches.
  bool crossings(std::span<const Vec3> origins, Vec3 dir, double tmin, double tmax, std::vector<Hit>& hits,
                 std::size_t most = SIZE_MAX) const;

  std::size_t nodes() const { return nodes_.size(); }
  std::size_t depth() const { return depth_; }

  struct Node {
    Vec3 lo, hi;
    std::uint32_t first = 0;  // a leaf's first triangle; an inner node's second child is at this + `first`
    std::uint32_t count = 0;  // a leaf's triangles (1 to 4); 0 for an inner node (first child: the next node)
  };
  struct Tri {
    Vec3 a, ab, ac;  // a corner and its two edges
    std::uint32_t face;
  };

 private:
  std::vector<Node> nodes_;
  std::vector<Tri> tris_;
  std::size_t depth_ = 0;
};

}  // namespace selfsim
