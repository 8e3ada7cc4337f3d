// Reading Wavefront OBJ for load(), info and diff: `v x y z` points, `f` polygons (each corner `i`,
// `i/t`, `i//n` or `i/t/n`; negative indices count back from the last point) and `l` polylines (corners `i`
// or `i/t`): a file of lines alone is a curve; in a file of faces they are the mesh's loose edges, skipped.
// Texture coordinates,
// normals, groups, smoothing and materials are skipped: materials are never opened (a `mtllib` could name
// any file). Strict: a face corner must name a point already defined, a face has at least three corners
// and no corner twice, and every number is finite, with the line named otherwise.
#include <algorithm>

#include "kernels/base/error.h"
#include "kernels/io/dataset/dataset.h"
#include "kernels/io/file_stream.h"
#include "kernels/io/mesh/mesh_readers.h"

namespace selfsim::io {

Dataset read_obj(const RegularFile& f) {
  Dataset d;
  d.shapes = CellShapes::polygons;
  FileStream in(f);
  std::string_view line;
  std::vector<std::size_t> face;
  bool faces = false, lines = false;
  std::vector<std::size_t> line_points, line_ends;  // `l` polylines, kept apart from the faces
  while (in.line(line)) {
    const auto w = words(line);
    if (w.empty() || w[0].front() == '#') continue;
    const std::string at = "line " + std::to_string(in.line_number());
    if (w[0] == "v") {
      // x y z, optionally w, or x y z with an r g b colour: nothing else, so no line can hide another.
      if (w.size() != 4 && w.size() != 5 && w.size() != 7 && w.size() != 8)
        throw Error(at + ": 'v' takes x y z, x y z w, or x y z r g b (with an optional w)");
      for (std::size_t k = 4; k < w.size(); ++k) number_word(w[k], at + ": 'v' value " + std::to_string(k));
      d.points.push_back({number_word(w[1], at + ": x"), number_word(w[2], at + ": y"), number_word(w[3], at + ": z")});
    } else if (w[0] == "f" || w[0] == "l") {
      const bool line_cell = w[0] == "l";
      (line_cell ? lines : faces) = true;
      if (line_cell && w.size() < 3) throw Error(at + ": a line has at least two points");
      if (!line_cell && w.size() < 4) throw Error(at + ": a face has at least three corners");
      face.clear();
      const long long n = static_cast<long long>(d.points.size());
      for (std::size_t k = 1; k < w.size(); ++k) {
        const std::string_view index = w[k].substr(0, w[k].find('/'));
        if (n == 0) throw Error(at + ": a face before any point");
        long long i = integer_word(index, -n, n, at + ": corner " + std::to_string(k) + "'s point");
        if (i == 0) throw Error(at + ": point indices start at 1 (or count back from -1)");
        i = i < 0 ? n + i : i - 1;
        face.push_back(static_cast<std::size_t>(i));
      }
      if (line_cell) {  // a polyline may pass a point again, but not stand still on it
        if (std::adjacent_find(face.begin(), face.end()) != face.end())
          throw Error(at + ": a line has a zero-length segment (one point twice in a row)");
        line_points.insert(line_points.end(), face.begin(), face.end());
        line_ends.push_back(line_points.size());
        continue;
      }
      std::vector<std::size_t> sorted = face;
      std::sort(sorted.begin(), sorted.end());
      if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        throw Error(at + ": a face uses one point twice");
      d.cell_points.insert(d.cell_points.end(), face.begin(), face.end());
      d.cell_ends.push_back(d.cell_points.size());
    }
    // Everything else (vt, vn, g, o, s, mtllib, usemtl, ...) holds nothing a mesh or curve keeps.
  }
  // A mesh's `l` lines are its loose edges (Blender writes them so): kept only in a file of lines alone.
  if (lines && !faces) {
    d.shapes = CellShapes::lines;
    d.cell_points = std::move(line_points);
    d.cell_ends = std::move(line_ends);
  }
  return d;
}

}  // namespace selfsim::io
