// The path data of one <path d="..."> element, read as it streams past, one character at a time: absolute
// M, L and Z commands with finite numbers in SVG's number grammar (svg_number.h), each subpath one polyline
// cell of the Dataset, its points as written (the reader transforms them once the element's tag is complete).
//
// Anything else is an error, never a guess: relative or curved commands, an odd number of coordinates in a
// subpath, an M or L without coordinates ("M 0 0 L 1 1 L"), coordinates after Z without a new M, NaN,
// infinity, overflow. A subpath of one point ("M 0 0", "M 0 0 Z", or the first M of "M 0 0 M 1 1 L 2 2")
// draws no line in SVG and is dropped, as SVG renderers do.
#pragma once

#include <cstddef>
#include <string>

#include "kernels/io/dataset/dataset.h"
#include "kernels/io/svg/svg_number.h"

namespace selfsim::io {

class PathData {
 public:
  explicit PathData(Dataset& d);

  void start();      // a d attribute begins
  void put(char c);  // its next character
  void finish();     // its closing quote: throws if the data ends incomplete

 private:
  void end_word();
  void end_number();
  void end_subpath();
  void need_no_coordinates() const;

  Dataset& d_;
  std::size_t max_points_;  // the reading limit (asked once: it costs a system call)
  SvgNumberToken number_;
  std::string word_;
  bool started_ = false, open_ = false;  // an M was seen; a subpath is open
  bool pending_ = false;                 // an x waits for its y
  char waiting_ = 0;                     // 'M' or 'L' while that command has no coordinates yet, else 0
  std::size_t subpath_first_ = 0;        // index of the current subpath's first point
  std::size_t points_in_subpath_ = 0;
  double x_ = 0;
};

}  // namespace selfsim::io
