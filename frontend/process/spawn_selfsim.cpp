#include "frontend/process/spawn_selfsim.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string_view>

#include "kernels/base/error.h"
#include "kernels/io/output_file.h"

extern char** environ;

namespace selfsim::interp {

pid_t spawn_selfsim(const std::string& exe, const std::vector<std::string>& args, const std::filesystem::path& root,
                    const std::filesystem::path& log) {
  const int fd = log.empty() ? -1 : io::open_log(root, log);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (fd >= 0) {
    posix_spawn_file_actions_adddup2(&actions, fd, 1);
    posix_spawn_file_actions_adddup2(&actions, fd, 2);
  }
  std::vector<std::string> words{"selfsim"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  // The child stops when this process dies, even by SIGKILL (run_command reads this; stop_with_parent).
  std::vector<std::string> env{std::string(stop_with_variable) + "=" + std::to_string(::getpid())};
  for (char** e = environ; *e; ++e)
    if (std::string_view(*e).substr(0, std::strlen(stop_with_variable) + 1) != std::string(stop_with_variable) + "=")
      env.emplace_back(*e);
  std::vector<char*> envp;
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  pid_t pid = 0;
  const int e = posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (fd >= 0) ::close(fd);
  if (e != 0) throw Error("cannot start '" + exe + "': " + std::strerror(e));
  return pid;
}

void stop_with_parent() {
  const char* parent = std::getenv(stop_with_variable);
  if (parent == nullptr) return;
  const long pid = std::strtol(parent, nullptr, 10);
  ::unsetenv(stop_with_variable);
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);        // stopped as by SIGTERM: cleanly, leaving no partial file
  if (::getppid() != pid) ::raise(SIGTERM);  // the parent died before the line above
}

int exit_code(int status) {
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
}

std::string selfsim_executable() {
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) throw Error("cannot find the selfsim executable (/proc/self/exe): " + ec.message());
  return p.string();
}

}  // namespace selfsim::interp
