// Points as messages show them: "{1, 2.5, -3}" (number_text's digits), or rounded for a reader in
// millimetres, "(12.31, 3.4, 8) mm".
#pragma once

#include <string>

#include "kernels/base/check.h"
#include "kernels/geom/vec3.h"

namespace selfsim {

inline std::string point_text(Vec3 p) {
  return "{" + number_text(p.x) + ", " + number_text(p.y) + ", " + number_text(p.z) + "}";
}

// v with `digits` significant digits, trailing zeros dropped: 0.31, 120, 1.3e-05.
inline std::string short_number(double v, int digits = 3) {
  if (!std::isfinite(v)) return number_text(v);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// A length in millimetres to a hundredth of a millimetre (a printer's resolution is coarser), "0.31 mm".
inline std::string mm_text(double v) {
  if (!std::isfinite(v)) return number_text(v) + " mm";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.2f", v);
  std::string s = buf;
  while (s.size() > 1 && s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s + " mm";
}

// An area in square millimetres: "0.0031 mm²" (two significant digits), "120 mm²" (whole from 10 up).
inline std::string area_text(double v) {
  if (!(std::abs(v) >= 10 && std::abs(v) < 1e15)) return short_number(v, 2) + " mm²";
  return std::to_string(static_cast<long long>(std::llround(v))) + " mm²";
}

// An area a print's surface has: "52 mm²" under a square centimetre, "3.1 cm²" from there (overhangs).
inline std::string larger_area_text(double v) {
  return std::abs(v) < 100 ? area_text(v) : short_number(v / 100, 2) + " cm²";
}

// A point in millimetres: "(12.31, 3.4, 8) mm".
inline std::string mm_point_text(Vec3 p) {
  auto number = [](double v) {
    std::string s = mm_text(v);
    return s.substr(0, s.size() - 3);
  };
  return "(" + number(p.x) + ", " + number(p.y) + ", " + number(p.z) + ") mm";
}

}  // namespace selfsim
