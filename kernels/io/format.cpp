#include "kernels/io/format.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "kernels/base/error.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/writers.h"

namespace selfsim::io {

namespace {

constexpr ValueKind C = ValueKind::Curve, C3 = ValueKind::Curve3, M = ValueKind::Mesh;

}  // namespace

const std::vector<Format>& formats() {
  static const std::vector<Format> all{
      {".vtp", "VTK PolyData: ParaView (curves as lines, meshes as polygons; every field)", {C, C3, M}, {}, write_vtp},
      {".vtu", "VTK unstructured grid: ParaView (every field)", {C, C3, M}, {}, write_vtu},
      {".svg", "SVG: browsers, Inkscape, plotters", {C}, {"stroke", "stroke_width", "fill", "size"}, write_svg},
      {".eps", "EPS: print, LaTeX, illustration programs", {C}, {"stroke", "stroke_width", "fill", "size"}, write_eps},
      {".3mf", "3MF in millimetres, with its name: slicers for 3D printing (a closed solid)", {M}, {"name"}, write_3mf},
      {".stl", "binary STL: slicers for 3D printing (no units: slicers guess millimetres)", {M}, {}, write_stl},
      {".obj", "Wavefront OBJ: Blender, MeshLab", {M}, {}, write_obj},
      {".ply", "binary PLY: MeshLab, Blender", {M}, {}, write_ply},
      {".vdb",
       "OpenVDB distance grid: Blender, Houdini (a closed mesh's level set, an open one's distance)",
       {M},
       {"voxel"},
       write_vdb},
  };
  return all;
}

const char* kind_name(ValueKind k) {
  switch (k) {
    case ValueKind::Curve:
      return "curve";
    case ValueKind::Curve3:
      return "3D curve";
    case ValueKind::Mesh:
      return "mesh";
  }
  return "value";
}

ValueKind kind_of(const ValueRef& v) { return static_cast<ValueKind>(v.index()); }

bool Format::holds(ValueKind k) const { return std::find(accepts.begin(), accepts.end(), k) != accepts.end(); }

const Format* find_format(std::string_view extension) {
  for (const Format& f : formats())
    if (f.extension == extension) return &f;
  return nullptr;
}

const Format& format_for(const std::string& name, ValueKind k) {
  const std::filesystem::path p(name);
  const std::string file = p.filename().string();
  const std::string ext = lower_case(p.extension().string());  // x.VTP too
  std::vector<std::string> able;
  for (const Format& f : formats())
    if (f.holds(k)) able.push_back(f.extension);
  std::sort(able.begin(), able.end());
  const Format* f = find_format(ext);
  if (f == nullptr || !f->holds(k))
    throw Error("cannot save a " + std::string(kind_name(k)) + " as '" + ext + "' (file '" + file +
                "'), expected one of: " + quoted_list(able));
  return *f;
}

void check_options(const Format& f, const std::vector<std::string>& given) {
  for (const std::string& name : given) {
    if (std::find(f.options.begin(), f.options.end(), name) != f.options.end()) continue;
    std::vector<std::string> owners;
    for (const Format& g : formats())
      if (std::find(g.options.begin(), g.options.end(), name) != g.options.end()) owners.push_back(g.extension);
    if (owners.empty()) continue;
    throw Error("option '" + name + "' does not apply to '" + f.extension + "' files (it is an option of " +
                quoted_list(owners) + "; '" + f.extension + "' takes " +
                (f.options.empty() ? std::string("no options") : "only " + quoted_list(f.options)) + ")");
  }
}

}  // namespace selfsim::io
