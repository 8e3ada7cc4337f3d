// Geometry-aware comparison of two files' contents, for `selfsim diff` and the golden tests: same points
// within a tolerance, same cells, same fields with values within the tolerance.
#pragma once

#include <string>
#include <vector>

#include "kernels/io/dataset/dataset.h"

namespace selfsim::analysis {

// Human-readable differences, at most max_reports of them (empty when the datasets match).
// Coordinates and field values match when |a - b| <= tol * max(1, |a|, |b|).
std::vector<std::string> dataset_diff(const io::Dataset& a, const io::Dataset& b, double tol,
                                      std::size_t max_reports = 10);

}  // namespace selfsim::analysis
