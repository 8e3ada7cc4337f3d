#include "kernels/develop/control_mesh.h"

#include <cstdint>
#include <limits>
#include <string>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/develop/level_stack.h"

namespace selfsim::develop {

Mesh control_mesh(std::span<const Polyline* const> levels, const ControlMeshOptions& opt, Progress& progress) {
  const int branching = refinement_branching(levels);
  const std::vector<double> z = level_heights(levels, opt.height);
  const bool closed = closed_levels(levels);
  const auto b = static_cast<std::size_t>(branching);
  // A closed level of two segments joins the same two points twice: its tiles would glue the loop shut.
  if (closed && levels.front()->segments() < 3)
    throw Error("a closed level needs at least 3 segments, level 0 has " + std::to_string(levels.front()->segments()));

  // Vertices of level l start at offset[l]; a closed level's last point is its first.
  std::vector<std::size_t> offset, count;
  std::size_t vertices = 0, faces = 0;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    offset.push_back(vertices);
    count.push_back(levels[l]->points.size() - (closed ? 1 : 0));
    vertices += count.back();
    if (l + 1 < levels.size()) faces += levels[l]->segments() * (1 + b);
  }
  if (vertices > std::numeric_limits<std::uint32_t>::max())
    throw Error("the control mesh would have " + std::to_string(vertices) + " points, more than 32-bit indices hold");

  progress.start("control mesh");
  Mesh m;
  m.points.reserve(vertices);
  std::vector<std::int32_t> point_level, face_level, tile;
  point_level.reserve(vertices);
  check_between(opt.corner_shift, 0, 0.5, "option 'corner_shift'");
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const auto pts = levels[l]->path(0);
    for (std::size_t i = 0; i < count[l]; ++i) {
      Vec2 p = pts[i];
      // A small Laplacian step: the ends of an open level stay, a closed level's every point moves.
      const bool inner = closed || (i > 0 && i + 1 < pts.size());
      if (opt.corner_shift > 0 && inner) {
        const Vec2 before = pts[i > 0 ? i - 1 : count[l] - 1], after = pts[i + 1];
        p = p + opt.corner_shift * (0.5 * (before + after) - p);
      }
      m.points.push_back({p.x, p.y, z[l]});
      point_level.push_back(static_cast<std::int32_t>(l));
    }
  }
  m.triangles.reserve(faces);
  face_level.reserve(faces);
  tile.reserve(faces);
  std::int32_t tiles = 0;
  const std::size_t split = b / 2;
  for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
    if (progress.cancelled()) throw Cancelled();
    const std::size_t segments = levels[l]->segments();
    auto coarse = [&](std::size_t j) { return static_cast<std::uint32_t>(offset[l] + j % count[l]); };
    auto fine = [&](std::size_t k) { return static_cast<std::uint32_t>(offset[l + 1] + k % count[l + 1]); };
    for (std::size_t j = 0; j < segments; ++j, ++tiles) {
      if ((j & 0xffff) == 0xffff && progress.cancelled()) throw Cancelled();
      const std::uint32_t a = coarse(j), e = coarse(j + 1);
      auto add = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r) {
        m.triangles.push_back({p, q, r});
        face_level.push_back(static_cast<std::int32_t>(l));
        tile.push_back(tiles);
      };
      for (std::size_t k = 0; k < split; ++k) add(a, fine(j * b + k), fine(j * b + k + 1));
      add(a, fine(j * b + split), e);
      for (std::size_t k = split; k < b; ++k) add(e, fine(j * b + k), fine(j * b + k + 1));
    }
  }
  m.point_fields.set(int_field("level", std::move(point_level)));
  m.face_fields.set(int_field("level", std::move(face_level)));
  m.face_fields.set(int_field("tile", std::move(tile)));
  return m;
}

}  // namespace selfsim::develop
