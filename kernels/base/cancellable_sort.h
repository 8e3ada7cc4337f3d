// std::sort that looks for a stop as it goes: sorting the sides of a mesh of millions of triangles takes
// a second or more, longer than a run may go on after --timeout or Ctrl-C. The comparison counts its calls
// and asks every 2^20 of them; Cancelled thrown from inside std::sort leaves the range in some order, which
// the caller, unwinding, no longer reads.
#pragma once

#include <algorithm>
#include <cstddef>

#include "kernels/base/progress.h"

namespace selfsim {

template <class It, class Less>
void cancellable_sort(It first, It last, Less less, Progress& progress) {
  std::size_t compared = 0;
  std::sort(first, last, [&](const auto& a, const auto& b) {
    if ((++compared & 0xfffff) == 0 && progress.cancelled()) throw Cancelled();
    return less(a, b);
  });
}

}  // namespace selfsim
