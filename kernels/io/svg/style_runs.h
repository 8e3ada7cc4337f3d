// A curve's paths as runs of one style, for the vector writers (SVG, EPS): consecutive paths of one style
// make one run (one <path> element, one PostScript path), so files stay small; a path styled segment by
// segment (curve_style.h: a turtle's widths and colours) is cut where its segments' style changes, each
// piece starting at the point where the last one ended.
#pragma once

#include <span>

#include "kernels/geom/polyline.h"
#include "kernels/io/svg/curve_style.h"

namespace selfsim::io {

// Calls sink.begin(style) when a run starts, sink.piece(points, closed) for each polyline in it (a closed
// one without its repeated last point: the writer closes it), and sink.end(style) when it ends.
template <class Sink>
void style_runs(const Polyline& c, const CurveStyles& styles, Sink& sink) {
  bool open = false;
  PathStyle current;
  auto use = [&](const PathStyle& s) {
    if (open && s == current) return;
    if (open) sink.end(current);
    current = s;
    open = true;
    sink.begin(current);
  };
  auto whole = [&](std::span<const Vec2> path) {
    const bool closed = closed_path(path);  // to a billionth of its size
    sink.piece(closed ? path.first(path.size() - 1) : path, closed);
  };
  for (std::size_t i = 0; i < c.paths(); ++i) {
    const PathStyle style = styles.at(i);
    const std::span<const Vec2> path = c.path(i);
    const std::size_t first = c.path_begin(i);
    if (!styles.per_segment(style)) {
      use(style);
      whole(path);
      continue;
    }
    // Segment k ends at point k and takes its style; a lone point (no segment) takes its own.
    PathStyle s = styles.segment(style, first + (path.size() > 1 ? 1 : 0));
    std::size_t begin = 0;
    for (std::size_t k = 2; k < path.size(); ++k) {
      PathStyle next = styles.segment(style, first + k);
      if (next == s) continue;
      use(s);
      sink.piece(path.subspan(begin, k - begin), false);
      begin = k - 1;
      s = std::move(next);
    }
    use(s);
    if (begin == 0)
      whole(path);  // one style throughout: closed as a whole path is
    else
      sink.piece(path.subspan(begin), false);
  }
  if (open) sink.end(current);
}

}  // namespace selfsim::io
