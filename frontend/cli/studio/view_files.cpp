#include "frontend/cli/studio/view_files.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <new>

#include "frontend/cli/sweep/sweep_plan.h"
#include "kernels/base/error.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/output_file.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/regular_file.h"
#include "kernels/io/text/json_text.h"
#include "kernels/io/vdb/vdb_read.h"
#include "kernels/io/view/geometry_payload.h"
#include "kernels/io/view/natural_field.h"
#include "kernels/io/view/series_file.h"
#include "kernels/io/view/up_axis.h"

namespace selfsim::interp {

namespace {

// One file of the output, opened below root (never through a link), with the reader `preview` uses.
io::Dataset read_below(const std::filesystem::path& root, const std::filesystem::path& rel, const RunConfig& limits) {
  const io::FileBeneath file(root, rel);
  if (lower_case(rel.extension().string()) == ".vdb") {
    io::VdbReadOptions read;
    read.shown_as = rel;
    read.budget.limit = limits.max_points;
    return io::read_vdb_surface(file.name(), read).mesh;
  }
  return io::read_dataset(file.name(), rel);
}

std::string bounds_json(const std::array<double, 6>& b) {
  std::string s;
  for (int j = 0; j < 6; ++j) s += (j ? ", " : "") + io::json_number(b[j]);
  return "[" + s + "]";
}

void widen(std::array<double, 6>& b, const io::Dataset& d) {
  for (const auto& p : d.points)
    for (int j = 0; j < 3; ++j)
      if (std::isfinite(p[j])) {
        b[2 * j] = std::min(b[2 * j], p[j]);
        b[2 * j + 1] = std::max(b[2 * j + 1], p[j]);
      }
}

}  // namespace

std::string view_folder(const std::string& file) { return ".studio/" + fitting_name("", file, ".3d"); }

void write_view(const std::filesystem::path& root, const std::string& file, const std::string& folder,
                const RunConfig& limits) {
  std::string index;
  try {
    // The steps, relative to root: the file itself, or each step its series names (read_series_steps refuses a
    // step outside the series' folder).
    std::vector<std::filesystem::path> steps{file};
    if (io::is_series_name(file)) {
      const io::FileBeneath series(root, file);  // the series file itself no link either
      steps.clear();
      const std::filesystem::path series_path = root / file;
      for (const std::filesystem::path& s : io::read_series_steps(series_path))  // each beside the series file
        steps.push_back(std::filesystem::path(file).parent_path() / s.lexically_relative(series_path.parent_path()));
    }
    // A series is read twice, so that only one step is held at a time: once for its one colouring and
    // camera, once for the payloads.
    std::vector<std::vector<io::FieldSummary>> summaries;
    std::array<double, 6> bounds{};
    for (int j = 0; j < 3; ++j) {
      bounds[2 * j] = std::numeric_limits<double>::infinity();
      bounds[2 * j + 1] = -std::numeric_limits<double>::infinity();
    }
    std::optional<io::Dataset> only;
    int up = 1;
    bool own = false;  // the last step's own colours, drawn as they are (as the preview draws them)
    std::size_t most_segments = 0;
    for (const std::filesystem::path& s : steps) {
      io::Dataset d = read_below(root, s, limits);
      summaries.push_back(io::summarise(d));
      most_segments = std::max(most_segments, io::line_segments(d));
      widen(bounds, d);
      if (&s == &steps.back()) {  // the grown result's up and colours, as the preview takes them
        up = io::up_axis(d, s.string());
        own = io::has_own_colours(d);
      }
      if (steps.size() == 1) only = std::move(d);
    }
    const io::Colouring colouring = own ? io::Colouring{} : io::summaries_colouring(summaries);
    // A curve's widths as tubes, as the preview draws them: the widest over every step 1.2% of the union's
    // diagonal across.
    io::TubeWidths widths;
    for (const auto& step : summaries)
      for (const io::FieldSummary& f : step)
        if (f.name == "width" && f.on_points && f.components == 1)
          widths.max_width = std::max({widths.max_width, std::abs(f.min), std::abs(f.max)});
    double diagonal = 0;
    for (int j = 0; j < 3; ++j)
      if (bounds[2 * j + 1] > bounds[2 * j]) diagonal += std::pow(bounds[2 * j + 1] - bounds[2 * j], 2);
    widths.diagonal = diagonal > 0 ? std::sqrt(diagonal) : 1;
    // Tubes for every step or for none: a growth that turned from tubes to lines halfway would not read as one.
    if (most_segments > io::max_tube_segments) widths.diagonal = 0;
    std::string names, urls;
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const io::Dataset d = only ? std::move(*only) : read_below(root, steps[i], limits);
      try {
        io::write_whole(root, folder + "/" + std::to_string(i) + ".bin",
                        io::geometry_payload(d, colouring, view_max_bytes, widths));
      } catch (const std::bad_alloc&) {
        throw;
      } catch (const Error& e) {
        throw Error("cannot show '" + io::one_line(steps[i].string()) + "' in 3D: " + e.what());
      }
      urls += std::string(i ? ", " : "") + "\"" + std::to_string(i) + ".bin\"";
      names += std::string(i ? ", " : "") + io::json_string(steps[i].string());
    }
    index = "{\"steps\": [" + urls + "], \"names\": [" + names + "], \"bounds\": " + bounds_json(bounds) +
            ", \"up\": " + std::to_string(up) + ", \"legend\": " + io::colouring_json(colouring, own) + "}\n";
  } catch (const std::bad_alloc&) {
    index = "{\"error\": " +
            io::json_string("'" + io::one_line(file) + "' needs more memory for its 3D view than --max-memory allows") +
            "}\n";
  } catch (const Error& e) {
    // A reader or VTK meeting the limit says "out of memory" or "Unable to allocate" without naming it.
    std::string why = io::one_line(e.what());
    if (why.find("out of memory") != std::string::npos || why.find("nable to allocate") != std::string::npos)
      why += " (perhaps --max-memory is too little)";
    index = "{\"error\": " + io::json_string(why) + "}\n";
  }
  io::write_whole(root, folder + "/index.json", index);
}

ViewChild::ViewChild(const RunConfig& limits, const std::filesystem::path& root,
                     const std::vector<std::string>& files) {
  const pid_t parent = ::getpid();
  std::uint64_t held = 0;  // what this process maps now: the --max-memory allowance is added to it
  {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
      if (line.starts_with("VmData:")) held = std::strtoull(line.c_str() + 7, nullptr, 10) * 1024;
  }
  pid_ = ::fork();
  if (pid_ < 0) throw Error("cannot start the 3D views' process");
  if (pid_ == 0) {
    // The child: nothing of the studio's (its sockets, its watcher) stays open here, its signals end it
    // (SIGTERM: a view is whole or not there, the confined writer's temporaries being anonymous), and it
    // ends with the studio. Nothing it does may return into the studio's loop: it leaves by _Exit alone.
    ::syscall(SYS_close_range, 3u, ~0u, 0u);
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGALRM}) ::signal(sig, SIG_DFL);
    sigset_t all;
    sigemptyset(&all);
    ::sigprocmask(SIG_SETMASK, &all, nullptr);
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != parent) std::_Exit(1);
    const double memory = limits.max_memory > 0 ? limits.max_memory : default_max_memory();
    if (rlimit data{}; held > 0 && ::getrlimit(RLIMIT_DATA, &data) == 0) {
      data.rlim_cur = std::min<rlim_t>(data.rlim_max, static_cast<rlim_t>(static_cast<double>(held) + memory));
      ::setrlimit(RLIMIT_DATA, &data);
    }
    if (limits.timeout > 0)
      ::alarm(static_cast<unsigned>(std::min(4e9, std::ceil(limits.timeout * static_cast<double>(files.size())))));
    // The last run's indexes go first: a view this child does not finish (stopped by the next run, out of
    // time) is then no view, shown as its PNG, never the last run's view under this run's name. Its steps go
    // too (N.bin): a series that grew shorter would leave its old last steps behind.
    const auto last_runs = [](const std::string& name) {
      return name == "index.json" ||
             (name.size() > 4 && name.ends_with(".bin") && name.find_first_not_of("0123456789") == name.size() - 4);
    };
    for (const std::string& f : files) try {
        io::remove_files(root, view_folder(f), last_runs);
      } catch (const Error&) {
      }
    int code = 0;
    for (const std::string& f : files) try {
        write_view(root, f, view_folder(f), limits);
      } catch (...) {  // the index itself could not be written: the page shows the PNG
        code = 1;
      }
    std::_Exit(code);
  }
  pidfd_ = static_cast<int>(::syscall(SYS_pidfd_open, pid_, 0));
}

ViewChild::~ViewChild() {
  if (pid_ > 0) {
    ::kill(pid_, SIGTERM);
    ::kill(pid_, SIGCONT);  // a stopped child would hold SIGTERM, and this wait, forever
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  }
  if (pidfd_ >= 0) ::close(pidfd_);
}

bool ViewChild::finished() {
  if (pid_ <= 0) return true;
  int status = 0;
  if (::waitpid(pid_, &status, WNOHANG) != pid_) return false;
  pid_ = -1;
  if (pidfd_ >= 0) ::close(pidfd_);
  pidfd_ = -1;
  return true;
}

}  // namespace selfsim::interp
