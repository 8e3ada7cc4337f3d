// .3mf: the 3D Manufacturing Format, which unlike STL says its unit (millimetres here) and names its objects,
// written by lib3mf (the 3MF Consortium's own library, Debian's lib3mf 1.8). lib3mf's C interface declares
// Windows-style types and SAL macros globally, so it stays in this one file. The model is serialised once,
// into memory through lib3mf's write and seek callbacks (its zip writer seeks back to patch headers), and the
// bytes then go to the OutputFile like every other format: atomic, and confined to the output folder.
// A 3MF is a printable object: the mesh must be closed. Coordinates are written with lib3mf's six decimals
// (a nanometre in millimetres).
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/geom/mesh_check.h"
#include "kernels/io/mesh/lib3mf_call.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/text/xml_text.h"
#include "kernels/io/writers.h"

namespace selfsim::io {

namespace {

// The zip stream lib3mf writes, held in memory.
struct Bytes {
  std::string data;
  std::size_t at = 0;
};

// The callbacks' types as lib3mf's NMR_ExportStream_Callback.h declares them (nfUint32, nfByte, nfUint64).
std::uint32_t write_bytes(const std::uint8_t* data, std::uint32_t size, void* user) {
  Bytes& b = *static_cast<Bytes*>(user);
  if (b.at + size > b.data.size()) b.data.resize(b.at + size);
  std::memcpy(b.data.data() + b.at, data, size);
  b.at += size;
  return 0;  // lib3mf's callbacks return 0 on success
}

std::uint32_t seek_bytes(std::uint64_t position, void* user) {
  Bytes& b = *static_cast<Bytes*>(user);
  if (position > b.data.size()) b.data.resize(position);
  b.at = position;
  return 0;
}

// lib3mf gives the object, the build and its item random UUIDs, so the same recipe would write different
// bytes each run. UUIDs derived from the content instead (FNV-1a over the points and triangles, and a
// salt per use, in the 8-4-4-4-12 form with the version-4 and variant bits) keep files repeatable.
std::string content_uuid(const std::vector<NMR::MODELMESHVERTEX>& points,
                         const std::vector<NMR::MODELMESHTRIANGLE>& triangles, const std::string& name,
                         std::uint64_t salt) {
  std::uint64_t h[2] = {1469598103934665603ull ^ salt, 1099511628211ull + salt};
  const auto mix = [&](const void* data, std::size_t n) {
    const auto* b = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) {
      h[0] = (h[0] ^ b[i]) * 1099511628211ull;
      h[1] = (h[1] ^ b[i]) * 0x100000001b3ull + 0x9e3779b97f4a7c15ull;
    }
  };
  mix(points.data(), points.size() * sizeof(points[0]));
  mix(triangles.data(), triangles.size() * sizeof(triangles[0]));
  mix(name.data(), name.size());
  char text[40];
  std::snprintf(text, sizeof text, "%08x-%04x-4%03x-%04x-%012llx", static_cast<unsigned>(h[0] >> 32),
                static_cast<unsigned>(h[0] >> 16) & 0xffff, static_cast<unsigned>(h[0]) & 0xfff,
                (static_cast<unsigned>(h[1] >> 48) & 0x3fff) | 0x8000,
                static_cast<unsigned long long>(h[1] & 0xffffffffffffull));
  return text;
}

}  // namespace

void write_3mf(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress) {
  const Mesh& m = *std::get<const Mesh*>(v);
  const std::string open = first_open_edge(m);
  if (!open.empty())
    throw Error("a .3mf holds a printable solid, but the mesh is open (" + open +
                "): thicken the surface first (solid.thicken)");
  if (m.points.size() > 0xffffffffu || m.faces() > 0xffffffffu) throw Error("too many points for a .3mf");
  std::vector<NMR::MODELMESHVERTEX> points(m.points.size());
  for (std::size_t i = 0; i < m.points.size(); ++i) {
    if ((i & 0xffff) == 0xffff && progress.cancelled()) throw Cancelled();
    points[i].m_fPosition[0] = static_cast<float>(m.points[i].x);
    points[i].m_fPosition[1] = static_cast<float>(m.points[i].y);
    points[i].m_fPosition[2] = static_cast<float>(m.points[i].z);
  }
  std::vector<NMR::MODELMESHTRIANGLE> triangles(m.faces());
  for (std::size_t f = 0; f < m.faces(); ++f)
    for (int k = 0; k < 3; ++k) triangles[f].m_nIndices[k] = m.triangles[f][k];
  if (progress.cancelled()) throw Cancelled();

  Lib3mfHandle model, mesh, item, writer;
  lib3mf_check(NMR::lib3mf_createmodel(&model.p), nullptr, "create a model");
  lib3mf_check(NMR::lib3mf_model_setunit(model.p, NMR::MODELUNIT_MILLIMETER), model.p, "set the unit");
  const std::string leaf = out.leaf();
  const std::string name = !opt.name.empty() ? opt.name : leaf.substr(0, leaf.rfind('.'));
  // lib3mf writes metadata values into the XML as they are (object names it escapes itself).
  lib3mf_check(NMR::lib3mf_model_addmetadatautf8(model.p, "Title", xml_escaped(name).c_str()), model.p,
               "write the title");
  lib3mf_check(NMR::lib3mf_model_addmetadatautf8(model.p, "Application", xml_escaped(opt.application).c_str()), model.p,
               "write the application");
  if (!opt.provenance.empty())
    // In the well-known Description (slicers show it): lib3mf writes no namespace for a name of our own.
    lib3mf_check(NMR::lib3mf_model_addmetadatautf8(
                     model.p, "Description", xml_escaped(std::string(provenance_key) + " " + opt.provenance).c_str()),
                 model.p, "write how it was made");
  lib3mf_check(NMR::lib3mf_model_addmeshobject(model.p, &mesh.p), model.p, "add the mesh");
  lib3mf_check(NMR::lib3mf_object_setnameutf8(mesh.p, name.c_str()), mesh.p, "name the mesh");
  lib3mf_check(NMR::lib3mf_meshobject_setgeometry(mesh.p, points.data(), static_cast<DWORD>(points.size()),
                                                  triangles.data(), static_cast<DWORD>(triangles.size())),
               mesh.p, "store the mesh");
  lib3mf_check(NMR::lib3mf_model_addbuilditem(model.p, mesh.p, nullptr, &item.p), model.p, "place the mesh");
  lib3mf_check(NMR::lib3mf_object_setuuidutf8(mesh.p, content_uuid(points, triangles, name, 1).c_str()), mesh.p,
               "set the object's UUID");
  lib3mf_check(NMR::lib3mf_builditem_setuuidutf8(item.p, content_uuid(points, triangles, name, 2).c_str()), item.p,
               "set the build item's UUID");
  lib3mf_check(NMR::lib3mf_model_setbuilduuidutf8(model.p, content_uuid(points, triangles, name, 3).c_str()), model.p,
               "set the build's UUID");
  lib3mf_check(NMR::lib3mf_model_querywriter(model.p, "3mf", &writer.p), model.p, "make a writer");
  Bytes bytes;
  lib3mf_check(NMR::lib3mf_writer_writetocallback(writer.p, reinterpret_cast<void*>(&write_bytes),
                                                  reinterpret_cast<void*>(&seek_bytes), &bytes),
               writer.p, "write the file");
  if (progress.cancelled()) throw Cancelled();
  out.write(bytes.data);
}

}  // namespace selfsim::io
