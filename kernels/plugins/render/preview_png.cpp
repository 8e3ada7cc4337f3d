// VTK's part of `selfsim preview` (see preview_png.h for what the picture holds).
#include "kernels/io/view/preview_png.h"

#include <vtkActor.h>
#include <vtkAutoInit.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkLightKit.h>
#include <vtkLogger.h>
#include <vtkLookupTable.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkVariant.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "kernels/base/error.h"
#include "kernels/io/child_process.h"
#include "kernels/io/dataset/dataset_pipe.h"
#include "kernels/io/read_error.h"
#include "kernels/io/view/natural_field.h"
#include "kernels/io/vtk/vtk_error_text.h"
#include "kernels/plugins/render/preview_scene.h"

// VTK's rendering classes are abstract until their OpenGL implementations register with the object
// factory. VTK's CMake does that through vtk_module_autoinit; these lines do it in the one file that
// renders, whatever the build system (without them vtkRenderWindow::New() returns nothing usable).
VTK_MODULE_INIT(vtkRenderingOpenGL2);
VTK_MODULE_INIT(vtkRenderingFreeType);
VTK_MODULE_INIT(vtkInteractionStyle);

namespace selfsim::io {

namespace {

// The child sends its first VTK error at once ('E', flushed: VTK may abort right after it), or the PNG.
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
constexpr double ink[3] = {0.1, 0.1, 0.1};

vtkSmartPointer<vtkTextActor> text(const std::string& s, int size, double x, double y, int justify) {
  auto t = vtkSmartPointer<vtkTextActor>::New();
  t->SetInput(s.c_str());
  vtkTextProperty* p = t->GetTextProperty();
  p->SetFontSize(size);
  p->SetColor(ink[0], ink[1], ink[2]);
  p->SetFontFamilyToArial();
  p->SetJustification(justify);
  p->SetVerticalJustificationToCentered();
  t->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  t->GetPositionCoordinate()->SetValue(x, y);
  return t;
}

std::string count_text(std::size_t n, const char* one, const char* many) {
  std::string digits = std::to_string(n), s;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) s += ',';
    s += digits[i];
  }
  return s + " " + (n == 1 ? one : many);
}

std::string shown_title(const std::string& title) {
  std::string t = one_line(title);
  return t.size() > 90 ? "..." + t.substr(t.size() - 87) : t;
}

// Places a perspective camera looking along -dir at centre at the distance where every point of d just
// fits the view (with a small margin): tighter than VTK's ResetCamera, which fits the bounding sphere.
void fit(vtkCamera* camera, const Dataset& d, const double centre[3], const double dir[3], double aspect) {
  double back[3] = {dir[0], dir[1], dir[2]}, up[3] = {0, 0, 1}, right[3];
  vtkMath::Normalize(back);
  vtkMath::Cross(up, back, right);
  vtkMath::Normalize(right);
  vtkMath::Cross(back, right, up);
  const double angle = 30;
  camera->SetViewAngle(angle);
  const double tan_v = std::tan(vtkMath::RadiansFromDegrees(angle / 2)) / 1.12, tan_h = tan_v * aspect;
  double distance = 0;
  for (const auto& p : d.points) {
    const double q[3] = {p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]};
    const double x = vtkMath::Dot(q, right), y = vtkMath::Dot(q, up), z = vtkMath::Dot(q, back);
    distance = std::max({distance, z + std::abs(x) / tan_h, z + std::abs(y) / tan_v});
  }
  if (!(distance > 0)) distance = 1;
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] + distance * back[0], centre[1] + distance * back[1], centre[2] + distance * back[2]);
  camera->SetViewUp(up);
}

// Everything VTK does, in the child: build the scene, render, send 'P' and the PNG's bytes.
int render_in_child(PipeOut& out, const Dataset& d, const std::string& title) {
  ::setenv("VTK_SMP_BACKEND_IN_USE", "Sequential", 1);  // no TBB threads in a forked child
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkNew<ErrorToPipe> window_errors;
  window_errors->out = &out;
  vtkOutputWindow::SetInstance(window_errors);

  const bool flat = flat_dataset(d);
  const PreviewSize size = preview_size(d);
  const Colouring colouring = natural_colouring(summarise(d));
  vtkSmartPointer<vtkPolyData> poly = poly_data(d, colouring);
  const bool coloured =
      (colouring.on_points ? poly->GetPointData()->GetScalars() : poly->GetCellData()->GetScalars()) != nullptr;
  const bool surface = poly->GetNumberOfPolys() > 0;

  vtkNew<vtkPolyDataMapper> mapper;
  vtkNew<vtkPolyDataNormals> normals;
  if (surface && !flat) {
    normals->SetInputData(poly);
    normals->SetFeatureAngle(60);
    normals->SplittingOn();
    normals->ConsistencyOn();
    normals->ComputeCellNormalsOff();
    mapper->SetInputConnection(normals->GetOutputPort());
  } else {
    mapper->SetInputData(poly);
  }
  vtkNew<vtkLookupTable> lut;
  if (coloured) {
    if (colouring.categorical)
      category_table(lut, colouring.categories);
    else
      continuous_table(lut, colouring.min, colouring.max);
    lut->Build();
    mapper->SetLookupTable(lut);
    mapper->UseLookupTableScalarRangeOn();
    mapper->ScalarVisibilityOn();
    if (colouring.on_points)
      mapper->SetScalarModeToUsePointData();
    else
      mapper->SetScalarModeToUseCellData();
  } else {
    mapper->ScalarVisibilityOff();
  }

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetSize(size.width, size.height);
  window->SetMultiSamples(8);
  window->SetWindowName("selfsim preview");

  // The views between a title strip at the top and a legend strip at the bottom.
  const double top = 0.93, bottom = coloured ? 0.13 : 0.02;
  const int views = flat ? 1 : 2;
  std::size_t segments = 0;
  for (std::size_t i = 0, begin = 0; i < d.cell_ends.size(); begin = d.cell_ends[i++])
    segments += d.cell_ends[i] - begin;
  for (int v = 0; v < views; ++v) {
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkProperty* p = actor->GetProperty();
    if (!coloured) p->SetColor(0.45, 0.58, 0.78);
    if (surface) {
      p->SetAmbient(0.15);
      p->SetDiffuse(0.8);
      p->SetSpecular(flat ? 0 : 0.15);
      p->SetSpecularPower(25);
    }
    p->SetLineWidth(segments < 4000 ? 2.5f : segments < 40000 ? 1.5f : 1.0f);
    p->SetPointSize(3);
    if (!surface) p->LightingOff();  // lines and points in their own colour, not shaded
    vtkNew<vtkRenderer> view;
    view->SetViewport(v * 1.0 / views, bottom, (v + 1) * 1.0 / views, top);
    view->SetBackground(white[0], white[1], white[2]);
    view->AddActor(actor);
    vtkCamera* camera = view->GetActiveCamera();
    double b[6];
    poly->GetBounds(b);
    const double centre[3] = {(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2};
    // 2D from +z; 3D from the front left above, then from the back right, lower.
    static const double directions[2][3] = {{-1.0, -1.4, 1.0}, {1.3, 1.0, 0.45}};
    const double* dir = flat ? nullptr : directions[v];
    camera->SetFocalPoint(centre);
    if (flat) {
      camera->SetPosition(centre[0], centre[1], centre[2] + 1);
      camera->SetViewUp(0, 1, 0);
      camera->ParallelProjectionOn();
    } else {
      camera->SetPosition(centre[0] + dir[0], centre[1] + dir[1], centre[2] + dir[2]);
      camera->SetViewUp(0, 0, 1);
      vtkNew<vtkLightKit> lights;
      lights->AddLightsToRenderer(view);
    }
    const double aspect = (size.width / double(views)) / (size.height * (top - bottom));
    if (flat) {
      // Fit the bounding box itself: the longer side fills 94% of the view.
      view->ResetCamera();
      const double w = std::max(b[1] - b[0], 1e-300), h = std::max(b[3] - b[2], 1e-300);
      camera->SetParallelScale(0.53 * std::max(h, w / aspect));
    } else {
      fit(camera, d, centre, dir, aspect);
    }
    view->ResetCameraClippingRange();
    window->AddRenderer(view);
  }

  // Title strip: the file name, and what it holds.
  vtkNew<vtkRenderer> head;
  head->SetViewport(0, top, 1, 1);
  head->SetBackground(white[0], white[1], white[2]);
  head->AddActor2D(text(shown_title(title), 20, 0.012, 0.5, VTK_TEXT_LEFT));
  std::string what = count_text(d.points.size(), "point", "points");
  if (!d.cell_ends.empty())
    what += ", " + count_text(d.cell_ends.size(), surface ? "face" : "curve", surface ? "faces" : "curves");
  head->AddActor2D(text(what, 14, 0.988, 0.5, VTK_TEXT_RIGHT));
  window->AddRenderer(head);

  // Legend strip: a colour bar for a continuous field, swatches for a few classes, a line for many.
  vtkNew<vtkRenderer> legend;
  legend->SetViewport(0, 0, 1, bottom);
  legend->SetBackground(white[0], white[1], white[2]);
  vtkNew<vtkScalarBarActor> bar;
  if (coloured) {
    const bool swatches = colouring.categorical && colouring.categories.size() <= (flat ? 10u : 16u);
    if (swatches) {  // a swatch per class with its value under it
      const std::size_t n = colouring.categories.size();
      legend->AddActor2D(text(colouring.field, 16, 0.19, 0.5, VTK_TEXT_RIGHT));
      for (std::size_t i = 0; i < n; ++i) {
        const double x = 0.22 + (static_cast<double>(i) + 0.5) * 0.6 / static_cast<double>(n);
        double rgb[3];
        lut->GetTableValue(static_cast<vtkIdType>(i), rgb);
        vtkSmartPointer<vtkTextActor> swatch = text("      ", 14, x, 0.68, VTK_TEXT_CENTERED);
        swatch->GetTextProperty()->SetBackgroundColor(rgb);
        swatch->GetTextProperty()->SetBackgroundOpacity(1);
        legend->AddActor2D(swatch);
        legend->AddActor2D(text(std::to_string(colouring.categories[i]), 14, x, 0.3, VTK_TEXT_CENTERED));
      }
    } else if (!colouring.categorical) {
      bar->SetLookupTable(lut);
      bar->SetOrientationToHorizontal();
      const double range = colouring.max - colouring.min;
      const bool whole = std::floor(colouring.min) == colouring.min && std::floor(range) == range && range <= 10;
      bar->SetNumberOfLabels(whole ? static_cast<int>(range) + 1 : 5);
      bar->SetLabelFormat(whole ? "%.0f" : "%.4g");
      legend->AddActor2D(text(colouring.field, 16, 0.19, 0.7, VTK_TEXT_RIGHT));
      bar->UnconstrainedFontSizeOn();
      bar->SetTextPositionToPrecedeScalarBar();
      bar->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
      bar->GetPositionCoordinate()->SetValue(0.2, 0.04);
      bar->GetPosition2Coordinate()->SetCoordinateSystemToNormalizedViewport();
      bar->GetPosition2Coordinate()->SetValue(0.6, 0.92);
      bar->SetBarRatio(0.3);
      for (vtkTextProperty* p :
           {bar->GetTitleTextProperty(), bar->GetLabelTextProperty(), bar->GetAnnotationTextProperty()}) {
        p->SetColor(ink[0], ink[1], ink[2]);
        p->ShadowOff();
        p->BoldOff();
        p->ItalicOff();
        p->SetFontSize(14);
        p->SetFontFamilyToArial();
      }
      legend->AddActor2D(bar);
    } else {
      const std::size_t n = colouring.categories.size();
      legend->AddActor2D(text(colouring.field + ": " + std::to_string(n) + " classes (" +
                                  std::to_string(colouring.categories.front()) + " to " +
                                  std::to_string(colouring.categories.back()) + "), one colour each",
                              16, 0.5, 0.5, VTK_TEXT_CENTERED));
    }
  }
  window->AddRenderer(legend);

  window->Render();
  if (window_errors->sent) return 0;
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->WriteToMemoryOn();
  png->Write();
  if (window_errors->sent) return 0;
  vtkUnsignedCharArray* bytes = png->GetResult();
  if (bytes == nullptr || bytes->GetNumberOfValues() == 0) {
    send_failure(out, "VTK wrote no PNG");
    return 0;
  }
  out.write("P", 1);
  put_count(out, static_cast<std::uint64_t>(bytes->GetNumberOfValues()));
  out.write(bytes->GetPointer(0), static_cast<std::size_t>(bytes->GetNumberOfValues()));
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

bool flat_dataset(const Dataset& d) {
  return std::all_of(d.points.begin(), d.points.end(), [](const std::array<double, 3>& p) { return p[2] == 0; });
}

PreviewSize preview_size(const Dataset& d) { return flat_dataset(d) ? PreviewSize{800, 800} : PreviewSize{1200, 600}; }

std::string render_preview_png(const Dataset& d, const std::string& title, Progress& progress) {
  if (d.points.empty()) throw Error("it holds no points");
  for (const auto& p : d.points)
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw Error("it holds a point that is not finite");
  if (progress.cancelled()) throw Cancelled();
  ChildLimits limits;
  limits.what = "the VTK renderer";
  limits.seconds = 60 + static_cast<double>(d.points.size() + d.cell_points.size()) / 2e5;
  std::string png;
  try {
    run_in_child(
        limits, [&](PipeOut& out) { return render_in_child(out, d, title); },
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
          std::uint64_t n = 0;
          in.read(&n, sizeof n);
          if (n > (std::uint64_t{1} << 30)) throw Error("the VTK renderer sent a malformed answer");
          png.resize(static_cast<std::size_t>(n));
          in.read(png.data(), png.size());
        });
  } catch (const Cancelled&) {
    throw;
  } catch (const Error& e) {
    throw Error(explained(e.what()));
  }
  if (progress.cancelled()) throw Cancelled();
  return png;
}

}  // namespace selfsim::io
