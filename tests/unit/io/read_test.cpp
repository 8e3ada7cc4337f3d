// Reading files back: every broken, truncated, crafted or special file is one Error line, "cannot read
// 'FILE': REASON", never a crash, a hang, an empty dataset or a partial one.
#include "kernels/io/read.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <iterator>

#include "io_fixtures.h"
#include "kernels/analysis/dataset_diff.h"
#include "kernels/base/error.h"
#include "kernels/io/save.h"

using namespace selfsim;
namespace fs = std::filesystem;
using io_fixtures::TempDir;
using io_fixtures::two_paths;

namespace {

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write(const fs::path& f, const std::string& bytes) {
  std::ofstream out(f, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// The message read_dataset throws for f; empty when f reads.
std::string read_error(const fs::path& f) {
  try {
    io::read_dataset(f);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

// f must fail to read with one line "cannot read '...': ..." that mentions `reason`.
void expect_read_error(const fs::path& f, const std::string& reason) {
  const std::string m = read_error(f);
  ASSERT_FALSE(m.empty()) << f << " read as a dataset";
  EXPECT_EQ(m.rfind("cannot read '", 0), 0u) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  EXPECT_NE(m.find(reason), std::string::npos) << "expected '" << reason << "' in: " << m;
}

std::string replaced(std::string s, const std::string& from, const std::string& to) {
  const std::size_t at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) s.replace(at, from.size(), to);
  return s;
}

// s with the value of the first attribute `name` set to `value`, however the writer spaced it.
std::string set_attribute(std::string s, const std::string& name, const std::string& value) {
  const std::size_t at = s.find(" " + name + "=\"");
  EXPECT_NE(at, std::string::npos) << name;
  if (at == std::string::npos) return s;
  const std::size_t begin = at + name.size() + 3;
  s.replace(begin, s.find('"', begin) - begin, value);
  return s;
}

std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 3; ++k) v = v << 8 | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
    for (std::size_t k = 0; k < 4; ++k) out += k <= n ? digits[(v >> (18 - 6 * k)) & 63] : '=';
  }
  return out;
}

std::string words64(std::initializer_list<std::uint64_t> words) {
  std::string s;
  for (std::uint64_t w : words)
    for (int k = 0; k < 8; ++k) s += static_cast<char>(w >> (8 * k));
  return s;
}

// Three points, the first at (x, 0, 0), and one line in appended raw data with UInt64 headers (as selfsim
// writes): the Points array's header says `points_bytes`, and the arrays start at the given offsets.
std::string raw_vtp(std::uint64_t points_bytes = 72, const std::string& offsets = "0 80 112", double x = 0) {
  std::string o[3];
  std::size_t at = 0;
  for (auto& each : o) {
    const std::size_t next = offsets.find(' ', at);
    each = offsets.substr(at, next - at);
    at = next + 1;
  }
  std::string s = R"(<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">
  <PolyData>
    <Piece NumberOfPoints="3" NumberOfVerts="0" NumberOfLines="1" NumberOfStrips="0" NumberOfPolys="0">
      <Points>
        <DataArray type="Float64" Name="Points" NumberOfComponents="3" format="appended" offset=")" +
                  o[0] + R"("/>
      </Points>
      <Lines>
        <DataArray type="Int64" Name="connectivity" format="appended" offset=")" +
                  o[1] + R"("/>
        <DataArray type="Int64" Name="offsets" format="appended" offset=")" +
                  o[2] + R"("/>
      </Lines>
    </Piece>
  </PolyData>
  <AppendedData encoding="raw">
   _)";
  s += words64({points_bytes});
  for (double v : {x, 0.0, 0.0, 1.0, 0.0, 0.0, 1.0, 1.0, 0.0}) s.append(reinterpret_cast<const char*>(&v), sizeof v);
  s += words64({24, 0, 1, 2}) + words64({8, 3});
  return s + "\n  </AppendedData>\n</VTKFile>\n";
}

// Three points and one line as vtkXMLPolyDataWriter writes them in binary mode: inline base64, UInt64
// headers, zlib compression (the data strings are that writer's output).
std::string small_compressed_vtp(
    const std::string& points_data = "AQAAAAAAAAAAgAAAAAAAAEgAAAAAAAAAEgAAAAAAAAA=eJxjYMAHPtjjF0fIAwBSZQOO") {
  return R"(<?xml version="1.0"?>
<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64" compressor="vtkZLibDataCompressor">
  <PolyData>
    <Piece NumberOfPoints="3" NumberOfVerts="0" NumberOfLines="1" NumberOfStrips="0" NumberOfPolys="0">
      <Points>
        <DataArray type="Float64" Name="Points" NumberOfComponents="3" format="binary">
          )" +
         points_data + R"(
        </DataArray>
      </Points>
      <Lines>
        <DataArray type="Int64" Name="connectivity" format="binary">
          AQAAAAAAAAAAgAAAAAAAABgAAAAAAAAAEAAAAAAAAAA=eJxjYIAARijNBKUBADgABA==
        </DataArray>
        <DataArray type="Int64" Name="offsets" format="binary">
          AQAAAAAAAAAAgAAAAAAAAAgAAAAAAAAACwAAAAAAAAA=eJxjZoAAAAAgAAQ=
        </DataArray>
      </Lines>
    </Piece>
  </PolyData>
</VTKFile>
)";
}

// Two points and a line in ascii, with `points` and `connectivity` as given.
std::string ascii_vtp(const std::string& points, const std::string& connectivity) {
  return R"(<VTKFile type="PolyData" version="1.0"><PolyData><Piece NumberOfPoints="2" NumberOfLines="1">
<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">)" +
         points + R"(</DataArray></Points>
<Lines><DataArray type="Int64" Name="connectivity" format="ascii">)" +
         connectivity + R"(</DataArray><DataArray type="Int64" Name="offsets" format="ascii">2</DataArray></Lines>
</Piece></PolyData></VTKFile>
)";
}

// Every prefix of `full` fails to read, except the whole file (and the whole file less trailing blanks),
// which reads as the original.
void expect_every_prefix_fails(const fs::path& full, const fs::path& part) {
  const std::string bytes = slurp(full);
  const io::Dataset whole = io::read_dataset(full);
  ASSERT_EQ(whole.points.size(), two_paths().points.size());
  for (std::size_t k = 0; k < bytes.size(); ++k) {
    write(part, bytes.substr(0, k));
    const std::string m = read_error(part);
    if (m.empty()) {
      EXPECT_EQ(bytes.find_first_not_of(" \t\r\n", k), std::string::npos)
          << "a prefix of " << k << " bytes read as a dataset";
      EXPECT_TRUE(analysis::dataset_diff(io::read_dataset(part), whole, 0).empty());
    } else {
      EXPECT_EQ(m.rfind("cannot read '", 0), 0u) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
}

}  // namespace

TEST(ReadVtp, EveryTruncationOfASavedFileIsAnError) {
  TempDir dir;
  io::save(&io_fixtures::two_paths_value, dir.path / "c.vtp", {}, no_progress());
  expect_every_prefix_fails(dir.path / "c.vtp", dir.path / "part.vtp");
}

TEST(ReadSvg, EveryTruncationOfASavedFileIsAnError) {
  TempDir dir;
  io::save(&io_fixtures::two_paths_value, dir.path / "c.svg", {}, no_progress());
  expect_every_prefix_fails(dir.path / "c.svg", dir.path / "part.svg");
}

TEST(ReadVtp, EveryTruncationOfACompressedFileIsAnError) {
  TempDir dir;
  const std::string text = small_compressed_vtp();
  write(dir.path / "c.vtp", text);
  const io::Dataset d = io::read_dataset(dir.path / "c.vtp");
  ASSERT_EQ(d.points.size(), 3u);
  EXPECT_EQ(d.points[2], (std::array<double, 3>{1, 1, 0}));
  EXPECT_EQ(d.cell_ends, (std::vector<std::size_t>{3}));
  for (std::size_t k = 0; k + 1 < text.size(); ++k) {
    write(dir.path / "part.vtp", text.substr(0, k));
    EXPECT_FALSE(read_error(dir.path / "part.vtp").empty()) << "a prefix of " << k << " bytes read as a dataset";
  }
}

TEST(ReadVtp, CraftedHeadersAreErrors) {
  // Each a file VTK's reader alone would crash on, abort on or misread.
  TempDir dir;
  io::save(&io_fixtures::two_paths_value, dir.path / "c.vtp", {}, no_progress());
  const std::string good = slurp(dir.path / "c.vtp");
  const struct {
    std::string attribute, value, reason;
  } cases[] = {
      {"NumberOfPoints", "-5", "NumberOfPoints=\"-5\""},
      {"NumberOfPoints", "1e15", "must be a whole number"},
      {"NumberOfPoints", "1000000000000000", "must be a whole number"},
      {"NumberOfPoints", "+5", "must be a whole number"},
      {"NumberOfPoints", "&#45;5", "must be a whole number"},
      {"NumberOfPoints", "100000000000", "reading limit"},
      {"NumberOfPoints", "6", "fewer than"},
      {"NumberOfLines", "-1", "NumberOfLines"},
      {"NumberOfLines", "99999999999999999999", "NumberOfLines"},
      {"NumberOfComponents", "12345678901234567890", "NumberOfComponents"},
      {"NumberOfComponents", "0", "NumberOfComponents"},
      {"NumberOfComponents", "4000", "fewer than"},
      {"format", "zipped", "unknown format"},
      {"offset", "99999999999999", "offset within the file"},
      {"offset", "-1", "offset within the file"},
      {"header_type", "UInt128", "header_type"},
      {"byte_order", "MiddleEndian", "byte_order"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.attribute + "=" + c.value);
    write(dir.path / "x.vtp", set_attribute(good, c.attribute, c.value));
    expect_read_error(dir.path / "x.vtp", c.reason);
  }
  const struct {
    std::string from, to, reason;
  } edits[] = {
      {"type=\"PolyData\"", "type=\"UnstructuredGrid\"", "not a VTK PolyData file"},
      {"type=\"Float64\"", "type=\"Float128\"", "unsupported type"},
      {"NumberOfLines=", "NumberOfLines=\"1\" NumberOfLines=", "given twice"},
      {"<VTKFile", "<!DOCTYPE x [<!ENTITY a \"aaaa\">]><VTKFile", "DOCTYPE"},
      {"</Points>", "</Lines>", "malformed XML"},
  };
  for (const auto& c : edits) {
    SCOPED_TRACE(c.to);
    write(dir.path / "x.vtp", replaced(good, c.from, c.to));
    expect_read_error(dir.path / "x.vtp", c.reason);
  }
  write(dir.path / "cut.vtp", good.substr(0, good.find("<AppendedData")) + "</VTKFile>\n");
  expect_read_error(dir.path / "cut.vtp", "no <AppendedData>");
  std::string deep;
  for (int i = 0; i < 100; ++i) deep += "<a>";
  write(dir.path / "deep.vtp", replaced(good, "<PolyData>", "<PolyData>" + deep));
  expect_read_error(dir.path / "deep.vtp", "nested deeper");
  write(dir.path / "long_tag.vtp", replaced(good, "<PolyData>", "<PolyData x=\"" + std::string(100000, 'x') + "\">"));
  expect_read_error(dir.path / "long_tag.vtp", "longer than 64 KiB");
}

TEST(ReadVtp, CraftedDataHeadersAreErrors) {
  TempDir dir;
  write(dir.path / "raw.vtp", raw_vtp());
  EXPECT_EQ(io::read_dataset(dir.path / "raw.vtp").points.size(), 3u);
  write(dir.path / "huge.vtp", raw_vtp(std::uint64_t{1} << 62));
  expect_read_error(dir.path / "huge.vtp", "reading limit");
  write(dir.path / "longer.vtp", raw_vtp(4096));
  expect_read_error(dir.path / "longer.vtp", "more than the file holds");
  write(dir.path / "shorter.vtp", raw_vtp(8));
  expect_read_error(dir.path / "shorter.vtp", "fewer than");
  write(dir.path / "offset.vtp", raw_vtp(72, "0 80 180"));
  expect_read_error(dir.path / "offset.vtp", "file");

  // Compression headers: 2^40 blocks; a block claiming to expand past any compressor; blocks past the end.
  const std::string blocks =
      small_compressed_vtp(base64(words64({std::uint64_t{1} << 40, 32768, 72, 18})) + "eJxjYMAHPtjjF0fIAwBSZQOO");
  write(dir.path / "blocks.vtp", blocks);
  expect_read_error(dir.path / "blocks.vtp", "1099511627776 blocks");
  write(dir.path / "ratio.vtp",
        small_compressed_vtp(base64(words64({1, std::uint64_t{1} << 30, 0, 18})) + "eJxjYMAHPtjjF0fIAwBSZQOO"));
  expect_read_error(dir.path / "ratio.vtp", "which no compressor makes");
  write(dir.path / "past.vtp",
        small_compressed_vtp(base64(words64({1, 32768, 72, 5000})) + "eJxjYMAHPtjjF0fIAwBSZQOO"));
  expect_read_error(dir.path / "past.vtp", "file");
  write(dir.path / "notbase64.vtp", small_compressed_vtp("AQAAAAAAAAAAgAAAA*AAAEgAAAAAAAAAEgAAAAAAAAA="));
  expect_read_error(dir.path / "notbase64.vtp", "base64");
}

TEST(ReadVtp, ArraysPointingIntoOtherArraysAreErrorsNotCrashes) {
  // Such files pass the header checks: VTK then takes a coordinate's bits (1.0 is 4607182418800017408 as
  // an Int64) for a cell offset and asks for exabytes, which its child process turns into an error line.
  TempDir dir;
  for (const char* offsets : {"0 80 0", "0 0 0", "0 0 112"}) {
    SCOPED_TRACE(offsets);
    write(dir.path / "x.vtp", raw_vtp(72, offsets, 1.0));
    const std::string m = read_error(dir.path / "x.vtp");
    EXPECT_EQ(m.rfind("cannot read '", 0), 0u) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
  // With a first coordinate of 0 the same files are consistent, and read.
  write(dir.path / "zero.vtp", raw_vtp(72, "0 0 0", 0.0));
  EXPECT_EQ(read_error(dir.path / "zero.vtp"), "");
}

TEST(ReadVtp, ReadsEveryDataLayoutAndChecksWhatItRead) {
  TempDir dir;
  write(dir.path / "ok.vtp", ascii_vtp("0 0 0 1 1 0", "0 1"));
  const io::Dataset d = io::read_dataset(dir.path / "ok.vtp");
  EXPECT_EQ(d.points.size(), 2u);
  EXPECT_EQ(d.cell_points, (std::vector<std::size_t>{0, 1}));
  write(dir.path / "id.vtp", ascii_vtp("0 0 0 1 1 0", "0 7"));
  expect_read_error(dir.path / "id.vtp", "refers to point 7");
  write(dir.path / "negative.vtp", ascii_vtp("0 0 0 1 1 0", "0 -1"));
  expect_read_error(dir.path / "negative.vtp", "refers to point -1");
  write(dir.path / "nan.vtp", ascii_vtp("0 0 0 nan 1 0", "0 1"));
  expect_read_error(dir.path / "nan.vtp", "nan.vtp");
  write(dir.path / "short.vtp", ascii_vtp("0 0 0 1 1", "0 1"));
  expect_read_error(dir.path / "short.vtp", "ascii data");
  write(dir.path / "junk.vtp", ascii_vtp("0 0 0 1 x 0", "0 1"));
  expect_read_error(dir.path / "junk.vtp", "VTK: ");
}

TEST(ReadFiles, GarbageEmptyAndSpecialFilesAreErrors) {
  TempDir dir;
  for (const char* ext : {".vtp", ".svg"}) {
    SCOPED_TRACE(ext);
    write(dir.path / (std::string("empty") + ext), "");
    expect_read_error(dir.path / (std::string("empty") + ext), "empty");
    std::string garbage;
    for (int i = 0; i < 3000; ++i) garbage += static_cast<char>((i * 7919) % 251);
    write(dir.path / (std::string("garbage") + ext), garbage);
    expect_read_error(dir.path / (std::string("garbage") + ext), "not a");
    write(dir.path / (std::string("text") + ext), "hello, world\n");
    expect_read_error(dir.path / (std::string("text") + ext), "not a");
    fs::create_directory(dir.path / (std::string("folder") + ext));
    expect_read_error(dir.path / (std::string("folder") + ext), "is a directory");
    ASSERT_EQ(::mkfifo((dir.path / (std::string("fifo") + ext)).c_str(), 0600), 0);
    expect_read_error(dir.path / (std::string("fifo") + ext), "FIFO");  // returns at once: no writer needed
    fs::create_symlink("/dev/zero", dir.path / (std::string("zero") + ext));
    expect_read_error(dir.path / (std::string("zero") + ext), "device");
    fs::create_symlink(std::string("loop") + ext, dir.path / (std::string("loop") + ext));
    expect_read_error(dir.path / (std::string("loop") + ext), "symbolic links");
    expect_read_error(dir.path / (std::string(300, 'n') + ext), "too long");
    expect_read_error(dir.path / (std::string("missing") + ext), "no such file");
  }
  write(dir.path / "c.txt", "x");
  expect_read_error(dir.path / "c.txt", "expected a .vtp, .vtu, .svg, .stl, .3mf, .obj or .ply file");
  // A .3mf that is not a zip, or a zip of nothing, is lib3mf's refusal in one line.
  std::string garbage;
  for (int i = 0; i < 3000; ++i) garbage += static_cast<char>((i * 7919) % 251);
  write(dir.path / "garbage.3mf", garbage);
  expect_read_error(dir.path / "garbage.3mf", "lib3mf could not read it");
  write(dir.path / "empty.3mf", "");
  expect_read_error(dir.path / "empty.3mf", "cannot read");
}

TEST(ReadSvg, PathDataMustBeFiniteAbsolutePairs) {
  TempDir dir;
  auto svg = [&](const std::string& d, const std::string& tail = "</svg>\n") {
    write(dir.path / "x.svg",
          "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"><g transform=\"scale(1,-1)\"><path d=\"" +
              d + "\"/></g>" + tail);
    return dir.path / "x.svg";
  };
  const io::Dataset d = io::read_dataset(svg("M0 0L1 1 2,2M-1-2 3e1 4"));
  EXPECT_EQ(d.points.size(), 5u);
  EXPECT_EQ(d.cell_ends, (std::vector<std::size_t>{3, 5}));
  EXPECT_EQ(d.points[3], (std::array<double, 3>{-1, -2, 0}));
  EXPECT_EQ(d.points[4], (std::array<double, 3>{30, 4, 0}));
  expect_read_error(svg("M0 0L1 NaN"), "non-finite");
  expect_read_error(svg("M0 0L1 nan"), "non-finite");
  expect_read_error(svg("M0 0L1 inf"), "non-finite");
  expect_read_error(svg("M0 0L1 -Infinity"), "non-finite");
  expect_read_error(svg("M0 0L1 1i"), "unsupported path command");
  expect_read_error(svg("M0 0L1 1e999"), "out of range");
  expect_read_error(svg("M0 0L1"), "odd number of coordinates");
  expect_read_error(svg("M0 0 1M2 3"), "odd number of coordinates");
  expect_read_error(svg("M0 0l1 1"), "unsupported path command 'l'");
  expect_read_error(svg("M0 0C1 1 2 2 3 3"), "unsupported path command 'C'");
  expect_read_error(svg("0 0L1 1"), "does not start with M");
  expect_read_error(svg("M0 0L1.2e 4 5"), "malformed number");  // "1.2.3" is 1.2 and .3, as SVG reads it
  expect_read_error(svg("M0 0L1 1", ""), "truncated");
  expect_read_error(svg("M0 0L1 1", "</g></svg>"), "malformed XML");
  write(dir.path / "html.svg", "<html><path d=\"M0 0\"/></html>");
  expect_read_error(dir.path / "html.svg", "not an SVG file");
  write(dir.path / "empty_svg.svg", "<svg xmlns=\"http://www.w3.org/2000/svg\"></svg>");
  // Well-formed but empty: selfsim never writes one, and two of them must not compare as "same".
  expect_read_error(dir.path / "empty_svg.svg", "holds no points");
}
