// The strips around a preview's views (preview_png.cpp): the title with what the file holds, and the legend
// of its colours. VTK's types are only declared here.
#pragma once

#include <vtkSmartPointer.h>

#include <string>

#include "kernels/io/dataset/dataset.h"
#include "kernels/io/view/natural_field.h"

class vtkLookupTable;
class vtkRenderer;
class vtkTextActor;

namespace selfsim::io {

// Dark text of `size` points at (x, y) in the renderer's normalized viewport, justified left, centred or
// right (VTK_TEXT_*), centred vertically.
vtkSmartPointer<vtkTextActor> text(const std::string& s, int size, double x, double y, int justify);

// "1,234 points, 56 faces": what d holds.
std::string holds_text(const Dataset& d, bool surface);

// A title shortened to 90 characters at its start.
std::string shown_title(const std::string& title);

// The legend of `colouring` drawn with `lut` into `legend` (a strip across the picture): a colour bar
// titled with the field for a continuous one, a swatch per class with its value for a few classes (at most
// `swatches`), one line for many.
void add_legend(vtkRenderer* legend, const Colouring& colouring, vtkLookupTable* lut, std::size_t swatches);

}  // namespace selfsim::io
