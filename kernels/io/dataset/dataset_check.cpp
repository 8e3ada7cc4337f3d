#include "kernels/io/dataset/dataset_check.h"

#include <cmath>
#include <string>

#include "kernels/base/error.h"

namespace selfsim::io {

namespace {

void check_fields(const std::map<std::string, FieldValues>& fields, std::size_t tuples, const char* where) {
  for (const auto& [name, f] : fields) {
    const std::string what = std::string(where) + " field '" + name + "'";
    if (f.components < 1) throw Error(what + " has " + std::to_string(f.components) + " components");
    if (f.values.size() != tuples * static_cast<std::size_t>(f.components))
      throw Error(what + " has " + std::to_string(f.values.size()) + " values, expected " + std::to_string(tuples) +
                  " " + where + "s x " + std::to_string(f.components) + " components");
    for (std::size_t i = 0; i < f.values.size(); ++i)
      if (!std::isfinite(f.values[i]))
        throw Error(what + " has a non-finite value (" + std::to_string(f.values[i]) + ") at " + where + " " +
                    std::to_string(i / static_cast<std::size_t>(f.components) + 1));  // from 1, as c:point(i)
  }
}

}  // namespace

void check_dataset(const Dataset& d) {
  for (std::size_t i = 0; i < d.points.size(); ++i)
    for (double v : d.points[i])
      if (!std::isfinite(v))
        throw Error("point " + std::to_string(i) + " has a non-finite coordinate (" + std::to_string(v) + ")");
  std::size_t begin = 0;
  for (std::size_t c = 0; c < d.cell_ends.size(); ++c) {
    if (d.cell_ends[c] < begin || d.cell_ends[c] > d.cell_points.size())
      throw Error("cell " + std::to_string(c) + " has a bad extent in the connectivity list");
    begin = d.cell_ends[c];
  }
  if (begin != d.cell_points.size()) throw Error("the connectivity list has point ids after the last cell");
  for (std::size_t i = 0; i < d.cell_points.size(); ++i)
    if (d.cell_points[i] >= d.points.size())
      throw Error("a cell refers to point " +
                  std::to_string(static_cast<long long>(d.cell_points[i])) +  // a negative id shows as one
                  ", but there are only " + std::to_string(d.points.size()) + " points");
  check_fields(d.point_fields, d.points.size(), "point");
  check_fields(d.cell_fields, d.cell_ends.size(), "cell");
}

}  // namespace selfsim::io
