// Seed 004's regions: any simple polygon, also non-convex (Figure 10's L), and polygons with holes; what
// is inside, how far from the boundary, and every malformed ring refused naming its problem.
#include "kernels/region/region.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "kernels/base/error.h"
#include "kernels/geom/segment2.h"
#include "kernels/geom/segment_grid.h"

using namespace selfsim;

namespace {

const std::vector<Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const std::vector<Vec2> l_shape{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};

std::string error_of(std::vector<std::vector<Vec2>> rings) {
  try {
    Region r(std::move(rings));
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Segment2, DistancesAndMeetings) {
  EXPECT_DOUBLE_EQ(point_segment_distance({0.5, 2}, {0, 0}, {1, 0}), 2);
  EXPECT_DOUBLE_EQ(point_segment_distance({4, 4}, {0, 0}, {1, 0}), 5);
  EXPECT_TRUE(segments_meet({0, 0}, {1, 1}, {0, 1}, {1, 0}));
  EXPECT_TRUE(segments_meet({0, 0}, {1, 0}, {1, 0}, {2, 5}));  // touching at an end
  EXPECT_TRUE(segments_meet({0, 0}, {2, 0}, {1, 0}, {3, 0}));  // collinear overlap
  EXPECT_FALSE(segments_meet({0, 0}, {1, 0}, {2, 0}, {3, 0}));
  EXPECT_DOUBLE_EQ(segment_distance({0, 0}, {1, 0}, {0.5, 0.3}, {0.5, 2}), 0.3);
  EXPECT_DOUBLE_EQ(segment_distance({0, 0}, {1, 1}, {0, 1}, {1, 0}), 0);
}

TEST(SegmentGrid, ReportsEachNearSegmentOnce) {
  SegmentGrid g({{0, 0}, {6, 6}}, 0.1);
  g.insert(3, {0, 0}, {1, 0});  // spans ten cells
  g.insert(7, {5, 5}, {5.05, 5});
  const auto near = g.near(BBox2{{0.2, -0.05}, {0.8, 0.05}});
  ASSERT_EQ(near.size(), 1u);
  EXPECT_EQ(near[0], 3u);
  EXPECT_TRUE(g.near(BBox2{{2, 2}, {3, 3}}).empty());
  EXPECT_EQ(g.near(BBox2{{-10, -10}, {10, 10}}).size(), 2u);
  EXPECT_THROW(SegmentGrid({{0, 0}, {1, 1}}, 0), Error);
  EXPECT_TRUE(g.near(BBox2{{0.9, 0.5}, {0.95, 0.6}}).empty());  // only the cells a segment passes through
  g.insert(9, {-3, 2}, {20, 2.5});                              // beyond the bounds: in the edge cells
  EXPECT_EQ(g.near(BBox2{{15, 2.3}, {16, 2.5}}), std::vector<std::uint32_t>{9});
  EXPECT_EQ(g.near(BBox2{{-5, 1.9}, {-4, 2.1}}), std::vector<std::uint32_t>{9});
}

TEST(Region, SquareContainsAndMeasures) {
  const Region r({square});
  EXPECT_TRUE(r.contains({0.5, 0.5}));
  EXPECT_TRUE(r.contains({0, 0.5}));  // on the boundary
  EXPECT_FALSE(r.contains({1.5, 0.5}));
  EXPECT_DOUBLE_EQ(r.distance({0.5, 0.25}), 0.25);
  EXPECT_DOUBLE_EQ(r.distance({3, 1}), 2);
  EXPECT_DOUBLE_EQ(r.distance({0.2, 0.5}, {0.5, 0.6}), 0.2);
  EXPECT_DOUBLE_EQ(r.distance({0.5, 0.5}, {2, 0.5}), 0);  // crosses the boundary
  EXPECT_EQ(r.edges(), 4u);
}

TEST(Region, NonConvexLShape) {
  const Region r({l_shape});
  EXPECT_TRUE(r.contains({0.5, 1.5}));
  EXPECT_TRUE(r.contains({1.5, 0.5}));
  EXPECT_FALSE(r.contains({1.5, 1.5}));  // the notch
  EXPECT_NEAR(r.distance({1.5, 1.5}), 0.5, 1e-15);
  // The segment across the notch's corner reaches the re-entrant corner (1, 1).
  EXPECT_NEAR(r.distance({0.5, 1.5}, {1.5, 0.5}), 0, 1e-15);
}

TEST(Region, HolesAreOutside) {
  const Region r({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {1, 2}, {2, 2}, {2, 1}}});
  EXPECT_FALSE(r.contains({1.5, 1.5}));
  EXPECT_TRUE(r.contains({1, 1.5}));  // on the hole's boundary
  EXPECT_TRUE(r.contains({3, 3}));
  EXPECT_NEAR(r.distance({1.5, 2.5}), 0.5, 1e-15);  // the hole's edge is nearer than the outer ring
}

TEST(Region, ManyPointsAgreeWithTheCircle) {
  // A circle of 20,000 points: distances from the grid agree with the circle's.
  std::vector<Vec2> circle;
  for (int k = 0; k < 20000; ++k) {
    const double t = 2 * std::numbers::pi * k / 20000;
    circle.push_back({std::cos(t), std::sin(t)});
  }
  const Region r({circle});
  for (double x : {0.0, 0.3, 0.9, 2.0}) EXPECT_NEAR(r.distance({x, 0.1}), std::abs(1 - std::hypot(x, 0.1)), 1e-7) << x;
  EXPECT_TRUE(r.contains({0.7, 0.7}));
  EXPECT_FALSE(r.contains({0.8, 0.8}));
  EXPECT_NEAR(r.distance({1e9, 0}), 1e9 - 1, 1e-3);
}

TEST(Region, MalformedRingsAreRefusedByName) {
  EXPECT_EQ(error_of({}), "a region needs an outer ring of at least 3 points");
  EXPECT_EQ(error_of({{{0, 0}, {1, 0}}}), "the outer ring needs at least 3 points, got 2");
  EXPECT_EQ(error_of({{{0, 0}, {1, 0}, {1, 0}, {0, 1}}}), "the outer ring has a zero-length edge at its point 2");
  EXPECT_EQ(error_of({{{0, 0}, {1, 1}, {1, 0}, {0, 1}}}),
            "the outer ring crosses or touches itself: edge 1 of the outer ring and edge 3 of the outer ring");
  EXPECT_EQ(error_of({square, {{5, 5}, {6, 5}, {6, 6}}}), "hole 1 lies outside the outer ring");
  EXPECT_EQ(error_of({square, {{0.5, 0.5}, {1.5, 0.5}, {0.5, 0.8}}}).substr(0, 24), "two rings cross or touch");
  EXPECT_EQ(error_of({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {3, 1}, {3, 3}}, {{1.5, 1.2}, {2, 1.2}, {2, 1.6}}}),
            "hole 2 and hole 1 overlap: holes must lie apart");
  EXPECT_EQ(error_of({{{0, 0}, {1, 0}, {std::nan(""), 1}}}), "the outer ring has a non-finite point 3");
  // A repeated first point at the end closes the ring, it is not a zero-length edge.
  EXPECT_EQ(error_of({{{0, 0}, {1, 0}, {1, 1}, {0, 0}}}), "");
}
