// Shared by the io tests: a fresh folder per test, and a small curve of two paths.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "kernels/geom/polyline.h"

namespace io_fixtures {

// A folder named after the process and the test, removed with everything in it at the end of the test.
struct TempDir {
  std::filesystem::path path =
      std::filesystem::temp_directory_path() / ("selfsim_io_" + std::to_string(::getpid()) + "_" +
                                                ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempDir() { std::filesystem::create_directories(path); }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

// A fresh folder per test and parameter, for tests parameterised by a file extension (GetParam()): the
// folder is named after the test, whose name holds a '/' that TempDir would not take.
class PerFormatTest : public ::testing::TestWithParam<const char*> {
 protected:
  std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("selfsim_" + std::to_string(::getpid()) + "_" + test_name());
  void SetUp() override { std::filesystem::create_directories(dir); }
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(dir, ignored);
  }
  // A file in the folder with the test's extension.
  std::filesystem::path file(const std::string& stem) const { return dir / (stem + GetParam()); }

 private:
  static std::string test_name() {
    std::string s = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    for (char& ch : s)
      if (ch == '/') ch = '_';
    return s;
  }
};

// Two paths: (0,0) (1,0) (1,1), then (2,2) (3,2.5); a uniform level field of 7.
inline selfsim::Polyline two_paths() {
  selfsim::Polyline c;
  c.points = {{0, 0}, {1, 0}, {1, 1}, {2, 2}, {3, 2.5}};
  c.path_ends = {3, 5};
  c.point_fields.set(selfsim::uniform_int("level", 7));
  return c;
}

// The whole text of a file.
inline std::string text_of(const std::filesystem::path& f) {
  std::ifstream in(f);
  return {std::istreambuf_iterator<char>(in), {}};
}

// How many times `word` occurs in `text`.
inline std::size_t count(const std::string& text, const std::string& word) {
  std::size_t n = 0;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
  return n;
}

// two_paths() as a value that lives for the whole test program (save() takes values by address).
inline const selfsim::Polyline two_paths_value = two_paths();

}  // namespace io_fixtures
