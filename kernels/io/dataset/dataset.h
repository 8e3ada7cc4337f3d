// A geometry file's content as read back for `selfsim diff` and `selfsim info`: points, polyline cells and
// named fields, whatever format it came from.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace selfsim::io {

// The most memory a Dataset read back from a file may need (its values as doubles): a sixth of this
// machine's memory, at most 16 GiB (2^28 points, the default --max-points, with cells and fields). Reading
// holds the data about twice (VTK's arrays in the reading child, then the Dataset), so a file declaring the
// most still leaves two thirds of the machine free. Readers refuse files that declare more before
// allocating anything: a few megabytes of compressed zeros cannot declare their way to an OOM kill.
std::uint64_t read_budget_bytes();

struct FieldValues {
  int components = 1;
  std::vector<double> values;  // tuple after tuple
};

// What a dataset's cells are: polylines (curves), polygons (surfaces), or both.
enum class CellShapes : std::uint64_t { lines = 0, polygons = 1, mixed = 2 };

struct Dataset {
  CellShapes shapes = CellShapes::lines;
  std::vector<std::array<double, 3>> points;
  std::vector<std::size_t> cell_ends;  // cell i uses point ids cell_points[cell_ends[i-1] .. cell_ends[i])
  std::vector<std::size_t> cell_points;
  std::map<std::string, FieldValues> point_fields;
  std::map<std::string, FieldValues> cell_fields;
  // How it was made (provenance.h), as the format holds it: a VTK file's FieldData string, a 3MF file's
  // Description; empty for other readers.
  std::string provenance;
};

}  // namespace selfsim::io
