// view.py's header: every dataset with its role, series flag and colouring as Python literals the body
// reads, names quoted so no file name can end the string, and the body appended.
#include "kernels/io/view/paraview_view.h"

#include <gtest/gtest.h>

#include <limits>

using namespace selfsim;

namespace {

io::ViewDataset dataset(std::string file, io::ViewRole role, bool flat) {
  io::ViewDataset d;
  d.file = file;
  d.name = file.substr(0, file.find('.'));
  d.role = role;
  d.flat = flat;
  return d;
}

}  // namespace

TEST(ParaviewView, NamesEachDatasetWithItsColouring) {
  std::vector<io::ViewDataset> ds{dataset("growth.pvd", io::ViewRole::surface, false),
                                  dataset("sphere.vtp", io::ViewRole::region, false)};
  ds[0].series = true;
  ds[0].colouring = {"tile_class", false, true, 0, 4, {0, 2, 4}};
  const std::string text = io::paraview_view_text(ds, "/data/out");
  EXPECT_NE(text.find("\"folder\": \"/data/out\""), std::string::npos);
  EXPECT_NE(
      text.find(
          "{\"file\": \"growth.pvd\", \"name\": \"growth\", \"role\": \"surface\", \"series\": True, \"flat\": False"),
      std::string::npos)
      << text;
  EXPECT_NE(text.find("\"field\": \"tile_class\", \"association\": \"CELLS\", \"categorical\": True"),
            std::string::npos);
  EXPECT_NE(text.find("\"categories\": [0, 2, 4]"), std::string::npos);
  EXPECT_NE(text.find("\"role\": \"region\", \"series\": False, \"flat\": False, \"up\": 1,\n         \"field\": None"),
            std::string::npos);
  EXPECT_NE(text.find("from paraview.simple import"), std::string::npos);  // the body
}

TEST(ParaviewView, EachDatasetSaysItsUpAxis) {
  std::vector<io::ViewDataset> ds{dataset("stack.vtp", io::ViewRole::surface, false)};
  ds[0].up = 2;  // a stack grown along z (up_axis.h)
  const std::string text = io::paraview_view_text(ds, "/o");
  EXPECT_NE(text.find("\"flat\": False, \"up\": 2,"), std::string::npos);
  EXPECT_NE(text.find("def with_tubes("), std::string::npos);  // widths drawn as tubes by the body
}

TEST(ParaviewView, FlatDatasetsAreMarkedForATopView) {
  std::vector<io::ViewDataset> ds{dataset("a.vtp", io::ViewRole::curve, true)};
  EXPECT_NE(io::paraview_view_text(ds, "/o").find("\"flat\": True"), std::string::npos);
}

TEST(ParaviewView, ARangeThatIsNotFiniteIsNone) {
  std::vector<io::ViewDataset> ds{dataset("a.vtp", io::ViewRole::curve, true)};
  ds[0].colouring = {"arclength", true, false, 0, std::numeric_limits<double>::infinity(), {}};
  const std::string text = io::paraview_view_text(ds, "/o");
  EXPECT_NE(text.find("\"range\": None"), std::string::npos) << text;
  EXPECT_EQ(text.find("inf"), std::string::npos);
}

TEST(ParaviewView, QuotesAndBackslashesInNamesStayInsideTheString) {
  std::vector<io::ViewDataset> ds{dataset("a\"b\\c\n.vtp", io::ViewRole::curve, true)};
  const std::string text = io::paraview_view_text(ds, "/o");
  EXPECT_NE(text.find("\"file\": \"a\\\"b\\\\c\\x0a.vtp\""), std::string::npos) << text;
}

TEST(ParaviewView, NamesThatAreNotUtf8AreLeftOut) {
  std::vector<io::ViewDataset> ds{
      dataset("ok.vtp", io::ViewRole::curve, true), dataset("bad\xff.vtp", io::ViewRole::curve, true),
      dataset("bad\xed\xa0\x80.vtp", io::ViewRole::curve, true), dataset("bad\xc0\x80.vtp", io::ViewRole::curve, true)};
  const std::string text = io::paraview_view_text(ds, "/o");
  EXPECT_NE(text.find("ok.vtp"), std::string::npos);
  EXPECT_EQ(text.find("bad"), std::string::npos);
}
