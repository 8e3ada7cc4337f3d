// VTK's part of `selfsim preview` (see preview_png.h for what the pictures hold).
#include "kernels/io/view/preview_png.h"

#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkCamera.h>
#include <vtkLightKit.h>
#include <vtkLogger.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPNGWriter.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/io/child_process.h"
#include "kernels/io/dataset/dataset_pipe.h"
#include "kernels/io/read_error.h"
#include "kernels/io/view/natural_field.h"
#include "kernels/io/view/up_axis.h"
#include "kernels/io/vtk/vtk_error_text.h"
#include "kernels/plugins/render/preview_camera.h"
#include "kernels/plugins/render/preview_legend.h"
#include "kernels/plugins/render/preview_scene.h"

// VTK's rendering classes are abstract until their OpenGL implementations register with the object
// factory. VTK's CMake does that through vtk_module_autoinit; these lines do it in the one file that
// renders, whatever the build system (without them vtkRenderWindow::New() returns nothing usable).
VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);
VTK_MODULE_INIT(vtkInteractionStyle);

namespace selfsim::io {

namespace {

// The child sends its first VTK error at once ('E', flushed: VTK may abort right after it), or the PNGs.
class ErrorToPipe : public vtkOutputWindow {
 public:
  static ErrorToPipe* New();
  vtkTypeMacro(ErrorToPipe, vtkOutputWindow);
  void DisplayText(const char*) override {}
  void DisplayErrorText(const char* text) override {
    if (sent || !out) return;
    sent = true;
    send_failure(*out, reason(text ? text : "unknown error"));
    out->flush();
  }
  void DisplayWarningText(const char*) override {}
  void DisplayGenericWarningText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  PipeOut* out = nullptr;
  bool sent = false;

  static std::string reason(const std::string& text) {
    const std::string line = vtk_error_line(text);
    return line.empty() ? text : line;
  }
};
vtkStandardNewMacro(ErrorToPipe);

constexpr double white[3] = {1, 1, 1};

// What the parent decided, for the child to draw.
struct Plan {
  std::string title;
  PreviewOptions options;
  Colouring colouring;
  bool direct = false;  // an SVG's own colours
  int up = 1;
};

// The window's picture as PNG bytes, zlib at `effort` (0-9; frames of an animation take less time over it);
// empty when VTK reported an error.
std::string grab_png(vtkRenderWindow* window, int effort = 5) {
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->SetCompressionLevel(effort);
  png->WriteToMemoryOn();
  png->Write();
  vtkUnsignedCharArray* bytes = png->GetResult();
  if (bytes == nullptr || bytes->GetNumberOfValues() == 0) return {};
  return std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)),
                     static_cast<std::size_t>(bytes->GetNumberOfValues()));
}

// A white renderer over `viewport` of `window` ([x0, y0, x1, y1]).
vtkSmartPointer<vtkRenderer> strip(vtkRenderWindow* window, double x0, double y0, double x1, double y1) {
  auto r = vtkSmartPointer<vtkRenderer>::New();
  r->SetViewport(x0, y0, x1, y1);
  r->SetBackground(white[0], white[1], white[2]);
  window->AddRenderer(r);
  return r;
}

// A view of the drawing: the top view of a flat one, else the front (`oblique` false) or oblique view,
// fitted to every step, lit by a light kit.
void place_view(vtkRenderer* view, std::span<const Dataset> steps, bool flat, bool oblique, int up, double aspect) {
  vtkCamera* camera = view->GetActiveCamera();
  if (flat) {
    fit_top(camera, steps, aspect);
  } else {
    const ViewFrame frame = view_frame(up);
    fit_perspective(camera, steps, steps_centre(steps), oblique ? oblique_direction(frame) : front_direction(frame),
                    frame, aspect);
    vtkNew<vtkLightKit> lights;
    lights->AddLightsToRenderer(view);
  }
}

// Everything VTK does, in the child: build the scenes, render, send 'P', the number of pictures and each
// PNG's bytes (the still, then with steps the filmstrip and the frames).
int render_in_child(PipeOut& out, std::span<const Dataset> steps, const Plan& plan) {
  ::setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 1);  // no TBB threads in a forked child
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkNew<ErrorToPipe> window_errors;
  window_errors->out = &out;
  vtkOutputWindow::SetInstance(window_errors);

  vtkNew<vtkLookupTable> lut;
  SceneStyle style = scene_style(steps, plan.colouring, plan.direct);
  const bool coloured = !plan.colouring.field.empty();
  if (coloured) {
    if (plan.colouring.categorical)
      category_table(lut, plan.colouring.categories, coloured_by_value(plan.colouring.field));
    else
      continuous_table(lut, plan.colouring.min, plan.colouring.max);
    lut->Build();
    style.lut = lut;
  }
  const bool flat = style.flat;
  // Antialiasing by 8 samples a pixel costs Mesa's software renderer most of a million-face preview; past
  // that many cells the faces are smaller than a pixel anyway.
  std::size_t cells = 0;
  for (const Dataset& d : steps) cells = std::max(cells, d.cell_ends.size());
  // A series' frames and filmstrip, a dozen pictures, are smoothed by FXAA (a pass over the finished
  // picture) instead, so that a 10-step growth costs a few previews, not ten.
  const bool frames_wanted = plan.options.steps && !steps.empty();
  const int samples = cells > 400000 || frames_wanted ? 0 : 8;
  const bool fxaa = samples == 0 && cells <= 400000;
  const PreviewSize size = flat ? PreviewSize{800, 800} : PreviewSize{1200, 600};
  const std::size_t n = steps.size();
  const bool frames = frames_wanted;
  std::vector<StepDrawing> drawings(n);
  auto drawing = [&](std::size_t k) -> const StepDrawing& {
    if (!drawings[k].mapper) drawings[k] = step_drawing(steps[k], style);
    return drawings[k];
  };
  auto label = [&](std::size_t k) {
    return k < plan.options.labels.size() ? plan.options.labels[k] : "step " + std::to_string(k + 1);
  };

  // The still and the frames: the views between a title strip at the top and a legend strip at the bottom.
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(size.width, size.height);
  window->SetMultiSamples(samples);
  window->SetWindowName("selfsim preview");
  const double top = 0.93, bottom = coloured ? 0.13 : 0.02;
  const int views = flat ? 1 : 2;
  std::vector<vtkSmartPointer<vtkActor>> actors;
  for (int v = 0; v < views; ++v) {
    auto actor = vtkSmartPointer<vtkActor>::New();
    vtkSmartPointer<vtkRenderer> view = strip(window, v * 1.0 / views, bottom, (v + 1) * 1.0 / views, top);
    view->AddActor(actor);
    view->SetUseFXAA(fxaa);
    place_view(view, steps, flat, v == 1, plan.up, (size.width / double(views)) / (size.height * (top - bottom)));
    // Which view is which, and which axis stands up: a reader cannot tell a front view from an oblique one.
    if (!flat)
      view->AddActor2D(text(v == 0 ? std::string("front, ") + "xyz"[plan.up] + " up" : std::string("oblique"), 13, 0.02,
                            0.03, VTK_TEXT_LEFT));
    actors.push_back(actor);
  }
  vtkSmartPointer<vtkRenderer> head = strip(window, 0, top, 1, 1);
  vtkSmartPointer<vtkTextActor> title = text(shown_title(plan.title), 20, 0.012, 0.5, VTK_TEXT_LEFT);
  vtkSmartPointer<vtkTextActor> holds = text("", 14, 0.988, 0.5, VTK_TEXT_RIGHT);
  head->AddActor2D(title);
  head->AddActor2D(holds);
  vtkSmartPointer<vtkRenderer> legend = strip(window, 0, 0, 1, bottom);
  if (coloured) add_legend(legend, plan.colouring, lut, flat ? 10 : 16);

  // Each frame captioned with its step in the middle of the title strip; the still is the last step, the last
  // frame itself when there are frames (its caption then says so too).
  vtkSmartPointer<vtkTextActor> caption = text("", 18, 0.5, 0.5, VTK_TEXT_CENTERED);
  head->AddActor2D(caption);
  // Frames are titled with the file's name alone: the plain title says "(last of N steps)", which every
  // frame but the last would then contradict.
  if (frames && !plan.options.name.empty()) title->SetInput(shown_title(plan.options.name).c_str());
  std::vector<std::string> pictures(1);
  auto picture = [&](std::size_t k) {
    const StepDrawing& d = drawing(k);
    for (vtkActor* actor : actors) show_step(actor, d, style);
    holds->SetInput(holds_text(steps[k], d.surface && !d.tubes).c_str());
    if (frames) caption->SetInput(label(k).c_str());
    window->Render();
    return window_errors->sent ? std::string() : grab_png(window, frames ? 2 : 5);
  };
  if (frames)
    for (std::size_t k = 0; k < n && !window_errors->sent; ++k) pictures.push_back(picture(k));
  if (!window_errors->sent) pictures[0] = frames ? pictures.back() : picture(n - 1);
  if (window_errors->sent) return 0;

  if (frames) {
    // The filmstrip: every step in a grid of cells (the oblique view of a 3D drawing), each captioned,
    // under one title and over one legend, in a window of its own. A long series shows filmstrip_cells of
    // its steps, evenly spaced from the first to the last: a grid of thousands of cells would be a picture
    // wider than OpenGL draws (16384 px) and too fine to read; its animation keeps every step.
    const std::vector<std::size_t> shown = filmstrip_steps(n);
    const std::size_t cells_n = shown.size();
    const int cell = 300,
              cols = static_cast<int>(std::min<std::size_t>(
                  cells_n, static_cast<std::size_t>(std::ceil(std::sqrt(2.0 * static_cast<double>(cells_n)))))),
              rows = static_cast<int>((cells_n + static_cast<std::size_t>(cols) - 1) / static_cast<std::size_t>(cols));
    const int head_px = 40, legend_px = coloured ? 80 : 0;
    const int width = std::max(cols * cell, 600), height = rows * cell + head_px + legend_px;
    vtkNew<vtkRenderWindow> strip_window;
    strip_window->SetOffScreenRendering(1);
    strip_window->SetSize(width, height);
    strip_window->SetMultiSamples(samples);
    // White under everything (the cells a short last row leaves empty), and each cell's caption on it, in a
    // band above the cell's drawing so that no drawing runs into the caption or the cell above.
    vtkSmartPointer<vtkRenderer> under = strip(strip_window, 0, 0, 1, 1);
    const double cell_w = static_cast<double>(cell) / width, cell_h = static_cast<double>(cell) / height;
    const double grid_top = 1 - static_cast<double>(head_px) / height, band = 24.0 / height;
    for (std::size_t i = 0; i < cells_n; ++i) {
      const std::size_t k = shown[i];
      const int c = static_cast<int>(i) % cols, r = static_cast<int>(i) / cols;
      const double top_y = grid_top - r * cell_h;
      vtkSmartPointer<vtkRenderer> view =
          strip(strip_window, c * cell_w, top_y - cell_h, (c + 1) * cell_w, top_y - band);
      vtkNew<vtkActor> actor;
      show_step(actor, drawing(k), style);
      view->AddActor(actor);
      view->SetUseFXAA(fxaa);
      under->AddActor2D(text(label(k), 13, (c + 0.04) * cell_w, top_y - band / 2, VTK_TEXT_LEFT));
      place_view(view, steps, flat, true, plan.up, static_cast<double>(cell) / (cell - 24.0));
    }
    vtkSmartPointer<vtkRenderer> strip_head = strip(strip_window, 0, grid_top, 1, 1);
    strip_head->AddActor2D(
        text(shown_title(plan.options.name.empty() ? plan.title : plan.options.name), 18, 0.012, 0.5, VTK_TEXT_LEFT));
    strip_head->AddActor2D(text((cells_n < n ? std::to_string(cells_n) + " of " : std::string()) + std::to_string(n) +
                                    " steps, one camera, one colour range",
                                13, 0.988, 0.5, VTK_TEXT_RIGHT));
    if (coloured) {
      vtkSmartPointer<vtkRenderer> strip_legend = strip(strip_window, 0, 0, 1, static_cast<double>(legend_px) / height);
      add_legend(strip_legend, plan.colouring, lut, 10);
    }
    strip_window->Render();
    if (window_errors->sent) return 0;
    pictures.insert(pictures.begin() + 1, grab_png(strip_window));
    if (window_errors->sent) return 0;
  }
  for (const std::string& p : pictures)
    if (p.empty()) {
      send_failure(out, "VTK wrote no PNG");
      return 0;
    }
  out.write("P", 1);
  put_count(out, pictures.size());
  for (const std::string& p : pictures) {
    put_count(out, p.size());
    out.write(p.data(), p.size());
  }
  out.flush();
  return 0;
}

// The renderer's reason, with what to install when it is OpenGL that is missing.
std::string explained(const std::string& reason) {
  static const char* const gl_words[] = {"GLX", "glX", "OpenGL", "context", "decent config", "visual", "GL version"};
  for (const char* w : gl_words)
    if (reason.find(w) != std::string::npos)
      return "cannot create an OpenGL context (" + reason +
             "); install Mesa's OpenGL drivers: apt-get install libgl1-mesa-dri libglx-mesa0";
  return reason;
}

}  // namespace

std::vector<std::size_t> filmstrip_steps(std::size_t n) {
  std::vector<std::size_t> shown;
  const std::size_t m = std::min(n, filmstrip_cells);
  for (std::size_t i = 0; i < m; ++i) shown.push_back(m == 1 ? n - 1 : (i * (n - 1) + (m - 1) / 2) / (m - 1));
  return shown;
}

bool flat_dataset(const Dataset& d) {
  return std::all_of(d.points.begin(), d.points.end(), [](const std::array<double, 3>& p) { return p[2] == 0; });
}

PreviewSize preview_size(const Dataset& d) { return flat_dataset(d) ? PreviewSize{800, 800} : PreviewSize{1200, 600}; }

PreviewPictures render_preview(std::span<const Dataset> steps, const std::string& title, const PreviewOptions& options,
                               Progress& progress) {
  if (steps.empty()) throw Error("it holds no steps");
  std::size_t total = 0;
  std::array<double, 3> lo{DBL_MAX, DBL_MAX, DBL_MAX}, hi{-DBL_MAX, -DBL_MAX, -DBL_MAX};
  for (const Dataset& d : steps) {
    if (d.points.empty()) throw Error(steps.size() > 1 ? "a step holds no points" : "it holds no points");
    for (const auto& p : d.points) {
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
        throw Error("it holds a point that is not finite");
      for (int j = 0; j < 3; ++j) lo[j] = std::min(lo[j], p[j]), hi[j] = std::max(hi[j], p[j]);
    }
    total += d.points.size() + d.cell_points.size();
  }
  // OpenGL draws in 32-bit floats: a drawing wider than one holds came out a blank picture, exit 0. The
  // studio's 3D view refuses the same extent (geometry_payload.cpp).
  for (int j = 0; j < 3; ++j)
    if (!(hi[j] / 2 - lo[j] / 2 < 0.5 * FLT_MAX))
      throw Error("it is too large to draw (an extent of " + number_text(hi[j] - lo[j]) +
                  "; the renderer draws in 32-bit floats)");
  if (progress.cancelled()) throw Cancelled();
  Plan plan;
  plan.title = title;
  plan.options = options;
  const Dataset& last = steps.back();
  plan.direct = options.field.empty() && has_direct_colours(last);
  if (!plan.direct) plan.colouring = steps_colouring(steps, options.field);  // throws for a field not there
  plan.up = options.up >= 0 && options.up <= 2 ? options.up : up_axis(last, options.name);
  ChildLimits limits;
  limits.what = "the VTK renderer";
  // Each frame of --steps is a render and a PNG of its own (about 0.1 s in Mesa's software renderer): a
  // growth of a thousand steps is not stopped at a limit sized for one picture (the user's --timeout is
  // the bound there).
  limits.seconds =
      60 + static_cast<double>(total) / 2e5 + (options.steps ? 0.5 * static_cast<double>(steps.size()) : 0);
  PreviewPictures pictures;
  try {
    run_in_child(
        limits, [&](PipeOut& out) { return render_in_child(out, steps, plan); },
        [&](PipeIn& in) {
          char kind = 0;
          in.read(&kind, 1);
          if (kind == 'E') {
            std::uint64_t n = 0;
            in.read(&n, sizeof n);
            std::string reason(static_cast<std::size_t>(std::min<std::uint64_t>(n, 4096)), '\0');
            in.read(reason.data(), reason.size());
            throw Error(one_line(reason));
          }
          if (kind != 'P') throw Error("the VTK renderer sent a malformed answer");
          std::uint64_t count = 0;
          in.read(&count, sizeof count);
          if (count != (options.steps ? steps.size() + 2 : 1)) throw Error("the VTK renderer sent a malformed answer");
          std::vector<std::string> got;
          for (std::uint64_t i = 0; i < count; ++i) {
            std::uint64_t n = 0;
            in.read(&n, sizeof n);
            if (n > (std::uint64_t{1} << 30)) throw Error("the VTK renderer sent a malformed answer");
            got.emplace_back(static_cast<std::size_t>(n), '\0');
            in.read(got.back().data(), got.back().size());
          }
          pictures.still = std::move(got[0]);
          if (options.steps) {
            pictures.filmstrip = std::move(got[1]);
            pictures.frames.assign(std::make_move_iterator(got.begin() + 2), std::make_move_iterator(got.end()));
          }
        });
  } catch (const Cancelled&) {
    throw;
  } catch (const Error& e) {
    throw Error(explained(e.what()));
  }
  if (progress.cancelled()) throw Cancelled();
  return pictures;
}

}  // namespace selfsim::io
