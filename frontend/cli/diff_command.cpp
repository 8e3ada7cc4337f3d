// `selfsim diff A B [--tol T]`: two geometry files read back and compared, the way the golden tests compare
// outputs.
#include <cstdio>

#include "frontend/cli/commands.h"
#include "frontend/lua/lua_support.h"
#include "kernels/analysis/dataset_diff.h"
#include "kernels/io/read.h"

namespace selfsim::interp {

int diff_command(const std::string& a, const std::string& b, double tol) {
  try {
    const io::Dataset da = io::read_dataset(a), db = io::read_dataset(b);
    const auto differences = analysis::dataset_diff(da, db, tol);
    for (const auto& d : differences) std::printf("%s\n", shown_text(d, 2000).c_str());
    if (differences.empty()) std::printf("same: %zu points, %zu cells\n", da.points.size(), da.cell_ends.size());
    return differences.empty() ? 0 : 1;
  } catch (...) {
    return report_failure("diff");
  }
}

}  // namespace selfsim::interp
