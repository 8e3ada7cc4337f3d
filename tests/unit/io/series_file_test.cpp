// ParaView time series: step files in a folder named for the series, the series file naming them with
// their times, written last; rewritten in place without stale steps; bad names and times refused.
#include "kernels/io/view/series_file.h"

#include <gtest/gtest.h>

#include <regex>

#include "io_fixtures.h"
#include "kernels/base/error.h"
#include "kernels/io/read.h"

using namespace selfsim;
using io_fixtures::TempDir;
namespace fs = std::filesystem;

namespace {

std::string text_of(const fs::path& p) {
  std::ifstream in(p);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The curves a0 (2 points), a1 (3), ... : one more point each.
std::vector<Polyline> growing(int n) {
  std::vector<Polyline> out;
  for (int k = 0; k < n; ++k) {
    std::vector<Vec2> pts;
    for (int i = 0; i <= k + 1; ++i) pts.push_back({i / double(k + 1), 0.1 * i * i});
    out.push_back(Polyline::single(pts));
  }
  return out;
}

std::vector<io::SeriesStep> steps_of(const std::vector<Polyline>& curves) {
  std::vector<io::SeriesStep> steps;
  for (std::size_t k = 0; k < curves.size(); ++k) steps.push_back({&curves[k], static_cast<double>(k)});
  return steps;
}

}  // namespace

TEST(SeriesFile, PvdNamesEveryStepWithItsTimeAndEachStepHoldsItsValue) {
  TempDir dir;
  const auto curves = growing(4);
  auto steps = steps_of(curves);
  steps[3].time = 7.5;
  const io::SeriesFiles w = io::save_series(steps, dir.path, "growth.pvd", {}, no_progress());
  const std::string pvd = text_of(dir.path / "growth.pvd");
  const std::regex entry("timestep=\"([^\"]*)\" group=\"\" part=\"0\" file=\"([^\"]*)\"");
  std::vector<std::pair<std::string, std::string>> found;
  for (auto it = std::sregex_iterator(pvd.begin(), pvd.end(), entry); it != std::sregex_iterator(); ++it)
    found.emplace_back((*it)[1], (*it)[2]);
  ASSERT_EQ(found.size(), 4u);
  EXPECT_EQ(found[0], (std::pair<std::string, std::string>{"0", "growth/growth_000.vtp"}));
  EXPECT_EQ(found[3], (std::pair<std::string, std::string>{"7.5", "growth/growth_003.vtp"}));
  for (std::size_t k = 0; k < 4; ++k)
    EXPECT_EQ(io::read_dataset(dir.path / found[k].second).points.size(), curves[k].points.size()) << k;
  EXPECT_EQ(w.steps.size(), 4u);
}

TEST(SeriesFile, JsonSeriesTakesItsStepFormatFromItsName) {
  TempDir dir;
  const auto curves = growing(2);
  io::save_series(steps_of(curves), dir.path, "sub/g.vtu.series", {}, no_progress());
  const std::string json = text_of(dir.path / "sub/g.vtu.series");
  EXPECT_NE(json.find("\"file-series-version\" : \"1.0\""), std::string::npos);
  EXPECT_NE(json.find("{ \"name\" : \"g/g_001.vtu\", \"time\" : 1 }"), std::string::npos) << json;
  EXPECT_EQ(io::read_dataset(dir.path / "sub/g/g_001.vtu").points.size(), 3u);
}

TEST(SeriesFile, RewritingReplacesTheSeriesAndRemovesOnlyItsOwnStaleSteps) {
  TempDir dir;
  const auto curves = growing(5);
  io::save_series(steps_of(curves), dir.path, "growth.pvd", {}, no_progress());
  // The user's own files in the steps folder, and one named almost like a step.
  std::ofstream(dir.path / "growth/notes.txt") << "mine";
  std::ofstream(dir.path / "growth/growth_final.vtp") << "mine";
  const std::vector<Polyline> fewer(curves.begin(), curves.begin() + 2);
  io::save_series(steps_of(fewer), dir.path, "growth.pvd", {}, no_progress());
  EXPECT_TRUE(fs::exists(dir.path / "growth/growth_001.vtp"));
  EXPECT_FALSE(fs::exists(dir.path / "growth/growth_002.vtp"));
  EXPECT_FALSE(fs::exists(dir.path / "growth/growth_004.vtp"));
  EXPECT_TRUE(fs::exists(dir.path / "growth/notes.txt"));
  EXPECT_TRUE(fs::exists(dir.path / "growth/growth_final.vtp"));
  const std::string pvd = text_of(dir.path / "growth.pvd");
  std::size_t entries = 0;
  for (std::size_t at = pvd.find("<DataSet"); at != std::string::npos; at = pvd.find("<DataSet", at + 1)) ++entries;
  EXPECT_EQ(entries, 2u) << pvd;
}

TEST(SeriesFile, StepNamesWidenForLongSeries) {
  const auto names = io::series_step_names("a/s.pvd", 1001);
  EXPECT_EQ(names.front(), "a/s/s_0000.vtp");
  EXPECT_EQ(names.back(), "a/s/s_1000.vtp");
}

TEST(SeriesFile, RefusesBadNamesTimesAndEmptySeriesWithoutWriting) {
  TempDir dir;
  const auto curves = growing(2);
  auto steps = steps_of(curves);
  EXPECT_THROW(io::save_series(steps, dir.path, "growth.series", {}, no_progress()), Error);
  EXPECT_THROW(io::save_series(steps, dir.path, "growth.stl.series", {}, no_progress()), Error);
  EXPECT_THROW(io::save_series(steps, dir.path, ".pvd", {}, no_progress()), Error);
  EXPECT_THROW(io::save_series({}, dir.path, "g.pvd", {}, no_progress()), Error);
  steps[1].time = 0;
  EXPECT_THROW(io::save_series(steps, dir.path, "g.pvd", {}, no_progress()), Error);
  steps[1].time = std::nan("");
  EXPECT_THROW(io::save_series(steps, dir.path, "g.pvd", {}, no_progress()), Error);
  EXPECT_TRUE(fs::is_empty(dir.path));
}

TEST(SeriesFile, AFailedStepLeavesNoSeriesFile) {
  TempDir dir;
  auto curves = growing(3);
  curves[2].points[1].x = std::nan("");
  try {
    io::save_series(steps_of(curves), dir.path, "g.pvd", {}, no_progress());
    FAIL() << "a non-finite step was written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("step 3 of 'g.pvd'"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir.path / "g.pvd"));
}

TEST(SeriesFile, StepsFolderThatIsALinkIsRefused) {
  TempDir dir;
  TempDir outside_holder;
  const fs::path outside = outside_holder.path / "elsewhere";
  fs::create_directories(outside);
  fs::create_directory_symlink(outside, dir.path / "g");
  const auto curves = growing(2);
  EXPECT_THROW(io::save_series(steps_of(curves), dir.path, "g.pvd", {}, no_progress()), Error);
  EXPECT_TRUE(fs::is_empty(outside));
}

TEST(SeriesFile, AStepNamedLikeOneButNotInTheOldSeriesIsKept) {
  TempDir dir;
  const auto curves = growing(3);
  io::save(&curves[0], dir.path, "growth/growth_9.vtp", {}, no_progress());  // the recipe's own file
  io::save_series(steps_of(curves), dir.path, "growth.pvd", {}, no_progress());
  const std::vector<Polyline> fewer(curves.begin(), curves.begin() + 1);
  io::save_series(steps_of(fewer), dir.path, "growth.pvd", {}, no_progress());
  EXPECT_TRUE(fs::exists(dir.path / "growth/growth_9.vtp"));
  EXPECT_FALSE(fs::exists(dir.path / "growth/growth_1.vtp"));
  EXPECT_FALSE(fs::exists(dir.path / "growth/growth_001.vtp"));
}

TEST(SeriesFile, ARewriteThatFailsLeavesTheOldSeriesAndItsStepsAsTheyWere) {
  TempDir dir;
  const auto curves = growing(3);
  io::save_series(steps_of(curves), dir.path, "growth.pvd", {}, no_progress());
  const std::string pvd = text_of(dir.path / "growth.pvd"), step0 = text_of(dir.path / "growth/growth_000.vtp");
  auto other = growing(4);
  other[3].points[0].x = std::nan("");  // the last step cannot be written
  std::reverse(other.begin(), other.end() - 1);
  EXPECT_THROW(io::save_series(steps_of(other), dir.path, "growth.pvd", {}, no_progress()), Error);
  EXPECT_EQ(text_of(dir.path / "growth.pvd"), pvd);
  EXPECT_EQ(text_of(dir.path / "growth/growth_000.vtp"), step0);
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir.path / "growth")) files += e.is_regular_file();
  EXPECT_EQ(files, 3u);  // no hidden step left behind
}

// The times come back for the captions of a preview's steps, from either form; a step without a readable
// time gives none at all.
TEST(SeriesFile, TimesReadBack) {
  TempDir dir;
  const auto curves = growing(3);
  auto steps = steps_of(curves);
  steps[2].time = 7.5;
  io::save_series(steps, dir.path, "g.pvd", {}, no_progress());
  io::save_series(steps, dir.path, "h.vtp.series", {}, no_progress());
  EXPECT_EQ(io::read_series_times(dir.path / "g.pvd"), (std::vector<double>{0, 1, 7.5}));
  EXPECT_EQ(io::read_series_times(dir.path / "h.vtp.series"), (std::vector<double>{0, 1, 7.5}));
  std::ofstream(dir.path / "odd.pvd") << "<VTKFile type=\"Collection\"><Collection><DataSet timestep=\"x\" "
                                         "file=\"a.vtp\"/></Collection></VTKFile>";
  EXPECT_TRUE(io::read_series_times(dir.path / "odd.pvd").empty());
}
