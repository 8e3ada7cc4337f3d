// The .vtp and .svg fuzz targets: the input is written to a file with the format's extension and read
// back with io::read_dataset, then handed to what `selfsim info` and `selfsim diff` do with a dataset. A
// selfsim::Error is a proper refusal; a crash, a hang, a leak or any other exception is a finding, as is
// a dataset whose cells are malformed (cell_ends must rise to cell_points.size()) or that differs from
// itself under dataset_diff.
//
// Environment:
//   SELFSIM_FUZZ_VERBOSE=1      print each refusal's message, or the size of what was read
//   SELFSIM_FUZZ_VTP_STRICT=1   .vtp only: VTK misbehaving in read_vtk's child process (a crash, a
//                               sanitizer report, a hang, running out of memory) is a finding too, although
//                               read_vtk turns it into an Error by design: it means check_vtk_header let
//                               through a file that VTK cannot handle.
#pragma once

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

#include "fuzz/fuzz_support.h"
#include "kernels/analysis/dataset_diff.h"
#include "kernels/base/error.h"
#include "kernels/io/read.h"

namespace selfsim::fuzz {

inline int read_one(const std::uint8_t* data, std::size_t size, const char* extension) {
  // One file per process, rewritten for every input (libFuzzer runs inputs one after another).
  static const std::filesystem::path file =
      std::filesystem::temp_directory_path() / ("selfsim-fuzz-" + std::to_string(::getpid()) + extension);
  static const struct Remove {
    ~Remove() { std::filesystem::remove(file); }
  } remove_at_exit;
  std::FILE* f = std::fopen(file.c_str(), "wb");
  if (f == nullptr) finding("cannot write " + file.string());
  if (size > 0 && std::fwrite(data, 1, size, f) != size) finding("cannot write " + file.string());
  std::fclose(f);

  static const bool verbose = env_flag("SELFSIM_FUZZ_VERBOSE");
  static const bool strict = env_flag("SELFSIM_FUZZ_VTP_STRICT");
  io::Dataset d;
  try {
    d = io::read_dataset(file);
  } catch (const Error& e) {
    const std::string_view message = e.what();
    if (verbose) std::fprintf(stderr, "refused: %s\n", e.what());
    // Only read_vtk's own words count: the reason comes right after "cannot read 'FILE': " (a file may
    // quote anything in the reasons VTK or the header check give).
    const std::string own = "cannot read '" + file.string() + "': the VTK reader ";
    if (strict && message.substr(0, own.size()) == own)
      for (const char* what :
           {"crashed (", "failed (exit status", "did not finish within", "was killed", "ran out of memory"})
        if (message.substr(own.size()).starts_with(what))
          finding(std::string("check_vtk_header let through a file VTK cannot read: the VTK reader ") + what);
    return 0;
  } catch (...) {
    unexpected_exception("io::read_dataset");
  }
  if (verbose) std::fprintf(stderr, "read: %zu points, %zu cells\n", d.points.size(), d.cell_ends.size());
  std::size_t begin = 0;
  for (std::size_t end : d.cell_ends) {
    require(end >= begin, "cell_ends decreases");
    begin = end;
  }
  require(begin == d.cell_points.size(), "cell_ends does not end at cell_points.size()");
  try {
    // What `selfsim diff` does: a file compared with itself has no differences (NaN matches NaN).
    const auto differences = analysis::dataset_diff(d, d, 1e-9);
    require(differences.empty(),
            "dataset_diff of a dataset with itself: " + (differences.empty() ? "" : differences[0]));
  } catch (...) {
    unexpected_exception("analysis::dataset_diff");
  }
  return 0;
}

}  // namespace selfsim::fuzz
