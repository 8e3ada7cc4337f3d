// One chunked writer for VTK's XML formats (.vtp lines and polygons, .vtu), used by every VTK writer.
// Arrays are produced chunk by chunk straight into the file: memory stays flat whatever the size, and
// progress is reported and cancellation checked per chunk.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/geom/field.h"
#include "kernels/io/output_file.h"

namespace selfsim::io {

// One appended array: `tuples` tuples of `components` values of VTK type `type`.
struct VtkArray {
  std::string name;
  std::string type;  // "Int32", "Int64", "Float64", "UInt8"
  int components = 1;
  std::size_t tuples = 0;
  // Writes the raw little-endian values of tuples [begin, end) to `out`, which has room for exactly them.
  std::function<void(std::size_t begin, std::size_t end, void* out)> fill;

  std::size_t value_bytes() const;
  std::size_t bytes() const { return tuples * static_cast<std::size_t>(components) * value_bytes(); }
};

// A named field as an array over `count` elements (a uniform field repeated).
VtkArray field_array(const Field& f, std::size_t count);

// An array whose tuple i is value(i), a single value of type T (int32, int64, uint8 or double).
template <class T, class Value>
VtkArray computed_array(std::string name, std::size_t tuples, Value value);

enum class VtkDataset { PolyDataLines, PolyDataPolys, UnstructuredGrid };

struct VtkPiece {
  VtkDataset dataset = VtkDataset::PolyDataLines;
  std::size_t points = 0, cells = 0;
  VtkArray coordinates;              // "Points", 3 components of Float64
  std::vector<VtkArray> topology;    // connectivity, offsets (and types for an unstructured grid)
  std::vector<VtkArray> point_data;  // written under their names
  std::vector<VtkArray> cell_data;
  std::string active_scalars;  // the point array ParaView colours by first; empty for none
  std::vector<std::pair<std::string, std::string>> field_strings;  // FieldData string arrays: name, text
};

// Writes VTK XML, version 1.0, appended raw little-endian data with UInt64 block headers.
void write_vtk_xml(const VtkPiece& piece, OutputFile& out, Progress& progress);

// VTK's name for the value type T.
template <class T>
constexpr const char* vtk_type_name() {
  if constexpr (std::is_same_v<T, std::int32_t>)
    return "Int32";
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return "Int64";
  else if constexpr (std::is_same_v<T, std::uint8_t>)
    return "UInt8";
  else {
    static_assert(std::is_same_v<T, double>, "int32, int64, uint8 or double");
    return "Float64";
  }
}

template <class T, class Value>
VtkArray computed_array(std::string name, std::size_t tuples, Value value) {
  return {std::move(name), vtk_type_name<T>(), 1, tuples, [value](std::size_t begin, std::size_t end, void* out) {
            T* o = static_cast<T*>(out);
            for (std::size_t i = begin; i < end; ++i) *o++ = static_cast<T>(value(i));
          }};
}

}  // namespace selfsim::io
