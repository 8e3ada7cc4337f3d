// Writes the seed corpora of fuzz/corpus/: grammars in the grammar target's text format, and small .vtp
// and .svg files written by selfsim's own writers (io::save). Run once and commit the output:
//   build-fuzz/fuzz/fuzz_make_seeds fuzz/corpus
// (The recipe target's seeds are hand-written recipes in fuzz/corpus/recipe/, plus examples/ and
// tests/errors/, which fuzz/run.sh adds. The .vdb seeds with active tiles are OpenVDB's own files, written
// by tests/robustness/vdb_tiles.py with python3-openvdb, so that no seed program links OpenVDB.)
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "kernels/geom/polyline.h"
#include "kernels/io/save.h"
#include "kernels/lsystem/turtle/turtle2d.h"

namespace {

namespace fs = std::filesystem;
using namespace selfsim;

struct Seed {
  const char* name;
  const char* text;  // grammar_text.h format
};

// Table 1 of seed 002 and a few shapes that reach other branches of the kernel: branches, moves, per-symbol
// angles, a start angle list, an irrational angle (free heading), a closed curve.
const std::vector<Seed> grammars = {
    {"dragon", "axiom FX\nrule X=X-YF\nrule Y=FX+Y\nangle 90\nshrink 0.7071067811865476\nlevel 6\n"},
    {"terdragon", "axiom F\nrule F=F-F+F\nangle 120\nlevel 4\n"},
    {"hilbert", "axiom +YF-XFX-FY+\nrule X=+YF-XFX-FY+\nrule Y=-XF+YFY+FX-\nangle 90\nshrink 0.5\nlevel 2\n"},
    {"arrowhead", "axiom XF\nrule X=YF-XF-Y\nrule Y=XF+YF+X\nangle 60\nshrink 0.5\nstart 0 60\nlevel 3\n"},
    {"koch", "axiom F\nrule F=F+F--F+F\nangle 60\nlevel 3\n"},
    {"snowflake", "axiom F++F++F\nrule F=F-F++F-F\nangle 60\nshrink 0.3333333333333333\nlevel 2\nnormalize 0\n"},
    {"gosper", "axiom FX\nrule X=X+YF++YF-FX--FXFX-YF+\nrule Y=-FX+YFYF++YF+FX--FX-Y\nangle 60\nlevel 2\n"},
    {"plant", "axiom X\nrule X=F+[[X]-X]-F[-FX]+X\nrule F=FF\nangle 25\nstart 70\nlevel 3\nnormalize 0\n"},
    {"moves", "axiom F\nrule F=F+f-FF+F+FF+Ff+FF-f+FF-F-FF-Ff-FFF\nrule f=ffffff\nangle 90\nlevel 1\n"},
    {"angles", "axiom A\nrule A=A+B\nrule B=A-B\nturn +=45\nturn -=-30\nturn A=7\ndraw AB\nlevel 5\n"},
    {"irrational", "axiom F\nrule F=F+F-F\nangle 51.42857142857143\nlevel 4\n"},
    {"turnaround", "axiom F|F\nrule F=F+F|F\nangle 90\nmove g\nlevel 3\n"},
};

Polyline seed_curve(const char* axiom, const char* rule, double angle, int level, bool normalize) {
  lsystem::Grammar g;
  g.axiom = axiom;
  g.rules['F'] = rule;
  g.angle = angle;
  lsystem::TurtleOptions opt;
  opt.level = level;
  opt.normalize = normalize;
  return lsystem::turtle2d(g, opt, no_progress());
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s CORPUS_DIR (fuzz/corpus)\n", argv[0]);
    return 2;
  }
  const fs::path dir = argv[1];
  fs::create_directories(dir / "grammar");
  for (const Seed& s : grammars)
    std::ofstream(dir / "grammar" / (std::string(s.name) + ".txt"), std::ios::binary) << s.text;

  struct File {
    const char* name;
    Polyline curve;
    io::SaveOptions opt;
  };
  std::vector<File> files;
  files.push_back({"dragon3", seed_curve("F", "F+F-", 90, 3, true), {}});
  files.push_back({"koch2", seed_curve("F", "F+F--F+F", 60, 2, true), {}});
  files.push_back(
      {"branches", seed_curve("F", "F[+F]F[-F]", 30, 1, false), {.stroke = {"black"}, .fill = {"#a8dadc"}}});
  files.push_back(
      {"square", Polyline::single({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}), {.stroke_width = {2}, .size = 64}});
  for (const char* ext : {".vtp", ".svg"}) {
    const fs::path sub = dir / (ext + 1);
    fs::create_directories(sub);
    for (const File& f : files) io::save(&f.curve, sub / (std::string(f.name) + ext), f.opt, no_progress());
  }
  std::printf("wrote %zu grammars and %zu .vtp/.svg files under %s\n", grammars.size(), files.size(), dir.c_str());
  return 0;
}
