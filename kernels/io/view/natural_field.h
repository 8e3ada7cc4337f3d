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

// More distinct values than this and a class field is drawn on a continuous map after all.
inline constexpr std::size_t max_categories = 256;

struct Colouring {
  std::string field;  // empty: one solid colour
  bool on_points = true;
  bool categorical = false;
  double min = 0, max = 0;
  std::vector<int> categories;  // the distinct values, when categorical
};

// The natural colouring among `fields`: a print check's wall (mm), then tile_class, then a surface or curve id that
// differs between elements, then a level that does, then arclength, then t; else the first other one-component field;
// else none.
Colouring natural_colouring(std::span<const FieldSummary> fields);

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

}  // namespace selfsim::io
