#include "kernels/io/text/colour.h"

#include <gtest/gtest.h>

#include <algorithm>

using selfsim::io::colour_names;
using selfsim::io::is_colour;

TEST(Colour, NamesInAnyCaseAndHexForms) {
  for (const char* ok : {"steelblue", "SteelBlue", "rebeccapurple", "#abc", "#A1B2C3", "#000000"})
    EXPECT_TRUE(is_colour(ok)) << ok;
  for (const char* bad : {"purpel", "", "#12345", "#1234567", "#ggg", "rgb(1,2,3)", "red\" onload=\"x", "none"})
    EXPECT_FALSE(is_colour(bad)) << bad;
  EXPECT_EQ(colour_names().size(), 148u);  // CSS Color Module Level 4's named colours
}

TEST(Colour, ValuesOfNamesAndHexForms) {
  using selfsim::io::colour_hex;
  using selfsim::io::colour_rgb;
  EXPECT_EQ(colour_hex(*colour_rgb("SteelBlue")), "#4682b4");
  EXPECT_EQ(colour_hex(*colour_rgb("grey")), "#808080");  // CSS grey, not X11's
  EXPECT_EQ(colour_hex(*colour_rgb("#AbC")), "#aabbcc");
  EXPECT_EQ(colour_hex(*colour_rgb("#0a1B2c")), "#0a1b2c");
  EXPECT_DOUBLE_EQ((*colour_rgb("white"))[1], 1.0);
  EXPECT_EQ(colour_hex({-1, 0.5, 7}), "#0080ff");  // clamped, rounded
  EXPECT_FALSE(colour_rgb("#12g").has_value());
  // Names are looked up by binary search: the table must be sorted.
  EXPECT_TRUE(std::is_sorted(selfsim::io::colour_names().begin(), selfsim::io::colour_names().end()));
  for (const std::string& name : selfsim::io::colour_names()) EXPECT_TRUE(colour_rgb(name).has_value()) << name;
}
