// Fuzz target: the L-system kernel (kernels/lsystem). Input: a grammar in the text format of
// grammar_text.h. Runs Grammar::validate, predict_counts and lsystem::curve at the decoded level with a
// small point budget (at most 1e5, the input may lower it), then checks what the kernel promises:
//   - a selfsim::Error is the only way to refuse; nothing else may escape;
//   - the curve's points are finite, its paths are well formed (path_ends strictly increasing, each path
//     at least one segment, the last end = points.size()), its level is the one asked for;
//   - its segment count equals predict_counts' prediction, and its point count is within max_points()
//     and within the point budget (--max-points);
//   - for small levels, its points are those of a plain turtle walking expand_string's string (the
//     streamed, lattice-block expansion against the obvious one).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

#include "fuzz/fuzz_support.h"
#include "fuzz/grammar_text.h"
#include "kernels/base/error.h"
#include "kernels/geom/polyline.h"
#include "kernels/lsystem/production_count.h"
#include "kernels/lsystem/rewrite.h"
#include "kernels/lsystem/turtle/turtle2d.h"

namespace {

using namespace selfsim;
using fuzz::require;

constexpr double max_reference = 2e5;  // symbols of the reference string

// The obvious turtle over the expanded string, unit steps, in the kernel's conventions: draw beats move,
// which beats '[' / ']', which beat turns; '[' keeps the current path, ']' and moves end it.
// Returns false if the string pops an empty stack.
bool reference_turtle(const lsystem::Grammar& g, const std::string& s, double start_degrees, Polyline& out) {
  std::vector<std::pair<Vec2, double>> stack;
  Vec2 pos{};
  double heading = 0;  // degrees turned since the start, in [0, 360)
  bool open = false;
  auto forward = [&] { return polar((start_degrees + heading) * std::numbers::pi / 180); };
  for (char c : s) {
    if (g.draws(c)) {
      if (!open) out.points.push_back(pos);
      open = true;
      pos += forward();
      out.points.push_back(pos);
    } else if (g.moves(c)) {
      out.close_path();
      open = false;
      pos += forward();
    } else if (c == '[') {
      stack.emplace_back(pos, heading);
    } else if (c == ']') {
      if (stack.empty()) return false;
      out.close_path();
      open = false;
      pos = stack.back().first;
      heading = stack.back().second;
      stack.pop_back();
    } else if (const double t = g.turn_of(c); t != 0) {
      heading = std::fmod(heading + std::fmod(t, 360.0) + 360.0, 360.0);
    }
  }
  out.close_path();
  return true;
}

bool moderate_turns(const lsystem::Grammar& g) {
  for (int s = 0; s < 256; ++s)
    if (std::abs(g.turn_of(static_cast<char>(s))) > 1e6) return false;
  for (double a : g.start_angles)
    if (std::abs(a) > 1e6) return false;
  return true;
}

void check_curve(const lsystem::Grammar& g, const lsystem::TurtleOptions& opt, const lsystem::LevelCounts& counts,
                 const Polyline& c) {
  const Field* level = c.point_fields.find("level");
  require(level != nullptr && level->uniform && level->at(0) == opt.level,
          "curve level field missing or != requested " + std::to_string(opt.level));
  require(c.finite(), "curve has non-finite points");
  std::size_t begin = 0;
  for (std::size_t end : c.path_ends) {
    require(end >= begin + 2, "a path with fewer than 2 points (path_ends not increasing by >= 2)");
    begin = end;
  }
  require(begin == c.points.size(), "path_ends does not end at points.size() (" + std::to_string(begin) + " vs " +
                                        std::to_string(c.points.size()) + ")");
  require(static_cast<double>(c.segments()) == counts.segments,
          "segments " + std::to_string(c.segments()) + " != predicted " + std::to_string(counts.segments));
  require(static_cast<double>(c.points.size()) <= counts.max_points(),
          "points " + std::to_string(c.points.size()) + " > predicted bound " + std::to_string(counts.max_points()));
  // --max-points: "refuse, before any work, a curve predicted to need more points" (README).
  require(static_cast<double>(c.points.size()) <= opt.budget.limit, "curve of " + std::to_string(c.points.size()) +
                                                                        " points accepted under a budget of " +
                                                                        std::to_string(opt.budget.limit));
  (void)g;
}

// The streamed curve (normalize = false) against the reference turtle. Tolerance: the kernel may snap
// turns to a lattice (at most 2*pi*1e-9 radians each), so m unit steps may drift by up to ~m^2 * 1e-8.
void check_against_reference(const lsystem::Grammar& g, int level, const Polyline& streamed) {
  std::string s;
  try {
    s = lsystem::expand_string(g, level, max_reference);
  } catch (const Error&) {
    return;
  }
  Polyline ref;
  if (!reference_turtle(g, s, g.start_angle(level), ref)) {
    fuzz::finding("the kernel drew a curve whose string pops an empty turtle stack");
  }
  require(ref.path_ends == streamed.path_ends, "paths differ from the reference turtle's (" +
                                                   std::to_string(ref.paths()) + " vs " +
                                                   std::to_string(streamed.paths()) + " paths)");
  const double scale = std::pow(g.shrink, level);
  const double m = static_cast<double>(ref.points.size());
  const double tol = (1e-9 + 1e-8 * m * m) * scale;
  for (std::size_t i = 0; i < ref.points.size(); ++i) {
    const Vec2 want = ref.points[i] * scale, got = streamed.points[i];
    if (!(norm(want - got) <= tol + 1e-12 * norm(want)))
      fuzz::finding("point " + std::to_string(i) + " is (" + std::to_string(got.x) + ", " + std::to_string(got.y) +
                    "), the reference turtle has (" + std::to_string(want.x) + ", " + std::to_string(want.y) + ")");
  }
  if (fuzz::env_flag("SELFSIM_FUZZ_VERBOSE"))
    std::fprintf(stderr, "level %d: %zu points in %zu paths, same as the reference turtle\n", level, ref.points.size(),
                 ref.paths());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const fuzz::GrammarCase in = fuzz::decode_grammar({reinterpret_cast<const char*>(data), size});
  const lsystem::Grammar& g = in.grammar;
  try {
    g.validate();
  } catch (const Error&) {
    return 0;
  } catch (...) {
    fuzz::unexpected_exception("Grammar::validate");
  }
  lsystem::TurtleOptions opt;
  opt.level = in.level;
  opt.normalize = in.normalize;
  opt.budget.limit = in.budget;  // at most 1e5: each execution stays in milliseconds

  lsystem::LevelCounts counts;
  const bool level_ok = in.level >= 0 && in.level <= lsystem::max_level;
  if (level_ok) {
    try {
      counts = lsystem::predict_counts(g, in.level);
    } catch (...) {
      fuzz::unexpected_exception("predict_counts");
    }
    require(counts.symbols >= 0 && counts.segments >= 0 && counts.breaks >= 0, "negative predicted counts");
  }

  Polyline c;
  try {
    c = lsystem::turtle2d(g, opt, no_progress());
  } catch (const Error&) {
    return 0;
  } catch (...) {
    fuzz::unexpected_exception("lsystem::curve");
  }
  require(level_ok, "curve accepted level " + std::to_string(in.level));
  check_curve(g, opt, counts, c);

  if (moderate_turns(g) && counts.symbols <= max_reference) {
    if (opt.normalize) {
      opt.normalize = false;
      try {
        c = lsystem::turtle2d(g, opt, no_progress());
      } catch (const Error&) {
        return 0;  // shrink^level overflows when not normalised
      } catch (...) {
        fuzz::unexpected_exception("lsystem::curve (normalize = false)");
      }
      check_curve(g, opt, counts, c);
    }
    check_against_reference(g, in.level, c);
  }
  return 0;
}
