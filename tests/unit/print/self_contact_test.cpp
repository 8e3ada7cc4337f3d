// Self-contact told apart (issue 40): every meeting pair gathered (mesh_intersections.h), crossings measured
// along their line, touches and specks apart.
#include "kernels/print/self_contact.h"

#include <gtest/gtest.h>

#include "kernels/region/box_mesh.h"
#include "print_fixtures.h"

using namespace selfsim;
using namespace selfsim::print;
using print_fixtures::joined;

TEST(SelfContact, CrossingLengthIsTheSharedLine) {
  // A horizontal triangle pierced by a vertical one along x = 0.5 .. 1 at y = 0.25.
  const std::array<Vec3, 3> flat{Vec3{0, 0, 0}, Vec3{2, 0, 0}, Vec3{0, 2, 0}};
  const std::array<Vec3, 3> wall{Vec3{0.5, 0.25, -1}, Vec3{1, 0.25, 1}, Vec3{0.5, 0.25, 1}};
  // The wall meets z = 0 from x = 0.5 to 0.75; all of it lies inside the flat triangle.
  EXPECT_NEAR(crossing_length(flat, wall), 0.25, 1e-12);
  // Resting on the plane (a corner on it) or beside it: a touch, no length.
  const std::array<Vec3, 3> resting{Vec3{0.5, 0.25, 0}, Vec3{1, 0.25, 1}, Vec3{0.5, 0.25, 1}};
  EXPECT_EQ(crossing_length(flat, resting), 0);
  const std::array<Vec3, 3> coplanar{Vec3{1, 1, 0}, Vec3{3, 1, 0}, Vec3{1, 3, 0}};
  EXPECT_EQ(crossing_length(flat, coplanar), 0);
}

TEST(SelfContact, GathersEveryPairUpToTheLimit) {
  const Mesh through = joined(box_mesh({0, 0, 0}, {10, 10, 10}), box_mesh({5, 5, 5}, {15, 15, 15}));
  const std::vector<TrianglePair> all = intersecting_pairs(through, 100000, no_progress());
  ASSERT_GT(all.size(), 1u);
  // Sorted, the first the one first_intersection finds.
  const auto first = first_intersection(through, no_progress());
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(all.front().first, first->first);
  EXPECT_EQ(all.front().second, first->second);
  for (std::size_t i = 1; i < all.size(); ++i)
    EXPECT_TRUE(all[i - 1].first < all[i].first ||
                (all[i - 1].first == all[i].first && all[i - 1].second < all[i].second));
  EXPECT_EQ(intersecting_pairs(through, 3, no_progress()).size(), 3u);
  EXPECT_TRUE(intersecting_pairs(box_mesh({0, 0, 0}, {1, 1, 1}), 100, no_progress()).empty());
  // Two closed solids overlapping: six segments of 5 mm where their faces pass through each other, an
  // overlap of 2 solids (a slicer unites them), not a crossing.
  const SelfContact c = self_contact(through, 0.4, no_progress());
  EXPECT_FALSE(c.crossing.has_value());
  ASSERT_TRUE(c.overlap.has_value());
  EXPECT_NEAR(c.overlap_length, 30, 1e-9);
  EXPECT_EQ(c.overlap_solids, 2u);
  EXPECT_FALSE(c.capped);
}

TEST(SelfContact, ASmallCrossingIsACreaseAndASmallPieceASpeck) {
  // Two blocks overlapping by 0.1 mm along one edge: they pass through each other over 10 mm of line, past a
  // 0.4 mm nozzle; with a 50 mm nozzle it is a pinch the slicer cannot resolve.
  const Mesh pinch = joined(box_mesh({0, 0, 0}, {10, 10, 10}), box_mesh({9.9, 9.9, 0.5}, {20, 20, 9.5}));
  EXPECT_TRUE(self_contact(pinch, 0.4, no_progress()).overlap.has_value());
  const SelfContact wide = self_contact(pinch, 50, no_progress());
  EXPECT_FALSE(wide.overlap.has_value());
  EXPECT_TRUE(wide.crease.has_value());
  // A 0.2 mm cube inside a 10 mm one: a speck; alone, it is the solid, no speck.
  const Mesh inside = joined(box_mesh({0, 0, 0}, {10, 10, 10}), box_mesh({3, 3, 3}, {3.2, 3.2, 3.2}));
  const SelfContact s = self_contact(inside, 0.4, no_progress());
  EXPECT_EQ(s.specks, 1u);
  EXPECT_NEAR(s.speck_across, 0.2, 1e-12);
  EXPECT_NEAR(s.speck_where.x, 3.1, 1e-12);
  EXPECT_EQ(self_contact(box_mesh({3, 3, 3}, {3.2, 3.2, 3.2}), 0.4, no_progress()).specks, 0u);
}

// A piece through itself is a crossing; a cavity (a closed piece facing inwards) through its solid's wall is
// one too: only separate closed solids facing outwards overlap.
TEST(SelfContact, OnlySeparateSolidsOverlap) {
  Mesh self = box_mesh({0, 0, 0}, {10, 10, 10});
  self.points[7] = {10, 10, -5};  // the top corner pushed through the bottom
  const SelfContact s = self_contact(self, 0.4, no_progress());
  ASSERT_TRUE(s.crossing.has_value());
  EXPECT_FALSE(s.overlap.has_value());
  EXPECT_GT(s.crossing_length, 1);
  Mesh cavity = box_mesh({8, 2, 2}, {12, 8, 8});
  for (Triangle& t : cavity.triangles) std::swap(t[1], t[2]);
  const SelfContact h = self_contact(joined(box_mesh({0, 0, 0}, {10, 10, 10}), cavity), 0.4, no_progress());
  EXPECT_TRUE(h.crossing.has_value());
  EXPECT_FALSE(h.overlap.has_value());
}

// The cap counts each kind apart: with a limit of 8, many touching pairs first (by triangle index) do not
// hide a crossing or an overlap after them, and the touches stop at the limit.
TEST(SelfContact, CrossingsAreNotHiddenBehindTheLimitOfTouches) {
  Mesh m;
  for (int i = 0; i < 6; ++i) {
    const double x = 25.0 * i;
    m = joined(joined(m, box_mesh({x, 0, 0}, {x + 10, 10, 10})), box_mesh({x + 10, 0, 0}, {x + 20, 10, 10}));
  }
  const std::size_t touching = intersecting_pairs(m, 100000, no_progress()).size();
  ASSERT_GT(touching, 8u);
  Mesh self = box_mesh({0, 30, 0}, {10, 40, 10});
  self.points[7] = {10, 40, -5};
  m = joined(joined(m, self), joined(box_mesh({0, 60, 0}, {10, 70, 10}), box_mesh({5, 65, 5}, {15, 75, 15})));
  const SelfContact c = self_contact(m, 0.4, no_progress(), 8);
  EXPECT_TRUE(c.capped);
  EXPECT_EQ(c.crease_pairs, 8u);
  EXPECT_FALSE(c.crossings_capped);
  ASSERT_TRUE(c.crossing.has_value());
  EXPECT_GE(c.crossing->first, 6u * 2 * 12);
  ASSERT_TRUE(c.overlap.has_value());
  EXPECT_NEAR(c.overlap_length, 30, 1e-9);
  // classified_pairs keeps each kind's least pairs, sorted.
  const auto kinds = classified_pairs(
      m, 5, 2, [](std::uint32_t a, std::uint32_t) { return a < 72 ? 0 : 1; }, no_progress());
  ASSERT_EQ(kinds.size(), 2u);
  EXPECT_EQ(kinds[0].size(), 5u);
  EXPECT_EQ(kinds[1].size(), 5u);
  EXPECT_GE(kinds[1].front().first, 72u);
}
