#include "kernels/geom/mesh_check.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "kernels/base/cancellable_sort.h"

namespace selfsim {

namespace {

// Union-find over indices, for counting connected pieces.
struct Components {
  std::vector<std::uint32_t> parent;
  explicit Components(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t root(std::uint32_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent[root(a)] = root(b); }
};

// A face's directed edge a→b, keyed by its undirected ends.
struct HalfEdge {
  std::uint32_t lo, hi;  // lo < hi
  std::uint32_t face;
  bool forward;  // the face goes lo → hi

  auto key() const { return std::pair{lo, hi}; }
};

// Points and faces in messages count from 1, as Mesh::validate and every other message does.
std::string edge_text(const HalfEdge& e) {
  return "(" + std::to_string(std::size_t{e.lo} + 1) + ", " + std::to_string(std::size_t{e.hi} + 1) + ")";
}

// Every face's half-edges ordered by (lo, hi, face): bucketed by lo in one counting pass, then each
// vertex's few edges sorted in place. Linear in the faces, where one sort of them all was the check's
// slowest step on a million triangles.
std::vector<HalfEdge> sorted_half_edges(const Mesh& m, Progress& progress) {
  std::vector<std::size_t> start(m.points.size() + 1, 0);
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++start[std::size_t{std::min(t[k], t[(k + 1) % 3])} + 1];
  for (std::size_t v = 0; v < m.points.size(); ++v) start[v + 1] += start[v];
  std::vector<HalfEdge> half(start.back());
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (std::uint32_t f = 0; f < m.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = m.triangles[f][k], b = m.triangles[f][(k + 1) % 3];
      half[fill[std::min(a, b)]++] = {std::min(a, b), std::max(a, b), f, a < b};
    }
  for (std::size_t v = 0; v < m.points.size(); ++v) {
    if (v % 65536 == 0 && progress.cancelled()) throw Cancelled();
    std::sort(half.begin() + static_cast<std::ptrdiff_t>(start[v]),
              half.begin() + static_cast<std::ptrdiff_t>(start[v + 1]),
              [](const HalfEdge& x, const HalfEdge& y) { return std::tie(x.hi, x.face) < std::tie(y.hi, y.face); });
  }
  return half;
}

}  // namespace

std::vector<std::uint32_t> face_components(const Mesh& m, Progress& progress) {
  const std::vector<HalfEdge> half = sorted_half_edges(m, progress);
  Components faces(m.triangles.size());
  for (std::size_t i = 1; i < half.size(); ++i)
    if (half[i].key() == half[i - 1].key()) faces.join(half[i - 1].face, half[i].face);
  std::vector<std::uint32_t> id(m.triangles.size()), number(m.triangles.size(), UINT32_MAX);
  std::uint32_t next = 0;
  for (std::uint32_t f = 0; f < m.triangles.size(); ++f) {
    std::uint32_t& n = number[faces.root(f)];
    if (n == UINT32_MAX) n = next++;
    id[f] = n;
  }
  return id;
}

MeshTopology mesh_topology(const Mesh& m, Progress& progress) {
  MeshTopology t;
  t.faces = m.triangles.size();
  std::vector<HalfEdge> half = sorted_half_edges(m, progress);
  std::vector<char> used(m.points.size(), 0);
  for (const Triangle& t3 : m.triangles)
    for (std::uint32_t v : t3) used[v] = 1;
  t.vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 1));

  Components faces(m.triangles.size()), boundary(m.points.size());
  std::vector<char> on_boundary(m.points.size(), 0);
  auto problem = [&](std::string s) {
    if (t.first_problem.empty()) t.first_problem = std::move(s);
  };
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].key() == half[i].key()) ++j;
    const std::size_t n = j - i;
    ++t.edges;
    if (n == 1) {
      ++t.boundary_edges;
      boundary.join(half[i].lo, half[i].hi);
      on_boundary[half[i].lo] = on_boundary[half[i].hi] = 1;
    } else if (n == 2) {
      faces.join(half[i].face, half[i + 1].face);
      if (half[i].forward == half[i + 1].forward) {
        ++t.misoriented_edges;
        problem("faces " + std::to_string(std::size_t{half[i].face} + 1) + " and " +
                std::to_string(std::size_t{half[i + 1].face} + 1) + " traverse edge " + edge_text(half[i]) +
                " in the same direction (inconsistent orientation)");
      }
    } else {
      ++t.nonmanifold_edges;
      for (std::size_t k = i + 1; k < j; ++k) faces.join(half[i].face, half[k].face);
      problem("edge " + edge_text(half[i]) + " is shared by " + std::to_string(n) + " faces");
    }
    i = j;
  }
  for (std::uint32_t f = 0; f < m.triangles.size(); ++f) t.components += faces.root(f) == f;
  for (std::uint32_t v = 0; v < m.points.size(); ++v)
    if (on_boundary[v] && boundary.root(v) == v) ++t.boundary_loops;

  // A vertex is manifold when its faces form one fan: joined across the edges through it. Each face
  // around v contributes its two other corners; faces sharing a corner share an edge through v.
  // The faces around each vertex, in one array (offsets per vertex): no allocation per vertex.
  std::vector<std::size_t> offset(m.points.size() + 1, 0);
  for (const Triangle& t3 : m.triangles)
    for (std::uint32_t v : t3) ++offset[v + 1];
  for (std::size_t v = 0; v < m.points.size(); ++v) offset[v + 1] += offset[v];
  std::vector<std::uint32_t> faces_around(offset.back());
  std::vector<std::size_t> fill(offset.begin(), offset.end() - 1);
  for (std::uint32_t f = 0; f < m.triangles.size(); ++f)
    for (std::uint32_t v : m.triangles[f]) faces_around[fill[v]++] = f;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> corners;  // (other corner, index into around[v])
  for (std::uint32_t v = 0; v < m.points.size(); ++v) {
    if ((v & 0xffff) == 0xffff && progress.cancelled()) throw Cancelled();
    const std::span<const std::uint32_t> fs(faces_around.data() + offset[v], offset[v + 1] - offset[v]);
    if (fs.size() < 2) continue;
    corners.clear();
    for (std::uint32_t k = 0; k < fs.size(); ++k)
      for (std::uint32_t w : m.triangles[fs[k]])
        if (w != v) corners.emplace_back(w, k);
    std::sort(corners.begin(), corners.end());
    Components fan(fs.size());
    for (std::size_t k = 1; k < corners.size(); ++k)
      if (corners[k].first == corners[k - 1].first) fan.join(corners[k].second, corners[k - 1].second);
    std::size_t fans = 0;
    for (std::uint32_t k = 0; k < fs.size(); ++k) fans += fan.root(k) == k;
    if (fans > 1) {
      ++t.nonmanifold_vertices;
      problem("vertex " + std::to_string(std::size_t{v} + 1) + " joins " + std::to_string(fans) +
              " fans of faces that share no edge through it (a bowtie)");
    }
  }
  return t;
}

std::string first_open_edge(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> edges;  // (low, high) -> triangles
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      edges[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      const std::vector<std::size_t>& owners = edges[{std::min(a, b), std::max(a, b)}];
      const std::string edge = "its edge from point " + std::to_string(a + 1) + " to point " + std::to_string(b + 1) +
                               " (in triangle " + std::to_string(t + 1) + ")";
      if (owners.size() == 1) return edge + " has no other triangle";
      if (owners.size() > 2) return edge + " has " + std::to_string(owners.size()) + " triangles";
      const std::size_t other = owners[0] == t ? owners[1] : owners[0];
      for (int j = 0; j < 3; ++j)
        if (m.triangles[other][j] == a && m.triangles[other][(j + 1) % 3] == b)
          return edge + " runs the same way in triangle " + std::to_string(other + 1) +
                 " (the triangles face opposite ways)";
    }
  return "";
}

}  // namespace selfsim
