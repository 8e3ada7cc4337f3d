// A PNG picture of a dataset without ParaView (`selfsim preview`), rendered by VTK. No VTK header here:
// VTK stays in preview_png.cpp.
//
// What it draws: a flat dataset (every z = 0: a curve, an SVG) from +z with a parallel projection, fitted,
// as lines, 800x800; anything else shaded from two angles side by side (front-left above, and back-right
// from lower down), 1200x600. Either way coloured by the field a ParaView view would use
// (natural_colouring), with a legend: a colour bar titled with the field for a continuous one, distinct
// colours per class for a categorical one (swatches with their values for a few classes, a one-line
// "tile_class: 131 classes" otherwise). White background, the title in the top-left corner.
//
// VTK on Debian renders through X only: the caller provides a reachable $DISPLAY (the interpreter starts
// an Xvfb when there is none, frontend/process/display_server.h). The rendering runs in a forked child
// (child_process.h): VTK aborts on a lost X connection and Xlib exits on some GL errors, and either must
// become one line, not end selfsim. VTK's messages never reach the terminal: its first error comes back as
// the reason.
#pragma once

#include <filesystem>
#include <string>

#include "kernels/base/progress.h"
#include "kernels/io/dataset/dataset.h"

namespace selfsim::io {

struct PreviewSize {
  int width = 0, height = 0;
};

// True when d is a flat picture: every point at z = 0.
bool flat_dataset(const Dataset& d);
// The picture size write_preview_png uses for d.
PreviewSize preview_size(const Dataset& d);

// The PNG file's bytes. Throws Error with one line: the renderer's first error (an OpenGL context that
// cannot be made names the package to install), a crash, or a hang (a time limit scaled to the size).
std::string render_preview_png(const Dataset& d, const std::string& title, Progress& progress);

// Renders d and writes it atomically as root/name through the confined writer (output_file.h): `name` may
// hold folders ("previews/level=1/a.vtp.png"), each created and opened below root, never through a link.
// Returns the path written.
std::string write_preview_png(const Dataset& d, const std::string& title, const std::filesystem::path& root,
                              const std::string& name, Progress& progress);

}  // namespace selfsim::io
