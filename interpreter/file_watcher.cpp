#include "interpreter/file_watcher.h"

#include <poll.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <deque>

#include "kernels/geom/error.h"

namespace selfsim::interp {

namespace {

constexpr std::uint32_t events = IN_CLOSE_WRITE | IN_MOVED_TO | IN_MOVED_FROM | IN_DELETE | IN_CREATE;

bool same_folder(const std::filesystem::path& a, const std::filesystem::path& b) {
  std::error_code ec;
  return std::filesystem::equivalent(a, b, ec);
}

// One name met on the way from a path to what it names: the folder it is in (a path with no link in it) and
// whether it is a link.
struct Step {
  std::filesystem::path folder;
  std::string name;
  bool link = false;
};

// The names of `path`, without the empty and "." ones (a trailing slash, "a/./b").
std::deque<std::string> names_of(const std::filesystem::path& path) {
  std::deque<std::string> names;
  for (const std::filesystem::path& c : path.relative_path())
    if (!c.empty() && c != ".") names.push_back(c.string());
  return names;
}

// The way from `file` (absolute) to what it finally names, resolved a name at a time as the kernel resolves
// it: a link at the file or at any folder on its path is read and its target walked in its place. Stops at a
// missing name (it is on the way: its creation is a change) and after 40 links, the kernel's limit (a loop:
// the links met so far are on the way, so re-pointing one ends the loop and is seen). `last` is the folder
// where the final name is (or would be), empty when the walk stopped before it.
std::vector<Step> way_to(const std::filesystem::path& file, std::filesystem::path& last) {
  std::vector<Step> way;
  std::deque<std::string> left = names_of(file);
  std::filesystem::path at = file.root_path();  // resolved so far
  int links = 0;
  last.clear();
  while (!left.empty()) {
    const std::string name = left.front();
    left.pop_front();
    if (name == "..") {  // the parent of what `at` is, not of the link that led there (as the kernel does)
      at = at.parent_path();
      continue;
    }
    struct stat st {};
    const bool exists = ::lstat((at / name).c_str(), &st) == 0;
    const bool link = exists && S_ISLNK(st.st_mode);
    way.push_back({at, name, link});
    if (left.empty() && !link) last = at;
    if (!exists) break;
    if (!link) {
      at /= name;
      continue;
    }
    std::error_code ec;
    const std::filesystem::path target = std::filesystem::read_symlink(at / name, ec);
    if (ec || ++links > 40) break;
    const std::deque<std::string> more = names_of(target);
    left.insert(left.begin(), more.begin(), more.end());
    if (target.is_absolute()) at = target.root_path();
  }
  return way;
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
  alone_.erase(wd);  // watched for its links before: now for all its files
  std::error_code ec0;
  real_[std::filesystem::canonical(folder, ec0).string()] = wd;
  if (depth >= 3) return;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name[0] != '.' && entry.is_directory(ec) && !entry.is_symlink(ec)) add(entry.path(), depth + 1);
  }
}

void FileWatcher::add_alone(const std::filesystem::path& folder) {
  const int wd = ::inotify_add_watch(fd_, folder.c_str(), events | IN_ONLYDIR);
  if (wd < 0) throw Error("cannot watch '" + folder.string() + "': " + std::strerror(errno));
  if (watched_.emplace(wd, folder).second) alone_.insert(wd);  // else already watched for all its files
  real_[folder.string()] = wd;
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
          // One watched for its links is watched again when a change brings it back on the way.
          if (alone_.erase(e->wd) == 0) lost_.push_back(w->second);
          watched_.erase(w);
          std::erase_if(real_, [&](const auto& r) { return r.second == e->wd; });
        }
        continue;
      }
      if (e->len == 0) continue;
      // A name on the way to a followed file counts whatever it is (a folder, a hidden link); others count
      // in folders watched for all their files, unless folders or an editor's side files.
      const auto way = on_the_way_.find(e->wd);
      const bool on_way = way != on_the_way_.end() && way->second.count(e->name) != 0;
      if (!on_way && ((e->mask & IN_ISDIR) || side_file(e->name) || alone_.count(e->wd) != 0)) continue;
      ((e->mask & (IN_MOVED_FROM | IN_DELETE)) ? gone : written) = e->name;
    }
  }
  refollow();  // a change in a watched folder may have made the recipe a link, or pointed it elsewhere
  return written.empty() ? gone : written;
}

void FileWatcher::follow(const std::filesystem::path& file) {
  followed_.push_back(std::filesystem::absolute(file));
  refollow();
}

void FileWatcher::refollow() {
  on_the_way_.clear();
  for (const std::filesystem::path& file : followed_) {
    std::filesystem::path last;
    const std::vector<Step> way = way_to(file, last);
    // The folder holding what the path names is watched for all its files (modules beside the recipe);
    // a folder holding a link or a missing name on the way, for those names only.
    for (const Step& step : way) {
      const bool all = step.folder == last;
      const auto known = real_.find(step.folder.string());
      if (known != real_.end() && (!all || alone_.count(known->second) == 0)) continue;
      if ((!all && !step.link && std::filesystem::exists(step.folder / step.name)) ||
          (!skip_.empty() && inside(step.folder, skip_)))
        continue;  // a plain folder on the way: watched only where a link or the end is
      try {
        all ? add(step.folder, 0) : add_alone(step.folder);
      } catch (const Error&) {  // not watchable (no permission): its changes go unseen, watching goes on
        real_[step.folder.string()] = -1;
      }
    }
    for (const Step& step : way)
      if (const auto known = real_.find(step.folder.string()); known != real_.end() && known->second >= 0)
        on_the_way_[known->second].insert(step.name);
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
