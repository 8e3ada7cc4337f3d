// Which field a picture of a value is coloured by, so that ParaView views and preview PNGs agree: the field
// that says most about how the value was made. Class fields (tile classes, surface and curve ids) are
// categorical: each value its own colour, never a continuous ramp that turns 131 classes into bands.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "kernels/geom/field.h"
#include "kernels/io/dataset/dataset.h"
#include "kernels/io/format.h"
#include "kernels/io/text/palette.h"

namespace selfsim::io {

// What a chooser needs to know of one field.
struct FieldSummary {
  std::string name;
  bool on_points = true;
  bool integer = false;  // int32, or (read back from a file) every value whole
  int components = 1;
  double min = 0, max = 0;
  std::vector<int> distinct;  // an integer field's distinct values, sorted; at most max_categories + 1 kept
};

// Whether a categorical field's classes take their colours by value, class_colour(value) (palette.h), rather
// than by their rank among the values present: a grammar's colour index `color` (from '), so that a preview, a
// ParaView view and the SVG or EPS the grammar strokes (style_runs.h) give index 3 the same colour.
inline bool coloured_by_value(const std::string& field) { return field == "color"; }
// The colour of a class: by value, class_colour(|value|) (a negative index is drawn as its magnitude, as the SVG
// writer strokes it), or by its rank among the values present. Every picture of a class field uses this.
Rgb category_colour(int value, std::size_t rank, bool by_value);

// More distinct values than this and a class field is drawn on a continuous map after all.
inline constexpr std::size_t max_categories = 256;

struct Colouring {
  std::string field;  // empty: one solid colour
  bool on_points = true;
  bool categorical = false;
  double min = 0, max = 0;
  std::vector<int> categories;  // the distinct values, when categorical
};

// The natural colouring among `fields`, the first that varies of: a print check's wall (mm), tile_class, a
// grammar's colour index `color` (from '), a plant's `branch_order` (bracket depth), a surface or curve id,
// `level`, arclength, t; else the first other one-component field (not `path`); else none.
Colouring natural_colouring(std::span<const FieldSummary> fields);

// The colouring by the field called `name` (a point field before a cell field of that name), whether or not
// it varies. Throws Error "--field: no field named 'NAME'; it holds A, B" (or "it holds no fields"), or for
// a field of more than one component.
Colouring named_colouring(std::span<const FieldSummary> fields, const std::string& name);

// The summaries of a value's fields (points first, then cells), and of a file's fields read back.
// Each looks for a stop every 2^20 values.
std::vector<FieldSummary> summarise(const Fields& points, std::size_t point_count, const Fields& cells,
                                    std::size_t cell_count, Progress& progress = no_progress());
std::vector<FieldSummary> summarise(const Dataset& d);
// A value's fields as its VTK file holds them: a curve's file adds `arclength` (along each path).
std::vector<FieldSummary> summarise(const ValueRef& v, Progress& progress = no_progress());

// The natural colouring of a time series: the last step's field, its range and categories over every step
// (so the colours mean the same at every step). Empty steps: none.
Colouring series_colouring(std::span<const ValueRef> steps, Progress& progress = no_progress());
// The same for datasets read back (a preview's steps): the field named `name` (named_colouring), or the
// natural one when `name` is empty, chosen on the last step, its range and categories over every step.
Colouring steps_colouring(std::span<const Dataset> steps, const std::string& name = {});
// The same from the steps' summaries alone (the studio reads one step at a time, steps_colouring holds them
// all): the natural choice on the last step, its range and classes over every step.
Colouring summaries_colouring(std::span<const std::vector<FieldSummary>> steps);

}  // namespace selfsim::io
