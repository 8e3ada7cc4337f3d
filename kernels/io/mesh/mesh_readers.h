// selfsim's own readers of the mesh formats (stl_read.cpp, obj_read.cpp, ply_read.cpp): strict, streaming,
// in double precision, and with the line or element named when a file is wrong. They replace OpenMesh's
// readers, which skip what they cannot parse, drop faces, read doubles as floats and open the material
// files an OBJ names. Each throws Error with the reason; read_dataset adds the file's name.
#pragma once

#include "kernels/io/dataset/dataset.h"
#include "kernels/io/regular_file.h"

namespace selfsim::io {

Dataset read_stl(const RegularFile& f);
Dataset read_obj(const RegularFile& f);
Dataset read_ply(const RegularFile& f);
Dataset read_3mf(const RegularFile& f);  // through lib3mf (threemf_read.cpp): millimetres, every mesh object

}  // namespace selfsim::io
