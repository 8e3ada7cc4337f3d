// The field views and previews colour by: class fields categorical, levels that vary, arclength for a plain
// curve, ranges over a whole series.
#include "kernels/io/view/natural_field.h"

#include <gtest/gtest.h>

using namespace selfsim;

namespace {

Mesh two_triangles() {
  Mesh m;
  m.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  m.triangles = {{0, 1, 2}, {1, 3, 2}};
  return m;
}

}  // namespace

TEST(NaturalField, TileClassesAreCategoricalAndWinOverLevel) {
  Mesh m = two_triangles();
  m.face_fields.set(int_field("level", {0, 1}));
  m.face_fields.set(int_field("tile_class", {5, 2}));
  const io::ValueRef v = &m;
  const io::Colouring c = io::natural_colouring(io::summarise(v));
  EXPECT_EQ(c.field, "tile_class");
  EXPECT_FALSE(c.on_points);
  EXPECT_TRUE(c.categorical);
  EXPECT_EQ(c.categories, (std::vector<int>{2, 5}));
}

TEST(NaturalField, OneSurfaceIdIsPassedOverForTheLevel) {
  Mesh m = two_triangles();
  m.face_fields.set(uniform_int("surface", 1));
  m.face_fields.set(int_field("level", {0, 3}));
  const io::ValueRef v = &m;
  const io::Colouring c = io::natural_colouring(io::summarise(v));
  EXPECT_EQ(c.field, "level");
  EXPECT_FALSE(c.categorical);
  EXPECT_EQ(c.max, 3);
}

TEST(NaturalField, APlainCurveIsColouredByTheArclengthItsFileCarries) {
  Polyline c = Polyline::single({{0, 0}, {3, 4}, {3, 5}});
  c.point_fields.set(uniform_int("level", 4));
  const io::ValueRef v = &c;
  const io::Colouring col = io::natural_colouring(io::summarise(v));
  EXPECT_EQ(col.field, "arclength");
  EXPECT_DOUBLE_EQ(col.max, 6);
}

TEST(NaturalField, TooManyClassesFallBackToAContinuousMap) {
  Mesh m;
  for (int i = 0; i < 300; ++i) {
    m.points.push_back({double(i), 0, 0});
    m.points.push_back({double(i), 1, 0});
    m.points.push_back({double(i) + 0.5, 0, 1});
    m.triangles.push_back({std::uint32_t(3 * i), std::uint32_t(3 * i + 1), std::uint32_t(3 * i + 2)});
  }
  std::vector<std::int32_t> classes(300);
  for (int i = 0; i < 300; ++i) classes[i] = i;
  m.face_fields.set(int_field("tile_class", classes));
  const io::ValueRef v = &m;
  const io::Colouring c = io::natural_colouring(io::summarise(v));
  EXPECT_EQ(c.field, "tile_class");
  EXPECT_FALSE(c.categorical);
  EXPECT_TRUE(c.categories.empty());
}

TEST(NaturalField, ASeriesRangeCoversEveryStep) {
  Polyline a = Polyline::single({{0, 0}, {1, 0}}), b = Polyline::single({{0, 0}, {0.5, 0}, {1, 0}});
  a.point_fields.set(int_field("level", {0, 0}));
  b.point_fields.set(int_field("level", {0, 1, 0}));
  const std::vector<io::ValueRef> steps{&a, &b};
  const io::Colouring c = io::series_colouring(steps);
  EXPECT_EQ(c.field, "level");
  EXPECT_EQ(c.min, 0);
  EXPECT_EQ(c.max, 1);
}

TEST(NaturalField, FieldsReadBackFromAFileAreSummarisedAlike) {
  io::Dataset d;
  d.shapes = io::CellShapes::polygons;
  d.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  d.cell_ends = {3};
  d.cell_points = {0, 1, 2};
  d.cell_fields["curve"] = {1, {1}};
  d.point_fields["t"] = {1, {0, 0.5, 1}};
  const io::Colouring c = io::natural_colouring(io::summarise(d));
  EXPECT_EQ(c.field, "t");  // one curve id does not vary: the next natural field
  EXPECT_TRUE(c.on_points);
}

TEST(NaturalField, ValuesDifferingOnlyByRoundingAreOneValue) {
  // A checked tube: every wall reads as the 1.2 mm cap, give or take the last bit.
  Mesh m = two_triangles();
  m.face_fields.set(real_field("wall", {1.2, 1.2000000000000006}));
  const io::ValueRef v = &m;
  const std::vector<io::FieldSummary> same = io::summarise(v);
  ASSERT_EQ(same.size(), 1u);
  EXPECT_EQ(same[0].min, same[0].max);
  EXPECT_TRUE(io::natural_colouring(same).field.empty());  // one colour, not a scale over the noise
  // A real difference, however small beside the value, stays.
  m.face_fields.set(real_field("wall", {1.2, 1.2001}));
  const io::Colouring d = io::natural_colouring(io::summarise(io::ValueRef{&m}));
  EXPECT_EQ(d.field, "wall");
  EXPECT_LT(d.min, d.max);
}

namespace {

// A branching curve as read back: a grammar's colour index, its branch depth, a path id, arclength.
io::Dataset plant() {
  io::Dataset d;
  d.points = {{0, 0, 0}, {0, 1, 0}, {0, 1, 0}, {1, 2, 0}};
  d.cell_ends = {2, 4};
  d.cell_points = {0, 1, 2, 3};
  d.point_fields["arclength"] = {1, {0, 1, 0, 1.4}};
  d.point_fields["branch_order"] = {1, {0, 0, 1, 1}};
  d.cell_fields["path"] = {1, {0, 1}};
  return d;
}

}  // namespace

TEST(NaturalField, BranchOrderBeforeArclengthAndColourIndexBeforeBoth) {
  io::Dataset d = plant();
  io::Colouring c = io::natural_colouring(io::summarise(d));
  EXPECT_EQ(c.field, "branch_order");
  EXPECT_FALSE(c.categorical);  // a depth: an ordered ramp
  d.point_fields["color"] = {1, {1, 1, 2, 3}};
  c = io::natural_colouring(io::summarise(d));
  EXPECT_EQ(c.field, "color");
  EXPECT_TRUE(c.categorical);  // colour indices are classes
  EXPECT_EQ(c.categories, (std::vector<int>{1, 2, 3}));
}

TEST(NaturalField, NamedFieldEvenIfItDoesNotVaryAndErrorsNamingWhatIsThere) {
  const io::Dataset d = plant();
  const io::Colouring c = io::named_colouring(io::summarise(d), "path");
  EXPECT_EQ(c.field, "path");
  EXPECT_FALSE(c.on_points);
  try {
    io::named_colouring(io::summarise(d), "widht");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(), "--field: no field named 'widht'; it holds arclength, branch_order, path");
  }
  io::Dataset coloured = plant();
  coloured.cell_fields["color"] = {3, {1, 0, 0, 0, 0, 1}};
  EXPECT_THROW(io::named_colouring(io::summarise(coloured), "color"), Error);
  EXPECT_THROW(io::named_colouring(io::summarise(io::Dataset{}), "x"), Error);
}

TEST(NaturalField, StepsShareTheRangeOfEveryStep) {
  io::Dataset first = plant(), last = plant();
  first.point_fields["branch_order"] = {1, {0, 0, 0, 0}};
  last.point_fields["branch_order"] = {1, {0, 0, 3, 4}};
  const std::vector<io::Dataset> steps{first, last};
  io::Colouring c = io::steps_colouring(steps);
  EXPECT_EQ(c.field, "branch_order");
  EXPECT_EQ(c.min, 0);
  EXPECT_EQ(c.max, 4);
  last.point_fields["arclength"] = {1, {0, 1, 0, 2}};
  first.point_fields["arclength"] = {1, {0, 5, 0, 1}};
  const std::vector<io::Dataset> again{first, last};
  c = io::steps_colouring(again, "arclength");
  EXPECT_EQ(c.max, 5);  // an earlier step's larger value widens the range
}

// --field on a series names a field of any step: the last step that holds it decides, and a name no step
// holds is refused listing every step's fields (it said "it holds no fields" when only the last had none).
TEST(NaturalField, ANamedFieldOfAnEarlierStep) {
  io::Dataset first = plant(), last = plant();
  first.point_fields["age"] = {1, {0, 1, 2, 7}};
  last.point_fields.clear();
  last.cell_fields.clear();
  const std::vector<io::Dataset> steps{first, last};
  const io::Colouring c = io::steps_colouring(steps, "age");
  EXPECT_EQ(c.field, "age");
  EXPECT_TRUE(c.on_points);
  EXPECT_EQ(c.min, 0);
  EXPECT_EQ(c.max, 7);
  try {
    io::steps_colouring(steps, "aeg");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("it holds age"), std::string::npos) << e.what();
  }
}
