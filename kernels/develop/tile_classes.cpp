#include "kernels/develop/tile_classes.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "kernels/base/error.h"

namespace selfsim::develop {

namespace {

// Coordinates agree to this (in units of |e − a|) for tiles of one class: rounding leaves ~1e-13. Classes
// can differ by little more than 1e-7 (Gosper tiles whose neighbourhoods differ only at the edge of the
// stencils' reach): a millionth merged some of them (1479 classes instead of 1486 at level 7).
constexpr double tolerance = 1e-9;

// Tile t's sampled points in its own frame, 3 coordinates a point, the same points in the same order for
// every tile.
std::vector<double> signature(const Mesh& m, const TileLayout& layout, std::size_t t) {
  const auto& ref = layout.reference[t];
  const Vec3 a = m.points[ref[0]], f = m.points[ref[1]], e = m.points[ref[2]];
  const double scale = norm(e - a);
  const Vec3 x = (e - a) / scale;
  const Vec3 y0 = (f - a) - dot(f - a, x) * x;
  if (!(scale > 0) || !(norm(y0) > 1e-9 * scale))
    throw Error("tile " + std::to_string(t) + " is degenerate: its middle fine point lies on its coarse segment");
  const Vec3 y = normalized(y0), z = cross(x, y);
  std::vector<double> s;
  std::vector<std::uint32_t> seen;  // a few dozen points: a linear search beats a hash set
  for (std::size_t f0 = t * layout.faces; f0 < (t + 1) * layout.faces; f0 += layout.stride)
    for (std::uint32_t p : m.triangles[f0])
      if (std::find(seen.begin(), seen.end(), p) == seen.end()) {
        seen.push_back(p);
        const Vec3 d = (m.points[p] - a) / scale;
        s.insert(s.end(), {dot(d, x), dot(d, y), dot(d, z)});
      }
  // A reflection flips z: choose the sign that makes the first clearly non-zero z positive, so mirror images
  // (the dragon's left- and right-turning tiles) have one signature.
  for (std::size_t i = 2; i < s.size(); i += 3)
    if (std::abs(s[i]) > 1e-3) {
      if (s[i] < 0)
        for (std::size_t j = 2; j < s.size(); j += 3) s[j] = -s[j];
      break;
    }
  return s;
}

bool same(const std::vector<double>& u, const std::vector<double>& v) {
  if (u.size() != v.size()) return false;
  for (std::size_t i = 0; i < u.size(); ++i)
    if (!(std::abs(u[i] - v[i]) <= tolerance)) return false;
  return true;
}

}  // namespace

std::vector<std::int32_t> tile_classes(const Mesh& surface, const TileLayout& layout, Progress& progress) {
  const std::size_t tiles = layout.reference.size();
  if (layout.faces == 0 || layout.stride == 0 || tiles * layout.faces != surface.faces())
    throw Error("tile classes: the surface's faces do not split into " + std::to_string(tiles) + " tiles");
  std::vector<std::vector<double>> sig(tiles);
  std::vector<double> key(tiles);
  for (std::size_t t = 0; t < tiles; ++t) {
    if ((t & 0xfff) == 0) progress.step(0.8 * static_cast<double>(t) / static_cast<double>(tiles));
    sig[t] = signature(surface, layout, t);
    // A fixed linear functional of the signature: similar tiles have keys within n·tolerance.
    double k = 0;
    for (std::size_t i = 0; i < sig[t].size(); ++i) k += (1 + 0.618034 * static_cast<double>(i % 7)) * sig[t][i];
    key[t] = k;
  }
  std::vector<std::size_t> order(tiles);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
            [&](std::size_t i, std::size_t j) { return key[i] != key[j] ? key[i] < key[j] : i < j; });
  const double window = 5 * tolerance * static_cast<double>(sig.empty() ? 0 : sig[0].size());
  std::vector<std::int64_t> group(tiles, -1);
  std::int64_t groups = 0;
  for (std::size_t k = 0; k < tiles; ++k) {
    if ((k & 0xfff) == 0) progress.step(0.8 + 0.2 * static_cast<double>(k) / static_cast<double>(tiles));
    const std::size_t t = order[k];
    for (std::size_t back = k; back-- > 0 && key[t] - key[order[back]] <= window;)
      if (same(sig[t], sig[order[back]])) {
        group[t] = group[order[back]];
        break;
      }
    if (group[t] < 0) group[t] = groups++;
  }
  // Number classes by their first tile.
  std::vector<std::int32_t> number(static_cast<std::size_t>(groups), -1), out(tiles);
  std::int32_t next = 0;
  for (std::size_t t = 0; t < tiles; ++t) {
    auto& n = number[static_cast<std::size_t>(group[t])];
    if (n < 0) n = next++;
    out[t] = n;
  }
  return out;
}

}  // namespace selfsim::develop
