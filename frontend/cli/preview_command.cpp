// `selfsim preview FILE... [-o DIR]`: a PNG of each geometry file (any that selfsim writes or reads), for
// a look without ParaView. Files are read with the readers `info` and `diff` use (a .vdb as its surface,
// vdb_read.h), rendered by VTK (preview_png.h) on the user's X display or an Xvfb of our own
// (display_server.h), and written atomically as NAME.png beside the input, or into DIR with -o, through the
// one confined writer (output_file.h) like every file selfsim writes. A series (.pvd, .series) is read whole
// and drawn as its last step in the camera and colours of all its steps; --steps adds NAME.steps.png (the
// filmstrip) and NAME.apng (the frames through apng.h), written before NAME.png.
// Limits as a run's: --max-memory bounds the memory it may add (RLIMIT_DATA, which the renderer's forked
// child inherits), --timeout ends it with one line; PNGs are anonymous files until whole, so a preview
// stopped anywhere (the limits, Ctrl-C, SIGTERM, SIGKILL) leaves no partial file. The studio and sweeps
// run it as a child process (preview_child.h).
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <set>
#include <thread>

#include "frontend/cli/commands.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/run_context.h"
#include "frontend/process/display_server.h"
#include "frontend/process/spawn_selfsim.h"
#include "kernels/base/error.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/output_file.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/vdb/vdb_read.h"
#include "kernels/io/view/apng.h"
#include "kernels/io/view/preview_png.h"
#include "kernels/io/view/series_file.h"
#include "kernels/io/view/up_axis.h"

namespace selfsim::interp {

namespace {

const char* const formats = ".vtp, .vtu, .svg, .stl, .obj, .ply, .3mf, .vdb, .pvd or .series";

bool known(const std::string& ext) {
  for (const char* e : {".vtp", ".vtu", ".svg", ".stl", ".obj", ".ply", ".3mf", ".vdb"})
    if (ext == e) return true;
  return false;
}

std::string error_line(const std::exception& e) {
  std::string m = e.what();
  for (char& c : m)
    if (c == '\n' || c == '\r') c = ' ';
  return m;
}

// Private writable memory this process maps now (VmData), the base the --max-memory allowance is added to.
std::uint64_t data_bytes() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.starts_with("VmData:")) return std::strtoull(line.c_str() + 7, nullptr, 10) * 1024;
  return 0;
}

// Ends the process at the deadline with one line: a read or a render that takes longer polls nothing.
// The renderer's child and Xvfb die with this process (PR_SET_PDEATHSIG); a named temporary is removed.
class PreviewTimer {
 public:
  explicit PreviewTimer(double seconds) {
    if (seconds <= 0) return;
    thread_ = std::thread([this, seconds] {
      std::unique_lock lock(mutex_);
      if (wake_.wait_for(lock, std::chrono::duration<double>(seconds), [this] { return done_; })) return;
      char line[160];
      const int n = std::snprintf(
          line, sizeof line, "selfsim preview: --timeout of %g s reached (the PNGs already written stay)\n", seconds);
      [[maybe_unused]] const auto w = ::write(2, line, static_cast<std::size_t>(std::max(0, n)));
      io::remove_temporaries();
      std::_Exit(1);
    });
  }
  ~PreviewTimer() {
    if (!thread_.joinable()) return;
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  PreviewTimer(const PreviewTimer&) = delete;
  PreviewTimer& operator=(const PreviewTimer&) = delete;

 private:
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  std::thread thread_;
};

// A PNG's width and height, from its header.
struct PngSize {
  int width = 0, height = 0;
};
PngSize png_size(const std::string& png) {
  if (png.size() < 24) return {};
  auto at = [&](std::size_t i) {
    return static_cast<int>((static_cast<unsigned char>(png[i]) << 24) |
                            (static_cast<unsigned char>(png[i + 1]) << 16) |
                            (static_cast<unsigned char>(png[i + 2]) << 8) | static_cast<unsigned char>(png[i + 3]));
  };
  return {at(16), at(20)};
}

// How long each frame of an animation shows: half a second, a growth of many steps a little faster, so that
// it plays through in about 10 s.
double frame_seconds(std::size_t frames) {
  return std::clamp(10.0 / static_cast<double>(std::max<std::size_t>(frames, 1)), 0.1, 0.5);
}

// NAME of the still NAME.png (a name given by --as without .png is NAME itself): its filmstrip and animation
// are NAME.steps.png and NAME.apng.
std::string still_base(const std::string& leaf) {
  return leaf.size() > 4 && lower_case(leaf.substr(leaf.size() - 4)) == ".png" ? leaf.substr(0, leaf.size() - 4) : leaf;
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
    } else if (options && a == "--timeout") {
      if (i + 1 >= args.size()) throw UsageError("--timeout expects seconds");
      c.timeout = number_argument(a, args[++i], 0, 1e9);
    } else if (options && a == "--max-memory") {
      if (i + 1 >= args.size()) throw UsageError("--max-memory expects a size");
      c.max_memory = size_argument(a, args[++i]);
    } else if (options && a == "--max-points") {  // a .vdb's tiles are weighed against it, as in a run
      if (i + 1 >= args.size()) throw UsageError("--max-points expects a number");
      c.max_points = std::floor(number_argument(a, args[++i], 1, highest_max_points));
    } else if (options && a == "--field") {
      if (i + 1 >= args.size() || args[i + 1].empty()) throw UsageError("--field expects a field's name");
      c.field = args[++i];
    } else if (options && a == "--up") {
      if (i + 1 >= args.size() || io::axis_from_name(args[i + 1]) < 0)
        throw UsageError("--up expects x, y or z" +
                         (i + 1 < args.size() ? ", got '" + args[i + 1] + "'" : std::string()));
      c.up = io::axis_from_name(args[++i]);
    } else if (options && a == "--steps") {
      c.steps = true;
    } else if (options && a == "--as") {
      // --as NAME FILE: FILE's PNG is DIR/NAME (folders in NAME made inside DIR, never through a link).
      if (i + 2 >= args.size() || args[i + 1].empty()) throw UsageError("--as expects a PNG name and a file");
      c.names.resize(c.files.size());
      c.names.push_back(args[++i]);
      c.files.push_back(args[++i]);
    } else if (options && a.size() > 1 && a[0] == '-') {
      throw UsageError("unknown preview option '" + a + "'");
    } else {
      c.files.push_back(a);
    }
  }
  if (c.files.empty()) throw UsageError("preview expects one or more files");
  if (!c.names.empty()) c.names.resize(c.files.size());
  return c;
}

int preview_command(const PreviewConfig& config) {
  stop_with_parent();  // started by the studio or a sweep: ends with it
  const double max_memory = config.max_memory > 0 ? config.max_memory : default_max_memory();
  if (const std::uint64_t base = data_bytes(); base > 0) {
    // The soft limit only: Xvfb, which this process may start, lifts it for itself (display_server.cpp).
    if (rlimit data{}; ::getrlimit(RLIMIT_DATA, &data) == 0) {
      data.rlim_cur = std::min<rlim_t>(data.rlim_max, static_cast<rlim_t>(base + max_memory));
      ::setrlimit(RLIMIT_DATA, &data);
    }
  }
  const PreviewTimer timer(config.timeout);
  std::unique_ptr<DisplayServer> display;  // started at the first file that reads
  std::set<std::string> written;
  int code = 0;
  for (const std::string& name : config.files) {
    const std::filesystem::path file(name);
    try {
      // A time series is drawn as its last step, the grown result, in the camera and colours of all its steps.
      const bool series = io::is_series_name(name);
      std::string stem = file.stem().string(), title = file.filename().string(), note;
      std::vector<std::filesystem::path> sources{file};
      if (series) {
        sources = io::read_series_steps(file);
        // growth.vtp.series draws growth.png, as growth.pvd does.
        for (const char* inner : {".vtp", ".vtu"})
          if (stem.size() > 4 && lower_case(stem.substr(stem.size() - 4)) == inner) stem.erase(stem.size() - 4);
        title += " (last of " + std::to_string(sources.size()) + " steps)";
        note = ", the last of " + std::to_string(sources.size()) + " steps";
      }
      std::vector<io::Dataset> steps;
      for (const std::filesystem::path& source : sources) {
        const std::string ext = lower_case(source.extension().string());
        if (!known(ext)) throw Error(io::cannot_read(source, std::string("expected a ") + formats + " file"));
        if (ext == ".vdb") {
          io::VdbReadOptions read;
          read.budget.limit = config.max_points;
          io::VdbSurface s = io::read_vdb_surface(source, read);
          steps.push_back(std::move(s.mesh));
          note = ", " + s.what;
        } else {
          steps.push_back(io::read_dataset(source));
        }
      }
      if (!display) display = std::make_unique<DisplayServer>();
      // NAME.png beside the input (its folder the root) or in DIR, or DIR/NAME given by --as.
      const std::size_t at = static_cast<std::size_t>(&name - config.files.data());
      const std::filesystem::path root = !config.out_dir.empty()      ? std::filesystem::path(config.out_dir)
                                         : file.parent_path().empty() ? std::filesystem::path(".")
                                                                      : file.parent_path();
      const bool named = at < config.names.size() && !config.names[at].empty();
      const bool filmed = config.steps && series;  // a single file has no steps to film: its PNG alone
      // The files a still named `leaf` comes with: with --steps, NAME.steps.png and NAME.apng beside NAME.png.
      auto names_with = [&](const std::string& still) {
        std::vector<std::string> names{still};
        if (filmed) {
          const std::string b = still_base(still);
          names.push_back(b + ".steps.png");
          names.push_back(b + ".apng");
        }
        return names;
      };
      auto taken = [&](const std::string& still) {
        for (const std::string& n : names_with(still))
          if (written.contains((root / n).lexically_normal().string())) return true;
        return false;
      };
      std::string leaf = named ? config.names[at] : stem + ".png";
      // A later input whose PNG, filmstrip or animation would take a name this run wrote (growth.steps.vtp's
      // PNG is growth.pvd's filmstrip) gets NAME_EXT.png, then NAME_EXT_2.png, ...
      if (!named && taken(leaf)) {
        const std::string base = stem + "_" + lower_case(file.extension().string()).substr(1);
        leaf = base + ".png";
        for (int n = 2; taken(leaf); ++n) leaf = base + "_" + std::to_string(n) + ".png";
      }
      for (const std::string& n : names_with(leaf)) written.insert((root / n).lexically_normal().string());
      io::PreviewOptions options;
      options.field = config.field;
      options.up = config.up;
      options.steps = filmed;
      options.name = file.filename().string();
      // "step 3 of 10", and the series' own time of the step where it gives one ("step 3 of 10, t = 2").
      const std::vector<double> times = series ? io::read_series_times(file) : std::vector<double>{};
      for (std::size_t k = 0; k < steps.size(); ++k) {
        std::string label = "step " + std::to_string(k + 1) + " of " + std::to_string(steps.size());
        if (times.size() == steps.size()) {
          char t[40];
          std::snprintf(t, sizeof t, ", t = %.6g", times[k]);
          label += t;
        }
        options.labels.push_back(label);
      }
      const io::PreviewPictures pictures = io::render_preview(steps, title, options, no_progress());
      // With --steps: NAME.steps.png (the filmstrip) and NAME.apng (the animation) beside NAME.png, written
      // before it, so that the still appearing says the others are there.
      const std::string base = still_base(leaf);
      std::vector<std::pair<std::string, const std::string*>> files;
      std::string animation;
      if (options.steps) {
        std::vector<io::ApngFrame> frames;
        for (const std::string& png : pictures.frames) frames.push_back({png, frame_seconds(pictures.frames.size())});
        animation = io::animated_png(frames);
        files.emplace_back(base + ".steps.png", &pictures.filmstrip);
        files.emplace_back(base + ".apng", &animation);
      }
      files.emplace_back(leaf, &pictures.still);
      // The three are one result: a folder in the way of the last is found before the first is written,
      // not after it (a filmstrip left without its still and animation).
      for (const auto& [leaf_name, bytes] : files)
        if (std::error_code ec; std::filesystem::is_directory(std::filesystem::symlink_status(root / leaf_name, ec)))
          throw Error("cannot write '" + (root / leaf_name).string() + "': a folder of that name is in the way");
      for (const auto& [leaf_name, bytes] : files) {
        io::OutputFile out_file(root, leaf_name);  // every folder of the name opened below root, never through a link
        out_file.write(*bytes);
        out_file.commit();
        if (!config.quiet) {
          const PngSize size = png_size(*bytes);
          std::printf(
              "wrote %s (%dx%d%s)\n", shown_text(out_file.path(), 4096).c_str(), size.width, size.height,
              shown_text(leaf_name == leaf              ? note
                         : leaf_name.ends_with(".apng") ? ", " + std::to_string(pictures.frames.size()) + " frames"
                                                        : ", " + std::to_string(steps.size()) + " steps",
                         300)
                  .c_str());
        }
      }
      std::fflush(stdout);
    } catch (const std::exception& e) {
      std::string message = error_line(e);
      if (dynamic_cast<const std::bad_alloc*>(&e) != nullptr)
        message = "it needs more memory than --max-memory allows (" +
                  std::to_string(static_cast<long long>(max_memory / (1 << 20))) + " MiB)";
      // Every message names the file: the readers' say "cannot read 'FILE'", the rest get it here.
      if (message.rfind("cannot read '", 0) != 0 && message.find("no X display") == std::string::npos)
        message = "cannot preview '" + io::one_line(name) + "': " + message;
      // OpenGL drivers meet an allocation failure with a crash or a failed context, not a message; VTK's own
      // say "out of memory" or "Unable to allocate" without naming the limit that caused them.
      if (config.max_memory > 0 &&
          (message.find("crashed") != std::string::npos || message.find("OpenGL context") != std::string::npos ||
           message.find("out of memory") != std::string::npos ||
           message.find("nable to allocate") != std::string::npos))
        message += " (perhaps --max-memory " + std::to_string(static_cast<long long>(max_memory / (1 << 20))) +
                   "M is too little)";
      std::fprintf(stderr, "selfsim preview: %s\n", message.c_str());
      code = 1;
      if (!display && message.find("X display") != std::string::npos) break;  // no display: no use going on
    }
  }
  return code;
}

}  // namespace selfsim::interp
