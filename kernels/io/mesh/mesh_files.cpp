// .stl (binary), .obj and .ply (binary) meshes, written by OpenMesh's own writers so that what slicers and
// Blender read is what OpenMesh, a reference implementation of these formats, writes. to_openmesh below is
// the one place selfsim's Mesh meets OpenMesh's half-edge mesh; OpenMesh's headers stay in this file (they
// are heavy). Fields are not written: these formats have no place for them (.vtp and .vtu do).
// OpenMesh's writers take points as single-precision floats, so all three hold float32 coordinates: plenty
// for printing and rendering; .vtp and .vtu keep the doubles.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>
#include <cmath>
#include <limits>
#include <ostream>
#include <streambuf>
#include <string>
#include <string_view>
#include <vector>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/writers.h"

namespace selfsim::io {

namespace {

struct OpenMeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;  // selfsim's coordinates are doubles; keep them up to the writer
  using Normal = OpenMesh::Vec3d;
};
using OMesh = OpenMesh::TriMesh_ArrayKernelT<OpenMeshTraits>;

// OpenMesh prints progress and complaints to the terminal; selfsim reports through its own messages.
void quiet_openmesh() {
  static const bool done = [] {
    omlog().disable();
    omout().disable();
    omerr().disable();
    return true;
  }();
  (void)done;
}

// m as an OpenMesh mesh. OpenMesh holds only manifold meshes: throws Error naming the first triangle it
// refuses (an edge of three faces, a bowtie, a flipped neighbour) rather than dropping it.
OMesh to_openmesh(const Mesh& m) {
  quiet_openmesh();
  OMesh om;
  om.reserve(m.points.size(), 3 * m.faces() / 2 + m.points.size(), m.faces());
  std::vector<OMesh::VertexHandle> v;
  v.reserve(m.points.size());
  for (const Vec3& p : m.points) v.push_back(om.add_vertex(OMesh::Point(p.x, p.y, p.z)));
  for (std::size_t f = 0; f < m.faces(); ++f) {
    const Triangle& t = m.triangles[f];
    if (!om.add_face(v[t[0]], v[t[1]], v[t[2]]).is_valid())
      throw Error(
          "triangle " + std::to_string(f + 1) +
          " makes the mesh non-manifold (an edge of three faces, two faces meeting at a point, or a "
          "flipped neighbour): STL, OBJ and PLY are written through OpenMesh, which holds manifold meshes only");
  }
  return om;
}

// An ostream's buffer that passes its bytes on to an OutputFile and checks cancellation every megabyte,
// so OpenMesh's writers stream into our atomic, confined file and a long write can still be stopped.
// `header_line`, when given, goes in after the writer's second line: a PLY header's comment, which must
// follow "ply" and "format ...".
class FileBuffer : public std::streambuf {
 public:
  FileBuffer(OutputFile& out, Progress& progress, std::string header_line)
      : out_(out), progress_(progress), buffer_(1 << 20), header_line_(std::move(header_line)) {
    setp(buffer_.data(), buffer_.data() + buffer_.size());
  }

 protected:
  int_type overflow(int_type c) override {
    flush_buffer();
    if (!traits_type::eq_int_type(c, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(c);
      pbump(1);
    }
    return traits_type::not_eof(c);
  }
  int sync() override {
    flush_buffer();
    return 0;
  }

 private:
  void flush_buffer() {
    std::string_view bytes(pbase(), static_cast<std::size_t>(pptr() - pbase()));
    for (std::size_t i = 0; lines_ < 2 && i < bytes.size(); ++i)
      if (bytes[i] == '\n' && ++lines_ == 2 && !header_line_.empty()) {
        out_.write(bytes.substr(0, i + 1));
        out_.write(header_line_);
        bytes.remove_prefix(i + 1);
        break;
      }
    out_.write(bytes);
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    if (progress_.cancelled()) throw Cancelled();
  }

  OutputFile& out_;
  Progress& progress_;
  std::vector<char> buffer_;
  std::string header_line_;
  int lines_ = 0;
};

// These formats hold floats: a coordinate beyond float's range would be written as inf, and a non-zero one
// below its smallest normal value would collapse to 0, folding triangles flat.
void check_single_precision(const Mesh& m, const char* ext) {
  for (std::size_t i = 0; i < m.points.size(); ++i)
    for (double x : {m.points[i].x, m.points[i].y, m.points[i].z})
      if (std::abs(x) > std::numeric_limits<float>::max() ||
          (x != 0 && std::abs(x) < std::numeric_limits<float>::min()))
        throw Error(std::string(ext) + " holds single-precision coordinates, and point " + std::to_string(i + 1) +
                    " has " + number_text(x) + " (scale the mesh, or save as .vtp or .vtu, which keep doubles)");
}

void write_with_openmesh(const ValueRef& v, OutputFile& out, Progress& progress, const char* ext,
                         OpenMesh::IO::Options opt, std::streamsize precision, std::string header_line = {}) {
  const Mesh& m = *std::get<const Mesh*>(v);  // the registry sends only meshes here
  check_single_precision(m, ext);
  OMesh om = to_openmesh(m);
  progress.step(0.3);
  if (opt.check(OpenMesh::IO::Options::FaceNormal)) {
    om.request_face_normals();
    om.update_face_normals();
  }
  FileBuffer buffer(out, progress, std::move(header_line));
  std::ostream os(&buffer);
  os.exceptions(std::ios::badbit);  // an exception from the buffer (cancelled, disk full) reaches us
  if (!OpenMesh::IO::write_mesh(om, os, ext, opt, precision) || !os.flush())
    throw Error(std::string("OpenMesh could not write the mesh as ") + ext);
}

}  // namespace

void write_stl(const ValueRef& v, OutputFile& out, const SaveOptions&, Progress& progress) {
  write_with_openmesh(v, out, progress, ".stl",
                      OpenMesh::IO::Options(OpenMesh::IO::Options::Binary | OpenMesh::IO::Options::FaceNormal), 9);
}

void write_obj(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress) {
  if (!opt.provenance.empty()) out.write("# " + std::string(provenance_key) + " " + opt.provenance + "\n");
  write_with_openmesh(v, out, progress, ".obj", OpenMesh::IO::Options::Default, 9);  // a float32 in full
}

void write_ply(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress) {
  write_with_openmesh(
      v, out, progress, ".ply", OpenMesh::IO::Options(OpenMesh::IO::Options::Binary), 9,
      opt.provenance.empty() ? "" : "comment " + std::string(provenance_key) + " " + opt.provenance + "\n");
}

}  // namespace selfsim::io
