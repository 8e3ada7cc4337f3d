// A turtle's widths ('!') and colour indices ('\'') reach the SVG and EPS writers' strokes (curve_style.h,
// style_runs.h): segment by segment, grouped into one element per run of one style.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include "io_fixtures.h"
#include "kernels/base/error.h"
#include "kernels/io/read.h"
#include "kernels/io/save.h"
#include "kernels/io/svg/curve_style.h"
#include "kernels/io/text/colour.h"
#include "kernels/io/text/palette.h"

using namespace selfsim;
using io_fixtures::count;
using io_fixtures::TempDir;
using io_fixtures::text_of;

namespace {

// A stem of three unit steps up (widths 10, 10, 1; colours 0, 0, 2), then a branch path of one step
// (width 1, colour 2): what the turtle writes for !(10) F F [ +!(1) '(2) F ] !(1) '(2) F, roughly.
Polyline plant() {
  Polyline c;
  c.points = {{0, 0}, {0, 1}, {0, 2}, {0, 3}, {0, 2}, {1, 3}};
  c.path_ends = {4, 6};
  c.point_fields.set(real_field("width", {10, 10, 10, 1, 1, 1}));
  c.point_fields.set(int_field("color", {0, 0, 0, 2, 2, 2}));
  return c;
}

// Each <path> element's stroke, stroke-width and d, in order.
struct Element {
  std::string stroke;
  double width;
  std::string d;
};
std::vector<Element> elements(const std::string& svg) {
  std::vector<Element> out;
  const std::regex path(R"re(<path fill="none" stroke="([^"]*)" stroke-width="([^"]*)" d="([^"]*)"/>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), path); it != std::sregex_iterator(); ++it)
    out.push_back({(*it)[1], std::stod((*it)[2]), (*it)[3]});
  return out;
}

std::string colour_of(std::size_t index) { return io::colour_hex(io::class_colour(index)); }

}  // namespace

TEST(TurtleStyle, WidthsAndColourIndicesBecomeStrokes) {
  TempDir dir;
  const Polyline c = plant();
  io::save(&c, dir.path / "p.svg", {}, no_progress());
  const std::vector<Element> e = elements(text_of(dir.path / "p.svg"));
  // Two runs: the trunk (two segments of width 10, colour 0), then the twig and the branch (width 1, colour
  // 2), the last as two subpaths of one element.
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].stroke, colour_of(0));
  EXPECT_EQ(e[1].stroke, colour_of(2));
  EXPECT_NE(e[0].stroke, e[1].stroke);
  // Widths relative to the drawing (drawn_width.h), in the path data's units: the widest (10) 2.4% of the
  // diagonal (the plant is 1 x 3, so sqrt(10)) across, the twig (1) a tenth of that.
  EXPECT_NEAR(e[0].width, 0.024 * std::sqrt(10.0), 1e-4);
  EXPECT_NEAR(e[1].width, 0.0024 * std::sqrt(10.0), 1e-5);
  EXPECT_EQ(e[0].d, "M0 0L0 1 0 2");
  EXPECT_EQ(e[1].d, "M0 2L0 3M0 2L1 3");  // the twig starts where the trunk's run ended
  // The points read back as drawn: nothing lost or doubled but the cut's shared point.
  EXPECT_EQ(io::read_dataset(dir.path / "p.svg").points.size(), 7u);
}

// Widths are drawn relative to the drawing and the widest width, so whatever unit a grammar writes them in
// (ABOP's !(10), a recipe's !(0.05)) a plant reads the same: a plant three times the size draws three times as
// wide in its own units, and widths a thousandth of the first draw the same.
TEST(TurtleStyle, WidthsAreRelativeToTheDrawingAndTheWidest) {
  TempDir dir;
  Polyline c = plant();
  io::save(&c, dir.path / "p.svg", {}, no_progress());
  const double first = elements(text_of(dir.path / "p.svg"))[0].width;
  for (Vec2& p : c.points) p = 3 * p;
  c.point_fields.set(real_field("width", {0.01, 0.01, 0.01, 0.001, 0.001, 0.001}));
  io::save(&c, dir.path / "q.svg", {}, no_progress());
  const std::vector<Element> e = elements(text_of(dir.path / "q.svg"));
  ASSERT_EQ(e.size(), 2u);
  EXPECT_NEAR(e[0].width, 3 * first, 1e-9);
  EXPECT_NEAR(e[1].width, 0.3 * first, 1e-9);
  // A width of 0 is drawn as the thinnest, a tenth of the widest, not as nothing; a huge one is the widest.
  c.point_fields.set(real_field("width", {1e300, 1e300, 1e300, 0, 0, 0}));
  io::save(&c, dir.path / "r.svg", {}, no_progress());
  const std::vector<Element> r = elements(text_of(dir.path / "r.svg"));
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0].width, 3 * first, 1e-9);
  EXPECT_NEAR(r[1].width, 0.3 * first, 1e-9);
}

TEST(TurtleStyle, GivenOptionsWin) {
  TempDir dir;
  const Polyline c = plant();
  io::save(&c, dir.path / "p.svg", {.stroke = {"#112233"}, .given = {"stroke"}}, no_progress());
  std::vector<Element> e = elements(text_of(dir.path / "p.svg"));
  ASSERT_EQ(e.size(), 2u);  // still cut by width
  EXPECT_EQ(e[0].stroke, "#112233");
  EXPECT_EQ(e[1].stroke, "#112233");
  EXPECT_DOUBLE_EQ(e[0].width / e[1].width, 10);
  io::save(&c, dir.path / "q.svg", {.stroke_width = {2}, .given = {"stroke_width"}}, no_progress());
  e = elements(text_of(dir.path / "q.svg"));
  ASSERT_EQ(e.size(), 2u);  // still cut by colour, one width for all
  EXPECT_DOUBLE_EQ(e[0].width, e[1].width);
  io::save(&c, dir.path / "r.svg", {.stroke = {"red"}, .stroke_width = {2}, .given = {"stroke", "stroke_width"}},
           no_progress());
  EXPECT_EQ(elements(text_of(dir.path / "r.svg")).size(), 1u);  // a plain curve again: one element
}

TEST(TurtleStyle, OneStyleThroughoutKeepsClosedPathsAndOneElement) {
  TempDir dir;
  Polyline c;
  c.points = {{0, 0}, {1, 0}, {1, 1}, {0, 0}};
  c.path_ends = {4};
  c.point_fields.set(int_field("color", {5, 5, 5, 5}));
  io::save(&c, dir.path / "t.svg", {}, no_progress());
  const std::string text = text_of(dir.path / "t.svg");
  EXPECT_EQ(count(text, "<path"), 1u);
  EXPECT_NE(text.find("stroke=\"" + colour_of(5) + "\""), std::string::npos);
  EXPECT_NE(text.find("Z\"/>"), std::string::npos);
}

TEST(TurtleStyle, EpsDrawsTheSameStrokes) {
  TempDir dir;
  const Polyline c = plant();
  io::save(&c, dir.path / "p.eps", {}, no_progress());
  const std::string eps = text_of(dir.path / "p.eps");
  EXPECT_EQ(count(eps, "stroke\n"), 2u);
  EXPECT_EQ(count(eps, "setlinewidth"), 2u);
}

TEST(TurtleStyle, BadPointFieldsAreRefusedNamingThePoint) {
  TempDir dir;
  Polyline c = plant();
  c.point_fields.set(real_field("width", {10, 10, std::nan(""), 1, 1, 1}));
  try {
    io::save(&c, dir.path / "p.svg", {}, no_progress());
    FAIL() << "a width that is not a number was written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("point field 'width' has a non-finite value"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path / "p.svg"));
}
