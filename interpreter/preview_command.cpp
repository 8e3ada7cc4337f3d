// `selfsim preview FILE... [-o DIR]`: a PNG of each geometry file (any that selfsim writes or reads), for
// a look without ParaView. Files are read with the readers `info` and `diff` use (a .vdb as its surface,
// vdb_read.h), rendered by VTK (preview_png.h) on the user's X display or an Xvfb of our own
// (display_server.h), and written atomically as NAME.png beside the input, or into DIR with -o.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>

#include "interpreter/commands.h"
#include "interpreter/display_server.h"
#include "interpreter/lua_support.h"
#include "kernels/geom/error.h"
#include "kernels/geom/lower_case.h"
#include "kernels/io/preview_png.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/series_file.h"
#include "kernels/io/vdb_read.h"

namespace selfsim::interp {

namespace {

const char* const formats = ".vtp, .vtu, .svg, .stl, .obj, .ply, .vdb, .pvd or .series";

bool known(const std::string& ext) {
  for (const char* e : {".vtp", ".vtu", ".svg", ".stl", ".obj", ".ply", ".vdb"})
    if (ext == e) return true;
  return false;
}

std::string error_line(const std::exception& e) {
  std::string m = e.what();
  for (char& c : m)
    if (c == '\n' || c == '\r') c = ' ';
  return m;
}

}  // namespace

PreviewConfig parse_preview_arguments(const std::vector<std::string>& args) {
  PreviewConfig c;
  bool options = true;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (options && a == "--") {
      options = false;
    } else if (options && (a == "-o" || a == "--output")) {
      if (i + 1 >= args.size() || args[i + 1].empty()) throw UsageError(a + " expects a folder");
      c.out_dir = args[++i];
    } else if (options && (a == "-q" || a == "--quiet")) {
      c.quiet = true;
    } else if (options && a.size() > 1 && a[0] == '-') {
      throw UsageError("unknown preview option '" + a + "'");
    } else {
      c.files.push_back(a);
    }
  }
  if (c.files.empty()) throw UsageError("preview expects one or more files");
  return c;
}

int preview_command(const PreviewConfig& config) {
  std::unique_ptr<DisplayServer> display;  // started at the first file that reads
  std::set<std::string> written;
  int code = 0;
  for (const std::string& name : config.files) {
    const std::filesystem::path file(name);
    try {
      // A time series is drawn as its last step, the grown result.
      const bool series = io::is_series_name(name);
      std::string stem = file.stem().string(), title = file.filename().string(), note;
      std::filesystem::path source = file;
      if (series) {
        const std::vector<std::filesystem::path> steps = io::read_series_steps(file);
        source = steps.back();
        // growth.vtp.series draws growth.png, as growth.pvd does.
        for (const char* inner : {".vtp", ".vtu"})
          if (stem.size() > 4 && lower_case(stem.substr(stem.size() - 4)) == inner) stem.erase(stem.size() - 4);
        title += " (last of " + std::to_string(steps.size()) + " steps)";
        note = ", the last of " + std::to_string(steps.size()) + " steps";
      }
      const std::string ext = lower_case(source.extension().string());
      if (!known(ext)) throw Error(io::cannot_read(source, std::string("expected a ") + formats + " file"));
      io::Dataset d;
      if (ext == ".vdb") {
        io::VdbSurface s = io::read_vdb_surface(source);
        d = std::move(s.mesh);
        note = ", " + s.what;
      } else {
        d = io::read_dataset(source);
      }
      if (!display) display = std::make_unique<DisplayServer>();
      // NAME.png beside the input or in DIR; a second input of the same name in this run gets NAME_EXT.png.
      const std::size_t at = static_cast<std::size_t>(&name - config.files.data());
      const std::filesystem::path folder = at < config.pngs.size()  ? config.pngs[at].parent_path()
                                           : config.out_dir.empty() ? file.parent_path()
                                                                    : std::filesystem::path(config.out_dir);
      std::string leaf = at < config.pngs.size() ? config.pngs[at].filename().string() : stem + ".png";
      const std::string key = (folder / leaf).lexically_normal().string();
      // A later input of the same name in this run gets NAME_EXT.png, then NAME_EXT_2.png, ...
      if (!written.insert(key).second) {
        const std::string base = stem + "_" + lower_case(file.extension().string()).substr(1);
        leaf = base + ".png";
        for (int n = 2; !written.insert((folder / leaf).lexically_normal().string()).second; ++n)
          leaf = base + "_" + std::to_string(n) + ".png";
      }
      const io::PreviewSize size = io::preview_size(d);
      const std::string out = io::write_preview_png(d, title, folder.empty() ? "." : folder, leaf, no_progress());
      if (!config.quiet)
        std::printf("wrote %s (%dx%d%s)\n", shown_text(out, 4096).c_str(), size.width, size.height,
                    shown_text(note, 300).c_str());
      std::fflush(stdout);
    } catch (const std::exception& e) {
      std::string message = error_line(e);
      // Every message names the file: the readers' say "cannot read 'FILE'", the rest get it here.
      if (message.rfind("cannot read '", 0) != 0 && message.find("no X display") == std::string::npos)
        message = "cannot preview '" + io::one_line(name) + "': " + message;
      std::fprintf(stderr, "selfsim preview: %s\n", message.c_str());
      code = 1;
      if (!display && message.find("X display") != std::string::npos) break;  // no display: no use going on
    }
  }
  return code;
}

}  // namespace selfsim::interp
