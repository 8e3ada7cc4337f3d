// .stl, .obj and .ply for selfsim info / diff and load(): selfsim's own strict readers (mesh_readers.h),
// then the same Dataset check every reader's result gets.
#include "kernels/base/error.h"
#include "kernels/io/dataset/dataset_check.h"
#include "kernels/io/mesh/mesh_readers.h"
#include "kernels/io/read.h"
#include "kernels/io/regular_file.h"

namespace selfsim::io {

// Errors are wrapped with the file's name by read_dataset.
Dataset read_mesh_file(const std::filesystem::path& file, const std::string& ext) {
  const RegularFile f(file);
  // Read data takes up to about 16 bytes per byte of file (an OBJ face "f 1 2 3": 8 bytes of text, 32 of
  // ids and ends, twice that while the arrays grow), so mesh files get a sixteenth of the reading limit.
  if (f.size() > read_budget_bytes() / 16)
    throw Error("the file is larger than the reading limit for mesh files (" +
                std::to_string(read_budget_bytes() / 16 >> 20) + " MiB, a sixteenth of " +
                std::to_string(read_budget_bytes() >> 20) + " MiB: reading takes up to 16 bytes per file byte)");
  Dataset d = ext == ".stl" ? read_stl(f) : ext == ".obj" ? read_obj(f) : ext == ".3mf" ? read_3mf(f) : read_ply(f);
  check_dataset(d);
  return d;
}

}  // namespace selfsim::io
