// Seed 002 §4.2: tiles of a Loop-smoothed developing surface fall into similarity classes, and their number
// stops growing with the level. With the paper's construction (inner corners shifted, Loop's bounded-
// curvature rules, two or more rounds) the counts are the paper's: 131 for the dragon, 135 for the terdragon
// and 125 for the Koch snowflake (the Gosper curve's 1487 is measured in bench/README.md: too big for a test).
#include "kernels/develop/tile_classes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../lsystem/table1.h"
#include "kernels/develop/develop.h"
#include "kernels/lsystem/turtle/turtle2d.h"

using namespace selfsim;
using namespace selfsim::develop;

namespace {

Mesh developed(const lsystem::Grammar& g, int top, int smooth, double shift, bool bounded) {
  std::vector<Polyline> levels;
  for (int l = 0; l <= top; ++l) levels.push_back(lsystem::turtle2d(g, {.level = l}, no_progress()));
  std::vector<const Polyline*> p;
  for (const Polyline& c : levels) p.push_back(&c);
  DevelopOptions opt;
  opt.smooth = smooth;
  opt.corner_shift = shift;
  opt.bounded = bounded;
  opt.check = smooth > 0;  // the unsmoothed dragon touches itself: kept here to count its tiles
  return develop_surface(p, opt, no_progress());
}

int classes(const Mesh& m) {
  const Field* c = m.face_fields.find("tile_class");
  EXPECT_NE(c, nullptr);
  int top = -1;
  for (std::size_t f = 0; f < m.faces(); ++f) top = std::max(top, static_cast<int>(c->at(f)));
  return top + 1;
}

}  // namespace

TEST(TileClasses, ThePapersCountsOnceTheyStopGrowing) {
  EXPECT_EQ(classes(developed(table1::dragon(), 7, 2, 0.1, true)), 99);  // still growing
  EXPECT_EQ(classes(developed(table1::dragon(), 9, 2, 0.1, true)), 131);
  EXPECT_EQ(classes(developed(table1::dragon(), 10, 2, 0.1, true)), 131);
  EXPECT_EQ(classes(developed(table1::dragon(), 9, 3, 0.1, true)), 131);  // more rounds: the same classes
  EXPECT_EQ(classes(developed(table1::terdragon(), 6, 2, 0.1, true)), 120);
  EXPECT_EQ(classes(developed(table1::terdragon(), 7, 2, 0.1, true)), 135);
  EXPECT_EQ(classes(developed(table1::koch_snowflake(), 7, 2, 0.1, true)), 125);
}

TEST(TileClasses, UnsmoothedTilesAreAllSimilar) {
  // §4.2: "in level 0 of the Loop subdivision all tiles are similar to each other".
  EXPECT_EQ(classes(developed(table1::dragon(), 8, 0, 0, false)), 1);
  EXPECT_EQ(classes(developed(table1::terdragon(), 5, 0, 0, false)), 1);
  EXPECT_EQ(classes(developed(table1::gosper(), 3, 0, 0, false)), 2);  // see tile_classes.h
  // Shifting the inner corners makes tiles differ with their neighbours along the curve.
  EXPECT_GT(classes(developed(table1::dragon(), 8, 0, 0.1, false)), 1);
}

TEST(TileClasses, ClassesDoNotChangeUnderASimilarity) {
  const Mesh m = developed(table1::dragon(), 7, 1, 0.1, true);
  Mesh moved = m;
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (Vec3& p : moved.points) p = 3.5 * Vec3{c * p.x - s * p.z, p.y, s * p.x + c * p.z} + Vec3{1, -2, 7};
  TileLayout layout;
  const Field* tile = m.face_fields.find("tile");
  const auto tiles = static_cast<std::size_t>(tile->at(m.faces() - 1)) + 1;
  layout.faces = m.faces() / tiles;
  // The reference points: any three points each tile has in the same place, here its first face's.
  for (std::size_t t = 0; t < tiles; ++t) layout.reference.push_back(m.triangles[t * layout.faces]);
  const auto a = tile_classes(m, layout, no_progress());
  const auto b = tile_classes(moved, layout, no_progress());
  EXPECT_EQ(a, b);
  EXPECT_GT(*std::max_element(a.begin(), a.end()), 10);
  // Classes are numbered in order of their first tile.
  EXPECT_EQ(a[0], 0);
  int seen = 0;
  for (int k : a) {
    EXPECT_LE(k, seen);
    seen = std::max(seen, k + 1);
  }
}

TEST(TileClasses, RefusesALayoutThatDoesNotFit) {
  const Mesh m = developed(table1::dragon(), 3, 0, 0, false);
  TileLayout layout{.faces = 5, .stride = 1, .reference = {{0, 1, 2}}};
  EXPECT_THROW(tile_classes(m, layout, no_progress()), Error);
}
