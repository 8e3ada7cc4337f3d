#include "kernels/io/save.h"

#include <cmath>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/read_error.h"
#include "kernels/io/text/colour.h"

namespace selfsim::io {

namespace {

template <class V>
void check_curve(const PolylineT<V>& c, const std::string& file) {
  if (c.points.empty()) throw Error("cannot save an empty curve to '" + file + "'");
  if (!c.paths_consistent()) throw Error("cannot save '" + file + "': the curve's paths do not cover its points");
  if (!c.finite()) throw Error("cannot save '" + file + "': the curve has non-finite coordinates");
  // Finite points can still overflow what a file derives from them: the extent (SVG viewBox, with its
  // margin) and the arclength field. Scale such a curve down before saving it.
  if (!is_finite(c.bbox().size() * 1.05) || !std::isfinite(c.length()))
    throw Error("cannot save '" + file + "': the curve's extent or length overflows (scale it down with c:transform)");
  c.point_fields.check(c.points.size(), "point");
  c.cell_fields.check(c.paths(), "cell");
}

void check_mesh(const Mesh& m, const std::string& file) {
  if (m.faces() == 0) throw Error("cannot save a mesh without triangles to '" + file + "'");
  m.validate();
  if (!is_finite(m.bbox().size() * 1.05))
    throw Error("cannot save '" + file + "': the mesh's extent overflows (scale it down)");
}

}  // namespace

void SaveOptions::validate() const {
  // Shown through one_line: a colour is recipe text, and may hold anything.
  if (stroke.empty() || stroke_width.empty())
    throw Error("options 'stroke' and 'stroke_width' need at least one value");
  for (const std::string& c : stroke)
    if (c != "none" && !is_colour(c))
      throw Error("option 'stroke' must be a CSS colour name, #rgb, #rrggbb or 'none', got '" + shown(c) + "'");
  for (const std::string& c : fill)
    if (c != "none" && !is_colour(c))
      throw Error("option 'fill' must be a CSS colour name, #rgb, #rrggbb or 'none', got '" + shown(c) + "'");
  for (std::size_t i = 0; i < stroke_width.size(); ++i)
    if (!(stroke_width[i] > 0 && stroke_width[i] < 1e6))
      throw Error("option 'stroke_width'" + (stroke_width.size() > 1 ? " entry " + std::to_string(i + 1) : "") +
                  " must be a positive number below 1000000, got " + number_text(stroke_width[i]));
  if (size_unit.empty() && !(size >= 16 && size <= 100000))
    throw Error("option 'size' must be in [16, 100000] pixels, got " + number_text(size));
  if (size_unit != "" && size_unit != "mm" && size_unit != "cm" && size_unit != "in")
    throw Error("option 'size' takes the units mm, cm or in, got '" + shown(size_unit) + "'");
  if (!size_unit.empty() && !(size > 0 && size <= 100000))
    throw Error("option 'size' must be a positive length of at most 100000" + size_unit);
  if (!(voxel >= 0 && voxel < 1e300))
    throw Error("option 'voxel' must be a positive number, got " + number_text(voxel));
}

std::string save(const ValueRef& v, const std::filesystem::path& root, const std::string& name, const SaveOptions& opt,
                 Progress& progress) {
  const std::string file = std::filesystem::path(name).filename().string();
  const Format& format = format_for(name, kind_of(v));
  check_options(format, opt.given);
  opt.validate();
  std::visit(
      [&](const auto* value) {
        if constexpr (std::is_same_v<std::decay_t<decltype(*value)>, Mesh>)
          check_mesh(*value, file);
        else
          check_curve(*value, file);
      },
      v);
  OutputFile out(root, name);
  const std::string task = "writing " + file;
  progress.start(task.c_str());
  format.write(v, out, opt, progress);
  if (progress.cancelled()) throw Cancelled();
  out.commit();
  // Formats with no place for text carry how they were made beside them: dragon.stl.json.
  if (!opt.provenance.empty() && provenance_beside(format.extension)) {
    OutputFile beside(root, name + ".json");
    beside.write(opt.provenance + "\n");
    beside.commit();
  }
  return out.path();
}

}  // namespace selfsim::io
