// A .3mf's unit: each of the six units of the 3MF core specification scales the points to millimetres, and
// a unit not among them (which lib3mf reads as millimetres, with only a warning) is refused in one line
// naming the file, the unit and the valid ones. The packages are made here, as stored zips.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "io_fixtures.h"
#include "kernels/base/error.h"
#include "kernels/io/mesh/zip_part.h"
#include "kernels/io/read.h"

using namespace selfsim;
using io_fixtures::TempDir;

namespace {

void put(std::string& s, std::uint32_t v, int bytes) {
  for (int k = 0; k < bytes; ++k) s += static_cast<char>((v >> (8 * k)) & 0xff);
}

// A zip of stored (uncompressed) entries.
std::string stored_zip(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::string out, directory;
  for (const auto& [name, data] : entries) {
    const auto crc = static_cast<std::uint32_t>(
        crc32(0, reinterpret_cast<const Bytef*>(data.data()), static_cast<uInt>(data.size())));
    const auto offset = static_cast<std::uint32_t>(out.size());
    const auto size = static_cast<std::uint32_t>(data.size());
    const auto n = static_cast<std::uint32_t>(name.size());
    put(out, 0x04034b50, 4), put(out, 20, 2), put(out, 0, 2), put(out, 0, 2), put(out, 0, 4);
    put(out, crc, 4), put(out, size, 4), put(out, size, 4), put(out, n, 2), put(out, 0, 2);
    out += name + data;
    put(directory, 0x02014b50, 4), put(directory, 20, 2), put(directory, 20, 2), put(directory, 0, 2);
    put(directory, 0, 2), put(directory, 0, 4), put(directory, crc, 4), put(directory, size, 4);
    put(directory, size, 4), put(directory, n, 2), put(directory, 0, 2), put(directory, 0, 2);
    put(directory, 0, 2), put(directory, 0, 2), put(directory, 0, 4), put(directory, offset, 4);
    directory += name;
  }
  const auto at = static_cast<std::uint32_t>(out.size());
  out += directory;
  put(out, 0x06054b50, 4), put(out, 0, 2), put(out, 0, 2), put(out, static_cast<std::uint32_t>(entries.size()), 2);
  put(out, static_cast<std::uint32_t>(entries.size()), 2), put(out, static_cast<std::uint32_t>(directory.size()), 4);
  put(out, at, 4), put(out, 0, 2);
  return out;
}

// A package of one tetrahedron with a corner at (2, 0, 0) in `unit`, its model part at `part`.
std::string package(const std::string& unit, const std::string& part = "3D/3dmodel.model") {
  const std::string types =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?><Types "
      "xmlns=\"http://schemas.openxmlformats.org/package/2006/content-types\"><Default Extension=\"rels\" "
      "ContentType=\"application/vnd.openxmlformats-package.relationships+xml\"/><Default Extension=\"model\" "
      "ContentType=\"application/vnd.ms-package.3dmanufacturing-3dmodel+xml\"/></Types>";
  const std::string rels =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?><Relationships "
      "xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\"><Relationship Target=\"/" +
      part + "\" Id=\"rel0\" Type=\"http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel\"/></Relationships>";
  const std::string model =
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- <model unit=\"decoy\"> -->\n<model unit=\"" + unit +
      "\" xml:lang=\"en-US\" xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\"><resources>"
      "<object id=\"1\" type=\"model\"><mesh><vertices><vertex x=\"0\" y=\"0\" z=\"0\"/><vertex x=\"2\" y=\"0\" "
      "z=\"0\"/><vertex x=\"0\" y=\"1\" z=\"0\"/><vertex x=\"0\" y=\"0\" z=\"1\"/></vertices><triangles>"
      "<triangle v1=\"0\" v2=\"2\" v3=\"1\"/><triangle v1=\"0\" v2=\"1\" v3=\"3\"/><triangle v1=\"0\" v2=\"3\" "
      "v3=\"2\"/><triangle v1=\"1\" v2=\"2\" v3=\"3\"/></triangles></mesh></object></resources><build><item "
      "objectid=\"1\"/></build></model>";
  return stored_zip({{"[Content_Types].xml", types}, {"_rels/.rels", rels}, {part, model}});
}

void write(const std::filesystem::path& f, const std::string& bytes) { std::ofstream(f, std::ios::binary) << bytes; }

}  // namespace

TEST(ThreemfUnits, EachUnitOfTheSpecificationScalesToMillimetres) {
  TempDir dir;
  for (const auto& [unit, mm] : std::vector<std::pair<std::string, double>>{
           {"micron", 1e-3}, {"millimeter", 1}, {"centimeter", 10}, {"inch", 25.4}, {"foot", 304.8}, {"meter", 1000}}) {
    const auto f = dir.path / (unit + ".3mf");
    write(f, package(unit));
    const io::Dataset d = io::read_dataset(f);
    ASSERT_EQ(d.points.size(), 4u) << unit;
    EXPECT_NEAR(d.points[1][0], 2 * mm, 1e-9 * mm) << unit;
  }
}

TEST(ThreemfUnits, AnUnknownUnitIsRefusedNamingIt) {
  TempDir dir;
  const std::string valid = "expected one of 'micron', 'millimeter', 'centimeter', 'inch', 'foot', 'meter'";
  const auto f = dir.path / "furlong.3mf";
  write(f, package("furlong"));
  try {
    io::read_dataset(f);
    FAIL() << "a model in furlongs was read";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot read '" + f.string() + "': the unit 'furlong' is not a 3MF unit; " + valid);
  }
  // The root model part found through the package's relationships; a case-different unit is not a unit.
  const auto g = dir.path / "elsewhere.3mf";
  write(g, package("Inch", "3D/other.model"));
  try {
    io::read_dataset(g);
    FAIL() << "a model in 'Inch' was read";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read '" + g.string() + "': the unit 'Inch' is not a 3MF unit; " + valid);
  }
}

TEST(ZipPart, ReadsTheNamedEntryAndRefusesBrokenZips) {
  const std::string zip = stored_zip({{"a.txt", "alpha"}, {"Dir/B.xml", "<x:b unit='m' y=\"unit='q'\"/>"}});
  EXPECT_EQ(io::zip_part_head(zip, "/dir/b.xml", 100).value(), "<x:b unit='m' y=\"unit='q'\"/>");
  EXPECT_EQ(io::zip_part_head(zip, "a.txt", 3).value(), "alp");
  EXPECT_FALSE(io::zip_part_head(zip, "c.txt", 100));
  EXPECT_EQ(io::xml_attribute("<x:b y=\"unit='q'\" unit='m'/>", "b", "unit").value(), "m");
  EXPECT_FALSE(io::xml_attribute("<x:b y=\"unit='q'\"/>", "b", "unit"));
  // Cut anywhere, the zip is no zip (and nothing is read past its end).
  for (std::size_t n = 0; n < zip.size(); n += 7) io::zip_part_head(zip.substr(0, n), "a.txt", 100);
  std::string wrong = zip;
  wrong[wrong.size() - 3] = '\x7f';  // the central directory's offset beyond the end
  EXPECT_FALSE(io::zip_part_head(wrong, "a.txt", 100));
}
