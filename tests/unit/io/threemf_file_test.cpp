// .3mf files read back by lib3mf's own reader: millimetres, the object's name, the points and triangles as
// written (to float precision), the application; an open mesh is refused and leaves no file.
#include <Model/COM/NMR_DLLInterfaces.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "io_fixtures.h"
#include "kernels/base/error.h"
#include "kernels/io/save.h"
#include "kernels/region/box_mesh.h"

using namespace selfsim;
using io_fixtures::TempDir;

namespace {

struct Read3mf {
  DWORD unit = 99;
  std::string name, title, application;
  std::vector<NMR::MODELMESHVERTEX> points;
  std::vector<NMR::MODELMESHTRIANGLE> triangles;
};

std::string text_of(NMR::PLib3MFBase* handle, LIB3MFRESULT (*get)(NMR::PLib3MFBase*, LPSTR, ULONG, ULONG*)) {
  ULONG need = 0;
  get(handle, nullptr, 0, &need);
  std::string s(need + 1, '\0');
  get(handle, s.data(), need + 1, &need);
  s.resize(need);
  return s;
}

Read3mf read_3mf(const std::filesystem::path& file) {
  Read3mf r;
  NMR::PLib3MFBase *model = nullptr, *reader = nullptr, *meshes = nullptr, *mesh = nullptr;
  EXPECT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_model_queryreader(model, "3mf", &reader), LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_reader_readfromfileutf8(reader, file.c_str()), LIB3MF_OK);
  NMR::lib3mf_model_getunit(model, &r.unit);
  DWORD count = 0;
  NMR::lib3mf_model_getmetadatacount(model, &count);
  for (DWORD i = 0; i < count; ++i) {
    char key[64] = {}, value[256] = {};
    ULONG need = 0;
    NMR::lib3mf_model_getmetadatakeyutf8(model, i, key, sizeof key, &need);
    NMR::lib3mf_model_getmetadatavalueutf8(model, i, value, sizeof value, &need);
    if (std::string(key) == "Title") r.title = value;
    if (std::string(key) == "Application") r.application = value;
  }
  EXPECT_EQ(NMR::lib3mf_model_getmeshobjects(model, &meshes), LIB3MF_OK);
  BOOL next = 0;
  NMR::lib3mf_resourceiterator_movenext(meshes, &next);
  EXPECT_TRUE(next);
  NMR::lib3mf_resourceiterator_getcurrent(meshes, &mesh);
  r.name = text_of(mesh, [](NMR::PLib3MFBase* h, LPSTR b, ULONG n, ULONG* need) {
    return NMR::lib3mf_object_getnameutf8(h, b, n, need);
  });
  DWORD nv = 0, nt = 0;
  NMR::lib3mf_meshobject_getvertexcount(mesh, &nv);
  NMR::lib3mf_meshobject_gettrianglecount(mesh, &nt);
  r.points.resize(nv);
  r.triangles.resize(nt);
  NMR::lib3mf_meshobject_getvertices(mesh, r.points.data(), nv, &nv);
  NMR::lib3mf_meshobject_gettriangleindices(mesh, r.triangles.data(), nt, &nt);
  for (NMR::PLib3MFBase* h : {mesh, meshes, reader, model}) NMR::lib3mf_release(h);
  return r;
}

}  // namespace

TEST(Save3mf, MillimetresNameAndGeometry) {
  TempDir dir;
  const Mesh box = box_mesh({0, 0, 0}, {120.5, 80.25, 10.125});
  io::SaveOptions opt;
  opt.application = "selfsim test";
  io::save(&box, dir.path / "pendant.3mf", opt, no_progress());
  const Read3mf r = read_3mf(dir.path / "pendant.3mf");
  EXPECT_EQ(r.unit, static_cast<DWORD>(NMR::MODELUNIT_MILLIMETER));
  EXPECT_EQ(r.name, "pendant");  // the file's name without its extension
  EXPECT_EQ(r.title, "pendant");
  EXPECT_EQ(r.application, "selfsim test");
  ASSERT_EQ(r.points.size(), box.points.size());
  ASSERT_EQ(r.triangles.size(), box.triangles.size());
  for (std::size_t i = 0; i < box.points.size(); ++i) {
    EXPECT_FLOAT_EQ(r.points[i].m_fPosition[0], static_cast<float>(box.points[i].x));
    EXPECT_FLOAT_EQ(r.points[i].m_fPosition[2], static_cast<float>(box.points[i].z));
  }
  for (std::size_t f = 0; f < box.faces(); ++f)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(r.triangles[f].m_nIndices[k], box.triangles[f][k]);

  opt.name = "dragon ü";
  io::save(&box, dir.path / "b.3mf", opt, no_progress());
  EXPECT_EQ(read_3mf(dir.path / "b.3mf").name, "dragon ü");
  // Characters XML escapes, in the name and so in the title: the file still parses.
  opt.name = "rock&roll <\"x'>";
  io::save(&box, dir.path / "c.3mf", opt, no_progress());
  const Read3mf c = read_3mf(dir.path / "c.3mf");
  EXPECT_EQ(c.name, opt.name);
  // lib3mf reads metadata back as it stands in the XML, entities and all (it writes it so too: hence the
  // escaping); an XML parser, as a slicer's, reads the name.
  EXPECT_EQ(c.title, "rock&amp;roll &lt;&quot;x'&gt;");
}

TEST(Save3mf, RefusesAnOpenMesh) {
  TempDir dir;
  Mesh open = box_mesh({0, 0, 0}, {1, 1, 1});
  open.triangles.pop_back();
  try {
    io::save(&open, dir.path / "open.3mf", {}, no_progress());
    FAIL() << "an open mesh was written";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("the mesh is open"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir.path / "open.3mf"));
}
