// The four ways a copy of a path running from 0 to 1 can sit on a segment (seed 000 §1, Figure 2, and §2.2's
// copies in MULTIPLY), in the segment's own frame (0 at its start, 1 at its end). Substitution names them by
// the segment (reflect_segment, reflect_bisector, half_turn), hoisting by the axes of the unit frame
// (reflect_x, reflect_y, rotate); they are the same four maps.
#pragma once

#include "kernels/geom/similarity.h"

namespace selfsim {

enum class SegmentTransform {
  Identity,         // z -> z
  ReflectSegment,   // z -> conj(z): mirrored across the segment (the x axis of the unit frame)
  ReflectBisector,  // z -> 1 - conj(z): mirrored across the perpendicular bisector (the line x = 1/2)
  HalfTurn,         // z -> 1 - z: turned half a circle about the segment's midpoint
};

// The transform as a map of the unit frame.
inline Similarity2 unit_map(SegmentTransform t) {
  switch (t) {
    case SegmentTransform::Identity:
      return {};
    case SegmentTransform::ReflectSegment:
      return {{1, 0}, {0, 0}, true};
    case SegmentTransform::ReflectBisector:
      return {{-1, 0}, {1, 0}, true};
    case SegmentTransform::HalfTurn:
      return {{-1, 0}, {1, 0}, false};
  }
  return {};
}

// True where the copy is walked from its end, so that it still runs from 0 to 1 and the path stays connected.
inline bool walks_backwards(SegmentTransform t) {
  return t == SegmentTransform::ReflectBisector || t == SegmentTransform::HalfTurn;
}

}  // namespace selfsim
