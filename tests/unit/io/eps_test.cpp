#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "io_fixtures.h"
#include "kernels/base/error.h"
#include "kernels/io/save.h"

using namespace selfsim;
using io_fixtures::count;
using io_fixtures::TempDir;
using io_fixtures::text_of;

namespace {

// An open path of three points (member 1, red) and a closed square (member 2, filled gold).
Polyline styled() {
  Polyline c = Polyline::single({{0, 0}, {1, 0}, {1, 1}});
  c.points.insert(c.points.end(), {{2, 0}, {3, 0}, {3, 1}, {2, 1}, {2, 0}});
  c.close_path();
  c.cell_fields.set(int_field("curve", {1, 2}));
  c.cell_fields.set(real_field("color", {1, 0, 0, 0, 0, 0}, 3));
  c.cell_fields.set(real_field("fill", {-1, -1, -1, 1, 215.0 / 255, 0}, 3));
  return c;
}

}  // namespace

TEST(SaveEps, HeaderPathsAndStyles) {
  TempDir dir;
  const Polyline c = styled();
  const auto f = dir.path / "c.eps";
  io::save(&c, f, {.size = 400}, no_progress());
  const std::string text = text_of(f);
  EXPECT_EQ(text.rfind("%!PS-Adobe-3.0 EPSF-3.0\n", 0), 0u);
  // 3 wide, 1 high, with a margin of 2% of the larger side on each side: 400 points by 400 · 1.12/3.12.
  std::istringstream header(text.substr(text.find("%%HiResBoundingBox:")));
  std::string tag;
  double x0, y0, w, h;
  header >> tag >> x0 >> y0 >> w >> h;
  EXPECT_NEAR(w, 400, 1e-6);
  EXPECT_NEAR(h, 400 * 1.12 / 3.12, 1e-6);
  EXPECT_NE(text.find("%%BoundingBox: 0 0 400 144\n"), std::string::npos);
  // One moveto per path, a lineto per further point; the square's return is a closepath.
  EXPECT_EQ(count(text, " m\n"), 2u);
  EXPECT_EQ(count(text, " l\n"), 2u + 3u);
  EXPECT_EQ(count(text, "closepath"), 1u);
  EXPECT_EQ(count(text, "eofill"), 1u);
  EXPECT_EQ(count(text, "stroke\n"), 2u);
  EXPECT_NE(text.find("1 0 0 setrgbcolor"), std::string::npos);
  EXPECT_NE(text.find("1 0.8431 0 setrgbcolor\neofill"), std::string::npos);
  EXPECT_EQ(text.substr(text.size() - 6), "%%EOF\n");
  // Coordinates are relative to the box: the first point is the margin in, 400 · 0.06/3.12.
  EXPECT_NE(text.find("newpath\n7.6923077 7.6923077 m\n"), std::string::npos) << text.substr(0, 400);
}

TEST(SaveEps, PhysicalSizeInPoints) {
  TempDir dir;
  const Polyline c = Polyline::single({{0, 0}, {1, 0}, {1, 1}});
  const auto f = dir.path / "c.eps";
  io::save(&c, f, {.stroke_width = {0.5}, .size = 100, .size_unit = "mm"}, no_progress());
  const std::string text = text_of(f);
  // 100 mm = 283.46 points; a 0.5 mm pen is 1.417 points wide.
  EXPECT_NE(text.find("%%BoundingBox: 0 0 284 284\n"), std::string::npos);
  EXPECT_NE(text.find("1.41732283 setlinewidth"), std::string::npos);
}
