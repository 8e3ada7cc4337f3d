#include "frontend/cli/watch/file_watcher.h"

#include <linux/magic.h>
#include <poll.h>
#include <sys/inotify.h>
#include <sys/stat.h>
#include <sys/statfs.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <deque>

#include "kernels/base/error.h"

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
  for (const std::filesystem::path& f : folders) {
    std::error_code ec;
    given_.emplace_back(std::filesystem::canonical(f, ec).string(), std::set<int>{});
    tree(f, 0, given_.back().second);
    base_.insert(given_.back().second.begin(), given_.back().second.end());
  }
  all_ = base_;
}

FileWatcher::~FileWatcher() {
  if (fd_ >= 0) ::close(fd_);
}

int FileWatcher::watch(const std::filesystem::path& folder) {
  // A pseudo file system's entries change by themselves and hold no one's sources: a link through /proc
  // (/proc/self/fd/0) is followed to what it names without watching /proc itself.
  static constexpr unsigned long pseudo[] = {PROC_SUPER_MAGIC,   SYSFS_MAGIC,         DEVPTS_SUPER_MAGIC,
                                             CGROUP_SUPER_MAGIC, CGROUP2_SUPER_MAGIC, DEBUGFS_MAGIC,
                                             TRACEFS_MAGIC,      SECURITYFS_MAGIC,    BPF_FS_MAGIC};
  struct statfs fs {};
  if (::statfs(folder.c_str(), &fs) == 0 && std::ranges::count(pseudo, static_cast<unsigned long>(fs.f_type)) != 0)
    return -1;
  const int wd = ::inotify_add_watch(fd_, folder.c_str(), events | IN_ONLYDIR);
  if (wd < 0) throw Error("cannot watch '" + folder.string() + "': " + std::strerror(errno));
  if (watched_.emplace(wd, folder).second) {  // the same folder watched again gives the same descriptor
    std::error_code ec;
    real_[std::filesystem::canonical(folder, ec).string()] = wd;
  }
  return wd;
}

void FileWatcher::tree(const std::filesystem::path& folder, int depth, std::set<int>& into) {
  if (!skip_.empty() && same_folder(folder, skip_)) return;
  const int wd = watch(folder);
  if (wd < 0) return;
  into.insert(wd);
  if (depth >= 3) return;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    if (name[0] != '.' && entry.is_directory(ec) && !entry.is_symlink(ec)) tree(entry.path(), depth + 1, into);
  }
}

void FileWatcher::forget(int wd) {
  watched_.erase(wd);
  std::erase_if(real_, [&](const auto& r) { return r.second == wd; });
  base_.erase(wd);
  all_.erase(wd);
  for (auto& [path, end] : ends_) end.all.erase(wd);
  on_the_way_.erase(wd);
}

std::string FileWatcher::drain() {
  // The name to report: the last file written or moved in (sed and many editors write a temporary and
  // rename it over the source: the source's name comes last), else the last one moved away or deleted.
  std::string written, gone;
  bool lost = false;
  alignas(inotify_event) char buffer[16384];
  for (;;) {
    const ssize_t n = ::read(fd_, buffer, sizeof buffer);
    if (n <= 0) break;
    for (ssize_t at = 0; at < n;) {
      const auto* e = reinterpret_cast<const inotify_event*>(buffer + at);
      at += static_cast<ssize_t>(sizeof(inotify_event) + e->len);
      const auto w = watched_.find(e->wd);
      if (w == watched_.end()) continue;  // removed by refollow: its events still queued are no change
      if (e->mask & IN_IGNORED) {         // the folder itself was deleted or moved away
        // A given folder is watched again when it is back; one on a way, when a change brings it back there.
        // An end's own folder, when back, is watched again by refollow (its name is on the way).
        if (base_.count(e->wd) != 0) lost_.emplace_back(w->second, "");
        for (const auto& [key, end] : ends_)
          if (end.root != e->wd && end.all.count(e->wd) != 0) lost_.emplace_back(w->second, key);
        forget(e->wd);
        lost = true;
        continue;
      }
      if (e->len == 0) continue;
      // A name on the way to a followed file counts whatever it is (a folder, a hidden link); others count
      // in folders watched for all their files, unless folders or an editor's side files.
      const auto way = on_the_way_.find(e->wd);
      const bool on_way = way != on_the_way_.end() && way->second.count(e->name) != 0;
      if (!on_way && ((e->mask & IN_ISDIR) || side_file(e->name) || all_.count(e->wd) == 0)) continue;
      // A device, pipe or socket written and closed (/dev/null, a terminal: every run writes them) is no
      // change; a file gone since it was written still is.
      struct stat st {};
      if ((e->mask & IN_CLOSE_WRITE) && ::lstat((w->second / e->name).c_str(), &st) == 0 && !S_ISREG(st.st_mode))
        continue;
      ((e->mask & (IN_MOVED_FROM | IN_DELETE)) ? gone : written) = e->name;
    }
  }
  // A change may have made the recipe a link, or pointed it elsewhere (a change of a link on the way is
  // counted, whatever its name); events that count for nothing change no way and cost no walk.
  if (lost || !written.empty() || !gone.empty()) refollow();
  return written.empty() ? gone : written;
}

void FileWatcher::follow(const std::filesystem::path& file) {
  const std::filesystem::path path = std::filesystem::absolute(file);
  followed_.emplace_back(path, false);
  followed_.emplace_back(path.parent_path(), true);
  // The file's own folder and the folder of what it links to now, when given, are followed as the ends of
  // these ways: watched while the ways lead there, not for good (r.lua -> ../e/t.lua made a regular file
  // again, or a folder link on the way re-pointed, left the old folder's writes starting runs). A folder
  // given for another reason too (the scripts folder) stays.
  std::error_code ec, ec2;
  const std::string real = std::filesystem::canonical(file, ec).parent_path().string();
  const std::string own = std::filesystem::canonical(path.parent_path(), ec2).string();
  for (const std::string& key : {ec ? std::string() : real, ec2 ? std::string() : own}) {
    const auto given = [&](const auto& g) { return g.first == key; };
    if (key.empty() || std::ranges::count_if(given_, given) != 1) continue;
    const auto it = std::ranges::find_if(given_, given);
    std::set<int> kept;
    for (const auto& [where, wds] : given_)
      if (where != key) kept.insert(wds.begin(), wds.end());
    for (const int wd : it->second)
      if (kept.count(wd) == 0) base_.erase(wd);
    given_.erase(it);
  }
  refollow();
}

void FileWatcher::refollow() {
  std::map<std::string, End> ends;
  on_the_way_.clear();
  // The end folder watched for all its files, and its subfolders; one watched already is kept as it is
  // (its subfolders are not walked again at every change).
  const auto end_at = [&](const std::filesystem::path& folder) {
    const std::string key = folder.string();
    if (const auto old = ends_.find(key); old != ends_.end() && watched_.count(old->second.root) != 0)
      ends[key] = old->second;
    End& end = ends[key];
    if (end.root < 0 && (end.root = watch(folder)) >= 0) tree(folder, 0, end.all);
  };
  for (const auto& [file, folder] : followed_) {
    std::filesystem::path last;
    const std::vector<Step> way = way_to(file, last);
    // The way ends at a regular file: its folder is watched for all its files (modules beside the recipe);
    // a followed folder, for all its files. At a device, pipe or socket (/dev/null, /proc/self/fd/0), not
    // at all: every process writes /dev, and what counts is the link to it re-pointed, seen in the link's
    // folder. At a missing name or one of another kind, only that name counts (its creation is a change).
    struct stat st {};
    const bool at_end = !last.empty() && ::lstat((last / way.back().name).c_str(), &st) == 0;
    const bool regular = at_end && !folder && S_ISREG(st.st_mode);
    const bool special = at_end && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
    const bool a_folder = at_end && folder && S_ISDIR(st.st_mode);
    for (const Step& step : way) {
      const bool final = &step == &way.back();
      if ((!skip_.empty() && inside(step.folder, skip_)) || (special && final)) continue;
      std::error_code ec;
      int wd = -1;
      try {
        if (regular && final) {
          end_at(step.folder);
          wd = ends[step.folder.string()].root;
        } else if (step.link || (final && !a_folder) || !std::filesystem::exists(step.folder / step.name, ec)) {
          wd = watch(step.folder);  // a link or a missing name: that name only
        } else if (const auto known = real_.find(step.folder.string()); known != real_.end()) {
          wd = known->second;  // a plain folder on the way, in a folder watched for another reason
        }
        if (a_folder && final) end_at(step.folder / step.name);
      } catch (const Error&) {  // not watchable (no permission): its changes go unseen, watching goes on
      }
      if (wd >= 0) on_the_way_[wd].insert(step.name);
    }
  }
  ends_ = std::move(ends);
  all_ = base_;
  for (const auto& [path, end] : ends_) all_.insert(end.all.begin(), end.all.end());
  // A watch kept for no reason any more (a link's old target, the folder of a name no longer on the way)
  // is removed: its files' writes must not start runs.
  std::vector<int> stale;
  for (const auto& [wd, folder] : watched_)
    if (all_.count(wd) == 0 && on_the_way_.count(wd) == 0) stale.push_back(wd);
  for (const int wd : stale) {
    ::inotify_rm_watch(fd_, wd);
    forget(wd);
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
    const auto end = ends_.find(it->second);
    if (!it->second.empty() && end == ends_.end()) {
      it = lost_.erase(it);  // its end is no longer on any way: no longer wanted
    } else if (std::filesystem::is_directory(it->first, ec)) {
      std::set<int>& into = it->second.empty() ? base_ : end->second.all;
      tree(it->first, 3, into);  // the folder alone: its subfolders come back with events of their own
      all_.insert(into.begin(), into.end());
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
