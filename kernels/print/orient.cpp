#include "kernels/print/orient.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <vector>

#include "kernels/print/overhang.h"

namespace selfsim::print {

namespace {

constexpr int cells_per_side = 64;  // of the cube map: about 1.4 degrees a cell at its centre
constexpr int face_searches = 48;   // cells looked at for a flat face, at most
constexpr int sample_directions = 1000;
constexpr int measured = 8;         // candidates measured exactly for the least overhang
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
double flat_tolerance(const Mesh& m) { return std::min(0.01, 1e-4 * norm(m.bbox().size())); }

double lowest_along(const Mesh& m, Vec3 up) {
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3& p : m.points) lowest = std::min(lowest, dot(p, up));
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

// Whether a is the better pose: by `first` (larger is better when `larger`), then the flat face, the
// height, and the turn from the pose it came in.
bool better_pose(const Candidate& a, const Candidate& b, bool by_overhang, double equal_overhang) {
  if (by_overhang && std::abs(a.overhang - b.overhang) > equal_overhang) return a.overhang < b.overhang;
  const double face_tolerance = 1e-6 * std::max(a.face, b.face);
  if (std::abs(a.face - b.face) > face_tolerance) return a.face > b.face;
  const double height_tolerance = 1e-9 * std::max(a.height, b.height);
  if (by_overhang && std::abs(a.height - b.height) > height_tolerance) return a.height < b.height;
  return a.up.z > b.up.z + 1e-12;
}

double height_along(const Mesh& m, Vec3 up) { return -lowest_along(m, -up) - lowest_along(m, up); }

}  // namespace

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
  OverhangOptions along{.angle = opt.overhang};
  Orientation out;
  out.overhang_before = overhang_of(m, along).area;
  for (Candidate& c : candidates) c.height = height_along(m, c.up);

  Candidate best{{0, 0, 1},
                 resting_on(m, f, {0, 0, 1}, flat_tolerance(m)).area,
                 0,
                 out.overhang_before,
                 height_along(m, {0, 0, 1})};
  if (!opt.least_overhang) {
    for (const Candidate& c : candidates)
      if (better_pose(c, best, false, 0)) best = c;
  } else {
    // Every direction estimated from the cells; the best few measured.
    const double past = std::sin(opt.overhang * degree);
    for (Candidate& c : candidates) c.estimate = estimate_overhang(cells, c.up, past) - c.face;
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
    const double equal = 1e-3 * std::accumulate(f.area.begin(), f.area.end(), 0.0);
    for (std::size_t k = 0; k < candidates.size(); ++k) {
      progress.step(0.5 + 0.5 * static_cast<double>(k) / measured);
      Candidate& c = candidates[k];
      along.up = c.up;
      c.overhang = overhang_of(m, along).area;
      c.face = resting_on(m, f, c.up, flat_tolerance(m)).area;
      c.height = height_along(m, c.up);
    }
    best = candidates.front();
    for (const Candidate& c : candidates)
      if (better_pose(c, best, true, equal)) best = c;
  }
  out.up = best.up;
  out.turn = turn_up(best.up);
  out.face = best.face;
  along.up = best.up;
  out.overhang = opt.least_overhang ? best.overhang : overhang_of(m, along).area;
  return out;
}

}  // namespace selfsim::print
