// A geometry file's content as read back for `selfsim diff` and `selfsim info`: points, polyline cells and
// named fields, whatever format it came from.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

namespace selfsim::io {

struct Field {
  int components = 1;
  std::vector<double> values;  // tuple after tuple
};

struct Dataset {
  std::vector<std::array<double, 3>> points;
  std::vector<std::size_t> cell_ends;  // cell i uses point ids cell_points[cell_ends[i-1] .. cell_ends[i])
  std::vector<std::size_t> cell_points;
  std::map<std::string, Field> point_fields;
  std::map<std::string, Field> cell_fields;
};

}  // namespace selfsim::io
