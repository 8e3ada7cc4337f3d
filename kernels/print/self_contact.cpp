#include "kernels/print/self_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "kernels/geom/mesh_check.h"

namespace selfsim::print {

namespace {

// The interval, along unit direction u, of where triangle t (signed distances d from the other's plane,
// both signs past tol) meets that plane.
std::array<double, 2> span_on_plane(const std::array<Vec3, 3>& t, const std::array<double, 3>& d, double tol, Vec3 u) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const auto take = [&](Vec3 p) {
    lo = std::min(lo, dot(p, u));
    hi = std::max(hi, dot(p, u));
  };
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    if (std::abs(d[i]) <= tol) take(t[i]);
    if ((d[i] > tol && d[j] < -tol) || (d[i] < -tol && d[j] > tol)) take(t[i] + (d[i] / (d[i] - d[j])) * (t[j] - t[i]));
  }
  return {lo, hi};
}

// Signed distances of t's corners from the plane through p with normal n (unit), and whether they lie
// strictly on both sides (past tol).
bool both_sides(const std::array<Vec3, 3>& t, Vec3 p, Vec3 n, double tol, std::array<double, 3>& d) {
  for (int i = 0; i < 3; ++i) d[i] = dot(t[i] - p, n);
  return *std::max_element(d.begin(), d.end()) > tol && *std::min_element(d.begin(), d.end()) < -tol;
}

// Whether each piece is a solid of its own: closed (each edge's reverse is in it too, so it is closed and
// its faces agree) and facing outwards (a positive volume). Not a cavity, not a loose sheet.
std::vector<char> solid_pieces(const Mesh& m, const std::vector<std::uint32_t>& piece, std::size_t pieces) {
  std::vector<char> solid(pieces, 1);
  std::vector<double> volume(pieces, 0);
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * m.faces());
  const BBox3 b = m.bbox();
  const Vec3 o = 0.5 * (b.min + b.max);
  for (std::size_t f = 0; f < m.faces(); ++f) {
    volume[piece[f]] += volume_term(m, m.triangles[f], o);
    for (int i = 0; i < 3; ++i) edges.push_back(std::uint64_t{m.triangles[f][i]} << 32 | m.triangles[f][(i + 1) % 3]);
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t f = 0; f < m.faces(); ++f)
    for (int i = 0; i < 3; ++i) {
      // Pieces are joined across edges, so a reverse edge present belongs to the same piece.
      const std::uint64_t back = std::uint64_t{m.triangles[f][(i + 1) % 3]} << 32 | m.triangles[f][i];
      if (!std::binary_search(edges.begin(), edges.end(), back)) solid[piece[f]] = 0;
    }
  for (std::size_t p = 0; p < pieces; ++p)
    if (!(volume[p] > 0)) solid[p] = 0;
  return solid;
}

}  // namespace

double crossing_length(const std::array<Vec3, 3>& a, const std::array<Vec3, 3>& b) {
  const Vec3 na = cross(a[1] - a[0], a[2] - a[0]), nb = cross(b[1] - b[0], b[2] - b[0]);
  const double la = norm(na), lb = norm(nb);
  if (!(la > 0) || !(lb > 0)) return 0;
  double longest = 0;
  for (const auto* t : {&a, &b})
    for (int i = 0; i < 3; ++i) longest = std::max(longest, norm((*t)[(i + 1) % 3] - (*t)[i]));
  // Coincident points and corners on the other's plane (a mesher's, to rounding) are touches.
  const double tol = 1e-6 * longest;
  std::array<double, 3> da{}, db{};
  if (!both_sides(a, b[0], (1 / lb) * nb, tol, da) || !both_sides(b, a[0], (1 / la) * na, tol, db)) return 0;
  const Vec3 line = cross(na, nb);
  const double ll = norm(line);
  if (!(ll > 0)) return 0;
  const Vec3 u = (1 / ll) * line;
  const auto sa = span_on_plane(a, da, tol, u), sb = span_on_plane(b, db, tol, u);
  return std::max(0.0, std::min(sa[1], sb[1]) - std::max(sa[0], sb[0]));
}

SelfContact self_contact(const Mesh& m, double nozzle, Progress& progress, std::size_t limit) {
  SelfContact out;
  // The pieces: a speck is one smaller than the nozzle's spot beside one that is not.
  const std::vector<std::uint32_t> piece = face_components(m, progress);
  std::vector<BBox3> box;
  std::vector<double> area;
  for (std::size_t f = 0; f < m.faces(); ++f) {
    if (piece[f] >= box.size()) {
      box.resize(piece[f] + 1);
      area.resize(piece[f] + 1, 0);
    }
    for (std::uint32_t v : m.triangles[f]) box[piece[f]].add(m.points[v]);
    area[piece[f]] += 0.5 * norm(area_normal(m, m.triangles[f]));
  }
  const double spot = 0.25 * 3.14159265358979 * nozzle * nozzle;
  std::vector<char> speck(box.size(), 0);
  const auto across = [&](std::size_t p) {
    const Vec3 s = box[p].size();
    return std::max({s.x, s.y, s.z});
  };
  for (std::size_t p = 0; p < box.size(); ++p) speck[p] = across(p) < nozzle || area[p] < spot;
  if (std::all_of(speck.begin(), speck.end(), [](char s) { return s != 0; })) speck.assign(speck.size(), 0);
  for (std::size_t p = 0; p < box.size(); ++p)
    if (speck[p]) {
      ++out.specks;
      if (across(p) > out.speck_across) {
        out.speck_across = across(p);
        out.speck_where = 0.5 * (box[p].min + box[p].max);
      }
    }

  const std::vector<char> solid = solid_pieces(m, piece, box.size());
  const auto corners = [&](std::uint32_t f) {
    const Triangle& t = m.triangles[f];
    return std::array<Vec3, 3>{m.points[t[0]], m.points[t[1]], m.points[t[2]]};
  };
  // Sorted as found, each kind capped on its own: thousands of touches never hide a crossing.
  enum Kind { touch, cross, overlap, kinds };
  const auto kind = [&](std::uint32_t a, std::uint32_t b) -> int {
    const std::uint32_t pa = piece[a], pb = piece[b];
    if (speck[pa] || speck[pb]) return -1;  // a speck's own contact: said with it
    if (!(crossing_length(corners(a), corners(b)) > 0)) return touch;
    return pa != pb && solid[pa] && solid[pb] ? overlap : cross;
  };
  const std::vector<std::vector<TrianglePair>> pairs = classified_pairs(m, limit, kinds, kind, progress);
  out.capped = pairs[touch].size() >= limit;
  out.crossings_capped = pairs[cross].size() >= limit || pairs[overlap].size() >= limit;
  for (const TrianglePair& p : pairs[touch]) {
    ++out.crease_pairs;
    if (!out.crease) out.crease = p.where;
  }
  const auto length = [&](const TrianglePair& p) { return crossing_length(corners(p.first), corners(p.second)); };
  for (const TrianglePair& p : pairs[cross]) out.crossing_length += length(p);
  std::vector<std::uint32_t> joined;
  for (const TrianglePair& p : pairs[overlap]) {
    out.overlap_length += length(p);
    joined.insert(joined.end(), {piece[p.first], piece[p.second]});
  }
  std::sort(joined.begin(), joined.end());
  // Passing through over less than the nozzle's width together: a pinch the slicer cannot resolve, a crease.
  const auto count = [&](const std::vector<TrianglePair>& found, double along, std::optional<TrianglePair>& first,
                         std::size_t& n) {
    if (found.empty()) return;
    if (along > nozzle) {
      first = found.front();
      n = found.size();
      return;
    }
    out.crease_pairs += found.size();
    if (!out.crease) out.crease = found.front().where;
  };
  count(pairs[cross], out.crossing_length, out.crossing, out.crossing_pairs);
  count(pairs[overlap], out.overlap_length, out.overlap, out.overlap_pairs);
  if (out.overlap) out.overlap_solids = std::size_t(std::unique(joined.begin(), joined.end()) - joined.begin());
  return out;
}

}  // namespace selfsim::print
