#include "frontend/cli/watch/live_run.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>

#include "frontend/cli/commands.h"
#include "frontend/cli/sweep/sweep.h"
#include "frontend/process/spawn_selfsim.h"
#include "kernels/io/output_file.h"
#include "kernels/io/regular_file.h"

namespace selfsim::interp {

namespace {

const char* const staging_name = ".selfsim-next";
const char* const log_name = ".selfsim-run.log";

// Moves every file of the staging folder to the same place in the output folder, deepest first (a series'
// steps before the series file that names them). Returns the top-level names moved.
std::vector<std::string> publish(const std::filesystem::path& staging, const std::filesystem::path& out) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(staging))
    if (entry.is_regular_file() && !entry.is_symlink()) files.push_back(entry.path().lexically_relative(staging));
  std::stable_sort(files.begin(), files.end(), [](const auto& a, const auto& b) {
    return std::distance(a.begin(), a.end()) > std::distance(b.begin(), b.end());
  });
  // Everything is checked before anything moves: a link planted on the way (it would lead a rename out of
  // the output folder) or a folder where a file goes refuses the whole run, not half of it.
  std::error_code ec;
  for (const std::filesystem::path& rel : files) {
    const std::filesystem::path to = out / rel;
    // The folders between the output folder and the file, walked down from the output folder: walking up
    // from the file until it equals `out` never ends when `out` is spelt otherwise ("out/", "./out").
    std::filesystem::path up = out;
    for (const std::filesystem::path& part : rel.parent_path()) {
      up /= part;
      if (std::filesystem::is_symlink(std::filesystem::symlink_status(up, ec)))
        throw Error("'" + up.string() + "' is a link; not writing through it");
    }
    if (std::filesystem::is_directory(std::filesystem::symlink_status(to, ec)))
      throw Error("'" + to.string() + "' is a folder where the run's file goes");
  }
  // Each move through the confined writer's folders (output_file.h): a link swapped in after the check
  // above is refused too, never followed.
  std::vector<std::string> names;
  for (const std::filesystem::path& rel : files) {
    io::move_file(out, staging.lexically_relative(out) / rel, rel);
    if (!rel.has_parent_path()) names.push_back(rel.string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace

LiveRun::LiveRun(RunConfig base, bool capture)
    : base_(std::move(base)),
      capture_(capture),
      staging_(base_.out_dir / staging_name),
      log_(base_.out_dir / log_name),
      exe_(selfsim_executable()) {
  std::filesystem::create_directories(base_.out_dir);
  // One live runner per output folder: two would remove each other's staging folder.
  lock_ = ::open((base_.out_dir / ".selfsim-lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (lock_ < 0 || ::flock(lock_, LOCK_EX | LOCK_NB) != 0)
    throw UsageError("another studio or --watch is using the output folder '" + base_.out_dir.string() +
                     "' (choose another -o)");
}

LiveRun::~LiveRun() {
  stop();
  std::error_code ec;
  std::filesystem::remove_all(staging_, ec);
  std::filesystem::remove(log_, ec);
  std::filesystem::remove(base_.out_dir / ".selfsim-lock", ec);
  if (lock_ >= 0) ::close(lock_);
}

void LiveRun::stop() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGINT);  // as Ctrl-C: the run stops at its next check and leaves no partial file
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  if (pidfd_ >= 0) ::close(pidfd_);
  pid_ = pidfd_ = -1;
}

void LiveRun::start(const std::map<std::string, std::string>& sets) {
  stop();
  std::error_code ec;
  std::filesystem::remove_all(staging_, ec);
  std::filesystem::create_directories(base_.out_dir);  // deleted meanwhile: made again
  io::make_folder(base_.out_dir, staging_name);        // a real folder, not a link planted in its place
  SweepRun one;
  one.sets = sets;
  std::vector<std::string> args = run_arguments(base_, one, staging_, base_.threads);
  // view.py names the output folder, where its files end up.
  args.insert(args.end() - 1, {"--view-folder", std::filesystem::absolute(base_.out_dir).lexically_normal().string()});
  args.insert(args.end() - 1, "--confined-output");  // a link planted where staging_ was made is refused
  started_ = std::chrono::steady_clock::now();
  pid_ = spawn_selfsim(exe_, args, base_.out_dir, capture_ ? log_name : "");
  pidfd_ = static_cast<int>(::syscall(SYS_pidfd_open, pid_, 0));
}

bool LiveRun::finished(LiveResult& result) {
  if (pid_ <= 0) return false;
  int status = 0;
  if (::waitpid(pid_, &status, WNOHANG) != pid_) return false;
  if (pidfd_ >= 0) ::close(pidfd_);
  pid_ = pidfd_ = -1;
  result = {};
  result.code = exit_code(status);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  if (capture_) {
    try {  // read as every input is: a FIFO swapped in at the log's name is refused, never waited on
      const io::RegularFile in(log_, true);
      result.log.resize(static_cast<std::size_t>(std::min<std::uint64_t>(in.size(), 16384)));
      result.log.resize(in.read_at(0, result.log.data(), result.log.size()));
    } catch (const Error&) {
      result.log.clear();
    }
  }
  std::error_code ec;
  try {
    if (result.code == 0 && std::filesystem::is_directory(staging_, ec))
      result.files = publish(staging_, base_.out_dir);
  } catch (const std::exception& e) {  // the run's files could not go in: it failed, and the last good files stay
    result.code = 1;
    result.log = std::string("cannot move the run's files into the output folder: ") + e.what() + "\n" + result.log;
    if (!capture_) std::fprintf(stderr, "selfsim: %s", result.log.substr(0, result.log.find('\n') + 1).c_str());
  }
  std::filesystem::remove_all(staging_, ec);
  return true;
}

std::vector<std::filesystem::path> recipe_folders(const RunConfig& config, const std::string& who) {
  // The recipe's folder, and the folder of the file it links to: an edit there is a change too.
  std::vector<std::filesystem::path> folders{std::filesystem::absolute(config.recipe).parent_path()};
  std::error_code ec;
  const std::filesystem::path real = std::filesystem::canonical(config.recipe, ec).parent_path();
  if (!ec && !std::filesystem::equivalent(real, folders[0], ec)) folders.push_back(real);
  // The runs' own writes must not count as changes: the output folder may not hold the recipe.
  std::filesystem::create_directories(config.out_dir);
  const std::string out = std::filesystem::canonical(config.out_dir, ec).string() + "/";
  for (const std::filesystem::path& f : folders)
    if ((std::filesystem::canonical(f, ec).string() + "/").starts_with(out))
      throw UsageError(who + ": the output folder '" + config.out_dir.string() +
                       "' holds the recipe; its writes would count as changes (choose another -o)");
  const char* scripts = std::getenv("SELFSIM_SCRIPTS");
  folders.emplace_back(scripts ? scripts : SELFSIM_SCRIPTS_DIR);
  return folders;
}

}  // namespace selfsim::interp
