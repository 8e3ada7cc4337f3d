#include "kernels/io/svg/curve_style.h"

#include <algorithm>
#include <cmath>

#include "kernels/base/check.h"
#include "kernels/base/error.h"
#include "kernels/io/drawn_width.h"
#include "kernels/io/text/colour.h"
#include "kernels/io/text/palette.h"

namespace selfsim::io {

namespace {

bool given(const SaveOptions& opt, const char* name) {
  return std::find(opt.given.begin(), opt.given.end(), name) != opt.given.end();
}

// A cell field of that name and component count, or null: a field of another shape is not a style.
const Field* style_field(const Polyline& c, const char* name, int components) {
  const Field* f = c.cell_fields.find(name);
  return f != nullptr && f->components == components ? f : nullptr;
}

Rgb rgb_at(const Field& f, std::size_t i) { return {f.at(i, 0), f.at(i, 1), f.at(i, 2)}; }

// RGB in [0, 1], or (any component negative) no colour at all.
bool colour_or_none(const Rgb& c) {
  return std::all_of(c.begin(), c.end(), [](double v) { return v >= 0 && v <= 1; }) ||
         std::any_of(c.begin(), c.end(), [](double v) { return v < 0; });
}

std::string colour_text(const Rgb& c) {
  return std::any_of(c.begin(), c.end(), [](double v) { return v < 0; }) ? "none" : colour_hex(c);
}

// A one-component point field of that name, or null.
const Field* point_style_field(const Polyline& c, const char* name) {
  const Field* f = c.point_fields.find(name);
  return f != nullptr && f->components == 1 ? f : nullptr;
}

template <class T>
const T& cycled(const std::vector<T>& palette, std::size_t member) {
  return palette[member % palette.size()];
}

}  // namespace

DrawingFrame drawing_frame(const Polyline& c, double size) {
  const BBox2 b = c.bbox();
  const Vec2 own = b.size();
  const double big = std::max({own.x, own.y, 1e-300});
  const double margin = 0.02 * big;
  DrawingFrame f{b.min - Vec2{margin, margin}, own + Vec2{2 * margin, 2 * margin}, 0, big, largest_coordinate(b)};
  f.scale = size / std::max(f.extent.x, f.extent.y);
  for (double v : {f.lo.x, f.lo.y + f.extent.y, f.extent.x * f.scale, f.extent.y * f.scale, 1 / f.scale})
    if (!std::isfinite(v)) throw Error(drawing_overflow);
  return f;
}

int coordinate_digits(const DrawingFrame& f) {
  if (!(f.reach > f.diameter)) return 9;
  return static_cast<int>(std::min(17.0, 9 + std::ceil(std::log10(f.reach / f.diameter))));
}

CurveStyles::CurveStyles(const Polyline& c, const SaveOptions& opt, double units)
    : opt_(opt),
      member_(style_field(c, "curve", 1)),
      color_(style_field(c, "color", 3)),
      width_(style_field(c, "width", 1)),
      fill_(style_field(c, "fill", 3)),
      point_width_(nullptr),
      point_color_(nullptr),
      stroke_given_(given(opt, "stroke")),
      width_given_(given(opt, "stroke_width")),
      fill_given_(given(opt, "fill")),
      units_(units) {
  if (!stroke_given_ && color_ == nullptr) point_color_ = point_style_field(c, "color");
  if (!width_given_ && width_ == nullptr) point_width_ = point_style_field(c, "width");
  // Checked once here, naming the point, rather than written as a colour or width nobody chose.
  for (std::size_t i = 0; point_color_ != nullptr && i < c.points.size(); ++i)
    if (const double k = point_color_->at(i); !(std::abs(k) <= 2147483647))
      throw Error("point field 'color' of point " + std::to_string(i + 1) +
                  " must be a colour index (a whole number), got " + number_text(k));
  // (point_style_field has refused a width that is not finite.)
  for (std::size_t i = 0; point_width_ != nullptr && i < c.points.size(); ++i)
    widest_ = std::max(widest_, std::abs(point_width_->at(i)));
  if (point_width_ != nullptr) {  // drawn relative to the drawing (drawn_width.h): its diagonal, in curve units
    Vec2 lo = c.points.empty() ? Vec2{} : c.points.front(), hi = lo;
    for (const Vec2& p : c.points) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    diagonal_ = std::hypot(hi.x - lo.x, hi.y - lo.y);
  }
  // Fields may come from a loaded file: check them once here rather than write a colour nobody chose.
  const bool palette = (stroke_given_ && opt.stroke.size() > 1) || (width_given_ && opt.stroke_width.size() > 1) ||
                       (fill_given_ && opt.fill.size() > 1);
  const Field* curve = c.cell_fields.find("curve");
  if (palette && curve != nullptr && curve->components != 1)
    throw Error("cell field 'curve' has " + std::to_string(curve->components) +
                " components; a palette needs one member number per path");
  for (std::size_t i = 0; i < c.paths(); ++i) {
    if (palette && member_) {
      const double k = member_->at(i);
      if (!(k >= 1 && k <= 2147483647 && k == std::floor(k)))
        throw Error("cell field 'curve' of path " + std::to_string(i + 1) +
                    " must be a whole number from 1 (a group's member number) for a palette");
    }
    const std::string where = " of path " + std::to_string(i + 1);
    if (color_ && !stroke_given_ && !colour_or_none(rgb_at(*color_, i)))
      throw Error("cell field 'color'" + where + " must hold red, green, blue in [0, 1], or negative values for none");
    if (width_ && !width_given_ && !(width_->at(i) > 0 && width_->at(i) < 1e6))
      throw Error("cell field 'width'" + where + " must be a positive stroke width");
    if (fill_ && !fill_given_) {
      if (!colour_or_none(rgb_at(*fill_, i)))
        throw Error("cell field 'fill'" + where + " must hold red, green, blue in [0, 1], or negative values for none");
    }
  }
}

PathStyle CurveStyles::at(std::size_t path) const {
  // Checked whole and in range where a palette reads it; any member is the first otherwise.
  const double number = member_ ? member_->at(path) : 1;
  const std::size_t member = number >= 1 && number <= 2147483647 ? static_cast<std::size_t>(number - 1) : 0;
  PathStyle s;
  if (stroke_given_ || !color_)
    s.stroke = cycled(opt_.stroke, member);
  else
    s.stroke = colour_text(rgb_at(*color_, path));
  s.width = width_given_ || !width_ ? cycled(opt_.stroke_width, member) : width_->at(path);
  if (fill_given_ || !fill_) {
    s.fill = opt_.fill.empty() ? "none" : cycled(opt_.fill, member);
  } else {
    s.fill = colour_text(rgb_at(*fill_, path));
  }
  return s;
}

bool CurveStyles::per_segment(const PathStyle& path_style) const {
  return (point_width_ != nullptr || point_color_ != nullptr) && path_style.fill == "none";
}

PathStyle CurveStyles::segment(const PathStyle& path_style, std::size_t point) const {
  PathStyle s = path_style;
  if (point_width_ != nullptr) s.width = 2 * drawn_radius(point_width_->at(point), widest_, diagonal_) * units_;
  if (point_color_ != nullptr) {
    // A negative index (ABOP's turtle allows any) is drawn as its magnitude.
    const auto k = static_cast<std::int64_t>(std::llround(std::abs(point_color_->at(point))));
    if (k != last_index_) {
      last_index_ = k;
      last_colour_ = colour_hex(class_colour(static_cast<std::size_t>(k)));
    }
    s.stroke = last_colour_;
  }
  return s;
}

}  // namespace selfsim::io
