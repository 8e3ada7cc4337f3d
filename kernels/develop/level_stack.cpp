#include "kernels/develop/level_stack.h"

#include <algorithm>
#include <string>

#include "kernels/base/check.h"
#include "kernels/base/error.h"

namespace selfsim::develop {

namespace {

void check_level(const Polyline& c, std::size_t l) {
  if (c.paths() != 1 || c.segments() < 1)
    throw Error("level " + std::to_string(l) + " must be one path with at least one segment, got " +
                std::to_string(c.paths()) + " paths");
  if (!c.finite()) throw Error("level " + std::to_string(l) + " has non-finite points");
  if (!(c.length() > 0)) throw Error("level " + std::to_string(l) + " has no length (all its points coincide)");
}

}  // namespace

std::vector<double> level_heights(std::span<const Polyline* const> levels, double height) {
  check_finite(height, "option 'height'");
  if (!(height > 0)) throw Error("option 'height' must be positive, got " + number_text(height));
  std::vector<double> z{0};
  for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
    check_level(*levels[l], l);
    const double segment = levels[l]->length() / static_cast<double>(levels[l]->segments());
    z.push_back(z.back() - height * segment);
    if (!std::isfinite(z.back())) throw Error("the level heights overflow (option 'height' is too large)");
  }
  return z;
}

int refinement_branching(std::span<const Polyline* const> levels) {
  if (levels.size() < 2) throw Error("a developing surface needs at least two levels (levels = 1 or more)");
  int branching = 0;
  for (std::size_t l = 0; l + 1 < levels.size(); ++l) {
    const Polyline &coarse = *levels[l], &fine = *levels[l + 1];
    check_level(coarse, l);
    check_level(fine, l + 1);
    const std::size_t s = coarse.segments(), f = fine.segments();
    const std::string where =
        "level " + std::to_string(l + 1) + " does not refine level " + std::to_string(l) + " segment by segment";
    // What the control mesh needs; curves made otherwise (Hilbert) need seed 002's direct parameterisation.
    const std::string need =
        ": the control mesh needs each segment replaced by the same number of consecutive "
        "segments with the same ends; develop it with method = \"bezier\" (seed 002 §3.1's direct "
        "parameterisation, which any stack of curves can take)";
    if (f % s != 0 || f / s < 1)
      throw Error(where + " (" + std::to_string(f) + " segments for " + std::to_string(s) + ")" + need);
    const int b = static_cast<int>(f / s);
    if (branching != 0 && b != branching)
      throw Error(where + " with the same branching as the levels above (" + std::to_string(b) +
                  " segments for one, not " + std::to_string(branching) + ")" + need);
    branching = b;
    const Vec2 size = coarse.bbox().size();
    const double tolerance = 1e-9 * std::max({size.x, size.y, 1e-300});
    for (std::size_t j = 0; j <= s; ++j)
      if (norm(fine.points[j * static_cast<std::size_t>(b)] - coarse.points[j]) > tolerance)
        throw Error(where + " (its point " + std::to_string(j * static_cast<std::size_t>(b) + 1) + " is not point " +
                    std::to_string(j + 1) + " of level " + std::to_string(l) + ")" + need);
  }
  return branching;
}

bool closed_levels(std::span<const Polyline* const> levels) {
  return std::all_of(levels.begin(), levels.end(), [](const Polyline* c) { return closed_path(c->path(0)); });
}

bool check_stack(std::span<const Polyline* const> levels) {
  if (levels.size() < 2)
    throw Error("a developing surface needs at least two levels, level 0 and a finer one; got " +
                std::to_string(levels.size()));
  bool closed = false;
  for (std::size_t l = 0; l < levels.size(); ++l) {
    const Polyline& c = *levels[l];
    const std::string name = "level " + std::to_string(l);
    if (c.paths() == 0) throw Error(name + " is empty: it has no path to develop");
    if (c.paths() != 1) throw Error(name + " must be one path, got " + std::to_string(c.paths()));
    if (c.segments() < 1) throw Error(name + " has no segment (it needs at least one)");
    if (!c.finite()) throw Error(name + " has non-finite points");
    const auto p = c.path(0);
    const double size = norm(c.bbox().size());
    for (std::size_t j = 0; j + 1 < p.size(); ++j)
      if (norm(p[j + 1] - p[j]) <= 1e-12 * size)  // no direction to smooth along (size 0: every point equal)
        throw Error(name + " has a zero-length segment (its points " + std::to_string(j + 1) + " and " +
                    std::to_string(j + 2) + " coincide)");
    const bool here = closed_path(p);
    if (l == 0) closed = here;
    if (here != closed)
      throw Error("levels must be all open or all closed: level 0 is " + std::string(closed ? "closed" : "open") +
                  ", " + name + " is " + (here ? "closed" : "open"));
    // Two segments make a loop there and back: its surface would join the same two points twice.
    if (closed && c.segments() < 3)
      throw Error("a closed level needs at least 3 segments, " + name + " has " + std::to_string(c.segments()));
  }
  return closed;
}

}  // namespace selfsim::develop
