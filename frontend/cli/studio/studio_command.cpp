// `selfsim studio RECIPE.lua [--port N]`: a page on http://127.0.0.1:N/ with a control per annotated
// parameter (param_spec.h), the run's outputs drawn (SVGs as they are, 3D results as a view to orbit,
// drawn by three.js from view_files.h's payloads, and as `selfsim preview` PNGs where the browser has no
// WebGL or three.js is not installed), re-running when a control moves (the run going is stopped) or the recipe is
// saved. The runs are live_run.h's, into the same output folder `run` writes: a failed run shows its error line in the
// page and leaves the last good files and pictures. One loop polls the socket, the file watcher and the run: no
// threads, no state shared between them.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <set>

#include "frontend/cli/commands.h"
#include "frontend/cli/preview_child.h"
#include "frontend/cli/studio/http_server.h"
#include "frontend/cli/studio/three_files.h"
#include "frontend/cli/studio/view_files.h"
#include "frontend/cli/sweep/sweep_plan.h"
#include "frontend/cli/watch/file_watcher.h"
#include "frontend/cli/watch/live_run.h"
#include "frontend/lua/lua_support.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/output_file.h"
#include "kernels/io/text/json_text.h"
#include "kernels/io/text/url_path.h"

namespace selfsim::interp {

namespace {

extern "C" void on_studio_signal(int) { interrupted.store(true); }

const char* const previews_folder = ".studio";

// The preview of the output `f` in .studio/: f.png, shortened as a sweep's names are when that would pass the
// 255-byte limit on a name (an output may use all 255 bytes itself).
std::string preview_png(const std::string& f) {
  return std::string(previews_folder) + "/" + fitting_name("", f, ".png");
}

bool previewable(const std::string& leaf) {
  const std::string ext = lower_case(std::filesystem::path(leaf).extension().string());
  for (const char* e : {".vtp", ".vtu", ".stl", ".obj", ".ply", ".3mf", ".vdb", ".pvd", ".series"})
    if (ext == e) return true;
  return false;
}

std::string file_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string content_type(const std::string& leaf) {
  const std::string ext = lower_case(std::filesystem::path(leaf).extension().string());
  if (ext == ".svg") return "image/svg+xml";
  if (ext == ".png") return "image/png";
  if (ext == ".json" || ext == ".series") return "application/json";
  if (ext == ".html") return "text/html; charset=utf-8";
  return "application/octet-stream";
}

// The page's view of the studio: what runs, what the last good run wrote, the last error.
struct Studio {
  RunConfig base;
  ParamsRead params;
  int params_version = 1;
  std::map<std::string, std::string> values;  // the --set values of the next run
  long generation = 0, shown_generation = 0, error_generation = 0;
  bool running = false;
  double seconds = 0;
  std::vector<std::string> files;  // of the last good run
  std::string error;               // of the last failed run (or recipe), empty after a good one

  std::string params_json_text() const {
    std::string v;
    for (const auto& [k, x] : values) v += (v.empty() ? "" : ", ") + io::json_string(k) + ": " + io::json_string(x);
    return "{\"recipe\": " + io::json_string(base.recipe.string()) +
           ", \"version\": " + std::to_string(params_version) +
           ", \"stopped_at\": " + io::json_string(params.stopped_at) + ", \"values\": {" + v +
           "}, \"parameters\": " + params_json(params.specs) + "}\n";
  }

  long version = 0;  // counts every change the page would show: /state?since=V waits for the next

  std::string state_json() const {
    std::string list;
    std::error_code ec;
    // A result that is also an SVG is drawn once, as the SVG: the page says so beside it.
    std::map<std::string, std::string> svgs;  // stem -> the SVG's name
    for (const std::string& f : files)
      if (lower_case(std::filesystem::path(f).extension().string()) == ".svg")
        svgs.emplace(std::filesystem::path(f).stem().string(), f);
    for (const std::string& f : files) {
      if (f.ends_with(".stl.json") || f.ends_with(".vdb.json")) continue;  // provenance beside a file
      std::string image = "null";
      if (lower_case(std::filesystem::path(f).extension().string()) == ".svg")
        image = io::json_string("/out/" + io::url_path(f) + "?g=" + std::to_string(shown_generation));
      else if (std::filesystem::is_regular_file(base.out_dir / preview_png(f), ec))
        image = io::json_string("/out/" + io::url_path(preview_png(f)) + "?g=" + std::to_string(shown_generation));
      // The 3D view's folder, once its index is there (the page reads index.json, then the steps).
      std::string view = "null";
      if (previewable(f) && std::filesystem::is_regular_file(base.out_dir / view_folder(f) / "index.json", ec))
        view = io::json_string("/out/" + io::url_path(view_folder(f)) + "/");
      std::string drawn_as = "null";
      if (const auto svg = svgs.find(std::filesystem::path(f).stem().string()); previewable(f) && svg != svgs.end())
        drawn_as = io::json_string(svg->second);
      list += std::string(list.empty() ? "" : ", ") + "{\"name\": " + io::json_string(f) +
              ", \"url\": " + io::json_string("/out/" + io::url_path(f)) + ", \"image\": " + image +
              ", \"view\": " + view + ", \"drawn_as\": " + drawn_as + "}";
    }
    return "{\"version\": " + std::to_string(version) + ", \"generation\": " + std::to_string(generation) +
           ", \"running\": " + (running ? "true" : "false") +
           ", \"params_version\": " + std::to_string(params_version) +
           ", \"shown\": " + std::to_string(shown_generation) + ", \"seconds\": " + io::json_number(seconds) +
           ", \"error\": " + io::json_string(error) + ", \"error_generation\": " + std::to_string(error_generation) +
           ", \"files\": [" + list + "]}\n";
  }

  // Throws Error naming the first value that is no parameter or outside its range or choices.
  void check(const std::map<std::string, std::string>& given) const {
    for (const auto& [key, value] : given) {
      const auto spec = std::find_if(params.specs.begin(), params.specs.end(),
                                     [&k = key](const ParamSpec& p) { return p.name == k; });
      if (spec == params.specs.end()) throw Error("the recipe has no parameter '" + key + "'");
      check_param_value(*spec, value);
    }
  }
};

// A file of the output folder, by its path below /out/: opened one component at a time below the folder,
// never through a link (O_NOFOLLOW at each step, so a link swapped in meanwhile is refused too), never
// '..', and only a regular file with one name (a hard link could name a file from anywhere).
void serve_output(HttpServer& http, HttpServer::Id id, const Studio& s, const std::string& rel) {
  const std::filesystem::path p(rel);
  bool ok = !rel.empty() && p.is_relative() && rel.find('\\') == std::string::npos;
  int dir = ::open(s.base.out_dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  std::vector<std::string> parts;
  for (const auto& part : p) parts.push_back(part.string());
  for (std::size_t i = 0; ok && dir >= 0 && i < parts.size(); ++i) {
    ok = parts[i] != ".." && parts[i] != "." && !parts[i].empty();
    if (!ok) break;
    const bool last = i + 1 == parts.size();
    const int next = ::openat(dir, parts[i].c_str(),
                              (last ? O_RDONLY : O_RDONLY | O_DIRECTORY) | O_NOFOLLOW | O_CLOEXEC |
                                  (last ? O_NONBLOCK : 0));  // a FIFO must not block
    ::close(dir);
    dir = next;
  }
  struct stat st {};
  ok = ok && dir >= 0 && ::fstat(dir, &st) == 0 && S_ISREG(st.st_mode) && st.st_nlink == 1 &&
       st.st_size <= (std::int64_t{1} << 30);
  if (!ok) {
    if (dir >= 0) ::close(dir);
    return http.respond(id, 404, "text/plain", "no such file\n");
  }
  // Sent from the open file as the client takes it: a large file held in memory, or a slow client
  // holding the loop, is what this avoids.
  http.respond_file(id, content_type(rel), dir, st.st_size);
}

// A file of the three.js package, by its address on three_files.h's list: any other address is not found.
void serve_three(HttpServer& http, HttpServer::Id id, const std::string& path) {
  const std::optional<std::filesystem::path> file = three_file(path);
  if (!file) return http.respond(id, 404, "text/plain", "not found\n");
  const int fd = ::open(file->c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK);
  struct stat st {};
  if (fd < 0 || ::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_size > (std::int64_t{64} << 20)) {
    if (fd >= 0) ::close(fd);
    return http.respond(id, 404, "text/plain", three_missing);
  }
  http.respond_file(id, "text/javascript; charset=utf-8", fd, st.st_size);
}

}  // namespace

int studio_command(const RunConfig& config, int port) {
  if (!std::filesystem::is_regular_file(config.recipe))
    throw UsageError("cannot open recipe '" + config.recipe.string() + "'");
  struct sigaction sa {};
  sa.sa_handler = on_studio_signal;  // no SA_RESTART: poll returns at Ctrl-C
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &sa, nullptr);
  Studio s;
  s.base = config;
  s.values = config.sets;
  s.params = read_params(config);
  s.check(s.values);
  FileWatcher watcher(recipe_folders(config, "studio"), config.out_dir);
  watcher.follow(config.recipe);  // the recipe may become a link (or point elsewhere) while watched
  LiveRun live(config, true);
  // The previews' folder: a link there is refused now, as the confined writer refuses it at every write.
  io::make_folder(config.out_dir, previews_folder);
  std::unique_ptr<PreviewBatches> drawing;  // the previews of `drawn`, the last good run, being drawn
  std::unique_ptr<ViewChild> viewing;       // and its 3D views being made
  LiveResult drawn;
  HttpServer http(port);
  const char* scripts = std::getenv("SELFSIM_SCRIPTS");
  const std::filesystem::path page = std::filesystem::path(scripts ? scripts : SELFSIM_SCRIPTS_DIR) / "studio.html";
  std::printf("studio: http://127.0.0.1:%d/ for %s; outputs in %s (Ctrl-C to stop)\n", http.port(),
              shown_text(config.recipe.string()).c_str(), shown_text(config.out_dir.string()).c_str());
  std::fflush(stdout);

  // A good run is shown once its previews are drawn (or could not be, or were stopped by the next run).
  const auto show = [&](const LiveResult& r) {
    s.running = false;
    ++s.version;
    s.files = r.files;
    s.seconds = r.seconds;
    s.shown_generation = s.generation;
    s.error.clear();
  };
  auto start = [&] {
    if (drawing || viewing) {  // the previews of the run before: stopped, its files shown as they are
      drawing.reset();
      viewing.reset();
      show(drawn);
    }
    ++s.generation;
    ++s.version;
    s.running = false;
    live.start(s.values);  // throws when the output folder cannot be written: the run never started
    s.running = true;
  };
  start();
  std::vector<std::pair<HttpServer::Id, std::chrono::steady_clock::time_point>> parked;  // long polls waiting
  long answered = s.version;
  // One request: its answer, or its connection parked as a long poll.
  auto answer = [&](const HttpServer::Id id, const bool local, const HttpRequest& q) {
    const std::string port_text = std::to_string(http.port());
    // Only this machine, by its own names: a page elsewhere cannot reach in through DNS rebinding, nor
    // make the browser send a request for it (an <img> on another site: its Origin or Sec-Fetch-Site).
    const std::string ours = "127.0.0.1:" + port_text, also = "localhost:" + port_text;
    const bool foreign = (!q.origin.empty() && q.origin != "http://" + ours && q.origin != "http://" + also) ||
                         q.fetch_site == "cross-site" || q.fetch_site == "same-site";
    if (!local || (q.host != ours && q.host != also) || foreign) {
      http.respond(id, 403, "text/plain", "the studio answers only to its own page at http://" + ours + "/\n");
    } else if (q.method != "GET") {
      http.respond(id, 405, "text/plain", "GET only\n");
    } else if (q.path == "/") {
      http.respond(id, 200, "text/html; charset=utf-8", file_text(page));
    } else if (q.path == "/params") {
      http.respond(id, 200, "application/json", s.params_json_text());
    } else if (q.path == "/state") {
      // A long poll: /state?since=V answers when the state is no longer version V (or after 20 s), so the
      // page hears of a finished run at once without asking again and again.
      const auto since = query_values(q.query);
      if (since && since->contains("since") && since->at("since") == std::to_string(s.version) && parked.size() < 32)
        parked.push_back({id, std::chrono::steady_clock::now() + std::chrono::seconds(20)});
      else
        http.respond(id, 200, "application/json", s.state_json());
    } else if (q.path == "/run") {
      try {
        const auto given = query_values(q.query);
        if (!given) throw Error("a value that does not decode");
        s.check(*given);
        for (const auto& [k, v] : *given) s.values[k] = v;
        start();
        http.respond(id, 200, "application/json", "{\"generation\": " + std::to_string(s.generation) + "}\n");
      } catch (const Error& e) {
        http.respond(id, 400, "application/json", "{\"error\": " + io::json_string(e.what()) + "}\n");
      }
    } else if (q.path.starts_with("/three/")) {
      serve_three(http, id, q.path);
    } else if (q.path.starts_with("/out/")) {
      serve_output(http, id, s, q.path.substr(5));
    } else {
      http.respond(id, 404, "text/plain", "not found\n");
    }
  };
  while (!interrupted.load()) {
    std::vector<pollfd> p{{watcher.fd(), POLLIN, 0},
                          {live.fd(), POLLIN, 0},
                          {drawing ? drawing->fd() : -1, POLLIN, 0},
                          {viewing ? viewing->fd() : -1, POLLIN, 0}};
    http.add_poll(p);  // its socket and every connection's after these, none waiting on another
    if (::poll(p.data(), p.size(), 250) < 0) continue;
    if (LiveResult r; live.finished(r)) {
      if (r.code == 0) {
        // 3D results as `selfsim preview` draws them, into the output folder's .studio/, by a child process
        // under the run's limits: the loop goes on answering meanwhile (preview_child.h).
        // A result that is also an SVG (curve.svg beside curve.vtp) is shown once, as the SVG.
        std::set<std::string> svgs;
        for (const std::string& f : r.files)
          if (lower_case(std::filesystem::path(f).extension().string()) == ".svg")
            svgs.insert(std::filesystem::path(f).stem().string());
        std::vector<std::string> files, names, views;
        for (const std::string& f : r.files)
          if (previewable(f) && !svgs.contains(std::filesystem::path(f).stem().string())) {
            files.push_back((config.out_dir / f).string());
            names.push_back(preview_png(f));
            views.push_back(f);
          }
        if (!files.empty()) drawing = std::make_unique<PreviewBatches>(config, config.out_dir, files, names);
        if (drawing && drawing->finished()) drawing.reset();  // no batch could start (each warned about)
        // The 3D views beside the PNGs, at the same time: the page shows both once both are made.
        if (!views.empty()) try {
            viewing = std::make_unique<ViewChild>(config, config.out_dir, views);
          } catch (const Error& e) {
            std::fprintf(stderr, "selfsim: warning: no 3D views: %s\n", e.what());
          }
        if (drawing || viewing)
          drawn = r;
        else
          show(r);
      } else {
        s.running = false;
        ++s.version;
        s.error = r.log.substr(0, r.log.find('\n'));
        if (s.error.empty()) s.error = "the run failed (exit " + std::to_string(r.code) + ")";
        s.error_generation = s.generation;
      }
    }
    if ((drawing || viewing) && (!drawing || drawing->finished()) && (!viewing || viewing->finished())) {
      drawing.reset();
      viewing.reset();
      show(drawn);
    }
    const bool back = watcher.restore();  // a folder deleted and brought back (git checkout)
    if ((p[0].revents & POLLIN) || back) {
      if (const std::string changed = back ? "(a folder, back)" : watcher.take(); !changed.empty()) {
        try {  // the recipe may now declare other parameters
          s.params = read_params(s.base);
          ++s.params_version;
          std::map<std::string, std::string> kept;
          for (const auto& [k, v] : s.values) try {
              s.check({{k, v}});
              kept[k] = v;
            } catch (const Error&) {
            }
          s.values = kept;
          start();
        } catch (const Error& e) {
          s.error = e.what();
          s.error_generation = ++s.generation;
          ++s.version;
        }
      }
    }
    for (const HttpServer::Incoming& in : http.step(p)) answer(in.id, in.local, in.request);
    const auto now = std::chrono::steady_clock::now();
    // Answer the parked long polls when the state changed, or when they have waited long enough.
    for (auto it = parked.begin(); it != parked.end();)
      if (s.version != answered || it->second <= now) {
        http.respond(it->first, 200, "application/json", s.state_json());
        it = parked.erase(it);
      } else {
        ++it;
      }
    answered = s.version;
  }
  return 130;
}

}  // namespace selfsim::interp
