// Similarity path substitution (seed 003 §1; seed 000 §1): every segment of a path is replaced by the
// image of a generator path running from 0 to 1, under the similarity taking 0 and 1 to the segment's ends,
// repeated `levels` times. Each generator segment may also carry one of the four transforms of seed 000
// Figure 2, which then applies at every deeper level, as in Kaplan's recursive KOCH(T∘Ti, level−1).
#pragma once

#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/progress.h"
#include "kernels/geom/polyline.h"
#include "kernels/geom/segment_transform.h"

namespace selfsim::substitute {

// How a copy of the generator sits on a segment: kernels/geom/segment_transform.h.
using selfsim::SegmentTransform;

struct SubstituteOptions {
  int levels = 1;                            // rounds of substitution, in [0, 64]
  std::vector<SegmentTransform> transforms;  // one per generator segment, or empty for all Identity
  PointBudget budget;                        // refuse (before any work) results predicted not to fit

  void validate(std::size_t generator_segments) const;
};

// The substituted curve. `path` is any curve (a path is closed if its ends coincide), each of its paths
// substituted on its own into one path of the result, which keeps the input's cell fields; `generator` must
// start at (0,0) and end at (1,0) with at least one segment. The result's level is opt.levels.
Polyline substitute(const Polyline& path, const Polyline& generator, const SubstituteOptions& opt, Progress& progress);

}  // namespace selfsim::substitute
