#include "interpreter/file_watcher.h"

#include <poll.h>
#include <sys/inotify.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "kernels/geom/error.h"

namespace selfsim::interp {

namespace {

constexpr std::uint32_t events = IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM | IN_DELETE | IN_CREATE;

bool same_folder(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec);
}

// The folders holding `file` and each link on the way to what it finally names (a link to a link, in
// another folder: changing the middle one changes the recipe too). Stops after 40 links (a loop).
std::vector<std::filesystem::path> link_chain_folders(const std::filesystem::path& file) {
  std::vector<std::filesystem::path> folders;
  std::filesystem::path p = std::filesystem::absolute(file);
  for (int hop = 0; hop < 40; ++hop) {
    folders.push_back(p.parent_path());
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec))) break;
    const std::filesystem::path target = std::filesystem::read_symlink(p, ec);
    if (ec) break;
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  return folders;
}

// Whether `folder` is `outer` or inside it, by their real paths.
bool inside(const std::filesystem::path& folder, const std::filesystem::path& outer) {
  std::error_code ec, ec2;
  const std::string f = std::filesystem::canonical(folder, ec).string() + "/";
  const std::string o = std::filesystem::canonical(outer, ec2).string() + "/";
  return !ec && !ec2 && f.starts_with(o);
}

}  // namespace

bool side_file(const std::string& name) {
  if (name.empty() || name[0] == '.' || name.back() == '~' || name[0] == '#') return true;
  for (const char* end : {".swp", ".swx", ".tmp"})
    if (name.size() > std::strlen(end) && name.ends_with(end)) return true;
  return name.find_first_not_of("0123456789") == std::string::npos;  // vim's "4913"
}

FileWatcher::FileWatcher(const std::vector<std::filesystem::path>& folders, const std::filesystem::path& skip)
    : skip_(skip) {
  fd_ = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (fd_ < 0) throw Error(std::string("cannot watch files (inotify): ") + std::strerror(errno));
  for (const std::filesystem::path& f : folders) add(f, 0);
}

FileWatcher::~FileWatcher() {
  if (fd_ >= 0) ::close(fd_);
}

void FileWatcher::add(const std::filesystem::path& folder, int depth) {
  if (!skip_.empty() && same_folder(folder, skip_)) return;
  const int wd = ::inotify_add_watch(fd_, folder.c_str(), events | IN_ONLYDIR);
  if (wd < 0) throw Error("cannot watch '" + folder.string() + "': " + std::strerror(errno));
  watched_[wd] = folder;
  std::error_code ec0;
  real_.insert(std::filesystem::canonical(folder, ec0).string());
  if (depth >= 3) return;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name[0] != '.' && entry.is_directory(ec) && !entry.is_symlink(ec)) add(entry.path(), depth + 1);
  }
}

std::string FileWatcher::drain() {
  // The name to report: the last file written or moved in (sed and many editors write a temporary and
  // rename it over the source: the source's name comes last), else the last one moved away or deleted.
  std::string written, gone;
  alignas(inotify_event) char buffer[16384];
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n <= 0) break;
    for (ssize_t at = 0; at < n;) {
      const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
      at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
      if (e->mask & IN_IGNORED) {  // the folder itself was deleted or moved away
        if (const auto w = watched_.find(e->wd); w != watched_.end()) {
          lost_.push_back(w->second);
          watched_.erase(w);
        }
        continue;
      }
      if (e->len == 0 || (e->mask & IN_ISDIR) || side_file(e->name)) continue;
      ((e->mask & (IN_MOVED_FROM | IN_DELETE)) ? gone : written) = e->name;
    }
  }
  refollow();  // a change in a watched folder may have made the recipe a link, or pointed it elsewhere
  return written.empty() ? gone : written;
}

void FileWatcher::follow(const std::filesystem::path& file) {
  followed_.push_back(file);
  refollow();
}

void FileWatcher::refollow() {
  for (const std::filesystem::path& file : followed_) {
    for (const std::filesystem::path& folder : link_chain_folders(file)) {
      std::error_code ec;
      const std::filesystem::path real = std::filesystem::canonical(folder, ec);
      if (ec || real_.count(real.string()) != 0 || (!skip_.empty() && inside(real, skip_))) continue;
      try {
        add(real, 0);
      } catch (const Error&) {  // not watchable (no permission): its edits go unseen, watching goes on
        real_.insert(real.string());
      }
    }
  }
}

std::string FileWatcher::take(std::chrono::milliseconds settle) {
  std::string changed = drain();
  if (changed.empty()) return {};
  // An editor's save is often several events (write, rename, attributes): gather them into one change.
  pollfd more{fd_, POLLIN, 0};
  while (::poll(&more, 1, static_cast<int>(settle.count())) > 0)
    if (std::string later = drain(); !later.empty()) changed = later;
  return changed;
}

bool FileWatcher::restore() {
  bool back = false;
  for (auto it = lost_.begin(); it != lost_.end();) {
    std::error_code ec;
    if (std::filesystem::is_directory(*it, ec)) {
      add(*it, 3);  // the folder alone: its subfolders come back with events of their own
      it = lost_.erase(it);
      back = true;
    } else {
      ++it;
    }
  }
  return back;
}

std::string FileWatcher::wait(std::chrono::milliseconds timeout, std::chrono::milliseconds settle) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return {};
    // A deleted folder cannot be watched until it is back (git checkout): look for it twice a second.
    if (!lost_.empty() && restore()) return "(a watched folder, back)";
    const long long wait_ms = lost_.empty() ? left.count() : std::min<long long>(left.count(), 500);
    pollfd p{fd_, POLLIN, 0};
    const int r = ::poll(&p, 1, static_cast<int>(wait_ms));
    if (r < 0) return {};  // a signal: the caller asks why
    if (r == 0) continue;
    if (std::string changed = take(settle); !changed.empty()) return changed;
  }
}

}  // namespace selfsim::interp
