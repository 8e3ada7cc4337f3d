// Reading .stl, .obj and .ply meshes back (selfsim info / diff, load()) with OpenMesh's readers, guarded as
// vtk_read.cpp guards VTK's: OpenMesh trusts the file, so it reads in a forked child process with memory
// and time limits (child_process.h), the mesh comes back over a pipe as a Dataset of triangles, and the
// Dataset is checked. OpenMesh merges an STL's repeated corners into shared points and splits polygons
// into triangles. A face OpenMesh cannot hold (an edge of three faces, a bowtie) is an error naming
// OpenMesh's complaint, never a silently smaller mesh.

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

#include "kernels/geom/error.h"
#include "kernels/io/child_process.h"
#include "kernels/io/dataset_check.h"
#include "kernels/io/dataset_pipe.h"
#include "kernels/io/openmesh_mesh.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/regular_file.h"

namespace selfsim::io {

namespace {

// A binary STL is an 80-byte header, a uint32 triangle count, and 50 bytes per triangle.
bool binary_stl(const RegularFile& f) {
  std::uint32_t n = 0;
  if (f.size() < 84 || f.read_at(80, &n, 4) != 4) return false;
  return f.size() == 84 + 50 * std::uint64_t{n};
}

// A PLY header's element counts checked against the file: every element takes at least a byte, so a
// 100-byte file cannot declare a billion vertices and send OpenMesh's reader into allocating for them.
void check_ply_counts(const RegularFile& f) {
  char head[4096] = {};
  const std::size_t n = f.read_at(0, head, sizeof head - 1);
  std::istringstream lines(std::string(head, n));
  for (std::string line; std::getline(lines, line) && line.rfind("end_header", 0) != 0;) {
    std::istringstream words(line);
    std::string keyword, element;
    double count = 0;
    if (words >> keyword >> element >> count && keyword == "element" && count > static_cast<double>(f.size()))
      throw Error("the header declares " + std::to_string(static_cast<unsigned long long>(count)) + " " +
                  shown(element) + " elements, more than the file's " + std::to_string(f.size()) + " bytes could hold");
  }
}

void send_mesh(PipeOut& out, const OMesh& om) {
  put_count(out, static_cast<std::uint64_t>(CellShapes::polygons));
  put_count(out, om.n_vertices());
  for (const auto& vh : om.vertices()) out.write(om.point(vh).data(), 3 * sizeof(double));
  put_count(out, om.n_faces());
  for (std::uint64_t end = 3; end <= 3 * om.n_faces(); end += 3) out.write(&end, sizeof end);
  put_count(out, 3 * om.n_faces());
  for (const auto& fh : om.faces())
    for (const auto& vh : om.fv_range(fh)) {
      const std::uint64_t id = static_cast<std::uint64_t>(vh.idx());
      out.write(&id, sizeof id);
    }
  put_count(out, 0);  // no point fields
  put_count(out, 0);  // no cell fields
}

int read_in_child(PipeOut& out, const std::string& name, const std::string& ext, bool binary) {
  std::ostringstream complaints;
  quiet_openmesh(&complaints);
  std::ifstream in(name, std::ios::binary);
  OMesh om;
  OpenMesh::IO::Options opt = binary ? OpenMesh::IO::Options::Binary : OpenMesh::IO::Options::Default;
  const bool ok = in && OpenMesh::IO::read_mesh(om, in, ext, opt);
  std::string error;
  const std::string said = complaints.str();
  if (!said.empty())
    error = "OpenMesh: " + said.substr(0, std::min(said.find('\n'), std::size_t{300}));
  else if (!ok)
    error = "OpenMesh could not read it";
  else if (om.n_faces() == 0)
    error = "it holds no triangles";
  if (!error.empty()) {
    send_failure(out, error);
    return 0;
  }
  send_success(out);
  send_mesh(out, om);
  return 0;
}

Dataset read_checked(const std::filesystem::path& file, const std::string& ext) {
  const RegularFile f(file);
  const bool binary = ext == ".stl" && binary_stl(f);
  if (ext == ".ply") check_ply_counts(f);
  const std::string name = f.reopen_name(file);
  ChildLimits limits;
  limits.what = "the OpenMesh reader";
  // OpenMesh's half-edge mesh takes a few hundred bytes a triangle; an ASCII file some 30 bytes a triangle.
  limits.memory_bytes = std::min((std::uint64_t{1} << 30) + 64 * f.size(), 3 * read_budget_bytes());
  limits.seconds = 30 + static_cast<double>(f.size()) / (4 << 20);
  Dataset d;
  run_in_child(
      limits, [&](PipeOut& out) { return read_in_child(out, name, ext, binary); },
      [&](PipeIn& in) { d = receive_answer(in, limits.what, read_budget_bytes() / 8); });
  check_dataset(d);
  return d;
}

}  // namespace

Dataset read_mesh_file(const std::filesystem::path& file, const std::string& ext) {
  try {
    return read_checked(file, ext);
  } catch (const std::bad_alloc&) {
    throw Error(cannot_read(file, "out of memory"));
  } catch (const std::exception& e) {
    throw Error(cannot_read(file, e.what()));
  }
}

}  // namespace selfsim::io
