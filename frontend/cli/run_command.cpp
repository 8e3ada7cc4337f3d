// `selfsim run RECIPE.lua`: runs a recipe in the sandbox and reports its outputs or its one-line error.
#include <fcntl.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <string_view>

#include "frontend/bindings/bindings.h"
#include "frontend/bindings/save_support.h"
#include "frontend/cli/commands.h"
#include "frontend/cli/sweep/literal_params.h"
#include "frontend/cli/sweep/sweep.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/nil_name_hint.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/sandbox.h"
#include "frontend/process/spawn_selfsim.h"
#include "frontend/process/watchdog.h"
#include "kernels/io/output_file.h"
#include "kernels/io/provenance/sha256.h"
#include "kernels/io/regular_file.h"
#include "kernels/io/text/json_text.h"

namespace selfsim::interp {

namespace {

extern "C" void on_interrupt(int) { interrupted.store(true); }

std::filesystem::path find_scripts_dir() {
  if (const char* env = std::getenv("SELFSIM_SCRIPTS")) return env;
  return SELFSIM_SCRIPTS_DIR;
}

const char* const error_where_key = "selfsim.error_where";

// The message handler of the recipe's pcall: every error becomes one string that names the recipe line,
// whatever was raised (a table, a number, nil, a value whose __tostring raises). Runs at the error site, so
// it can still read the stack; the location is also kept for errors whose handler fails.
int message_handler(lua_State* L) {
  RunContext& run = RunContext::of(L);
  run.ended = true;  // the recipe is over: a __tostring called below cannot save either
  const std::string where = recipe_where(L);
  lua_pushstring(L, where.c_str());
  lua_setfield(L, LUA_REGISTRYINDEX, error_where_key);
  if (lua_type(L, 1) == LUA_TSTRING) {
    // A misspelt global or DSL function names the closest name (nil_name_hint.h); any other text as it is.
    const std::string text = with_nil_name_hint(L, lua_tostring(L, 1));
    lua_pushlstring(L, text.data(), text.size());
    return 1;
  }
  // A __tostring is called under pcall: one that raises or loops (the hook stops it) still gives a line.
  std::string text;
  lua_getglobal(L, "tostring");
  lua_pushvalue(L, 1);
  const bool has_text = luaL_getmetafield(L, 1, "__tostring") != LUA_TNIL;
  if (has_text) lua_pop(L, 1);
  if (has_text && lua_pcall(L, 1, 1, 0) == LUA_OK && lua_type(L, -1) == LUA_TSTRING) {
    std::size_t n = 0;
    const char* own = lua_tolstring(L, -1, &n);
    text = where + "error: " + std::string(own, n);
  } else if (const std::string stop = run.stop_reason(); !stop.empty()) {
    text = where + stop;
  } else {
    text = where + "error raised with " + describe(L, 1);
  }
  lua_pushlstring(L, text.data(), text.size());
  return 1;
}

// True when text starts with "FILE:LINE: ", as Lua's located messages do.
bool starts_with_location(std::string_view text) {
  const std::size_t colon = text.find(':');
  if (colon == 0 || colon == std::string_view::npos ||
      text.substr(0, colon).find_first_of(" \t") != std::string_view::npos)
    return false;
  std::size_t i = colon + 1;
  while (i < text.size() && text[i] >= '0' && text[i] <= '9') ++i;
  return i > colon + 1 && text.substr(i, 2) == ": ";
}

// The text of a failed pcall as one line that starts with a recipe location.
std::string failure_message(lua_State* L, RunContext& run, int status) {
  if (status == LUA_ERRMEM) return memory_message(run.memory);  // before anything that may allocate
  // The recipe could not be read (load_lua_file): its message names it already.
  if (status == LUA_ERRFILE) return shown_text(lua_tostring(L, -1), 2000);
  lua_getfield(L, LUA_REGISTRYINDEX, error_where_key);
  const std::string where = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : run.config.recipe.string() + ": ";
  lua_pop(L, 1);
  std::size_t n = 0;
  const char* text = lua_type(L, -1) == LUA_TSTRING ? lua_tolstring(L, -1, &n) : nullptr;
  if (text == nullptr) return where + "error (status " + std::to_string(status) + ")";
  // Lua's own messages end where the recipe's text does; a long error string is cut after 2000 bytes.
  std::string message = shown_text(std::string_view(text, n), 2000);
  // Lua adds no location to some errors ("error in error handling", error("x", 0)): add the recipe's.
  if (!starts_with_location(message)) message = where + message;
  // Lines a kernel gave to show under its message (a rule with a caret under the fault), each kept to one
  // line of its own.
  const std::string detail = error_detail(L, -1);
  for (std::size_t begin = 0; begin < detail.size();) {
    const std::size_t end = std::min(detail.find('\n', begin), detail.size());
    message += "\n" + shown_text(std::string_view(detail).substr(begin, end - begin), 400);
    begin = end + 1;
  }
  return message;
}

// view.py beside the run's VTK outputs (kernels/io/view/paraview_view.h), unless --no-view: the one command that
// opens them in ParaView as they are meant to be seen.
void write_view(const RunContext& run) {
  if (!run.config.view || run.view_datasets.empty()) return;
  // A dataset view.py cannot name is said, not dropped silently; with none left there is no view to write.
  std::size_t named = 0;
  for (const io::ViewDataset& d : run.view_datasets)
    if (io::view_can_name(d))
      ++named;
    else
      std::fprintf(stderr, "selfsim: warning: view.py leaves out '%s': its name is not UTF-8 text\n",
                   shown_text(d.file).c_str());
  if (named == 0) return;
  try {
    const std::string written =
        io::write_paraview_view(run.view_datasets, run.config.out_dir, "view.py", run.config.view_folder);
    if (!run.config.quiet)
      std::printf("wrote %s (open in ParaView: paraview --script=%s)\n", shown_text(written, 4096).c_str(),
                  shell_word(written).c_str());
  } catch (const Error& e) {
    std::fprintf(stderr, "selfsim: warning: no ParaView view written: %s\n", e.what());
  }
}

// An earlier run's results.json in the output folder goes when this run gives none or fails: left there it
// would stand for this run's, and a sweep gathering the folder would report numbers this run never gave.
void remove_old_results(const std::filesystem::path& out) {
  std::error_code ec;
  if (!std::filesystem::is_directory(out, ec)) return;  // a run that failed before making its folder
  io::remove_files(out, {}, [](const std::string& name) { return name == io::results_file; });
}

// results.json beside the run's outputs when the recipe gave results (result(), bind_result.cpp): what a
// sweep gathers into results.csv. A run that gave none writes nothing, as before results existed.
void write_results(lua_State* L, const RunContext& run) {
  if (run.results.empty()) return remove_old_results(run.config.out_dir);
  const std::string text = io::results_json(run.results, run_provenance(L, io::results_file));
  io::write_whole(run.config.out_dir, io::results_file, text);
  if (run.config.quiet) return;
  std::string shown;
  for (std::size_t i = 0; i < run.results.size() && i < 4; ++i)
    shown += (i ? ", " : "") + run.results[i].name + " = " + io::json_number(run.results[i].value);
  if (run.results.size() > 4) shown += ", ... (" + std::to_string(run.results.size()) + " results)";
  std::printf("wrote %s (%s)\n", shown_text((run.config.out_dir / io::results_file).string(), 4096).c_str(),
              shown.c_str());
}

// Sends stdout to /dev/null while it lives: under `selfsim params` the recipe's print() and a kernel's
// messages must not mix with the JSON.
class QuietStdout {
 public:
  explicit QuietStdout(bool on) {
    if (!on) return;
    std::fflush(stdout);
    saved_ = ::dup(1);
    const int null = ::open("/dev/null", O_WRONLY | O_CLOEXEC);
    if (saved_ >= 0 && null >= 0) ::dup2(null, 1);
    if (null >= 0) ::close(null);
  }
  ~QuietStdout() {
    if (saved_ < 0) return;
    std::fflush(stdout);
    ::dup2(saved_, 1);
    ::close(saved_);
  }
  QuietStdout(const QuietStdout&) = delete;
  QuietStdout& operator=(const QuietStdout&) = delete;

 private:
  int saved_ = -1;
};

// Loads and runs the recipe in L (the sandbox of `run`) and returns the status of its pcall; the run has
// ended when it returns (finalizers still to run at lua_close can no longer write).
int run_recipe(lua_State* L, RunContext& run) {
  open_all(L);
  lua_pushcfunction(L, message_handler);
  int status = LUA_OK;
  {
    const QuietStdout quiet(run.config.params_only);
    std::string text;
    status = load_lua_file(L, run.config.recipe, "recipe", &text);
    run.recipe_sha256 = io::sha256_hex(text);  // of the bytes that ran, not of the file at the first save
    if (status == LUA_OK) status = lua_pcall(L, 0, 0, 1);
  }
  run.ended = true;
  return status;
}

// `selfsim params`: the parameters as JSON, and whether the recipe ran to its end or stopped at its first
// heavy step (a param() after that step is not listed).
int print_params(const RunContext& run, const std::string& stopped_at) {
  std::printf("{\"recipe\": %s, \"complete\": %s,%s \"parameters\": %s}\n",
              io::json_string(run.config.recipe.string()).c_str(), stopped_at.empty() ? "true" : "false",
              stopped_at.empty() ? "" : (" \"stopped_at\": " + io::json_string(stopped_at) + ",").c_str(),
              params_json(run.params).c_str());
  return 0;
}

// The run's --set values with their escapes undone ("a\\,b" is the one value "a,b"; sweep_plan.h).
RunConfig with_plain_values(RunConfig c) {
  for (auto& [key, value] : c.sets) value = sweep_values(key, value).front();
  return c;
}

}  // namespace

ParamsRead read_params(const RunConfig& given) {
  RunConfig config = given;
  config.params_only = true;
  config.quiet = true;
  config.view = false;
  if (config.timeout == 0) config.timeout = 30;
  RunContext run(config);
  run.scripts_dir = find_scripts_dir();
  // A finalizer that loops runs with hooks off, where only the watchdog can stop it.
  const Watchdog watchdog(run, config.recipe.string());
  lua_State* L = new_sandbox(run);
  if (L == nullptr) throw Error("cannot create a Lua state (out of memory)");
  const int status = run_recipe(L, run);
  const std::string message = status == LUA_OK ? std::string() : failure_message(L, run, status);
  lua_close(L);
  if (status != LUA_OK && !message.ends_with(params_stop)) throw Error(message);
  ParamsRead read;
  read.specs = run.params;
  if (status != LUA_OK) read.stopped_at = message.substr(0, message.find(": "));
  return read;
}

void check_sweep_params(const RunConfig& sweep, const SweepPlan& plan) {
  RunConfig config = sweep;
  config.sets = plan.runs.front().sets;
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on_interrupt);
  const ParamsRead read = read_params(config);
  // Stopped at a heavy step, the recipe may declare a parameter later: its text tells, where every param()
  // in it names a literal (else each run checks the key, after a warning here).
  const std::optional<std::set<std::string>> literal =
      read.stopped_at.empty() ? std::nullopt : recipe_literal_params(config.recipe);
  std::vector<std::string> names;
  for (const ParamSpec& p : read.specs) names.push_back(p.name);
  if (literal) names.insert(names.end(), literal->begin(), literal->end());
  for (const auto& [key, text] : sweep.sets) {
    const auto spec =
        std::find_if(read.specs.begin(), read.specs.end(), [&k = key](const ParamSpec& p) { return p.name == k; });
    if (spec == read.specs.end()) {
      const std::string near = suggestion(key, names);
      if (!read.stopped_at.empty() && (!literal || literal->contains(key))) {
        std::fprintf(stderr, "selfsim: warning: --set %s: no param '%s' is read before %s%s\n", shown_text(key).c_str(),
                     shown_text(key).c_str(), read.stopped_at.c_str(),
                     near.empty() ? "" : (" (did you mean '" + near + "'?)").c_str());
        continue;
      }
      throw Error("--set " + key + "=" + text + ": the recipe declares no parameter '" + key + "'" +
                  (near.empty() ? "" : " (did you mean '" + near + "'?)"));
    }
    const std::vector<std::string> values = sweep_values(key, text);
    for (const std::string& value : values) check_param_value(*spec, value);
    check_distinct_values(*spec, key + "=" + text, values);
  }
}

int run_command(const RunConfig& given) {
  if (is_sweep(given.sets)) {
    if (given.params_only) throw UsageError("params reads one run's parameters: give each --set one value");
    SweepConfig sweep;
    sweep.run = given;
    return sweep_command(sweep);
  }
  const RunConfig config = with_plain_values(given);
  if (config.watch) return watch_command(config);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(config.recipe, ec)) {
    std::string why = ec ? ec.message() : "not a regular file";
    if (!ec) try {  // what it is instead ("is a FIFO, not a regular file"), asked without blocking on it
        const io::RegularFile check(config.recipe, true);
      } catch (const Error& e) {
        why = e.what();
      }
    throw UsageError("cannot open recipe '" + config.recipe.string() + "': " + why);
  }
  RunContext run(config);
  run.scripts_dir = find_scripts_dir();
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) std::signal(sig, on_interrupt);  // stop cleanly: no partial files
  stop_with_parent();
  const Watchdog watchdog(run, config.recipe.string());
  // --threads bounds every parallel kernel of the run; results never depend on it (DESIGN.md, Threads).
  std::optional<tbb::global_control> threads;
  if (config.threads > 0) threads.emplace(tbb::global_control::max_allowed_parallelism, config.threads);

  lua_State* L = new_sandbox(run);
  if (L == nullptr) {
    std::fprintf(stderr, "selfsim: cannot create a Lua state (out of memory)\n");
    return 1;
  }
  const int status = run_recipe(L, run);
  run.finish_bar();
  int code = 0;
  std::string message = status == LUA_OK ? std::string() : failure_message(L, run, status);
  if (config.params_only && (status == LUA_OK || message.ends_with(params_stop))) {
    code = print_params(run, message.substr(0, message.find(": ")));
  } else if (status != LUA_OK) {
    std::fprintf(stderr, "%s\n", message.c_str());
    std::fflush(stderr);
    run.reported = true;
    code = interrupted.load() ? 130 : 1;
    try {
      remove_old_results(config.out_dir);
    } catch (const Error&) {  // the run's own failure is the message that matters
    }
  } else {
    write_view(run);
    try {
      write_results(L, run);
    } catch (const Error& e) {  // the results are part of what the run made: the run fails without them
      std::fprintf(stderr, "selfsim: %s\n", e.what());
      code = 1;
    }
    const std::vector<std::string> read(run.used_params.begin(), run.used_params.end());
    for (const auto& [key, value] : config.sets)
      if (!run.used_params.contains(key)) {
        const std::string near = suggestion(key, read);
        std::fprintf(stderr, "selfsim: warning: --set %s=%s was not read by any param() in the recipe%s\n",
                     shown_text(key).c_str(), shown_text(value).c_str(),
                     near.empty() ? "" : (" (did you mean '" + shown_text(near) + "'?)").c_str());
      }
  }
  std::fflush(stdout);
  lua_close(L);  // finalizers run here: one that fails ends the run with its own message first
  // A recipe that ran to its end and wrote nothing most likely forgot its save(): said, not an error (a
  // recipe may only print), so the exit status stays 0. results.json counts as something written.
  if (status == LUA_OK && code == 0 && !config.params_only && run.saved.empty() && run.results.empty())
    std::fprintf(stderr, "selfsim: warning: %s saved nothing (call save(value, \"name.ext\") to write a file)\n",
                 shown_text(config.recipe.string()).c_str());
  return code;
}

}  // namespace selfsim::interp
