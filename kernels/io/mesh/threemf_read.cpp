// Reading .3mf files back (selfsim diff, selfsim info) with lib3mf's own reader: every mesh object, its
// points converted to millimetres from the model's unit (any of the six the 3MF core specification names;
// another is refused, where lib3mf would read it as millimetres), its triangles, and the object's name as
// the cell field `object` (the objects in file order, counted from 0). Build items' placements are not applied:
// objects are compared as they are defined. Like threemf_file.cpp, lib3mf's C interface stays in this file.
#include <Common/NMR_ErrorConst.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/io/dataset/dataset_pipe.h"
#include "kernels/io/mesh/lib3mf_call.h"
#include "kernels/io/mesh/mesh_readers.h"
#include "kernels/io/mesh/zip_part.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/text/xml_text.h"

namespace selfsim::io {

namespace {

// The units of the 3MF core specification (its `unit` attribute), which lib3mf maps to MODELUNIT_*.
const std::vector<std::string> units{"micron", "millimeter", "centimeter", "inch", "foot", "meter"};

// lib3mf reads a unit it does not know as millimetres, with only a warning: refuse it, naming it (read
// from the root model part ourselves: lib3mf keeps nothing of the text).
void refuse_unknown_unit(NMR::PLib3MFBase* reader, const std::vector<BYTE>& bytes) {
  DWORD count = 0;
  if (NMR::lib3mf_reader_getwarningcount(reader, &count) != LIB3MF_OK) return;
  bool invalid = false;
  for (DWORD i = 0; i < count && !invalid; ++i) {
    DWORD code = 0;
    ULONG need = 0;
    if (NMR::lib3mf_reader_getwarningutf8(reader, i, &code, nullptr, 0, &need) == LIB3MF_OK)
      invalid = code == NMR_ERROR_INVALIDMODELUNIT;
  }
  if (!invalid) return;
  const std::string_view zip(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  // The root model part: the package relationship of type .../3dmodel, by default /3D/3dmodel.model.
  std::string root = "3D/3dmodel.model";
  if (const auto rels = zip_part_head(zip, "_rels/.rels", 1 << 16))
    for (std::size_t at = 0; (at = rels->find("<Relationship ", at)) != std::string::npos; ++at) {
      const std::string_view one = std::string_view(*rels).substr(at);
      const auto type = xml_attribute(one, "Relationship", "Type");
      const auto target = xml_attribute(one, "Relationship", "Target");
      if (type && target && type->ends_with("/3dmodel")) {
        root = *target;
        break;
      }
    }
  std::optional<std::string> unit;
  if (const auto model = zip_part_head(zip, root, 1 << 16)) unit = xml_attribute(*model, "model", "unit");
  throw Error("the unit " + (unit ? "'" + shown(*unit) + "' " : std::string()) + "is not a 3MF unit; expected one of " +
              quoted_list(units));
}

// Millimetres per unit of a 3MF model (its `unit` attribute).
double millimetres(DWORD unit) {
  switch (unit) {
    case NMR::MODELUNIT_MICROMETER:
      return 1e-3;
    case NMR::MODELUNIT_CENTIMETER:
      return 10;
    case NMR::MODELUNIT_INCH:
      return 25.4;
    case NMR::MODELUNIT_FOOT:
      return 304.8;
    case NMR::MODELUNIT_METER:
      return 1000;
    default:
      return 1;
  }
}

// The model's metadata value under `key`, or empty.
std::string metadata_value(NMR::PLib3MFModel* model, const std::string& key) {
  DWORD count = 0;
  if (NMR::lib3mf_model_getmetadatacount(model, &count) != LIB3MF_OK) return {};
  for (DWORD i = 0; i < count; ++i) {
    ULONG n = 0;
    if (NMR::lib3mf_model_getmetadatakeyutf8(model, i, nullptr, 0, &n) != LIB3MF_OK) continue;
    std::string name(n + 1, '\0');
    if (NMR::lib3mf_model_getmetadatakeyutf8(model, i, name.data(), n + 1, &n) != LIB3MF_OK) continue;
    name.resize(std::min<std::size_t>(n, std::strlen(name.c_str())));  // n may count the terminating NUL
    if (name != key) continue;
    if (NMR::lib3mf_model_getmetadatavalueutf8(model, i, nullptr, 0, &n) != LIB3MF_OK || n > (1u << 16)) return {};
    std::string value(n + 1, '\0');
    if (NMR::lib3mf_model_getmetadatavalueutf8(model, i, value.data(), n + 1, &n) != LIB3MF_OK) return {};
    value.resize(std::min<std::size_t>(n, std::strlen(value.c_str())));
    return xml_unescaped(value);  // lib3mf hands back the XML text as it is in the file
  }
  return {};
}

// The file parsed by lib3mf, in this process.
Dataset parse_3mf(const RegularFile& f) {
  std::vector<BYTE> bytes(f.size());
  if (f.read_at(0, bytes.data(), bytes.size()) != bytes.size()) throw Error("the file changed while it was read");
  Lib3mfHandle model, reader, meshes;
  lib3mf_check(NMR::lib3mf_createmodel(&model.p), nullptr, "create a model");
  lib3mf_check(NMR::lib3mf_model_queryreader(model.p, "3mf", &reader.p), model.p, "make a reader");
  lib3mf_check(NMR::lib3mf_reader_readfrombuffer(reader.p, bytes.data(), bytes.size()), reader.p, "read it");
  refuse_unknown_unit(reader.p, bytes);
  DWORD unit = NMR::MODELUNIT_MILLIMETER;
  lib3mf_check(NMR::lib3mf_model_getunit(model.p, &unit), model.p, "read its unit");
  const double scale = millimetres(unit);
  lib3mf_check(NMR::lib3mf_model_getmeshobjects(model.p, &meshes.p), model.p, "list its meshes");
  Dataset d;
  d.shapes = CellShapes::polygons;
  d.provenance = metadata_value(model.p, "Description");
  FieldValues object;
  BOOL next = 0;
  for (int k = 0; NMR::lib3mf_resourceiterator_movenext(meshes.p, &next) == LIB3MF_OK && next; ++k) {
    Lib3mfHandle mesh;
    lib3mf_check(NMR::lib3mf_resourceiterator_getcurrent(meshes.p, &mesh.p), meshes.p, "open a mesh");
    DWORD nv = 0, nt = 0;
    lib3mf_check(NMR::lib3mf_meshobject_getvertexcount(mesh.p, &nv), mesh.p, "count its points");
    lib3mf_check(NMR::lib3mf_meshobject_gettrianglecount(mesh.p, &nt), mesh.p, "count its triangles");
    std::vector<NMR::MODELMESHVERTEX> points(nv);
    std::vector<NMR::MODELMESHTRIANGLE> triangles(nt);
    if (nv > 0)
      lib3mf_check(NMR::lib3mf_meshobject_getvertices(mesh.p, points.data(), nv, &nv), mesh.p, "read its points");
    if (nt > 0)
      lib3mf_check(NMR::lib3mf_meshobject_gettriangleindices(mesh.p, triangles.data(), nt, &nt), mesh.p,
                   "read its triangles");
    const std::size_t base = d.points.size();
    for (const auto& p : points)
      d.points.push_back({scale * p.m_fPosition[0], scale * p.m_fPosition[1], scale * p.m_fPosition[2]});
    for (const auto& t : triangles) {
      for (DWORD i : t.m_nIndices) {
        if (i >= nv) throw Error("a triangle of mesh " + std::to_string(k + 1) + " names point " + std::to_string(i));
        d.cell_points.push_back(base + i);
      }
      d.cell_ends.push_back(d.cell_points.size());
      object.values.push_back(k);
    }
  }
  d.cell_fields["object"] = std::move(object);
  return d;
}

}  // namespace

Dataset read_3mf(const RegularFile& f) {
  // lib3mf trusts the file (a zip whose model can inflate without bound): it parses in a child process
  // with limits, as VTK's reader does (kernels/plugins/vtk/vtk_read.cpp), and the Dataset comes back over a
  // pipe; a crash or a runaway allocation ends the child, not the run.
  ChildLimits limits;
  limits.what = "the 3MF reader";
  limits.memory_bytes = std::min<std::uint64_t>((std::uint64_t{1} << 30) + 64 * f.size(), 3 * read_budget_bytes());
  limits.seconds = 30 + static_cast<double>(f.size()) / (4 << 20);
  Dataset d;
  run_in_child(
      limits,
      [&](PipeOut& out) {
        try {
          const Dataset parsed = parse_3mf(f);
          send_success(out);
          send_dataset(out, parsed);
        } catch (const std::exception& e) {
          send_failure(out, e.what());
        }
        return 0;
      },
      [&](PipeIn& in) { d = receive_answer(in, limits.what, read_budget_bytes() / 8); });
  return d;
}

}  // namespace selfsim::io
