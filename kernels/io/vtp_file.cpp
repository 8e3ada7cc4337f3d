// VTK XML PolyData (.vtp): what ParaView opens. Polylines are cells; point fields `level` and `arclength`
// and cell field `path` let a user colour by construction level, by distance along the curve, or by path.

#include <cstdint>
#include <string>

#include "kernels/geom/error.h"
#include "kernels/io/save.h"

namespace selfsim::io {

namespace {

// Appended raw arrays are written in chunks: bounded memory whatever the curve, and a progress report
// and cancellation check per chunk.
constexpr std::size_t chunk_points = std::size_t{1} << 16;

struct ArrayWriter {
  OutputFile& out;
  Progress& progress;
  double total_bytes, written = 0;

  void header(std::uint64_t bytes) { out.write(&bytes, sizeof bytes); }
  template <class T>
  void chunk(const std::vector<T>& values) {
    out.write(values.data(), values.size() * sizeof(T));
    written += static_cast<double>(values.size() * sizeof(T));
    progress.step(written / total_bytes);
  }
  // Writes one appended array of n values, produced chunk by chunk by fill(begin, end, buffer).
  template <class T, class Fill>
  void array(std::size_t n, Fill fill) {
    header(n * sizeof(T));
    std::vector<T> buffer;
    for (std::size_t begin = 0; begin < n; begin += chunk_points) {
      buffer.clear();
      fill(begin, std::min(n, begin + chunk_points), buffer);
      chunk(buffer);
    }
  }
};

}  // namespace

// Written directly rather than through vtkXMLPolyDataWriter: VTK would first copy the curve into its own
// arrays (about 3.5 GiB more for a level-26 dragon) and cannot be interrupted while it writes. The
// format is VTK's XML PolyData, version 1.0, appended raw little-endian data with UInt64 block headers;
// VTK's reader (and so ParaView) reads it back, which the viewer test checks.
void write_vtp(const Polyline& c, OutputFile& out, const SaveOptions&, Progress& progress) {
  const std::size_t n = c.points.size(), paths = c.paths();
  const std::size_t sizes[] = {n * 4, n * 8, paths * 4, n * 24, n * 8, paths * 8};  // in the order written below
  std::size_t offsets[6], at = 0;
  for (int i = 0; i < 6; ++i) {
    offsets[i] = at;
    at += sizes[i] + sizeof(std::uint64_t);
  }
  using std::to_string;
  std::string h;
  auto array = [&](const char* type, const char* name, int components, int i) {
    h += std::string("        <DataArray type=\"") + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" +
         to_string(components) + "\" format=\"appended\" offset=\"" + to_string(offsets[i]) + "\"/>\n";
  };
  h += "<?xml version=\"1.0\"?>\n"
       "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
       "  <PolyData>\n"
       "    <Piece NumberOfPoints=\"" +
       to_string(n) + "\" NumberOfVerts=\"0\" NumberOfLines=\"" + to_string(paths) +
       "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
       "      <PointData Scalars=\"arclength\">\n";
  array("Int32", "level", 1, 0);
  array("Float64", "arclength", 1, 1);
  h += "      </PointData>\n      <CellData>\n";
  array("Int32", "path", 1, 2);
  h += "      </CellData>\n      <Points>\n";
  array("Float64", "Points", 3, 3);
  h += "      </Points>\n      <Lines>\n";
  array("Int64", "connectivity", 1, 4);
  array("Int64", "offsets", 1, 5);
  h += "      </Lines>\n    </Piece>\n  </PolyData>\n  <AppendedData encoding=\"raw\">\n   _";
  out.write(h);

  ArrayWriter w{out, progress, static_cast<double>(at)};
  w.array<std::int32_t>(n, [&](std::size_t begin, std::size_t end, auto& b) { b.assign(end - begin, c.level); });
  std::size_t path = 0;
  double run = 0;
  w.array<double>(n, [&](std::size_t begin, std::size_t end, auto& b) {
    for (std::size_t i = begin; i < end; ++i) {
      if (i == c.path_begin(path))
        run = 0;  // arclength restarts on every path
      else
        run += norm(c.points[i] - c.points[i - 1]);
      b.push_back(run);
      if (i + 1 == c.path_ends[path]) ++path;
    }
  });
  w.array<std::int32_t>(paths, [](std::size_t begin, std::size_t end, auto& b) {
    for (std::size_t i = begin; i < end; ++i) b.push_back(static_cast<std::int32_t>(i));
  });
  w.array<double>(n * 3, [&](std::size_t begin, std::size_t end, auto& b) {
    for (std::size_t i = begin; i < end; ++i)
      b.push_back(i % 3 == 0 ? c.points[i / 3].x : i % 3 == 1 ? c.points[i / 3].y : 0.0);
  });
  w.array<std::int64_t>(n, [](std::size_t begin, std::size_t end, auto& b) {
    for (std::size_t i = begin; i < end; ++i) b.push_back(static_cast<std::int64_t>(i));
  });
  w.array<std::int64_t>(paths, [&](std::size_t begin, std::size_t end, auto& b) {
    for (std::size_t i = begin; i < end; ++i) b.push_back(static_cast<std::int64_t>(c.path_ends[i]));
  });
  out.write(std::string_view("\n  </AppendedData>\n</VTKFile>\n"));
}

}  // namespace selfsim::io
