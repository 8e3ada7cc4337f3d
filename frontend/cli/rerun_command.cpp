// `selfsim rerun FILE [-o DIR]`: runs again the recipe a file records it was made by (provenance.h), with
// the same --set values and seed, into a new folder, and says whether the file comes out byte for byte the
// same. The answer a reader of a paper or a sweep's results wants: can this picture be made again here?
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <iterator>

#include "frontend/cli/commands.h"
#include "frontend/cli/sweep/sweep_plan.h"
#include "frontend/lua/lua_support.h"
#include "frontend/process/spawn_selfsim.h"
#include "kernels/base/error.h"
#include "kernels/io/provenance/provenance.h"
#include "kernels/io/provenance/sha256.h"

namespace selfsim::interp {

namespace {

std::string bytes_of(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// "rerun", or "rerun-2", "rerun-3", ...: a folder that does not exist yet.
std::filesystem::path fresh_folder() {
  std::error_code ec;
  std::filesystem::path p = "rerun";
  for (int n = 2; std::filesystem::exists(std::filesystem::symlink_status(p, ec)); ++n)
    p = "rerun-" + std::to_string(n);
  return p;
}

}  // namespace

int rerun_command(const std::string& file, const std::string& out) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))  // never a FIFO (reading it would wait forever)
    throw UsageError("cannot read '" + shown_text(file) + "': not a regular file");
  const std::optional<io::Provenance> p = io::read_provenance(file);
  if (!p)
    throw UsageError("'" + shown_text(file) +
                     "' records no recipe (selfsim " SELFSIM_VERSION
                     " records one in every file a run saves; .stl and .vdb beside them, as NAME.json)");
  // The record is only text in a file: it may name nothing but a file inside the new folder, and --set
  // keys a run could have had. A NUL would cut a path where it reaches the system (the parser refuses one
  // in any field; this is where the paths are used).
  for (const auto& [what, path] :
       {std::pair<const char*, const std::string*>{"recipe", &p->recipe}, {"name", &p->name}})
    if (path->find('\0') != std::string::npos)
      throw UsageError("'" + shown_text(file) + "' records a " + what + " path holding a NUL character");
  const std::filesystem::path name(p->name);
  bool inside = !p->name.empty() && name.is_relative();
  for (const auto& part : name) inside = inside && part != "..";
  if (!inside)
    throw UsageError("'" + shown_text(file) + "' records the name '" + shown_text(p->name) +
                     "', not a file inside a run's folder");
  for (const auto& [k, v] : p->sets) {
    if (k.empty() || k.find_first_of(std::string("=\n\r\0", 4)) != std::string::npos || k[0] == '-')
      throw UsageError("'" + shown_text(file) + "' records a --set key '" + shown_text(k) + "' no run could have had");
    if (v.find('\0') != std::string::npos)  // the key is fine: blame the value
      throw UsageError("'" + shown_text(file) + "' records a --set value for '" + shown_text(k) +
                       "' holding a NUL character, which no run could have had");
  }
  if (!std::filesystem::is_regular_file(p->recipe, ec))
    throw UsageError("'" + shown_text(file) + "' was made by " + shown_text(p->recipe) +
                     ", which is not there any more");
  const std::filesystem::path folder = out.empty() ? fresh_folder() : std::filesystem::path(out);
  const auto st = std::filesystem::symlink_status(folder, ec);
  if (std::filesystem::exists(st) && (!std::filesystem::is_directory(st) || !std::filesystem::is_empty(folder, ec)))
    throw UsageError("-o '" + folder.string() + "' is not an empty folder: rerun writes into a new folder");
  if (io::sha256_hex(bytes_of(p->recipe)) != p->sha256)
    std::fprintf(stderr,
                 "selfsim: warning: %s has changed since '%s' was made (its SHA-256 differs): rerunning it as "
                 "it is now\n",
                 shown_text(p->recipe).c_str(), shown_text(file).c_str());
  if (p->version != SELFSIM_VERSION)
    std::fprintf(stderr, "selfsim: note: '%s' was made by selfsim %s; this is %s\n", shown_text(file).c_str(),
                 shown_text(p->version, 40).c_str(), SELFSIM_VERSION);
  std::vector<std::string> args{"run", p->recipe, "-o", folder.string()};
  for (const auto& [k, v] : p->sets) args.insert(args.end(), {"--set", k + "=" + escaped_value(v)});
  args.insert(args.end(), {"--seed", std::to_string(p->seed), "-q"});
  std::printf("%s\n", shown_text(shell_command(args), 4096).c_str());
  std::fflush(stdout);
  const pid_t pid = spawn_selfsim(selfsim_executable(), args, {});
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (const int code = exit_code(status); code != 0) {
    std::fprintf(stderr, "selfsim: the rerun failed (exit %d)\n", code);
    return 1;
  }
  const std::filesystem::path again = folder / name;
  if (!std::filesystem::is_regular_file(again, ec)) {
    std::fprintf(stderr, "selfsim: the rerun wrote no %s\n", shown_text(again.string()).c_str());
    return 1;
  }
  if (bytes_of(again) == bytes_of(file)) {
    std::printf("same bytes: %s is %s byte for byte\n", shown_text(again.string()).c_str(), shown_text(file).c_str());
    return 0;
  }
  std::printf("different: %s differs from %s (selfsim diff %s %s says where)\n", shown_text(again.string()).c_str(),
              shown_text(file).c_str(), shell_word(file).c_str(), shell_word(again.string()).c_str());
  return 1;
}

}  // namespace selfsim::interp
