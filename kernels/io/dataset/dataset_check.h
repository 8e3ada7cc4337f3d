// Sanity checks on a Dataset just read, whatever reader made it: cells in order and referring to existing
// points, one field tuple per point or cell, every coordinate and field value finite (NaN and infinity are
// errors in selfsim, never data). Throws Error with the reason.
#pragma once

#include "kernels/io/dataset/dataset.h"

namespace selfsim::io {

void check_dataset(const Dataset& d);

}  // namespace selfsim::io
