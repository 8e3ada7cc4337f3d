#include "kernels/io/text/palette.h"

#include <algorithm>
#include <cmath>

namespace selfsim::io {

namespace {

// One channel of a colour given as hue, lightness and saturation (the standard HLS model).
double hls_channel(double m1, double m2, double h) {
  h -= std::floor(h);
  if (h < 1.0 / 6) return m1 + (m2 - m1) * h * 6;
  if (h < 0.5) return m2;
  if (h < 2.0 / 3) return m1 + (m2 - m1) * (2.0 / 3 - h) * 6;
  return m1;
}

}  // namespace

Rgb ramp_colour(double t) {
  static const double stops[][3] = {{0.267, 0.005, 0.329},
                                    {0.231, 0.322, 0.545},
                                    {0.129, 0.569, 0.549},
                                    {0.369, 0.788, 0.384},
                                    {0.992, 0.906, 0.145}};
  const double s = (std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0) * 4;
  const int k = std::min(3, static_cast<int>(s));
  const double f = s - k;
  Rgb c;
  for (int j = 0; j < 3; ++j) c[j] = stops[k][j] * (1 - f) + stops[k + 1][j] * f;
  return c;
}

Rgb class_colour(std::size_t i) {
  const double golden = (3 - std::sqrt(5.0)) / 2;  // the golden angle, in turns
  static const double lightness[3] = {0.50, 0.68, 0.36}, saturation[3] = {0.75, 0.55, 0.90};
  const double hue = std::fmod(0.58 + static_cast<double>(i) * golden, 1.0);
  const double l = lightness[i % 3], sat = saturation[(i / 3) % 3];
  const double m2 = l <= 0.5 ? l * (1 + sat) : l + sat - l * sat, m1 = 2 * l - m2;
  return {hls_channel(m1, m2, hue + 1.0 / 3), hls_channel(m1, m2, hue), hls_channel(m1, m2, hue - 1.0 / 3)};
}

}  // namespace selfsim::io
