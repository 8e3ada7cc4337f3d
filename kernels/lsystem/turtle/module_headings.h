// The module turtle's headings (module_turtle.cpp): one type for 2D and one for 3D, with the same turns, so
// one turtle template serves both. Internal to kernels/lsystem.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>

#include "kernels/geom/vec2.h"
#include "kernels/geom/vec3.h"
#include "kernels/lsystem/compiled_grammar.h"
#include "kernels/lsystem/turtle/turtle_frame3.h"

namespace selfsim::lsystem {

// What `$` keeps the left vector perpendicular to: up on the screen, where plants grow (start_angle 90).
inline constexpr Vec3 vertical{0, 1, 0};

// Directions of recent headings: a plant turns between a few headings millions of times, and a look-up
// returns exactly what the sine and cosine would.
struct DirectionCache {
  std::array<std::pair<double, Vec2>, 64> entries;
  DirectionCache() { entries.fill({std::numeric_limits<double>::quiet_NaN(), Vec2{}}); }
  Vec2 of(double radians) {
    const auto bits = std::bit_cast<std::uint64_t>(radians);
    auto& e = entries[(bits ^ (bits >> 29) ^ (bits >> 47)) & 63];
    if (!(e.first == radians)) e = {radians, polar(radians)};
    return e.second;
  }
};

// The 2D turtle's heading: an angle, so any number of turns leaves no drift (its direction follows it, so
// a step costs no sine). 3D turns do nothing.
struct Heading2 {
  double radians;
  Vec2 direction;
  DirectionCache* cache;
  // Degrees are reduced first (fmod is exact): a turn of 1e20 degrees is the turn it is, as in 3D.
  Heading2(double degrees, DirectionCache* c)
      : radians(std::fmod(degrees, 360.0) * degree), direction(polar(radians)), cache(c) {}
  Vec2 forward() const { return direction; }
  void yaw(double degrees) {
    radians += std::fmod(degrees, 360.0) * degree;
    if (std::abs(radians) > 16) radians = std::remainder(radians, 2 * std::numbers::pi);  // exact
    direction = cache->of(radians);
  }
  void turn_around() { yaw(180); }
  void pitch(double) {}
  void roll(double) {}
  void level() {}
  void bend(Vec3) {}
};

// The 3D turtle's heading: its frame (turtle_frame3.h), made orthonormal again every 1024 turns.
struct Heading3 {
  TurtleFrame3 frame;
  unsigned turns = 0;
  Heading3(double degrees, DirectionCache*) : frame(TurtleFrame3::heading(degrees)) {}
  Vec3 forward() const { return frame.h; }
  void yaw(double degrees) { turned(), frame.yaw(degrees); }
  void turn_around() { frame.turn_around(); }
  void pitch(double degrees) { turned(), frame.pitch(degrees); }
  void roll(double degrees) { turned(), frame.roll(degrees); }
  void level() { turned(), frame.level(vertical); }
  void bend(Vec3 t) { turned(), frame.bend(t); }
  void turned() {
    if (++turns % 1024 == 0) frame.orthonormalise();
  }
};

}  // namespace selfsim::lsystem
