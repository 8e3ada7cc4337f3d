// The scene of a preview (preview_png.cpp): a Dataset as VTK poly data with its colouring field, the colour
// tables, and one step's drawing (mapper and look). VTK's types are only declared here (but its smart pointer):
// the .cpp files that use them include VTK's headers.
#pragma once

#include <vtkSmartPointer.h>

#include <span>
#include <string>
#include <vector>

#include "kernels/io/dataset/dataset.h"
#include "kernels/io/view/natural_field.h"

class vtkActor;
class vtkLookupTable;
class vtkPolyData;
class vtkPolyDataMapper;

namespace selfsim::io {

// A drawing's own colours: a cell field `color` of 3 components, red, green, blue in [0, 1], as an SVG's
// stroke colours read back (svg_read.cpp) and a curve's per-path colours are; drawn as they are when no
// --field is asked. (A grammar's colour index, `color` of one component, is a field like any other.)
inline constexpr const char* direct_colour_field = "color";
// Whether d holds its own colours.
bool has_direct_colours(const Dataset& d);

// A perceptually even blue-green-yellow ramp from lo to hi.
void continuous_table(vtkLookupTable* lut, double lo, double hi);
// One colour per class, the same as a ParaView view's (paraview_view_body.py), each annotated: the i-th
// class's, or with `by_value` (coloured_by_value) each value's own.
void category_table(vtkLookupTable* lut, const std::vector<int>& categories, bool by_value = false);
// The dataset's points, cells (lines, polygons) and the field `c` names as a named array (not the active
// scalars).
vtkSmartPointer<vtkPolyData> poly_data(const Dataset& d, const Colouring& c);

// What is the same for every step of a preview.
struct SceneStyle {
  Colouring colouring;  // field empty: one colour (or `direct`)
  bool direct = false;  // draw the cell field `color` as colours (has_direct_colours)
  bool flat = false;
  double size = 1;       // the diagonal of every step's bounding box: tube radii are a fraction of it
  double max_width = 0;  // the largest point field `width` over every step; 0: none
  vtkLookupTable* lut = nullptr;
};

// The style of every step: what `colouring` and the datasets say.
SceneStyle scene_style(std::span<const Dataset> steps, const Colouring& colouring, bool direct);

// One step's drawing: surfaces shaded with normals, curves with a `width` as tubes of radius proportional
// to it (when small enough to build them), other 3D curves as lines drawn as lit tubes, points as dots.
struct StepDrawing {
  vtkSmartPointer<vtkPolyDataMapper> mapper;
  bool surface = false;  // shaded polygons
  bool tubes = false;    // lines drawn as tube geometry or as tubes by the line shader
  bool lit_lines = false;
  float line_width = 1;
};
StepDrawing step_drawing(const Dataset& d, const SceneStyle& style);

// Gives `actor` the drawing's mapper and look.
void show_step(vtkActor* actor, const StepDrawing& drawing, const SceneStyle& style);

}  // namespace selfsim::io
