#include "kernels/plugins/render/preview_legend.h"

#include <vtkCoordinate.h>
#include <vtkDoubleArray.h>
#include <vtkLookupTable.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <cmath>

#include "kernels/io/read_error.h"
#include "kernels/io/view/result_plot.h"

namespace selfsim::io {

namespace {

constexpr double ink[3] = {0.1, 0.1, 0.1};

std::string count_text(std::size_t n, const char* one, const char* many) {
  std::string digits = std::to_string(n), s;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) s += ',';
    s += digits[i];
  }
  return s + " " + (n == 1 ? one : many);
}

}  // namespace

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

std::string holds_text(const Dataset& d, bool surface) {
  std::string what = count_text(d.points.size(), "point", "points");
  if (!d.cell_ends.empty())
    what += ", " + count_text(d.cell_ends.size(), surface ? "face" : "curve", surface ? "faces" : "curves");
  return what;
}

std::string shown_title(const std::string& title) {
  std::string t = one_line(title);
  return t.size() > 90 ? "..." + t.substr(t.size() - 87) : t;
}

void add_legend(vtkRenderer* legend, const Colouring& colouring, vtkLookupTable* lut, std::size_t swatches) {
  if (colouring.categorical && colouring.categories.size() <= swatches) {  // a swatch per class, its value under it
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
    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(lut);
    bar->SetOrientationToHorizontal();
    // Labels at round numbers inside the bar's range (the result plots' ticks, result_plot.h): 0, 2, 4, ... for
    // a whole-number field of 0..11 and 0.7, 0.8, ... for a wall of 0.6982..1.033, not the range's fifths.
    const double lo = colouring.min, hi = colouring.max > lo ? colouring.max : lo + 1;  // continuous_table's
    vtkNew<vtkDoubleArray> labels;
    for (double t : legend_ticks(lo, hi)) labels->InsertNextValue(t);
    if (labels->GetNumberOfTuples() >= 2) {
      bar->SetCustomLabels(labels);
      bar->UseCustomLabelsOn();
      bar->SetLabelFormat("%.6g");
    } else {
      bar->SetNumberOfLabels(5);
      bar->SetLabelFormat("%.4g");
    }
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

}  // namespace selfsim::io
