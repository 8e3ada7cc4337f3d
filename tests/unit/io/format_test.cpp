#include "kernels/io/format.h"

#include <gtest/gtest.h>

#include <string>

#include "kernels/base/error.h"

using namespace selfsim;
using io::ValueKind;

namespace {

std::string format_error(const std::string& name, ValueKind k) {
  try {
    io::format_for(name, k);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

std::string options_error(const std::string& ext, const std::vector<std::string>& given) {
  const io::Format* f = io::find_format(ext);
  if (f == nullptr) return "no format " + ext;
  try {
    io::check_options(*f, given);
  } catch (const Error& e) {
    return e.what();
  }
  return {};
}

}  // namespace

TEST(Format, FindFormatKnowsEachExtension) {
  for (const char* ext : {".vtp", ".vtu", ".svg", ".eps", ".3mf", ".stl", ".obj", ".ply", ".vdb"}) {
    const io::Format* f = io::find_format(ext);
    ASSERT_NE(f, nullptr) << ext;
    EXPECT_EQ(f->extension, ext);
    EXPECT_FALSE(f->description.empty()) << ext;
    EXPECT_NE(f->write, nullptr) << ext;
  }
  EXPECT_EQ(io::formats().size(), 9u);
  EXPECT_EQ(io::find_format(".dxf"), nullptr);
  EXPECT_EQ(io::find_format("vtp"), nullptr);  // the dot is part of the extension
  EXPECT_EQ(io::find_format(""), nullptr);
}

TEST(Format, WhatEachFormatHolds) {
  const io::Format &vtp = *io::find_format(".vtp"), &vtu = *io::find_format(".vtu"), &svg = *io::find_format(".svg");
  for (const io::Format* f : {&vtp, &vtu}) {
    EXPECT_TRUE(f->holds(ValueKind::Curve));
    EXPECT_TRUE(f->holds(ValueKind::Curve3));
    EXPECT_TRUE(f->holds(ValueKind::Mesh));
  }
  EXPECT_TRUE(svg.holds(ValueKind::Curve));
  EXPECT_FALSE(svg.holds(ValueKind::Curve3));
  EXPECT_FALSE(svg.holds(ValueKind::Mesh));
  for (const char* ext : {".stl", ".obj", ".ply"}) {
    const io::Format& f = *io::find_format(ext);
    EXPECT_TRUE(f.holds(ValueKind::Mesh)) << ext;
    EXPECT_FALSE(f.holds(ValueKind::Curve)) << ext;
    EXPECT_FALSE(f.holds(ValueKind::Curve3)) << ext;
    EXPECT_TRUE(f.options.empty()) << ext;
  }
  EXPECT_EQ(svg.options, (std::vector<std::string>{"stroke", "stroke_width", "fill", "size"}));
  const io::Format& vdb = *io::find_format(".vdb");
  EXPECT_TRUE(vdb.holds(ValueKind::Mesh));
  EXPECT_FALSE(vdb.holds(ValueKind::Curve));
  EXPECT_EQ(vdb.options, (std::vector<std::string>{"voxel"}));
}

TEST(Format, KindNamesAndKindOf) {
  EXPECT_STREQ(io::kind_name(ValueKind::Curve), "curve");
  EXPECT_STREQ(io::kind_name(ValueKind::Curve3), "3D curve");
  EXPECT_STREQ(io::kind_name(ValueKind::Mesh), "mesh");
  const Polyline c;
  const Polyline3 c3;
  const Mesh m;
  EXPECT_EQ(io::kind_of(&c), ValueKind::Curve);
  EXPECT_EQ(io::kind_of(&c3), ValueKind::Curve3);
  EXPECT_EQ(io::kind_of(&m), ValueKind::Mesh);
}

TEST(Format, FormatForFindsTheFormat) {
  EXPECT_EQ(io::format_for("dragon.vtp", ValueKind::Curve).extension, ".vtp");
  EXPECT_EQ(io::format_for("sub/dir/dragon.svg", ValueKind::Curve).extension, ".svg");
  EXPECT_EQ(io::format_for("helix.vtu", ValueKind::Curve3).extension, ".vtu");
  EXPECT_EQ(io::format_for("surface.stl", ValueKind::Mesh).extension, ".stl");
  EXPECT_EQ(io::format_for("surface.ply", ValueKind::Mesh).extension, ".ply");
  EXPECT_EQ(io::format_for("surface.obj", ValueKind::Mesh).extension, ".obj");
}

TEST(Format, FormatForUnknownExtensionListsTheValidOnes) {
  EXPECT_EQ(format_error("c.dxf", ValueKind::Curve),
            "cannot save a curve as '.dxf' (file 'c.dxf'), expected one of: '.eps', '.svg', '.vtp', '.vtu'");
  EXPECT_EQ(format_error("out/m.dxf", ValueKind::Mesh),
            "cannot save a mesh as '.dxf' (file 'm.dxf'), expected one of: '.3mf', '.obj', '.ply', '.stl', '.vdb', "
            "'.vtp', '.vtu'");
  EXPECT_EQ(format_error("noext", ValueKind::Curve3),
            "cannot save a 3D curve as '' (file 'noext'), expected one of: '.vtp', '.vtu'");
}

TEST(Format, FormatForAFormatThatCannotHoldTheValue) {
  EXPECT_EQ(format_error("m.svg", ValueKind::Mesh),
            "cannot save a mesh as '.svg' (file 'm.svg'), expected one of: '.3mf', '.obj', '.ply', '.stl', '.vdb', "
            "'.vtp', '.vtu'");
  EXPECT_EQ(format_error("c.stl", ValueKind::Curve),
            "cannot save a curve as '.stl' (file 'c.stl'), expected one of: '.eps', '.svg', '.vtp', '.vtu'");
  EXPECT_EQ(format_error("helix.svg", ValueKind::Curve3),
            "cannot save a 3D curve as '.svg' (file 'helix.svg'), expected one of: '.vtp', '.vtu'");
}

TEST(Format, CheckOptionsRefusesAnotherFormatsOption) {
  EXPECT_EQ(
      options_error(".stl", {"stroke"}),
      "option 'stroke' does not apply to '.stl' files (it is an option of '.svg', '.eps'; '.stl' takes no options)");
  EXPECT_EQ(
      options_error(".vtp", {"size"}),
      "option 'size' does not apply to '.vtp' files (it is an option of '.svg', '.eps'; '.vtp' takes no options)");
  // The first offending name is the one reported.
  EXPECT_EQ(
      options_error(".ply", {"colour", "fill", "stroke"}),
      "option 'fill' does not apply to '.ply' files (it is an option of '.svg', '.eps'; '.ply' takes no options)");
}

TEST(Format, CheckOptionsPassesOwnOptionsAndLeavesUnknownNames) {
  EXPECT_EQ(options_error(".svg", {"stroke"}), "");
  EXPECT_EQ(options_error(".svg", {"stroke", "stroke_width", "fill", "size"}), "");
  EXPECT_EQ(options_error(".stl", {"colour"}), "");  // no format's option: the caller's unknown-option check
  EXPECT_EQ(options_error(".svg", {"colour"}), "");
  EXPECT_EQ(options_error(".stl", {}), "");
}
