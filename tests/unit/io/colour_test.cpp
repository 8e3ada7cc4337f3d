#include "kernels/io/colour.h"

#include <gtest/gtest.h>

using selfsim::io::colour_names;
using selfsim::io::is_colour;

TEST(Colour, NamesInAnyCaseAndHexForms) {
  for (const char* ok : {"steelblue", "SteelBlue", "rebeccapurple", "#abc", "#A1B2C3", "#000000"})
    EXPECT_TRUE(is_colour(ok)) << ok;
  for (const char* bad : {"purpel", "", "#12345", "#1234567", "#ggg", "rgb(1,2,3)", "red\" onload=\"x", "none"})
    EXPECT_FALSE(is_colour(bad)) << bad;
  EXPECT_EQ(colour_names().size(), 148u);  // CSS Color Module Level 4's named colours
}
