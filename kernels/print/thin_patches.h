// Where a solid is thin, place by place. A wall or gap under its threshold is a finding only where one
// place of it covers at least the nozzle's spot: the faces under the threshold, joined where they share a
// corner, are the places, and each is judged by its own area. Added up over a whole tree, a few hundred
// specks of a hundredth of a square millimetre each (where a grid tube's branches part, a ray from beside
// the notch between them crosses only a chord) read as one thin wall of a square millimetre that nothing
// in the print has.
#pragma once

#include <cstddef>
#include <vector>

#include "kernels/geom/mesh.h"

namespace selfsim::print {

struct Patches {
  std::size_t count = 0;  // patches
  double largest = 0;     // mm², the largest one's area
};

// The patches of faces whose `flagged` entry is non-zero, joined through shared points.
Patches thin_patches(const Mesh& m, const std::vector<char>& flagged);

}  // namespace selfsim::print
