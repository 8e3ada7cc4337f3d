// The scene of a preview (preview_png.cpp): a Dataset as VTK poly data with its colouring field, and the
// colour tables. VTK's types are only declared here: the .cpp files that use them include VTK's headers.
#pragma once

#include <vector>

#include "kernels/io/dataset/dataset.h"
#include "kernels/io/view/natural_field.h"

class vtkLookupTable;
class vtkPolyData;
template <class T>
class vtkSmartPointer;

namespace selfsim::io {

// A perceptually even blue-green-yellow ramp from lo to hi.
void continuous_table(vtkLookupTable* lut, double lo, double hi);
// One colour per class, the same as a ParaView view's (paraview_view_body.py), each annotated.
void category_table(vtkLookupTable* lut, const std::vector<int>& categories);
// The dataset's points, cells (lines, polygons) and the field `c` names as the active scalars.
vtkSmartPointer<vtkPolyData> poly_data(const Dataset& d, const Colouring& c);

}  // namespace selfsim::io
