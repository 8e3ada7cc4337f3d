// The scene of a preview (preview_png.cpp): a Dataset as VTK poly data with its colouring field, and the
// colour tables. VTK types in its signatures: include it only from the preview's own .cpp files.
#pragma once

#include <vtkLookupTable.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <vector>

#include "kernels/io/dataset.h"
#include "kernels/io/natural_field.h"

namespace selfsim::io {

// A perceptually even blue-green-yellow ramp from lo to hi.
void continuous_table(vtkLookupTable* lut, double lo, double hi);
// One colour per class, the same as a ParaView view's (paraview_view_body.py), each annotated.
void category_table(vtkLookupTable* lut, const std::vector<int>& categories);
// The dataset's points, cells (lines, polygons) and the field `c` names as the active scalars.
vtkSmartPointer<vtkPolyData> poly_data(const Dataset& d, const Colouring& c);

}  // namespace selfsim::io
