// The writers the format registry (format.cpp) calls: each writes one value into an OutputFile that save()
// then commits. Each is defined in the file named for its format.
#pragma once

#include "kernels/io/format.h"
#include "kernels/io/save.h"

namespace selfsim::io {

void write_vtp(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress);  // vtk_files.cpp
void write_vtu(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress);  // vtk_files.cpp
void write_svg(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress);  // svg_file.cpp
void write_eps(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress);  // eps_file.cpp
void write_stl(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress);  // mesh_files.cpp
void write_obj(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress);  // mesh_files.cpp
void write_ply(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress);  // mesh_files.cpp
void write_3mf(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress);  // threemf_file.cpp
void write_vdb(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress);  // vdb_file.cpp

}  // namespace selfsim::io
