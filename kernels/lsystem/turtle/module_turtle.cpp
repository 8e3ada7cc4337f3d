#include "kernels/lsystem/turtle/module_turtle.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string_view>
#include <vector>

#include "kernels/base/budget.h"
#include "kernels/base/count_text.h"
#include "kernels/base/error.h"
#include "kernels/geom/polygon_triangles.h"
#include "kernels/geom/similarity3.h"
#include "kernels/lsystem/compiled_grammar.h"
#include "kernels/lsystem/module_count.h"
#include "kernels/lsystem/module_pipe.h"
#include "kernels/lsystem/module_rewrite.h"
#include "kernels/lsystem/polled_growth.h"
#include "kernels/lsystem/turtle/module_headings.h"
#include "kernels/lsystem/turtle/plant.h"
#include "kernels/lsystem/turtle/turtle_frame3.h"

namespace selfsim::lsystem {

namespace {

// Modules read per point drawn before a level is refused as all rewriting and no drawing (as turtle2d).
constexpr double modules_per_point = 64;

Vec3 lift(Vec2 p) { return {p.x, p.y, 0}; }
Vec3 lift(Vec3 p) { return p; }

template <class V, class Heading>
class Turtle final : public ModuleSink {
 public:
  Turtle(const Grammar& g, const TurtleOptions& opt, PolylineT<V>& out, Mesh* polygons, Progress& progress)
      : g_(g),
        c_(g),
        opt_(opt),
        out_(out),
        polygons_(polygons),
        progress_(progress),
        tree_(branches(g)),
        widths_kept_(writes_symbol(g, '!')),
        colors_kept_(writes_symbol(g, '\'')),
        heading_(start_heading(g, opt), &directions_) {
    // '+', '-' and '|' turn by their parameter even where the grammar's angle makes them turn by nothing.
    for (std::uint8_t s : {'+', '-', '|'})
      if (c_.action[s] == Action::None) c_.action[s] = Action::Turn;
    if constexpr (std::is_same_v<V, Vec3>)
      for (char s : turns_3d)
        if (c_.action[static_cast<std::uint8_t>(s)] == Action::Turn)
          c_.action[static_cast<std::uint8_t>(s)] = Action::None;
  }

  void modules(const ModuleRun& r) override {
    for (std::size_t i = r.begin; i < r.end; ++i) Turtle::module(r.symbols[i], r.args_of(i));
  }

  void module(std::uint8_t s, std::span<const double> a) override {
    switch (c_.action[s]) {
      case Action::Draw:
      case Action::Move:
        step(s, a);
        return;
      case Action::Turn:
        if (s == '|')
          heading_.turn_around();
        else
          heading_.yaw(a.empty() ? c_.turn[s] : (s == '-' || (s != '+' && c_.turn[s] < 0)) ? -a[0] : a[0]);
        return;
      case Action::Push:
        saved_.push_back({pos_, heading_, walked_, width_, color_});
        return;
      case Action::Pop:
        if (saved_.empty()) throw Error("option 'axiom'/'rules': ']' without a matching '['");
        out_.close_path();
        path_open_ = false;
        pos_ = saved_.back().pos;
        heading_ = saved_.back().heading;
        walked_ = saved_.back().walked;
        width_ = saved_.back().width;
        color_ = saved_.back().color;
        saved_.pop_back();
        return;
      case Action::None:
        break;
    }
    const double degrees = a.empty() ? angle_of(s) : a[0];
    switch (s) {
      case '&':
        heading_.pitch(degrees);
        break;
      case '^':
        heading_.pitch(-degrees);
        break;
      case '\\':
        heading_.roll(degrees);
        break;
      case '/':
        heading_.roll(-degrees);
        break;
      case '$':
        heading_.level();
        break;
      case '!':
        if (!a.empty() && !(a[0] >= 0))
          throw Error("level " + std::to_string(opt_.level) + ": " + module_text(s, a) + " sets a negative line width");
        width_ = a.empty() ? std::max(0.0, width_ - 1) : a[0];
        break;
      case '\'':  // the nearest whole index
        color_ = a.empty() ? color_ + 1 : static_cast<std::int32_t>(std::lround(std::clamp(a[0], -1e9, 1e9)));
        break;
      case '{':
        polygon_.push_back({lift(pos_)});
        break;
      case '.':
        corner();
        break;
      case '}':
        close_polygon();
        break;
      default:
        break;
    }
  }

  // Places everything drawn (unit steps) and attaches the fields.
  void finish() {
    out_.close_path();
    const double steps = std::max(walked_, 1.0);
    double scale = 1;
    if constexpr (std::is_same_v<V, Vec2>) {
      const Similarity2 place = turtle_placement(g_, opt_, pos_, steps);
      place_all(out_.points, place);
      scale = norm(place.a);
    } else {
      const bool closed = norm(pos_) <= 1e-9 * steps;
      const Similarity3 place = normalizes(g_, opt_) && !closed ? Similarity3::to_unit({}, pos_)
                                                                : Similarity3::scaling(std::pow(g_.shrink, opt_.level));
      place_all(out_.points, place);
      if (polygons_ != nullptr) place_all(polygons_->points, place);
      scale = place.scale();
    }
    if (tree_ && !out_.points.empty()) {  // a level that draws nothing has nothing to colour
      for (double& d : root_distance_) d *= scale;
      out_.point_fields.set(int_field("branch_order", std::move(branch_order_)));
      out_.point_fields.set(real_field("root_distance", std::move(root_distance_)));
    }
    // Each only when the grammar sets it: a drawing whose widths are all the default 1 is drawn with the
    // writer's own line width, not one a step wide.
    if (widths_kept_ && !out_.points.empty()) {
      for (double& w : widths_) w *= scale;  // widths are in turtle steps, like lengths
      out_.point_fields.set(real_field("width", std::move(widths_)));
    }
    if (colors_kept_ && !out_.points.empty()) out_.point_fields.set(int_field("color", std::move(colors_)));
    if (polygons_ != nullptr) {
      polygons_->face_fields.set(int_field("polygon", std::move(polygon_ids_)));
      polygons_->face_fields.set(int_field("color", std::move(polygon_colors_)));
    }
  }

 private:
  template <class Points, class Place>
  void place_all(Points& points, const Place& place) {
    in_pieces(points.size(), progress_, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i) points[i] = place(points[i]);
    });
  }

  // The most points the budget lets the curve (or the polygons) hold: no array grows past it.
  std::size_t most_points() const { return static_cast<std::size_t>(std::clamp(opt_.budget.left(), 0.0, 1e15)) + 1; }

  // Room for one more point in every per-point array, grown together and looking for a stop as they grow.
  void make_room_for_point() {
    grow_polled(out_.points, out_.points.size() + 1, most_points(), progress_);
    const std::size_t n = out_.points.capacity();
    if (tree_) {
      grow_polled(branch_order_, n, n, progress_);
      grow_polled(root_distance_, n, n, progress_);
    }
    if (widths_kept_) grow_polled(widths_, n, n, progress_);
    if (colors_kept_) grow_polled(colors_, n, n, progress_);
  }

  struct State {
    V pos;
    Heading heading;
    double walked, width;
    std::int32_t color;
  };

  double angle_of(std::uint8_t s) const {
    const auto it = g_.angles.find(static_cast<char>(s));
    return it != g_.angles.end() ? std::abs(it->second) : g_.angle;
  }

  void step(std::uint8_t s, std::span<const double> a) {
    const double length = a.empty() ? 1 : a[0];
    const bool draws = c_.action[s] == Action::Draw && polygon_.empty();
    if (draws && !path_open_) add_point();
    if (!draws && polygon_.empty()) {
      out_.close_path();
      path_open_ = false;
    }
    pos_ += length * heading_.forward();
    walked_ += std::abs(length);
    if (draws) {
      path_open_ = true;
      add_point();
    }
    if (!polygon_.empty()) corner();
    if (g_.tropism != Vec3{}) heading_.bend(g_.tropism);
  }

  void corner() {
    if (polygon_.empty()) return;
    std::vector<Vec3>& p = polygon_.back();
    if (p.empty() || p.back() != lift(pos_)) {
      count_point();
      p.push_back(lift(pos_));
    }
  }

  void close_polygon() {
    if (polygon_.empty()) return;
    std::vector<Vec3> corners = std::move(polygon_.back());
    polygon_.pop_back();
    // A turtle that walks back to where the polygon began arrives a rounding error away: that is the first
    // corner again, not a corner of its own.
    double perimeter = 0;
    for (std::size_t k = 1; k < corners.size(); ++k) perimeter += norm(corners[k] - corners[k - 1]);
    while (corners.size() > 1 && norm(corners.back() - corners.front()) <= 1e-9 * perimeter) corners.pop_back();
    if (polygons_ == nullptr || corners.size() < 3) return;
    Vec3 normal{};  // Newell's: zero for corners on one line, which fill nothing
    for (std::size_t k = 0; k < corners.size(); ++k) normal += cross(corners[k], corners[(k + 1) % corners.size()]);
    if (!(norm(normal) > 1e-12 * perimeter * perimeter)) return;
    const std::size_t first = triangles_.size();
    try {
      polygon_triangles(corners, triangles_);
    } catch (const Error& e) {
      throw Error("level " + std::to_string(opt_.level) + ": polygon " +
                  std::to_string(polygon_ids_.empty() ? 1 : polygon_ids_.back() + 2) + ": " + e.what());
    }
    const std::size_t faces = polygons_->triangles.size() + triangles_.size() - first;
    grow_polled(polygons_->points, polygons_->points.size() + corners.size(), most_points(), progress_);
    grow_polled(polygons_->triangles, faces, most_points(), progress_);
    grow_polled(polygon_ids_, faces, most_points(), progress_);
    grow_polled(polygon_colors_, faces, most_points(), progress_);
    const auto base = static_cast<std::uint32_t>(polygons_->points.size());
    polygons_->points.insert(polygons_->points.end(), corners.begin(), corners.end());
    const std::int32_t id = polygon_count_++;
    for (std::size_t t = first; t < triangles_.size(); ++t) {
      const auto& k = triangles_[t];
      polygons_->triangles.push_back({base + static_cast<std::uint32_t>(k[0]), base + static_cast<std::uint32_t>(k[1]),
                                      base + static_cast<std::uint32_t>(k[2])});
      polygon_ids_.push_back(id);
      polygon_colors_.push_back(color_);
    }
    triangles_.clear();
  }

  void count_point() {
    if (++points_ > opt_.budget.left()) check_budget(points_, opt_.budget, "level " + std::to_string(opt_.level));
  }

  void add_point() {
    count_point();
    if (out_.points.size() == out_.points.capacity()) make_room_for_point();
    out_.points.push_back(pos_);
    if (tree_) {
      branch_order_.push_back(static_cast<std::int32_t>(saved_.size()));
      root_distance_.push_back(walked_);
    }
    if (widths_kept_) widths_.push_back(width_);
    if (colors_kept_) colors_.push_back(color_);
  }

  DirectionCache directions_;  // before heading_, which points to it
  const Grammar& g_;
  Compiled c_;
  const TurtleOptions& opt_;
  PolylineT<V>& out_;
  Mesh* polygons_;
  Progress& progress_;
  bool tree_, widths_kept_, colors_kept_;
  Heading heading_;
  bool path_open_ = false;
  V pos_{};
  double walked_ = 0, width_ = 1, points_ = 0;
  std::int32_t color_ = 0, polygon_count_ = 0;
  std::vector<State> saved_;
  std::vector<std::vector<Vec3>> polygon_;  // polygons open, innermost last
  std::vector<std::array<std::size_t, 3>> triangles_;
  std::vector<std::int32_t> branch_order_, colors_, polygon_ids_, polygon_colors_;
  std::vector<double> root_distance_, widths_;
};

ModuleLimits limits_for(const Grammar& g, const TurtleOptions& opt) {
  ModuleLimits limits;
  limits.work = modules_per_point * opt.budget.left();
  limits.held = opt.budget.left();
  // Each drawing step makes a point (a corner inside a polygon): interpretations are counted in them.
  limits.points = opt.budget;
  const Compiled c(g);
  for (int s = 0; s < 256; ++s) limits.steps[s] = c.action[s] == Action::Draw;
  return limits;
}

// A level whose size follows from its rules (module_count.h) is refused at once when it would make more
// points than the budget leaves, or feed the turtle more modules than the work limit: not after drawing up
// to the budget. Its steps are a lower bound on its points: each makes one (a corner inside a polygon).
void refuse_predicted(const Grammar& g, const TurtleOptions& opt, const ModuleLimits& limits, Progress& progress) {
  const std::optional<ModuleCounts> n = predict_module_counts(g, opt.level, limits.steps, true, progress);
  if (!n) return;
  const std::string what = "level " + std::to_string(opt.level);
  check_budget(n->steps, opt.budget, what);
  if (n->modules > limits.work)
    throw BudgetError(what + " would rewrite more than " + count_text(limits.work) +
                      " modules, over the limit (64 x --max-points)");
}

template <class V, class Heading>
PolylineT<V> draw(const Grammar& g, const TurtleOptions& opt, Mesh* polygons, Progress& progress) {
  g.validate();
  opt.validate();
  const ModuleLimits limits = limits_for(g, opt);
  refuse_predicted(g, opt, limits, progress);
  PolylineT<V> out;
  out.point_fields.set(uniform_int("level", opt.level));
  progress.start("L-system");
  Turtle<V, Heading> turtle(g, opt, out, polygons, progress);
  // With a second core, the derivation runs beside the turtle (the same modules, in the same order).
  if (tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism) >= 2)
    rewrite_modules_piped(g, opt.level, turtle, limits, progress, true);
  else
    rewrite_modules(g, opt.level, turtle, limits, progress, true);
  turtle.finish();
  progress.fraction(1);
  if (!out.finite() || (polygons != nullptr && !polygons->finite()))
    throw Error("level " + std::to_string(opt.level) + " has non-finite coordinates (its steps overflow)");
  return out;
}

}  // namespace

Polyline module_turtle2d(const Grammar& g, const TurtleOptions& opt, Progress& progress) {
  return draw<Vec2, Heading2>(g, opt, nullptr, progress);
}

Polyline3 module_turtle3d(const Grammar& g, const TurtleOptions& opt, Progress& progress) {
  return draw<Vec3, Heading3>(g, opt, nullptr, progress);
}

Mesh module_polygons(const Grammar& g, const TurtleOptions& opt, Progress& progress) {
  Mesh m;
  draw<Vec3, Heading3>(g, opt, &m, progress);
  return m;
}

double module_segments(const Grammar& g, int level, double max_points, Progress& progress) {
  // Without polygons every drawing module is a segment: a level whose size follows from its rules is
  // counted from them, however long (as the byte kernel's count is).
  if (!writes_symbol(g, '{')) {
    const Compiled c(g);
    std::array<bool, 256> draws{};
    for (int s = 0; s < 256; ++s) draws[s] = c.action[s] == Action::Draw;
    if (const std::optional<ModuleCounts> n = predict_module_counts(g, level, draws, true, progress)) return n->steps;
  }
  struct Counter : ModuleSink {
    Compiled c;
    double segments = 0;
    explicit Counter(const Grammar& g) : c(g) {}
    int polygons = 0;  // open: steps inside a polygon draw no line
    void module(std::uint8_t s, std::span<const double>) override {
      polygons += s == '{' ? 1 : s == '}' && polygons > 0 ? -1 : 0;
      segments += c.action[s] == Action::Draw && polygons == 0;
    }
  } counter(g);
  ModuleLimits limits;
  limits.work = modules_per_point * max_points;
  limits.held = max_points;
  rewrite_modules(g, level, counter, limits, progress, true);
  return counter.segments;
}

}  // namespace selfsim::lsystem
