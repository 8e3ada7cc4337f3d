#include "kernels/io/svg/svg_path_data.h"

#include "kernels/base/error.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/svg/svg_number.h"
#include "kernels/io/text/xml_text.h"

namespace selfsim::io {

namespace {

const char* const odd = "the path data has an odd number of coordinates in a subpath";
const char* const unsupported = " (only absolute M, L and Z are read)";

}  // namespace

PathData::PathData(Dataset& d) : d_(d), max_points_(read_budget_bytes() / 40) {}

void PathData::start() {
  number_.clear();
  word_.clear();
  started_ = open_ = pending_ = false;
  waiting_ = 0;
  points_in_subpath_ = 0;
}

void PathData::put(char c) {
  const bool letter = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z');
  if (!word_.empty()) {  // "nan", "inf", "infinity": names of numbers, never commands
    if (letter && word_.size() < 16) return word_.push_back(c);
    end_word();
  }
  if (c == 'n' || c == 'N' || c == 'i' || c == 'I') {
    if (number_.text() == "-" || number_.text() == "+") number_.clear();
    end_number();
    word_.assign(1, c);
    return;
  }
  if (!number_.empty() && number_.continues(c)) return number_.add(c, "in the path data");
  end_number();
  if (svg_number_start(c)) return number_.add(c, "in the path data");
  if (xml_space(c) || c == ',') return;
  if (c == 'M') {
    end_subpath();
    started_ = open_ = true;
    waiting_ = 'M';
  } else if (c == 'L') {
    if (!open_)
      throw Error(started_ ? "the path data has L after Z (a new subpath needs M)"
                           : "the path data does not start with M");
    need_no_coordinates();
    waiting_ = 'L';
  } else if (c == 'Z' || c == 'z') {  // closes the subpath: back to its first point
    if (!open_) throw Error(started_ ? "the path data has Z after Z" : "the path data does not start with M");
    need_no_coordinates();
    if (points_in_subpath_ > 1) {
      d_.cell_points.push_back(d_.points.size());
      d_.points.push_back(d_.points[subpath_first_]);
      ++points_in_subpath_;
    }
    end_subpath();
  } else if (letter) {
    throw Error(std::string("unsupported path command '") + c + "'" + unsupported);
  } else {
    throw Error("unexpected character '" + one_line(std::string(1, c)) + "' in the path data");
  }
}

void PathData::finish() {
  if (!word_.empty()) end_word();
  end_number();
  end_subpath();
}

void PathData::end_word() {
  const std::string w = lower_case(word_);
  word_.clear();
  if (w == "nan" || w == "inf" || w == "infinity") throw Error("the path data holds a non-finite number ('" + w + "')");
  if (w.size() == 1) throw Error("unsupported path command '" + w + "'" + unsupported);
  throw Error("unexpected text '" + one_line(w) + "' in the path data");
}

void PathData::end_number() {
  if (number_.empty()) return;
  const double v = svg_number_value(number_.text(), "in the path data");
  number_.clear();
  if (!open_)
    throw Error(started_ ? "the path data has coordinates after Z (a new subpath needs M)"
                         : "the path data does not start with M");
  if (!pending_) {
    x_ = v;
    pending_ = true;
    return;
  }
  pending_ = false;
  waiting_ = 0;
  if (d_.points.size() >= max_points_) throw Error("the path data holds more points than the reading limit");
  if (points_in_subpath_ == 0) subpath_first_ = d_.points.size();
  d_.cell_points.push_back(d_.points.size());
  d_.points.push_back({x_, v, 0});
  ++points_in_subpath_;
}

// An M or L must have coordinates, and every x its y, before the next command or the end.
void PathData::need_no_coordinates() const {
  if (pending_) throw Error(odd);
  if (waiting_ != 0) throw Error(std::string("the path data has an ") + waiting_ + " command without coordinates");
}

void PathData::end_subpath() {
  if (!open_) return;
  need_no_coordinates();
  if (points_in_subpath_ == 1) {  // one point draws no line: dropped
    d_.points.pop_back();
    d_.cell_points.pop_back();
  } else {
    d_.cell_ends.push_back(d_.cell_points.size());
  }
  open_ = false;
  points_in_subpath_ = 0;
}

}  // namespace selfsim::io
