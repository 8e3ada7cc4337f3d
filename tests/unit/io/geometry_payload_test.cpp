// The studio's 3D view payload: the arrays a browser reads, coloured as the preview colours, vertices split
// only where a cell field changes colour, sizes refused before they are made.
#include "kernels/io/view/geometry_payload.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "kernels/base/error.h"
#include "kernels/io/text/palette.h"

using namespace selfsim;

namespace {

// The payload read back as the page reads it.
struct Decoded {
  std::string header;
  std::size_t vertices = 0, triangles = 0, segments = 0;
  std::vector<float> positions;
  std::vector<std::uint32_t> indices;
  std::vector<std::uint8_t> colours;
};

std::size_t header_count(const std::string& header, const std::string& key) {
  const std::size_t at = header.find("\"" + key + "\": ");
  EXPECT_NE(at, std::string::npos) << key;
  return std::stoul(header.substr(at + key.size() + 4));
}

Decoded decode(const std::string& bytes) {
  Decoded d;
  EXPECT_EQ(bytes.substr(0, 4), "SSG1");
  EXPECT_EQ(bytes.size() % 4, 0u);
  std::uint32_t h = 0;
  std::memcpy(&h, bytes.data() + 4, 4);
  EXPECT_EQ(h % 4, 0u);  // the arrays start aligned
  d.header = bytes.substr(8, h);
  d.vertices = header_count(d.header, "vertices");
  d.triangles = header_count(d.header, "triangles");
  d.segments = header_count(d.header, "segments");
  std::size_t at = 8 + h;
  d.positions.resize(3 * d.vertices);
  std::memcpy(d.positions.data(), bytes.data() + at, 12 * d.vertices);
  at += 12 * d.vertices;
  d.indices.resize(3 * d.triangles + 2 * d.segments);
  std::memcpy(d.indices.data(), bytes.data() + at, 4 * d.indices.size());
  at += 4 * d.indices.size();
  d.colours.assign(bytes.begin() + static_cast<std::ptrdiff_t>(at),
                   bytes.begin() + static_cast<std::ptrdiff_t>(at + 3 * d.vertices));
  EXPECT_LE(bytes.size() - (at + 3 * d.vertices), 3u);  // nothing after the colours but padding
  return d;
}

io::Dataset two_triangles() {
  io::Dataset d;
  d.shapes = io::CellShapes::polygons;
  d.points = {{10, 0, 0}, {12, 0, 0}, {10, 2, 0}, {12, 2, 2}};
  d.cell_ends = {3, 6};
  d.cell_points = {0, 1, 2, 1, 3, 2};
  return d;
}

std::array<std::uint8_t, 3> rgb(const io::Rgb& c) {
  return {static_cast<std::uint8_t>(std::lround(c[0] * 255)), static_cast<std::uint8_t>(std::lround(c[1] * 255)),
          static_cast<std::uint8_t>(std::lround(c[2] * 255))};
}

std::array<std::uint8_t, 3> colour_of(const Decoded& d, std::size_t v) {
  return {d.colours[3 * v], d.colours[3 * v + 1], d.colours[3 * v + 2]};
}

}  // namespace

TEST(GeometryPayload, PointFieldSharesVerticesAndUsesTheRamp) {
  io::Dataset d = two_triangles();
  d.point_fields["height"] = {1, {0, 1, 2, 4}};
  const io::Colouring c = io::natural_colouring(io::summarise(d));
  ASSERT_EQ(c.field, "height");
  const Decoded p = decode(io::geometry_payload(d, c, 1 << 20));
  EXPECT_EQ(p.vertices, 4u);
  EXPECT_EQ(p.triangles, 2u);
  EXPECT_EQ(p.segments, 0u);
  EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 3, 2}));
  // Positions relative to the bounds' centre (11, 1, 1), which the header gives as the origin.
  EXPECT_EQ(p.positions[0], -1.0f);
  EXPECT_EQ(p.positions[10], 1.0f);
  EXPECT_NE(p.header.find("\"origin\": [11, 1, 1]"), std::string::npos) << p.header;
  EXPECT_NE(p.header.find("\"bounds\": [10, 12, 0, 2, 0, 2]"), std::string::npos) << p.header;
  EXPECT_EQ(colour_of(p, 0), rgb(io::ramp_colour(0)));
  EXPECT_EQ(colour_of(p, 3), rgb(io::ramp_colour(1)));
  EXPECT_EQ(colour_of(p, 2), rgb(io::ramp_colour(0.5)));
  EXPECT_NE(p.header.find("\"field\": \"height\""), std::string::npos);
  EXPECT_NE(p.header.find("\"min\": 0, \"max\": 4"), std::string::npos);
}

TEST(GeometryPayload, CellClassesSplitOnlyTheVerticesBetweenColours) {
  io::Dataset d = two_triangles();
  d.cell_fields["tile_class"] = {1, {7, 3}};
  const io::Colouring c = io::natural_colouring(io::summarise(d));
  ASSERT_TRUE(c.categorical);
  const Decoded p = decode(io::geometry_payload(d, c, 1 << 20));
  EXPECT_EQ(p.vertices, 6u);  // the two shared points once per colour
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(colour_of(p, p.indices[k]), rgb(io::class_colour(1)));      // class 7, the second of {3, 7}
    EXPECT_EQ(colour_of(p, p.indices[3 + k]), rgb(io::class_colour(0)));  // class 3
  }
  EXPECT_NE(p.header.find("\"classes\": [3, 7]"), std::string::npos) << p.header;

  d.cell_fields["tile_class"] = {1, {5, 5}};
  d.cell_fields["level"] = {1, {0, 1}};
  const Decoded same = decode(io::geometry_payload(d, io::Colouring{"tile_class", false, true, 5, 5, {5}}, 1 << 20));
  EXPECT_EQ(same.vertices, 4u);  // one colour: nothing split
}

// A grammar's colour index takes the colour of its value, as the SVG strokes it and the preview draws it, not
// of its rank among the indices present; a negative index the colour of its magnitude.
TEST(GeometryPayload, ColourIndicesTakeTheirValuesColour) {
  io::Dataset d = two_triangles();
  d.cell_fields["color"] = {1, {4, -2}};
  const io::Colouring c = io::natural_colouring(io::summarise(d));
  ASSERT_TRUE(c.categorical);
  ASSERT_EQ(c.field, "color");
  const Decoded p = decode(io::geometry_payload(d, c, 1 << 20));
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(colour_of(p, p.indices[k]), rgb(io::class_colour(4)));
    EXPECT_EQ(colour_of(p, p.indices[3 + k]), rgb(io::class_colour(2)));
  }
  // The legend's swatches are the same colours.
  EXPECT_NE(p.header.find(io::colour_hex(io::class_colour(4))), std::string::npos) << p.header;
  EXPECT_NE(p.header.find(io::colour_hex(io::class_colour(2))), std::string::npos) << p.header;
}

TEST(GeometryPayload, PolylinesBecomeSegmentsAndPolygonsFans) {
  io::Dataset d;
  d.shapes = io::CellShapes::mixed;
  d.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}};
  d.cell_ends = {4, 6};
  d.cell_points = {0, 1, 2, 3, 3, 4};  // a quad, then a line
  const Decoded p = decode(io::geometry_payload(d, {}, 1 << 20));
  EXPECT_EQ(p.triangles, 2u);
  EXPECT_EQ(p.segments, 1u);
  EXPECT_EQ(p.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 3, 4}));
  EXPECT_EQ(colour_of(p, 4), io::value_colour(io::Colouring{}, 0));  // uncoloured: the preview's solid colour
}

// The count that decides tubes for a whole series: a polyline of n points has n - 1 segments, a lone point none.
TEST(GeometryPayload, LineSegmentsOfPolylines) {
  io::Dataset d;
  d.points = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {5, 5, 5}, {0, 1, 0}, {0, 2, 0}};
  d.cell_ends = {3, 4, 6};
  d.cell_points = {0, 1, 2, 3, 4, 5};
  EXPECT_EQ(io::line_segments(d), 3u);
  EXPECT_EQ(io::line_segments(io::Dataset{}), 0u);
}

TEST(GeometryPayload, RefusesWhatCannotBeDrawn) {
  io::Dataset d = two_triangles();
  EXPECT_THROW(io::geometry_payload(d, {}, 200), Error);  // over the size it may take
  try {
    io::geometry_payload(d, {}, 200);
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("MiB a view may take"), std::string::npos) << e.what();
  }
  d.points[1][2] = std::nan("");
  EXPECT_THROW(io::geometry_payload(d, {}, 1 << 20), Error);
  d.points.clear();
  EXPECT_THROW(io::geometry_payload(d, {}, 1 << 20), Error);
  io::Dataset bad = two_triangles();
  bad.cell_points[4] = 9;  // no such point
  EXPECT_THROW(io::geometry_payload(bad, {}, 1 << 20), Error);
  // Far apart beyond what float32 holds (the page's positions would be infinite); near the largest double the
  // origin must not overflow either. Far from zero but small is fine: positions are relative to the origin.
  io::Dataset far = two_triangles();
  far.points[0] = {-1e300, 0, 0};
  EXPECT_THROW(io::geometry_payload(far, {}, 1 << 20), Error);
  far.points = {{1.7e308, 0, 0}, {1.7e308, 1, 0}, {1.7e308, 0, 1}, {1.7e308, 1, 1}};
  const Decoded p = decode(io::geometry_payload(far, {}, 1 << 20));
  for (float v : p.positions) EXPECT_TRUE(std::isfinite(v));
}

TEST(GeometryPayload, StepsShareOneRangeAndTheLastStepsField) {
  io::Dataset a = two_triangles(), b = two_triangles();
  a.cell_fields["level"] = {1, {0, 1}};
  b.cell_fields["level"] = {1, {2, 5}};
  const std::vector<std::vector<io::FieldSummary>> steps{io::summarise(a), io::summarise(b)};
  const io::Colouring c = io::summaries_colouring(steps);
  EXPECT_EQ(c.field, "level");
  EXPECT_EQ(c.min, 0);
  EXPECT_EQ(c.max, 5);
  // The first step's cells are coloured on the whole series' range: level 1 is a fifth of the way.
  const Decoded p = decode(io::geometry_payload(a, c, 1 << 20));
  EXPECT_EQ(colour_of(p, p.indices[3]), rgb(io::ramp_colour(0.2)));
}

TEST(GeometryPayload, ACurvesOwnColoursAreDrawnAsTheyAre) {
  io::Dataset d;
  d.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 0, 1}};
  d.cell_ends = {3, 4};
  d.cell_points = {0, 1, 2, 3};
  d.cell_fields["color"] = {3, {1, 0, 0, 0, 0, 1}};  // red, then blue
  ASSERT_TRUE(io::has_own_colours(d));
  const Decoded p = decode(io::geometry_payload(d, {}, 1 << 20));
  EXPECT_EQ(p.segments, 2u);
  EXPECT_EQ(colour_of(p, p.indices[0]), (std::array<std::uint8_t, 3>{255, 0, 0}));
  EXPECT_EQ(colour_of(p, p.indices[2]), (std::array<std::uint8_t, 3>{255, 0, 0}));
  EXPECT_NE(p.header.find("\"own\": true"), std::string::npos) << p.header;
  // A field asked for wins over them; a surface has none (the preview draws only a curve's).
  EXPECT_EQ(io::geometry_payload(d, {"t", true, false, 0, 1, {}}, 1 << 20).find("\"own\": true"), std::string::npos);
  d.shapes = io::CellShapes::polygons;
  EXPECT_FALSE(io::has_own_colours(d));
}

// Every cell its own colour (a curve of 60,000 coloured segments): each drawn in its colour. The colours are
// found by a hash map, not a sorted list whose inserts took quadratic time (measured, not asserted here).
TEST(GeometryPayload, ManyOwnColoursEachDrawnAsItIs) {
  io::Dataset d;
  const std::size_t n = 60000;
  std::vector<double> colours;
  for (std::size_t i = 0; i < n; ++i) {
    d.points.push_back({static_cast<double>(i), 0, 0});
    d.points.push_back({static_cast<double>(i), 1, 1});
    d.cell_points.insert(d.cell_points.end(), {2 * i, 2 * i + 1});
    d.cell_ends.push_back(2 * i + 2);
    colours.insert(colours.end(), {(i & 255) / 255.0, ((i >> 8) & 255) / 255.0, 7 / 255.0});
  }
  d.cell_fields["color"] = {3, colours};
  const Decoded p = decode(io::geometry_payload(d, {}, 1 << 26));
  ASSERT_EQ(p.segments, n);
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t v : {p.indices[2 * i], p.indices[2 * i + 1]})
      ASSERT_EQ(colour_of(p, v), (std::array<std::uint8_t, 3>{static_cast<std::uint8_t>(i & 255),
                                                              static_cast<std::uint8_t>((i >> 8) & 255), 7}))
          << "segment " << i;
}

TEST(GeometryPayload, ACurvesWidthsAreTubes) {
  io::Dataset d;
  d.points = {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}, {0, 1, 0}, {1, 2, 0}};
  d.cell_ends = {3, 5};
  d.cell_points = {0, 1, 2, 3, 4};  // a trunk and a branch
  d.point_fields["width"] = {1, {4, 2, 1, 2, 0}};
  d.point_fields["branch_order"] = {1, {0, 0, 0, 1, 1}};
  const io::Colouring c = io::natural_colouring(io::summarise(d));
  const io::TubeWidths widths{10, 4};  // a drawing 10 across: the widest radius 0.012 of that (drawn_width.h)
  ASSERT_TRUE(io::drawn_as_tubes(d, widths));
  const Decoded p = decode(io::geometry_payload(d, c, 1 << 20, widths));
  EXPECT_EQ(p.segments, 0u);
  EXPECT_EQ(p.triangles, 3u * 16);  // 16 a segment
  EXPECT_EQ(p.vertices, 5u * 8);    // a ring of 8 a point
  // The widest point's ring has the radius, the thinnest (width 0) a tenth of it; positions are relative to
  // the bounds' centre (0.5, 1, 0).
  const auto radius = [&](std::size_t ring, const std::array<double, 3>& centre) {
    return std::hypot(p.positions[24 * ring] + 0.5 - centre[0], p.positions[24 * ring + 1] + 1 - centre[1],
                      p.positions[24 * ring + 2] - centre[2]);
  };
  EXPECT_NEAR(radius(0, {0, 0, 0}), 0.12, 1e-6);
  EXPECT_NEAR(radius(4, {1, 2, 0}), 0.012, 1e-6);
  // Each ring coloured as its point: the branch's by branch_order 1, the trunk's by 0.
  EXPECT_EQ(colour_of(p, 0), rgb(io::ramp_colour(0)));
  EXPECT_EQ(colour_of(p, 39), rgb(io::ramp_colour(1)));
  // No widths, or too many segments: lines.
  EXPECT_EQ(decode(io::geometry_payload(d, c, 1 << 20)).segments, 3u);
  d.point_fields.erase("width");
  EXPECT_FALSE(io::drawn_as_tubes(d, widths));
}
