#include "kernels/plugins/render/preview_camera.h"

#include <vtkCamera.h>
#include <vtkMath.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace selfsim::io {

namespace {

Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec3 unit(Vec3 v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (n > 0)
    for (double& x : v) x /= n;
  return v;
}
double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// [xmin, xmax, ymin, ymax, zmin, zmax] of every point of every step.
std::array<double, 6> bounds(std::span<const Dataset> steps) {
  const double inf = std::numeric_limits<double>::infinity();
  std::array<double, 6> b{inf, -inf, inf, -inf, inf, -inf};
  for (const Dataset& d : steps)
    for (const auto& p : d.points)
      for (int a = 0; a < 3; ++a) {
        b[2 * a] = std::min(b[2 * a], p[a]);
        b[2 * a + 1] = std::max(b[2 * a + 1], p[a]);
      }
  for (double& x : b)
    if (!std::isfinite(x)) x = 0;
  return b;
}

}  // namespace

ViewFrame view_frame(int up_axis) {
  switch (up_axis) {
    case 0:
      return {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}};
    case 2:
      return {{1, 0, 0}, {0, 0, 1}, {0, -1, 0}};
    default:
      return {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  }
}

Vec3 front_direction(const ViewFrame& f) { return f.back; }

Vec3 oblique_direction(const ViewFrame& f) {
  Vec3 d;
  for (int a = 0; a < 3; ++a) d[a] = f.back[a] + 0.8 * f.right[a] + 0.55 * f.up[a];
  return unit(d);
}

Vec3 steps_centre(std::span<const Dataset> steps) {
  const std::array<double, 6> b = bounds(steps);
  return {(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2};
}

void fit_perspective(vtkCamera* camera, std::span<const Dataset> steps, const Vec3& centre, const Vec3& dir,
                     const ViewFrame& frame, double aspect) {
  const Vec3 back = unit(dir), right = unit(cross(frame.up, back)), up = cross(back, right);
  const double angle = 30;
  camera->SetViewAngle(angle);
  const double tan_v = std::tan(vtkMath::RadiansFromDegrees(angle / 2)) / 1.12, tan_h = tan_v * aspect;
  double distance = 0, reach = 0;  // reach: the farthest point from the centre
  for (const Dataset& d : steps)
    for (const auto& p : d.points) {
      const Vec3 q{p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
      const double x = dot(q, right), y = dot(q, up), z = dot(q, back);
      distance = std::max({distance, z + std::abs(x) / tan_h, z + std::abs(y) / tan_v});
      reach = std::max(reach, std::sqrt(dot(q, q)));
    }
  if (!(distance > 0) || !std::isfinite(distance)) distance = 1;
  if (!std::isfinite(reach)) reach = distance;
  camera->SetFocalPoint(centre.data());
  camera->SetPosition(centre[0] + distance * back[0], centre[1] + distance * back[1], centre[2] + distance * back[2]);
  camera->SetViewUp(up.data());
  camera->ParallelProjectionOff();
  // The clipping range from the drawing itself, set here because the views are placed before their actors
  // have anything to draw (VTK's reset would then keep its default range, 0.1 to 1000, and a drawing a few
  // hundred units across would vanish). Every point lies within `reach` of the centre.
  camera->SetClippingRange(std::max(distance - 1.01 * reach, 1e-4 * (distance + reach)), distance + 1.01 * reach);
}

void fit_top(vtkCamera* camera, std::span<const Dataset> steps, double aspect) {
  const std::array<double, 6> b = bounds(steps);
  const double cx = (b[0] + b[1]) / 2, cy = (b[2] + b[3]) / 2;
  const double w = std::max(b[1] - b[0], 1e-300), h = std::max(b[3] - b[2], 1e-300);
  const double scale = 0.53 * std::max(h, w / aspect);
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(cx, cy, 0);
  // Far enough above that nothing is clipped, whatever the drawing's size.
  camera->SetPosition(cx, cy, 4 * scale);
  camera->SetViewUp(0, 1, 0);
  camera->SetParallelScale(scale);
  camera->SetClippingRange(2 * scale, 6 * scale);  // the drawing lies at 4 × scale (see fit_perspective)
}

}  // namespace selfsim::io
