#include "kernels/io/svg/curve_style.h"

#include <gtest/gtest.h>

#include <fstream>

#include "io_fixtures.h"
#include "kernels/base/error.h"
#include "kernels/io/read.h"

using namespace selfsim;
using io::CurveStyles;
using io::PathStyle;
using io_fixtures::count;
using io_fixtures::TempDir;
using io_fixtures::text_of;
using io_fixtures::two_paths;

namespace {

// three paths, members 1, 2, 2, with style fields on each path.
Polyline styled() {
  Polyline c = two_paths();
  c.points.push_back({4, 4});
  c.points.push_back({5, 4});
  c.close_path();
  c.cell_fields.set(int_field("curve", {1, 2, 2}));
  c.cell_fields.set(real_field("color", {1, 0, 0, 0, 0, 1, 0, 0, 1}, 3));
  c.cell_fields.set(real_field("width", {1, 3, 3}));
  c.cell_fields.set(real_field("fill", {-1, -1, -1, 1, 0.8, 0, 1, 0.8, 0}, 3));
  return c;
}

}  // namespace

TEST(CurveStyle, FieldsGiveEachPathItsStyle) {
  const Polyline c = styled();
  const CurveStyles s(c, {});
  EXPECT_EQ(s.at(0), (PathStyle{"#ff0000", 1, "none"}));
  EXPECT_EQ(s.at(1), (PathStyle{"#0000ff", 3, "#ffcc00"}));
  EXPECT_EQ(s.at(2), s.at(1));
}

TEST(CurveStyle, GivenOptionsOverrideFieldsAndCycleOverMembers) {
  const Polyline c = styled();
  const io::SaveOptions opt{
      .stroke = {"red", "green"}, .stroke_width = {2}, .fill = {"none"}, .given = {"stroke", "stroke_width", "fill"}};
  const CurveStyles s(c, opt);
  EXPECT_EQ(s.at(0), (PathStyle{"red", 2, "none"}));
  EXPECT_EQ(s.at(1), (PathStyle{"green", 2, "none"}));
  // Without a `curve` field the whole curve is one member: the palette's first entry.
  Polyline plain = two_paths();
  const CurveStyles p(plain, opt);
  EXPECT_EQ(p.at(1).stroke, "red");
}

TEST(CurveStyle, OutOfRangeFieldsAreRefused) {
  Polyline c = styled();
  c.cell_fields.set(real_field("color", {1, 0, 0, 0, 0, 255, 0, 0, 1}, 3));
  try {
    CurveStyles s(c, {});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_STREQ(e.what(),
                 "cell field 'color' of path 2 must hold red, green, blue in [0, 1], or negative values for none");
  }
  c = styled();
  c.cell_fields.set(real_field("width", {1, 0, 3}));
  EXPECT_THROW(CurveStyles(c, {}), Error);
  // An overriding option makes the field irrelevant.
  EXPECT_NO_THROW(CurveStyles(c, {.stroke_width = {1}, .given = {"stroke_width"}}));
}

TEST(CurveStyle, OnePathElementPerRunOfOneStyle) {
  TempDir dir;
  const Polyline c = styled();
  const auto f = dir.path / "g.svg";
  io::save(&c, f, {}, no_progress());
  const std::string text = text_of(f);
  EXPECT_EQ(count(text, "<path "), 2u) << text;
  EXPECT_NE(text.find("stroke=\"#ff0000\""), std::string::npos);
  EXPECT_NE(text.find("fill=\"#ffcc00\" stroke=\"#0000ff\""), std::string::npos);
  // All three paths read back, in order.
  const io::Dataset d = io::read_dataset(f);
  EXPECT_EQ(d.cell_ends, (std::vector<std::size_t>{3, 5, 7}));
}
