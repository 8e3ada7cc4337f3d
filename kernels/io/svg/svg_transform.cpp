#include "kernels/io/svg/svg_transform.h"

#include <cmath>
#include <numbers>
#include <string>

#include "kernels/base/error.h"
#include "kernels/io/read_error.h"
#include "kernels/io/svg/svg_number.h"
#include "kernels/io/text/xml_text.h"

namespace selfsim::io {

bool Affine2::finite() const {
  return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d) && std::isfinite(e) &&
         std::isfinite(f);
}

namespace {

// Cosine and sine of an angle in degrees, exact at multiples of 90 so that rotate(90) maps (1, 0) to (0, 1).
Vec2 turn(double degrees) {
  const double r = std::fmod(degrees, 360.0);  // in (-360, 360)
  if (std::fmod(r, 90.0) == 0) {
    constexpr Vec2 quarter[] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    return quarter[(static_cast<int>(r / 90) + 4) % 4];
  }
  return polar(r * std::numbers::pi / 180);
}

Affine2 translate(double x, double y) { return {1, 0, 0, 1, x, y}; }

class TransformText {
 public:
  explicit TransformText(std::string_view s) : s_(s) {}

  Affine2 parse() {
    Affine2 m;
    space();
    while (at_ < s_.size()) {
      m = m.after(one());
      if (!m.finite()) throw Error("the transform attribute '" + shown(s_) + "' overflows");
      space();
      if (at_ < s_.size() && s_[at_] == ',') {
        ++at_;
        space();
        if (at_ == s_.size()) expected("a transform after ','");
      }
    }
    return m;
  }

 private:
  [[noreturn]] void expected(const std::string& what) const {
    throw Error("malformed transform attribute '" + shown(s_) + "': expected " + what);
  }

  void space() {
    while (at_ < s_.size() && xml_space(s_[at_])) ++at_;
  }

  // One transform: its name, '(', its numbers and ')'.
  Affine2 one() {
    const std::size_t begin = at_;
    while (at_ < s_.size() && ((s_[at_] >= 'a' && s_[at_] <= 'z') || (s_[at_] >= 'A' && s_[at_] <= 'Z'))) ++at_;
    const std::string name(s_.substr(begin, at_ - begin));
    const bool known = name == "matrix" || name == "translate" || name == "scale" || name == "rotate" ||
                       name == "skewX" || name == "skewY";
    if (!known) expected("matrix, translate, scale, rotate, skewX or skewY");
    space();
    if (at_ == s_.size() || s_[at_] != '(') expected("'(' after " + name);
    ++at_;
    double v[6];
    int n = 0;
    space();
    while (at_ == s_.size() || s_[at_] != ')') {
      if (n > 0 && at_ < s_.size() && s_[at_] == ',') {
        ++at_;
        space();
        if (at_ == s_.size() || !svg_number_start(s_[at_])) expected("a number after ',' in " + name);
      }
      if (at_ == s_.size() || !svg_number_start(s_[at_])) expected(n == 0 ? "a number" : "a number or ')'");
      if (n == 6) expected("at most 6 numbers in " + name);
      v[n++] = number();
      space();
    }
    ++at_;
    return make(name, v, n);
  }

  double number() {
    SvgNumberToken number;
    number.add(s_[at_++], "in the transform attribute");
    while (at_ < s_.size() && number.continues(s_[at_])) number.add(s_[at_++], "in the transform attribute");
    const std::string_view token = number.text();
    double v = 0;
    const std::errc e = svg_number_parse(token, v);
    if (e == std::errc::result_out_of_range)
      throw Error("the number '" + std::string(token) + "' in the transform attribute is out of range");
    if (e != std::errc()) expected("a number, not '" + std::string(token) + "'");
    return v;
  }

  Affine2 make(const std::string& name, const double* v, int n) const {
    auto count = [&](bool ok, const char* how_many) {
      if (!ok) expected(std::string(how_many) + " in " + name + "(...), not " + std::to_string(n));
    };
    if (name == "matrix") {
      count(n == 6, "6 numbers");
      return {v[0], v[1], v[2], v[3], v[4], v[5]};
    }
    if (name == "translate") {
      count(n == 1 || n == 2, "1 or 2 numbers");
      return translate(v[0], n == 2 ? v[1] : 0);
    }
    if (name == "scale") {
      count(n == 1 || n == 2, "1 or 2 numbers");
      return {v[0], 0, 0, n == 2 ? v[1] : v[0], 0, 0};
    }
    if (name == "rotate") {
      count(n == 1 || n == 3, "1 or 3 numbers");
      const Vec2 t = turn(v[0]);
      const Affine2 r{t.x, t.y, -t.y, t.x, 0, 0};
      return n == 1 ? r : translate(v[1], v[2]).after(r).after(translate(-v[1], -v[2]));
    }
    count(n == 1, "1 number");
    const double slope = std::tan(std::fmod(v[0], 360.0) * std::numbers::pi / 180);
    return name == "skewX" ? Affine2{1, 0, slope, 1, 0, 0} : Affine2{1, slope, 0, 1, 0, 0};
  }

  std::string_view s_;
  std::size_t at_ = 0;
};

}  // namespace

Affine2 parse_svg_transform(std::string_view text) { return TransformText(text).parse(); }

}  // namespace selfsim::io
