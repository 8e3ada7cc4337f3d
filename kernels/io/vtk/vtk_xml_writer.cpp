// Written directly rather than through VTK's writers: VTK would first copy the geometry into its own
// arrays (about 3.5 GiB more for a level-26 dragon) and cannot be interrupted while it writes. VTK's reader
// (and so ParaView) reads what this writes back, which the unit tests and the viewer test check.
#include "kernels/io/vtk/vtk_xml_writer.h"

#include <cstdint>
#include <cstring>

#include "kernels/base/error.h"

namespace selfsim::io {

namespace {

// Values per chunk: bounded memory whatever the size, and a progress report and cancellation check each.
constexpr std::size_t chunk_values = std::size_t{1} << 16;

const char* dataset_name(VtkDataset d) { return d == VtkDataset::UnstructuredGrid ? "UnstructuredGrid" : "PolyData"; }

}  // namespace

std::size_t VtkArray::value_bytes() const {
  if (type == "UInt8") return 1;
  if (type == "Int32") return 4;
  return 8;
}

VtkArray field_array(const Field& f, std::size_t count) {
  const std::size_t k = static_cast<std::size_t>(f.components);
  VtkArray a{f.name, f.scalar() == Scalar::Int32 ? "Int32" : "Float64", f.components, count, {}};
  a.fill = [&f, k](std::size_t begin, std::size_t end, void* out) {
    std::visit(
        [&](const auto& values) {
          using T = std::decay_t<decltype(values[0])>;
          T* o = static_cast<T*>(out);
          if (f.uniform) {
            for (std::size_t i = begin; i < end; ++i)
              for (std::size_t c = 0; c < k; ++c) *o++ = values[c];
          } else {
            std::memcpy(o, values.data() + begin * k, (end - begin) * k * sizeof(T));
          }
        },
        f.data);
  };
  return a;
}

void write_vtk_xml(const VtkPiece& piece, OutputFile& out, Progress& progress) {
  // Offsets of each appended array, in the order written: point data, cell data, points, topology.
  std::vector<const VtkArray*> order;
  for (const auto& a : piece.point_data) order.push_back(&a);
  for (const auto& a : piece.cell_data) order.push_back(&a);
  order.push_back(&piece.coordinates);
  for (const auto& a : piece.topology) order.push_back(&a);
  std::vector<std::size_t> offset;
  std::size_t at = 0;
  for (const VtkArray* a : order) {
    offset.push_back(at);
    at += a->bytes() + sizeof(std::uint64_t);
  }
  const double total = static_cast<double>(at);

  using std::to_string;
  std::size_t next = 0;
  std::string h;
  auto declare = [&](const char* indent) {
    const VtkArray& a = *order[next];
    h += std::string(indent) + "<DataArray type=\"" + a.type + "\" Name=\"" + a.name + "\" NumberOfComponents=\"" +
         to_string(a.components) + "\" format=\"appended\" offset=\"" + to_string(offset[next]) + "\"/>\n";
    ++next;
  };
  const std::string dataset = dataset_name(piece.dataset);
  h += "<?xml version=\"1.0\"?>\n<VTKFile type=\"" + dataset +
       "\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <" + dataset + ">\n";
  // Strings in FieldData (ParaView's Information panel shows them): VTK's ASCII form, character codes
  // ending in 0.
  if (!piece.field_strings.empty()) {
    h += "    <FieldData>\n";
    for (const auto& [name, text] : piece.field_strings) {
      h += "      <Array type=\"String\" Name=\"" + name + "\" NumberOfTuples=\"1\" format=\"ascii\">\n        ";
      for (unsigned char c : text) h += to_string(static_cast<unsigned>(c)) + " ";
      h += "0\n      </Array>\n";
    }
    h += "    </FieldData>\n";
  }
  h += "    <Piece NumberOfPoints=\"" + to_string(piece.points) + "\"";
  const std::string cells = to_string(piece.cells);
  switch (piece.dataset) {
    case VtkDataset::PolyDataLines:
      h += " NumberOfVerts=\"0\" NumberOfLines=\"" + cells + "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n";
      break;
    case VtkDataset::PolyDataPolys:
      h += " NumberOfVerts=\"0\" NumberOfLines=\"0\" NumberOfStrips=\"0\" NumberOfPolys=\"" + cells + "\">\n";
      break;
    case VtkDataset::UnstructuredGrid:
      h += " NumberOfCells=\"" + cells + "\">\n";
      break;
  }
  h += piece.active_scalars.empty() ? "      <PointData>\n"
                                    : "      <PointData Scalars=\"" + piece.active_scalars + "\">\n";
  for (std::size_t i = 0; i < piece.point_data.size(); ++i) declare("        ");
  h += "      </PointData>\n      <CellData>\n";
  for (std::size_t i = 0; i < piece.cell_data.size(); ++i) declare("        ");
  h += "      </CellData>\n      <Points>\n";
  declare("        ");
  const char* cell_tag = piece.dataset == VtkDataset::PolyDataLines   ? "Lines"
                         : piece.dataset == VtkDataset::PolyDataPolys ? "Polys"
                                                                      : "Cells";
  h += "      </Points>\n      <" + std::string(cell_tag) + ">\n";
  for (std::size_t i = 0; i < piece.topology.size(); ++i) declare("        ");
  h += "      </" + std::string(cell_tag) + ">\n    </Piece>\n  </" + dataset +
       ">\n  <AppendedData encoding=\"raw\">\n   _";
  out.write(h);

  std::vector<char> buffer;
  double written = 0;
  for (const VtkArray* a : order) {
    const std::uint64_t bytes = a->bytes();
    out.write(&bytes, sizeof bytes);
    const std::size_t tuple_bytes = static_cast<std::size_t>(a->components) * a->value_bytes();
    const std::size_t chunk = std::max<std::size_t>(1, chunk_values / static_cast<std::size_t>(a->components));
    for (std::size_t begin = 0; begin < a->tuples; begin += chunk) {
      const std::size_t end = std::min(a->tuples, begin + chunk);
      buffer.resize((end - begin) * tuple_bytes);
      a->fill(begin, end, buffer.data());
      out.write(buffer.data(), buffer.size());
      written += static_cast<double>(buffer.size());
      progress.step(written / total);
    }
  }
  out.write(std::string_view("\n  </AppendedData>\n</VTKFile>\n"));
}

}  // namespace selfsim::io
