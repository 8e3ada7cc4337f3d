#include "kernels/io/output_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "io_fixtures.h"
#include "kernels/base/error.h"

using namespace selfsim;
namespace fs = std::filesystem;
using io_fixtures::TempDir;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

TEST(OutputFile, AppearsOnlyWhenCommitted) {
  TempDir d;
  {
    io::OutputFile f(d.path / "out", "sub/a.txt");
    f.write(std::string_view("hello"));
    EXPECT_FALSE(fs::exists(d.path / "out/sub/a.txt"));
    EXPECT_TRUE(names_in(d.path / "out/sub").empty());  // anonymous while being written
    f.commit();
    EXPECT_EQ(f.path(), (d.path / "out/sub/a.txt").string());
  }
  EXPECT_EQ(read(d.path / "out/sub/a.txt"), "hello");
  EXPECT_EQ(names_in(d.path / "out/sub"), std::vector<std::string>{"a.txt"});
}

TEST(OutputFile, UncommittedLeavesNothingAndKeepsTheOldFile) {
  TempDir d;
  std::ofstream(d.path / "a.txt") << "old";
  {
    io::OutputFile f(d.path, "a.txt");
    f.write(std::string(3 << 20, 'x'));  // past the buffer: bytes reached the temporary
  }
  EXPECT_EQ(read(d.path / "a.txt"), "old");
  EXPECT_EQ(names_in(d.path), std::vector<std::string>{"a.txt"});
}

TEST(OutputFile, ReplacesAnOlderFile) {
  TempDir d;
  std::ofstream(d.path / "a.txt") << "old";
  io::OutputFile f(d.path, "a.txt");
  f.write(std::string_view("new"));
  f.commit();
  EXPECT_EQ(read(d.path / "a.txt"), "new");
}

TEST(OutputFile, NeverFollowsALinkOutOfTheFolder) {
  TempDir d;
  fs::create_directories(d.path / "out");
  fs::create_directories(d.path / "elsewhere");
  fs::create_directory_symlink(d.path / "elsewhere", d.path / "out/link");
  EXPECT_THROW(io::OutputFile(d.path / "out", "link/x.svg"), Error);
  EXPECT_THROW(io::OutputFile(d.path / "out", "link/deeper/x.svg"), Error);
  EXPECT_TRUE(names_in(d.path / "elsewhere").empty());
}

TEST(OutputFile, ReplacesAPlantedLinkInsteadOfWritingThroughIt) {
  TempDir d;
  fs::create_directories(d.path / "out");
  fs::create_symlink(d.path / "target.svg", d.path / "out/x.svg");
  io::OutputFile f(d.path / "out", "x.svg");
  f.write(std::string_view("data"));
  f.commit();
  EXPECT_FALSE(fs::exists(d.path / "target.svg"));
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(d.path / "out/x.svg")));
  EXPECT_EQ(read(d.path / "out/x.svg"), "data");
}

TEST(OutputFile, RefusesNamesThatLeaveTheFolder) {
  TempDir d;
  for (const char* name : {"../x.svg", "/tmp/x.svg", "a/../../x.svg", "", ".", "a/.."})
    EXPECT_THROW(io::OutputFile(d.path, name), Error) << name;
  EXPECT_TRUE(names_in(d.path).empty());
}

TEST(OutputFile, AFolderInTheWayIsAnError) {
  TempDir d;
  fs::create_directories(d.path / "x.svg/inside");
  io::OutputFile f(d.path, "x.svg");
  f.write(std::string_view("data"));
  EXPECT_THROW(f.commit(), Error);
}

TEST(OutputFile, OverlongNamesAreErrors) {
  TempDir d;
  EXPECT_THROW(io::OutputFile(d.path, std::string(300, 'a') + ".svg"), Error);
}

// The rest of what selfsim writes goes through the same confined folders: a sweep's folders (make_folder),
// a child's log (open_log), a staged file published (move_file). A link anywhere on the way is refused.
TEST(OutputFile, FoldersLogsAndMovesRefuseLinksOnTheWay) {
  TempDir d;
  fs::create_directories(d.path / "out/real");
  fs::create_directories(d.path / "elsewhere");
  fs::create_directory_symlink(d.path / "elsewhere", d.path / "out/real/link");
  fs::create_symlink(d.path / "elsewhere/log.txt", d.path / "out/log.txt");
  EXPECT_THROW(io::make_folder(d.path / "out", "real/link/deeper"), Error);
  EXPECT_THROW(::close(io::open_log(d.path / "out", "real/link/run.log")), Error);
  EXPECT_THROW(::close(io::open_log(d.path / "out", "log.txt")), Error);  // the file itself a link
  {
    io::OutputFile f(d.path / "out", "staged/a.svg");
    f.write(std::string_view("a"));
    f.commit();
  }
  EXPECT_THROW(io::move_file(d.path / "out", "staged/a.svg", "real/link/a.svg"), Error);
  EXPECT_THROW(io::move_file(d.path / "out", "staged/a.svg", "../a.svg"), Error);
  EXPECT_TRUE(names_in(d.path / "elsewhere").empty());
  EXPECT_TRUE(fs::is_regular_file(d.path / "out/staged/a.svg"));  // nothing moved

  io::make_folder(d.path / "out", "made/on/the/way");
  EXPECT_TRUE(fs::is_directory(d.path / "out/made/on/the/way"));
  const int fd = io::open_log(d.path / "out", "made/run.log");
  EXPECT_EQ(::write(fd, "x", 1), 1);
  ::close(fd);
  EXPECT_EQ(read(d.path / "out/made/run.log"), "x");
  io::move_file(d.path / "out", "staged/a.svg", "made/on/a.svg");
  EXPECT_EQ(read(d.path / "out/made/on/a.svg"), "a");
  EXPECT_FALSE(fs::exists(d.path / "out/staged/a.svg"));
}

// A FIFO at a log's name is refused at once, never waited on for a reader (the studio opens run logs in its
// own loop).
TEST(OutputFile, OpenLogRefusesAFifoWithoutWaiting) {
  TempDir d;
  fs::create_directories(d.path / "out");
  ASSERT_EQ(::mkfifo((d.path / "out/run.log").c_str(), 0600), 0);
  EXPECT_THROW(::close(io::open_log(d.path / "out", "run.log")), Error);
}

// make_folder takes the rule of every other name below the root: no absolute path, no climbing out.
TEST(OutputFile, MakeFolderRefusesFoldersOutsideTheRoot) {
  TempDir d;
  fs::create_directories(d.path / "out");
  for (const char* folder : {"../x", "a/../../x", "..", "/tmp/selfsim_make_folder_absolute"})
    EXPECT_THROW(io::make_folder(d.path / "out", folder), Error) << folder;
  EXPECT_FALSE(fs::exists(d.path / "x"));
  EXPECT_FALSE(fs::exists("/tmp/selfsim_make_folder_absolute"));
  io::make_folder(d.path / "out", "a/../b");  // stays inside: fine
  EXPECT_TRUE(fs::is_directory(d.path / "out/b"));
}

// A child whose output folder its parent made (confine_output_root): a link put in the folder's place after
// it was made is refused at the root itself, not written through; a real folder, or a missing one, works.
TEST(OutputFile, AConfinedRootRefusesALinkInItsPlace) {
  TempDir d;
  fs::create_directories(d.path / "out");
  fs::create_directories(d.path / "elsewhere");
  fs::create_directory_symlink(d.path / "elsewhere", d.path / "out/run");
  io::confine_output_root();
  EXPECT_THROW(io::write_whole(d.path / "out/run", "a.svg", "a"), Error);
  EXPECT_THROW(io::write_whole(d.path / "out/run/", "a.svg", "a"), Error);
  EXPECT_THROW(io::make_folder(d.path / "out/run", "sub"), Error);
  io::write_whole(d.path / "out/new", "a.svg", "a");
  io::confine_output_root(false);
  EXPECT_TRUE(names_in(d.path / "elsewhere").empty());
  EXPECT_EQ(read(d.path / "out/new/a.svg"), "a");
  io::write_whole(d.path / "out/run", "b.svg", "b");  // the user's own -o may be a link
  EXPECT_EQ(read(d.path / "elsewhere/b.svg"), "b");
}
