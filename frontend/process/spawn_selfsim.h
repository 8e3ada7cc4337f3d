// Starting a `selfsim run` as a child process: a sweep's runs and --watch's re-runs. A child rather than a
// thread: a run that fails, runs out of memory or is stopped takes nothing else down.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace selfsim::interp {

// The running selfsim's own path (/proc/self/exe), for the runs a sweep, --watch, rerun or a preview starts.
std::string selfsim_executable();

// Starts `exe` with `args` (after the program name); its stdout and stderr go to root/log (created or
// truncated through the confined writer's folders, output_file.h: never through a link) or, when `log` is
// empty, where ours go. Returns its pid; throws Error.
pid_t spawn_selfsim(const std::string& exe, const std::vector<std::string>& args, const std::filesystem::path& root,
                    const std::filesystem::path& log = {});

// The environment variable that tells a child whose parent it should stop with.
inline constexpr const char* stop_with_variable = "SELFSIM_STOP_WITH";

// In a child started by spawn_selfsim: asks the kernel for SIGTERM when the parent dies (a sweep or
// --watch killed by SIGKILL must not leave its runs going). Call after the SIGTERM handler is installed.
void stop_with_parent();

// A child's exit code as a shell reports it: its exit status, or 128 + the signal that ended it.
int exit_code(int wait_status);

}  // namespace selfsim::interp
