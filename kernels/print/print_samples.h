// Where the print check measures walls and gaps (print_check.h): from points inside every triangle, along
// its normal. Not from the mesh's points: a point on a sharp edge (a thickened sheet's rim) has no normal a
// ray can follow. A triangle no longer than the spacing gives its incentre (its point farthest from its
// edges); a longer one is halved across its longest edge until the halves are that small, each giving its
// incentre, so a coarse CAD face (a wedge of 8 triangles) is measured as densely as a finely meshed one: one
// ray from a long face's middle would miss a thin strip along its edge.
#pragma once

#include <cstdint>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/mesh.h"

namespace selfsim::print {

struct Samples {
  std::vector<Vec3> points, normals;  // normals: unit, outwards (a zero one for a triangle with no area)
  std::vector<std::uint32_t> face;    // the triangle each point is on; a triangle's points are consecutive
  std::vector<double> area;           // mm² of its triangle each point stands for
};

// How far apart the points are, and where each run of triangles' points start (runs of sample_run
// triangles; the last entry is the count).
struct SamplePlan {
  double spacing = 0;
  std::vector<std::size_t> starts;
  std::size_t count() const { return starts.back(); }
};
inline constexpr std::size_t sample_run = 4096;

// Points `finest` apart, or, where that makes more than `most`, the finest spacing that does not among
// sqrt(area / (0.433 most)) and that times 1.25, 1.25², ... (halves no longer than s have at most
// sqrt(3)/4 s² of area each: any finer spacing would surely make more). Counted in parallel, a ladder of
// spacings in one pass, past the rungs a lower bound rules out. `most` at least the triangles (each gives
// a point at least). Cancelled when progress says stop.
SamplePlan plan_samples(const Mesh& m, double finest, double area, double most, Progress& progress);

// The points of the plan (normals flipped for a mesh facing inwards), in parallel.
Samples samples_of(const Mesh& m, bool inward, const SamplePlan& plan);

// Leaves out the points within `inset` of a sharp edge or corner of the solid (sharp_edges.h), for the
// distance grid: a ray from beside one runs along the face beyond it, within the grid's interpolation error
// of crossing it, and reads a thick body as thin. Measured from the solid's edges, not the triangle's, so
// the same face as two triangles or as 20,000 slivers keeps the same points. A smooth patch narrower than
// two insets (a thin slab's side, a tube's facet) keeps its points at least half as far from its edges as
// its farthest.
void clear_of_edges(const Mesh& m, Samples& s, double inset);

}  // namespace selfsim::print
