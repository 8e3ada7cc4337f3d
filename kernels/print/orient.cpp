#include "kernels/print/orient.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

#include "kernels/geom/principal_axes.h"
#include "kernels/print/first_layer.h"
#include "kernels/print/footing.h"
#include "kernels/print/overhang.h"

namespace selfsim::print {

namespace {

constexpr int cells_per_side = 64;  // of the cube map: about 1.4 degrees a cell at its centre
constexpr int face_searches = 48;   // cells looked at for a flat face, at most
constexpr int sample_directions = 1000;
constexpr int measured = 8;         // candidates measured exactly for the least overhang, by estimate
constexpr int measured_faces = 8;   // and by flat face
constexpr double flat_degrees = 2;  // a face this near the plane's normal lies in it
constexpr double degree = std::numbers::pi / 180;

struct FaceNormals {
  std::vector<Vec3> normal;  // unit, or zero for a degenerate face
  std::vector<double> area;
};

FaceNormals face_normals(const Mesh& m) {
  FaceNormals f;
  f.normal.resize(m.faces());
  f.area.resize(m.faces());
  for (std::size_t i = 0; i < m.faces(); ++i) {
    const Vec3 n = area_normal(m, m.triangles[i]);
    const double twice = norm(n);
    if (twice > 0) f.normal[i] = n / twice, f.area[i] = 0.5 * twice;
  }
  return f;
}

// Faces this close to the bounding plane lie in it: a hundredth of a millimetre (below any layer), or less
// on a small solid (one still in model units).
double flat_tolerance(const Mesh& m) { return std::min(0.01, 1e-4 * norm(corner_bbox(m).size())); }

// The lowest of the triangles' corners along `up` (a point no triangle uses holds nothing up).
double lowest_along(const Mesh& m, Vec3 up) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Triangle& t : m.triangles)
    for (std::uint32_t v : t) lowest = std::min(lowest, dot(m.points[v], up));
  return lowest;
}

// The area on the bounding plane below `up`, and the area-weighted normal of the faces there.
struct Resting {
  double area = 0;
  Vec3 normal{};
};

Resting resting_on(const Mesh& m, const FaceNormals& f, Vec3 up, double tolerance) {
  const double lowest = lowest_along(m, up), facing = -std::cos(flat_degrees * degree);
  Resting r;
  for (std::size_t i = 0; i < m.faces(); ++i) {
    if (!(dot(f.normal[i], up) < facing)) continue;
    const Triangle& t = m.triangles[i];
    if (std::all_of(t.begin(), t.end(), [&](std::uint32_t v) { return dot(m.points[v], up) - lowest <= tolerance; })) {
      r.area += f.area[i];
      r.normal += f.area[i] * f.normal[i];
    }
  }
  return r;
}

struct Cell {
  double area = 0;
  Vec3 normal{};  // area-weighted sum, then unit
};

// The faces' normals gathered on a cube map: the cells that hold any, with their area and mean normal.
std::vector<Cell> normal_cells(const FaceNormals& f) {
  constexpr int n = cells_per_side;
  std::vector<Cell> grid(6 * n * n);
  for (std::size_t i = 0; i < f.area.size(); ++i) {
    const Vec3 v = f.normal[i];
    if (!(f.area[i] > 0)) continue;
    const double ax = std::abs(v.x), ay = std::abs(v.y), az = std::abs(v.z);
    const int major = ax >= ay && ax >= az ? 0 : (ay >= az ? 1 : 2);
    const double big = std::max({ax, ay, az});
    const double u = (major == 0 ? v.y : v.x) / big, w = (major == 2 ? v.y : v.z) / big;
    const bool negative = (major == 0 ? v.x : major == 1 ? v.y : v.z) < 0;
    const int iu = std::clamp(static_cast<int>((u + 1) * 0.5 * n), 0, n - 1);
    const int iw = std::clamp(static_cast<int>((w + 1) * 0.5 * n), 0, n - 1);
    Cell& c = grid[static_cast<std::size_t>(((2 * major + negative) * n + iu) * n + iw)];
    c.area += f.area[i];
    c.normal += f.area[i] * v;
  }
  std::vector<Cell> cells;
  for (Cell c : grid)
    if (c.area > 0 && norm(c.normal) > 0) cells.push_back({c.area, normalized(c.normal)});
  return cells;
}

struct Candidate {
  Vec3 up;
  double face = 0;      // mm² resting on the bed
  double estimate = 0;  // the overhang from the cells
  double overhang = 0;  // measured
  double height = 0;
  double first_layer = 0;  // measured
  bool steady = false;     // its centre of mass over its footprint (footing.h)
};

// Flat faces the solid can rest on, looked for under the cells of most area.
std::vector<Candidate> resting_faces(const Mesh& m, const FaceNormals& f, std::vector<Cell> cells, Progress& progress) {
  std::stable_sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.area > b.area; });
  const double tolerance = flat_tolerance(m), apart = std::cos(flat_degrees * degree);
  std::vector<Candidate> found;
  double best = 0;
  for (std::size_t k = 0; k < cells.size() && k < static_cast<std::size_t>(face_searches); ++k) {
    if (cells[k].area <= best) break;  // no face in its direction can be larger
    const Vec3 up = -cells[k].normal;
    if (std::any_of(found.begin(), found.end(), [&](const Candidate& c) { return dot(c.up, up) > apart; })) continue;
    progress.step(static_cast<double>(k) / face_searches);
    Resting r = resting_on(m, f, up, tolerance);
    if (!(r.area > 0)) continue;
    // The face's own normal (a face split between cells, or off a cell's mean): measured again along it.
    const Vec3 exact = -normalized(r.normal);
    if (const Resting again = resting_on(m, f, exact, tolerance); again.area >= r.area) {
      found.push_back({exact, again.area});
    } else {
      found.push_back({up, r.area});
    }
    best = std::max(best, found.back().face);
  }
  return found;
}

double estimate_overhang(const std::vector<Cell>& cells, Vec3 up, double past) {
  double area = 0;
  for (const Cell& c : cells)
    if (-dot(c.normal, up) > past) area += c.area;
  return area;
}

// Whether a is the better pose: by overhang (when `by_overhang`; within `equal_overhang` counts as equal),
// then the first layer (by overhang) or the flat face, the height, and the turn from the pose it came in.
bool better_pose(const Candidate& a, const Candidate& b, bool by_overhang, double equal_overhang) {
  if (by_overhang && std::abs(a.overhang - b.overhang) > equal_overhang) return a.overhang < b.overhang;
  const double a_base = by_overhang ? a.first_layer : a.face, b_base = by_overhang ? b.first_layer : b.face;
  if (std::abs(a_base - b_base) > 1e-6 * std::max(a_base, b_base)) return a_base > b_base;
  const double height_tolerance = 1e-9 * std::max(a.height, b.height);
  if (by_overhang && std::abs(a.height - b.height) > height_tolerance) return a.height < b.height;
  return a.up.z > b.up.z + 1e-12;
}

double height_along(const Mesh& m, Vec3 up) { return -lowest_along(m, -up) - lowest_along(m, up); }

// First layers of m in several poses, and whether each stands by itself: one copy of the triangles over the
// points they use (a point no triangle uses would lower the first layer's plane), turned for each pose.
class FirstLayers {
 public:
  FirstLayers(const Mesh& m, double layer) : layer_(layer), centre_(mass_centre(m)) {
    std::vector<std::uint32_t> index(m.points.size(), unused);
    turned_.triangles = m.triangles;
    for (Triangle& t : turned_.triangles)
      for (std::uint32_t& v : t) {
        if (index[v] == unused) index[v] = static_cast<std::uint32_t>(used_.size()), used_.push_back(m.points[v]);
        v = index[v];
      }
    turned_.points.resize(used_.size());
  }
  // The first layer along `up`; `steady`: the centre over the footprint (the corners within a layer of the
  // bed, give or take a layer).
  double along(Vec3 up, bool* steady = nullptr) {
    const Affine3 turn = turn_up(up);
    for (std::size_t i = 0; i < used_.size(); ++i) turned_.points[i] = turn.linear(used_[i]);
    if (steady) *steady = centre_over_footprint(turned_, turn.linear(centre_), layer_, layer_);
    return first_layer_area(turned_, layer_);
  }

 private:
  static constexpr std::uint32_t unused = 0xffffffff;
  double layer_;
  Vec3 centre_;
  std::vector<Vec3> used_;  // the points the triangles use, in the order they first use them
  Mesh turned_;
};

// Measures c exactly: overhang, flat face, height and first layer along c.up.
void measure(const Mesh& m, const FaceNormals& f, const OrientOptions& opt, FirstLayers& layers, Candidate& c) {
  c.overhang = overhang_of(m, {.angle = opt.overhang, .up = c.up}).area;
  c.face = resting_on(m, f, c.up, flat_tolerance(m)).area;
  c.height = height_along(m, c.up);
  c.first_layer = layers.along(c.up, &c.steady);
}

}  // namespace

double OrientOptions::least_first_layer() const { return std::numbers::pi * nozzle * nozzle; }

Affine3 turn_up(Vec3 up) {
  const Vec3 axis = cross(up, Vec3{0, 0, 1});
  const double sine = norm(axis), cosine = dot(up, Vec3{0, 0, 1});
  if (sine > 1e-15) return rotation(axis / sine, std::atan2(sine, cosine) / degree);
  return cosine > 0 ? Affine3{} : rotation({1, 0, 0}, 180);
}

double resting_area(const Mesh& m, Vec3 up) { return resting_on(m, face_normals(m), up, flat_tolerance(m)).area; }

Vec3 bed_shift(const BBox3& box) {
  const Vec3 centre = 0.5 * (box.min + box.max);
  return {-centre.x, -centre.y, -box.min.z};
}

Orientation best_orientation(const Mesh& m, const OrientOptions& opt, Progress& progress) {
  const FaceNormals f = face_normals(m);
  const std::vector<Cell> cells = normal_cells(f);
  ProgressStage faces(progress, 0, 0.5);
  std::vector<Candidate> candidates = resting_faces(m, f, cells, faces);
  for (Candidate& c : candidates) c.height = height_along(m, c.up);
  const double least = opt.least_first_layer();
  FirstLayers layers(m, 0.5 * opt.nozzle);

  Candidate as_it_came{{0, 0, 1}};
  measure(m, f, opt, layers, as_it_came);
  Candidate best = as_it_came;
  std::vector<Candidate> principal;
  for (Vec3 up : principal_directions(m)) principal.push_back({up});
  if (!opt.least_overhang) {
    // What it stands on, the most of: the largest flat faces of at least the first layer's threshold, the
    // principal directions and the pose as it came, each by its first layer (a tube lying flat stands on more
    // than its end's flat disc). It turns only to stand on a tenth more than before (not for a faceting's
    // difference between two poses of a ball).
    std::vector<Candidate> poses;
    for (const Candidate& c : candidates)
      if (c.face >= least) poses.push_back(c);
    std::stable_sort(poses.begin(), poses.end(),
                     [](const Candidate& a, const Candidate& b) { return a.face > b.face; });
    poses.resize(std::min<std::size_t>(poses.size(), measured_faces));
    for (Candidate& c : principal) c.face = resting_on(m, f, c.up, flat_tolerance(m)).area;
    poses.insert(poses.end(), principal.begin(), principal.end());
    for (Candidate& c : poses) {
      c.first_layer = layers.along(c.up, &c.steady);
      c.height = height_along(m, c.up);
      if (c.first_layer >= least && c.first_layer > best.first_layer * 1.1) best = c;
    }
  } else {
    // Every direction estimated from the cells; the best few, the largest faces and the pose as it came
    // measured.
    const double past = std::sin(opt.overhang * degree);
    for (Candidate& c : candidates) c.estimate = estimate_overhang(cells, c.up, past) - c.face;
    std::vector<Candidate> by_face;
    for (const Candidate& c : candidates)
      if (c.face >= least) by_face.push_back(c);
    std::stable_sort(by_face.begin(), by_face.end(),
                     [](const Candidate& a, const Candidate& b) { return a.face > b.face; });
    by_face.resize(std::min<std::size_t>(by_face.size(), measured_faces));
    std::vector<Candidate> samples;
    for (Vec3 axis : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, -1, 0}})
      samples.push_back({axis});
    const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
    for (int i = 0; i < sample_directions; ++i) {
      const double z = 1 - (2 * i + 1.0) / sample_directions, r = std::sqrt(1 - z * z);
      samples.push_back({{r * std::cos(golden * i), r * std::sin(golden * i), z}});
    }
    for (Candidate& c : samples) c.estimate = estimate_overhang(cells, c.up, past);
    candidates.insert(candidates.end(), samples.begin(), samples.end());
    std::stable_sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
      return a.estimate < b.estimate || (a.estimate == b.estimate && a.face > b.face);
    });
    candidates.resize(std::min<std::size_t>(candidates.size(), measured));
    candidates.insert(candidates.end(), by_face.begin(), by_face.end());
    candidates.insert(candidates.end(), principal.begin(), principal.end());
    const double equal = 1e-3 * std::accumulate(f.area.begin(), f.area.end(), 0.0);
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      progress.step(0.5 + 0.5 * static_cast<double>(k) / static_cast<double>(candidates.size()));
      measure(m, f, opt, layers, candidates[k]);
    }
    // Of the poses that stand on enough, by themselves if any does, the least overhang; if none stands on
    // enough, the one that stands on most.
    const auto rank = [&](const Candidate& c) { return c.first_layer >= least ? (c.steady ? 2 : 1) : 0; };
    for (const Candidate& c : candidates) {
      if (rank(c) != rank(best)) {
        if (rank(c) > rank(best)) best = c;
      } else if (rank(c) > 0 ? better_pose(c, best, true, equal) : c.first_layer > best.first_layer) {
        best = c;
      }
    }
  }
  Orientation out;
  out.up = best.up;
  out.turn = turn_up(best.up);
  out.face = best.face;
  out.overhang = best.overhang;
  out.overhang_before = as_it_came.overhang;
  out.first_layer = best.first_layer;
  out.steady = best.steady;
  out.kept = best.up.z == 1;
  if (!opt.least_overhang && !out.kept) out.overhang = overhang_of(m, {.angle = opt.overhang, .up = best.up}).area;
  return out;
}

Orientation orientation_by(const Mesh& m, const Affine3& turn, const OrientOptions& opt) {
  // The direction the rotation takes to +z: its inverse (its transpose) applied to +z, its last row.
  const Vec3 up = normalized(turn.rows[2]);
  const FaceNormals f = face_normals(m);
  FirstLayers layers(m, 0.5 * opt.nozzle);
  Candidate c{up};
  measure(m, f, opt, layers, c);
  Orientation out;
  out.up = up;
  out.turn = turn;
  out.turn.t = {};
  out.face = c.face;
  out.overhang = c.overhang;
  out.overhang_before = overhang_of(m, {.angle = opt.overhang}).area;
  out.first_layer = c.first_layer;
  out.steady = c.steady;
  out.kept = up.z == 1;
  return out;
}

}  // namespace selfsim::print
