// Checks a .vtp or .vtu file's XML part against the file itself before VTK's reader sees it: VTK trusts declared
// sizes (NumberOfPoints="-5", a 1e15-point piece, a 2^40-block compression header) and then crashes,
// throws std::bad_alloc or loops. The XML part is streamed (tags of at most 64 KiB, no DOCTYPE or CDATA,
// bounded depth and array count; memory stays small whatever the file), up to <AppendedData> or the end.
// Checked: the root is <VTKFile type="PolyData"> (.vtp) or "UnstructuredGrid" (.vtu) with a known byte order, header
// type and compressor; every NumberOf* attribute is a plain non-negative decimal within limits; every array has a known
// type, a format, and data that fits the file: inline ascii holds at least as many characters as declared values,
// binary and appended data headers announce at least the declared bytes, inside the file (compressed
// blocks at most a compressor's maximum ratio larger than their compressed size); an appended file ends
// with </AppendedData></VTKFile> (a truncated tail is an error too); and the whole declared dataset fits
// read_budget_bytes. Throws Error with the reason.
#pragma once

#include <cstdint>
#include <string>

#include "kernels/io/regular_file.h"

namespace selfsim::io {

struct VtkDeclared {
  std::uint64_t points = 0;  // NumberOfPoints, summed over pieces
  std::uint64_t cells = 0;   // NumberOfVerts + Lines + Strips + Polys (or NumberOfCells), summed over pieces
  std::uint64_t bytes = 0;   // the dataset's size once read (values as doubles): the reader's memory need
};

// `dataset` is the VTKFile type the file must have: "PolyData" or "UnstructuredGrid".
VtkDeclared check_vtk_header(const RegularFile& file, const std::string& dataset);

}  // namespace selfsim::io
