// .vtp and .vtu: what ParaView opens. Both come from one piece per value (vtk_pieces.cpp) written by the
// one VTK XML writer; they differ only in the dataset type.
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/vtk/vtk_pieces.h"
#include "kernels/io/writers.h"

namespace selfsim::io {

namespace {

VtkPiece piece(const ValueRef& v, bool unstructured) {
  const VtkDataset lines = unstructured ? VtkDataset::UnstructuredGrid : VtkDataset::PolyDataLines;
  const VtkDataset polys = unstructured ? VtkDataset::UnstructuredGrid : VtkDataset::PolyDataPolys;
  return std::visit(
      [&](const auto* value) {
        using T = std::decay_t<decltype(*value)>;
        if constexpr (std::is_same_v<T, Mesh>)
          return mesh_piece(*value, polys);
        else
          return curve_piece(*value, lines);
      },
      v);
}

VtkPiece with_provenance(VtkPiece p, const SaveOptions& opt) {
  if (!opt.provenance.empty()) p.field_strings.emplace_back(provenance_key, opt.provenance);
  return p;
}

}  // namespace

void write_vtp(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress) {
  write_vtk_xml(with_provenance(piece(v, false), opt), out, progress);
}

void write_vtu(const ValueRef& v, OutputFile& out, const SaveOptions& opt, Progress& progress) {
  write_vtk_xml(with_provenance(piece(v, true), opt), out, progress);
}

}  // namespace selfsim::io
