// PNG pictures of a dataset, or of every step of a series, without ParaView (`selfsim preview`), rendered by
// VTK. No VTK header here: VTK stays in the rendering plugin (kernels/plugins/render/).
//
// What it draws: a flat dataset (every z = 0: a curve, an SVG) from +z with a parallel projection, fitted,
// 800x800; anything else upright, 1200x600: a front view (its up axis up, up_axis.h: +y unless a `level`
// field says the dataset grew along another axis, or `up` given) and an oblique view from the front right
// above, the same two for every file, lit by a light kit so that depth reads. Surfaces are shaded; a curve
// with a point field `width` (from a grammar's '!') is drawn as tubes of radius proportional to it; other 3D
// curves as lines shaded like tubes. Coloured by the field a ParaView view would use (natural_colouring), or
// the one asked for, or an SVG's own stroke colours; with a legend: a colour bar titled with the field for a
// continuous one, distinct colours per class for a categorical one. White background, the title in the
// top-left corner.
//
// A series' steps are drawn with ONE camera, fitted to every step's points, and ONE colour range, over every
// step: the still is its last step; with `steps`, each step is also drawn as a frame of the still's size
// (the frames of an animation) and all of them side by side in a filmstrip, each labelled, one legend.
//
// VTK on Debian renders through X only: the caller provides a reachable $DISPLAY (the interpreter starts
// an Xvfb when there is none, frontend/process/display_server.h). The rendering runs in one forked child
// (child_process.h) for every picture: VTK aborts on a lost X connection and Xlib exits on some GL errors,
// and either must become one line, not end selfsim. VTK's messages never reach the terminal: its first
// error comes back as the reason.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "kernels/base/progress.h"
#include "kernels/io/dataset/dataset.h"

namespace selfsim::io {

struct PreviewSize {
  int width = 0, height = 0;
};

struct PreviewOptions {
  std::string field;                // colour by this field; empty: an SVG's own colours, else the natural one
  int up = -1;                      // 0, 1, 2: that axis up in 3D views; -1: up_axis() of the last step
  bool steps = false;               // also the frames and the filmstrip
  std::vector<std::string> labels;  // one per step ("step 2 of 10"): the frames' and filmstrip's captions
  std::string name;                 // the filmstrip's title (the series file's name); empty: the still's
};

struct PreviewPictures {
  std::string still;                // the last step: PNG bytes
  std::string filmstrip;            // with `steps`: every step in a grid (filmstrip_steps of a long series)
  std::vector<std::string> frames;  // with `steps`: every step as the still draws the last
};

// The filmstrip shows at most this many steps: a long series, evenly spaced ones from the first to the last.
inline constexpr std::size_t filmstrip_cells = 48;
// The steps (0-based, increasing) a filmstrip of n steps shows: all of them, or filmstrip_cells of them
// starting at the first and ending at the last.
std::vector<std::size_t> filmstrip_steps(std::size_t n);

// True when d is a flat picture: every point at z = 0.
bool flat_dataset(const Dataset& d);
// The size of the still (and of each frame) for steps whose last is d.
PreviewSize preview_size(const Dataset& d);

// The pictures of `steps` (one dataset, or a series' steps in order). Throws Error with one line: a field
// that is not there ("--field: no field named 'x'; it holds a, b"), no points or a point that is not finite,
// the renderer's first error (an OpenGL context that cannot be made names the package to install), a crash,
// or a hang (a time limit scaled to the size).
PreviewPictures render_preview(std::span<const Dataset> steps, const std::string& title, const PreviewOptions& options,
                               Progress& progress);

}  // namespace selfsim::io
