// The triangles' tree finds exactly the triangles a ray crosses: the same set as testing every triangle,
// on random soups and rays, one at a time or several of one direction together; a ray through a shared edge or vertex
// reports each triangle there; a ray in a triangle's plane or past tmax reports nothing; a stop is honoured.
#include "kernels/geom/triangle_bvh.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "kernels/region/box_mesh.h"

using namespace selfsim;

namespace {

// Every triangle of m that origin + t·dir crosses for tmin < t <= tmax, tested one by one (by the signs of
// the ray's volumes against the three edges: another way than the tree's barycentric one).
std::set<std::uint32_t> brute(const Mesh& m, Vec3 o, Vec3 d, double tmin, double tmax) {
  std::set<std::uint32_t> out;
  for (std::uint32_t f = 0; f < m.faces(); ++f) {
    const Vec3 a = m.points[m.triangles[f][0]], b = m.points[m.triangles[f][1]], c = m.points[m.triangles[f][2]];
    const Vec3 n = cross(b - a, c - a);
    const double along = dot(n, d);
    if (along == 0) continue;
    const double t = dot(n, a - o) / along;
    if (!(t > tmin && t <= tmax)) continue;
    const Vec3 x = o + t * d;
    const double u = dot(cross(b - a, x - a), n), v = dot(cross(c - b, x - b), n), w = dot(cross(a - c, x - c), n);
    if (u >= 0 && v >= 0 && w >= 0) out.insert(f);
  }
  return out;
}

std::set<std::uint32_t> faces(const std::vector<TriangleBvh::Hit>& hits) {
  std::set<std::uint32_t> out;
  for (const auto& h : hits) out.insert(h.face);
  return out;
}

struct Stopped : Progress {
  bool cancelled() override { return true; }
};

}  // namespace

TEST(TriangleBvh, FindsWhatTestingEveryTriangleFinds) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  Mesh soup;
  for (int i = 0; i < 3000; ++i) {
    const Vec3 c{5 * u(rng), 5 * u(rng), 5 * u(rng)};
    for (int k = 0; k < 3; ++k) soup.points.push_back(c + 0.4 * Vec3{u(rng), u(rng), u(rng)});
    soup.triangles.push_back({std::uint32_t(3 * i), std::uint32_t(3 * i + 1), std::uint32_t(3 * i + 2)});
  }
  const TriangleBvh bvh(soup, no_progress());
  EXPECT_GT(bvh.nodes(), 1000u);
  EXPECT_LE(bvh.depth(), 12u);  // median splits: about log2(3000 / 4) + 1
  std::size_t found = 0;
  for (int r = 0; r < 400; ++r) {
    const Vec3 o{5 * u(rng), 5 * u(rng), 5 * u(rng)};
    const Vec3 d = normalized(Vec3{u(rng), u(rng), u(rng)});
    const double tmin = r % 2 == 0 ? 0 : -3, tmax = r % 3 == 0 ? 1.5 : 20;
    std::vector<TriangleBvh::Hit> hits;
    bvh.crossings(o, d, tmin, tmax, hits);
    EXPECT_EQ(faces(hits), brute(soup, o, d, tmin, tmax)) << "ray " << r;
    for (const auto& h : hits) {
      EXPECT_GT(h.t, tmin);
      EXPECT_LE(h.t, tmax);
      EXPECT_LE(std::abs(h.facing), 1 + 1e-12);
    }
    found += hits.size();
  }
  EXPECT_GT(found, 100u);  // the rays did cross things
  // Rays of one direction through the tree together find what each finds alone.
  for (int r = 0; r < 100; ++r) {
    const Vec3 d = normalized(Vec3{u(rng), u(rng), u(rng)});
    const Vec3 c{5 * u(rng), 5 * u(rng), 5 * u(rng)};
    std::vector<Vec3> origins;
    for (int k = 0; k < 1 + r % 16; ++k) origins.push_back(c + (r % 2 == 0 ? 0.3 : 2.0) * Vec3{u(rng), u(rng), u(rng)});
    std::vector<TriangleBvh::Hit> together;
    bvh.crossings(origins, d, -1, 2, together);
    for (std::size_t k = 0; k < origins.size(); ++k) {
      std::vector<TriangleBvh::Hit> alone, mine;
      bvh.crossings(origins[k], d, -1, 2, alone);
      for (const auto& h : together)
        if (h.ray == k) mine.push_back(h);
      EXPECT_EQ(faces(mine), faces(alone)) << "packet " << r << ", ray " << k;
      EXPECT_EQ(faces(mine), brute(soup, origins[k], d, -1, 2)) << "packet " << r << ", ray " << k;
    }
  }
}

TEST(TriangleBvh, EdgesVerticesAndPlanes) {
  // The unit cube of 12 triangles: a ray down its middle crosses the top and bottom faces where their two
  // triangles share the diagonal (x = y): both of each pair report it.
  const Mesh cube = box_mesh({0, 0, 0}, {1, 1, 1});
  const TriangleBvh bvh(cube, no_progress());
  std::vector<TriangleBvh::Hit> hits;
  bvh.crossings({0.5, 0.5, 2}, {0, 0, -1}, 0, 10, hits);
  ASSERT_EQ(hits.size(), 4u);
  for (const auto& h : hits) {
    EXPECT_TRUE(std::abs(h.t - 1) < 1e-12 || std::abs(h.t - 2) < 1e-12) << h.t;
    // Entering at the top (its outward normal against the ray), leaving at the bottom.
    EXPECT_NEAR(h.facing, h.t < 1.5 ? -1 : 1, 1e-12);
  }
  // Through a corner (0, 0, 0): each triangle there reports it.
  hits.clear();
  bvh.crossings({-1, -1, -1}, normalized({1, 1, 1}), 0, 2, hits);  // not as far as (1, 1, 1)
  EXPECT_GE(hits.size(), 3u);
  for (const auto& h : hits) EXPECT_NEAR(h.t, std::sqrt(3.0), 1e-9);
  // Along the top face's plane, and short of the cube: nothing.
  hits.clear();
  bvh.crossings({-1, 0.5, 1 + 1e-6}, {1, 0, 0}, 0, 10, hits);
  bvh.crossings({0.5, 0.5, 3}, {0, 0, -1}, 0, 1.9, hits);
  EXPECT_TRUE(hits.empty());
}

TEST(TriangleBvh, DegenerateTrianglesAreLeftOutAndAStopIsHonoured) {
  Mesh m = box_mesh({0, 0, 0}, {1, 1, 1});
  m.points.push_back({0.5, 0.5, 0.5});
  m.triangles.push_back({8, 8, 8});  // no area
  const TriangleBvh bvh(m, no_progress());
  std::vector<TriangleBvh::Hit> hits;
  bvh.crossings({0.5, 0.5, 2}, {0, 0, -1}, 0, 10, hits);
  for (const auto& h : hits) EXPECT_LT(h.face, 12u);
  // A stop is looked for on ranges of 16,384 triangles and more.
  Mesh big;
  for (std::uint32_t i = 0; i < 20000; ++i) {
    big.points.insert(big.points.end(), {{double(i), 0, 0}, {double(i) + 1, 0, 0}, {double(i), 1, 0}});
    big.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  Stopped stop;
  EXPECT_THROW(TriangleBvh(big, stop), Cancelled);
  EXPECT_GT(TriangleBvh::size(big.faces()), 13.0 * big.faces());  // over 200 bytes a triangle
}
