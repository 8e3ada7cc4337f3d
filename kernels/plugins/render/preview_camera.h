// Where a preview looks from (preview_png.h): the same views for every 3D file, standing on its up axis
// (up_axis.h), and a fit that keeps every point of every step in view, so that a series' steps share one
// camera. No VTK types but the camera, declared.
#pragma once

#include <array>
#include <span>

#include "kernels/io/dataset/dataset.h"

class vtkCamera;

namespace selfsim::io {

using Vec3 = std::array<double, 3>;

// A right-handed frame of a 3D picture: `up` is the up axis, `back` points from the drawing towards the
// front view's eye, `right` = up x back points right in the front view. Up y: right x, back z (ABOP's
// figures); up z: right x, back -y (a stack seen from the front); up x: right y, back -z.
struct ViewFrame {
  Vec3 right, up, back;
};
ViewFrame view_frame(int up_axis);

// The two views of every 3D preview, as the direction from the drawing towards the eye: the front view
// (back) and the oblique one from the front right above.
Vec3 front_direction(const ViewFrame& f);
Vec3 oblique_direction(const ViewFrame& f);

// The centre of the bounding box of every point of every step.
Vec3 steps_centre(std::span<const Dataset> steps);

// A perspective camera looking along -dir at `centre`, `frame.up` kept up on the screen, at the distance where
// every point of every step just fits a view of width/height `aspect` (with a small margin): tighter than
// VTK's ResetCamera, which fits the bounding sphere.
void fit_perspective(vtkCamera* camera, std::span<const Dataset> steps, const Vec3& centre, const Vec3& dir,
                     const ViewFrame& frame, double aspect);
// A parallel camera looking down -z at the bounding box of every step (every z = 0), its longer side filling
// 94% of a view of width/height `aspect`.
void fit_top(vtkCamera* camera, std::span<const Dataset> steps, double aspect);

}  // namespace selfsim::io
