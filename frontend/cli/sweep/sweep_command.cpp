// `selfsim run RECIPE --set level=4..10 [--jobs N]` and `selfsim sweep`: one `selfsim run` per combination
// of the --set values (sweep_plan.h), each a child process writing into its own folder, N at a time; then
// the contact sheets and ParaView series (sweep_collect.cpp). Child processes rather than threads: a run
// that fails, runs out of memory or is killed takes nothing else down, and a run here is byte for byte the
// run a job list sends to GNU parallel or Slurm.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <thread>

#include "frontend/cli/commands.h"
#include "frontend/cli/sweep/sweep.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/process/spawn_selfsim.h"
#include "kernels/io/output_file.h"
#include "kernels/io/text/json_text.h"

namespace selfsim::interp {

namespace {

extern "C" void on_sweep_signal(int) { interrupted.store(true); }

// Ctrl-C, SIGTERM and SIGHUP set `interrupted`: the runs and the preview children are stopped cleanly and
// the sweep ends with 130 (also under --collect, whose preview child would otherwise be left to finish).
void catch_stop_signals() {
  struct sigaction sa {};
  sa.sa_handler = on_sweep_signal;  // no SA_RESTART: waitpid returns at Ctrl-C
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) sigaction(sig, &sa, nullptr);
}

// "exit 1", or "killed by signal 9 (Killed)" for a run a signal ended.
std::string exit_text(int code) {
  if (code <= 128) return "exit " + std::to_string(code);
  return "killed by signal " + std::to_string(code - 128) + " (" + strsignal(code - 128) + ")";
}

// The first line of a failed run's log: its error.
std::string first_line(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line;
  std::getline(in, line);
  return shown_text(line, 300);
}

// sweep.json: what the sweep ran, for people and tools; the sweep itself never reads it back.
std::string manifest(const SweepConfig& c, const SweepPlan& plan) {
  std::string s =
      "{\n  \"recipe\": " + io::json_string(std::filesystem::absolute(c.run.recipe).string()) + ",\n  \"keys\": [";
  for (std::size_t k = 0; k < plan.keys.size(); ++k) s += (k ? ", " : "") + io::json_string(plan.keys[k]);
  s += "],\n  \"runs\": [\n";
  for (std::size_t i = 0; i < plan.runs.size(); ++i) {
    s += "    {\"folder\": " + io::json_string(plan.runs[i].folder) + ", \"set\": {";
    bool first = true;
    for (const auto& [key, value] : plan.runs[i].sets) {
      s += (first ? "" : ", ") + io::json_string(key) + ": " + io::json_string(value);
      first = false;
    }
    s += std::string("}}") + (i + 1 < plan.runs.size() ? ",\n" : "\n");
  }
  return s + "  ]\n}\n";
}

struct Child {
  std::size_t index;
  std::chrono::steady_clock::time_point started;
};

// Runs every run of the plan, `jobs` at a time. Returns each run's exit code (-1: not run).
std::vector<int> run_all(const SweepConfig& c, const SweepPlan& plan, int jobs) {
  const std::filesystem::path& out = c.run.out_dir;
  const std::string exe = selfsim_executable();
  const int cores = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const int threads = c.run.threads > 0 ? c.run.threads : std::max(1, cores / jobs);
  // N runs at once share the machine: each may hold its share of the default --max-memory.
  RunConfig each = c.run;
  if (each.max_memory == 0) each.max_memory = std::max(256.0 * (1 << 20), default_max_memory() / jobs);
  catch_stop_signals();

  std::vector<int> codes(plan.runs.size(), -1);
  std::map<pid_t, Child> live;
  std::size_t next = 0, done = 0;
  const std::size_t n = plan.runs.size();
  while (done < n && !(interrupted.load() && live.empty())) {
    while (!interrupted.load() && live.size() < static_cast<std::size_t>(jobs) && next < n) {
      const SweepRun& run = plan.runs[next];
      // The folder is the run's alone: what an earlier sweep left there must not reach this one's sheets.
      std::filesystem::remove_all(out / run.folder);
      io::make_folder(out, run.folder);  // confined: a link planted meanwhile is refused, not followed
      // The child opens its -o refusing a link there too: one planted after make_folder is not written through.
      std::vector<std::string> args = run_arguments(each, run, out / run.folder, threads);
      args.insert(args.end() - 1, "--confined-output");
      const pid_t pid = spawn_selfsim(exe, args, out, std::filesystem::path(run.folder) / "selfsim.log");
      live[pid] = {next++, std::chrono::steady_clock::now()};
    }
    if (live.empty()) break;
    int status = 0;
    const pid_t pid = ::waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR && interrupted.load())
        for (const auto& [p, child] : live) ::kill(p, SIGINT);  // each stops cleanly, leaving no partial file
      continue;
    }
    const auto it = live.find(pid);
    if (it == live.end()) continue;
    const Child child = it->second;
    live.erase(it);
    const SweepRun& run = plan.runs[child.index];
    const int code = exit_code(status);
    codes[child.index] = code;
    ++done;
    try {  // below `out`, the run folder opened as any folder on the way (never through a link)
      io::write_whole(out, run.folder + "/selfsim.exit", std::to_string(code) + "\n");
    } catch (const Error& e) {
      std::fprintf(stderr, "selfsim: %s\n", e.what());
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - child.started).count();
    if (code == 0) {
      if (!c.run.quiet) std::printf("[%zu/%zu] %s: ok (%.2f s)\n", done, n, shown_text(run.caption).c_str(), seconds);
    } else if (!interrupted.load()) {
      std::fprintf(stderr, "[%zu/%zu] %s: failed (%s): %s\n", done, n, shown_text(run.caption).c_str(),
                   exit_text(code).c_str(), first_line(out / run.folder / "selfsim.log").c_str());
    }
    std::fflush(stdout);
  }
  return codes;
}

}  // namespace

void check_sweep_folders(const SweepConfig& c, const SweepPlan& plan) {
  const std::filesystem::path& out = c.run.out_dir;
  std::vector<std::string> ours{"previews", "slurm"};
  for (const SweepRun& run : plan.runs) ours.push_back(run.folder);
  for (const SweepRun& run : plan.runs) ours.push_back("previews/" + run.folder);  // each folder on the way
  // A link where a folder of the sweep goes would lead its writes out of the output folder; a file there
  // would stop the sweep halfway. Both are refused before anything starts.
  for (const std::string& name : ours) {
    std::error_code ec;
    const auto st = std::filesystem::symlink_status(out / name, ec);
    if (std::filesystem::is_symlink(st))
      throw UsageError("'" + (out / name).string() + "' is a link: a sweep writes only inside its output folder");
    if (std::filesystem::exists(st) && !std::filesystem::is_directory(st))
      throw UsageError("'" + (out / name).string() + "' is a file where the sweep's folder goes");
  }
  for (const std::string* file : {&c.jobs_file, &c.slurm}) {
    if (file->empty()) continue;
    // One rule (sweep_reserved_name) for what the sweep writes or keeps, now or at --collect, applied to the
    // name's first part in the output folder ("level=1/j.txt" would go where a run's folder is emptied).
    const std::filesystem::path rel = std::filesystem::path(*file).lexically_normal();
    const std::string first = rel.empty() ? std::string() : rel.begin()->string();
    const bool taken = sweep_reserved_name(first) || std::find(ours.begin(), ours.end(), first) != ours.end() ||
                       (file == &c.jobs_file && (*file == c.slurm || *file == "collect-" + c.slurm)) ||
                       (file == &c.slurm && c.jobs_file.empty() && *file == "jobs.txt");
    if (taken) throw UsageError("'" + *file + "' is a name the sweep uses itself: give the job list another name");
  }
}

int sweep_command(const SweepConfig& c) {
  const SweepPlan plan = plan_sweep(c.run.sets);
  const std::filesystem::path& out = c.run.out_dir;
  if (c.collect_only) {  // reads what the runs left; writes only the sheets and series
    std::error_code ec;
    if (!std::filesystem::is_directory(out, ec))
      throw UsageError("--collect: no sweep in '" + out.string() + "' (not a folder)");
    catch_stop_signals();
    const int code = collect_sweep(c, plan, read_exit_codes(out, plan));
    if (interrupted.load()) std::fprintf(stderr, "selfsim: sweep --collect interrupted\n");
    return interrupted.load() ? 130 : code;
  }
  check_sweep_params(c.run, plan);
  check_sweep_folders(c, plan);
  const bool lists = !c.jobs_file.empty() || !c.slurm.empty();
  if (lists) check_job_lists(c, plan, selfsim_executable());
  std::filesystem::create_directories(out);
  io::write_whole(out, "sweep.json", manifest(c, plan));
  if (lists) return write_job_lists(c, plan, selfsim_executable());

  const int jobs = c.run.jobs > 0 ? c.run.jobs : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  if (!c.run.quiet)
    std::printf("sweep: %zu runs of %s, %d at a time, into %s\n", plan.runs.size(),
                shown_text(c.run.recipe.string()).c_str(), jobs, shown_text(out.string()).c_str());
  std::fflush(stdout);
  const std::vector<int> codes = run_all(c, plan, jobs);
  if (interrupted.load()) {
    std::size_t done = 0;
    for (int code : codes) done += code == 0;
    std::fprintf(stderr, "selfsim: sweep interrupted: %zu of %zu runs finished\n", done, plan.runs.size());
    return 130;
  }
  return collect_sweep(c, plan, codes);
}

}  // namespace selfsim::interp
