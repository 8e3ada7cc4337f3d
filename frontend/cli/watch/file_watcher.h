// Waiting for a recipe's sources to change, for `run --watch` and the studio: inotify on the recipe's
// folder (and its subfolders, where `require "lib.x"` finds lib/x.lua, and where load() reads data), and on
// the DSL's own scripts folder. The kernel says when a file is written; nothing is polled.
//
// Editors save in many ways (write in place, write a temporary and rename it over, vim's "4913" probe), so
// any file written, moved in or deleted counts, except hidden files, backups ("x~", ".swp") and the output
// folder (a run's own writes must not start the next run). A device, pipe or socket written and closed is
// no change: its content is no source, and every run writes /dev/null or a terminal.
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace selfsim::interp {

class FileWatcher {
 public:
  // Watches `folders` and their subfolders (to a depth of 3), never `skip` (the output folder) or a hidden
  // folder. Throws Error when inotify is unavailable or a folder cannot be watched.
  FileWatcher(const std::vector<std::filesystem::path>& folders, const std::filesystem::path& skip);
  ~FileWatcher();
  FileWatcher(const FileWatcher&) = delete;
  FileWatcher& operator=(const FileWatcher&) = delete;

  // Waits up to `timeout` for a change; returns the changed file's name (relative to its folder), or empty
  // on timeout or when a signal interrupted the wait. Changes that come together (an editor's save is often
  // several events) are gathered for `settle` after the first and reported as one.
  std::string wait(std::chrono::milliseconds timeout, std::chrono::milliseconds settle = std::chrono::milliseconds(30));

  // The descriptor to poll beside others (a run's pidfd, the studio's socket); readable when events are
  // pending. Then take() reads them: the changed file's name, or empty when they were only side files.
  int fd() const { return fd_; }
  std::string take(std::chrono::milliseconds settle = std::chrono::milliseconds(30));
  // Watches again the folders that were deleted, where they exist again; true when one came back.
  bool restore();
  // Watches also the folder of every link on the way from `file` to what it names: links at the file and at
  // any folder on its path (`proj/current -> v2`), and in their targets, up to 40 links as the kernel allows
  // (a loop stops there). Resolved again after every change seen, so a recipe that becomes a link or a folder
  // link re-pointed while watched (an editor or stow replacing them) has its new target's edits seen. In a
  // folder watched only for its links, only the names on the way count, hidden or not (`.config` folded by
  // stow); other files there are no change. The folder at the end is watched for all its files only when
  // the way ends at a regular file (not /dev/null, a terminal, a folder or a missing name: only that name
  // counts there); `file`'s own folder, as its path names it now, too (modules beside a link). Those two, when
  // among `folders`, are watched only while the ways lead there: folders no longer on any way are no longer
  // watched (a link's old target, a folder link's old folder); folders inside `skip` (a run's writes) and on
  // pseudo file systems (/proc, /sys) never are.
  void follow(const std::filesystem::path& file);

 private:
  // The folder at the end of a followed way, watched for all its files, and its subfolders.
  struct End {
    int root = -1;
    std::set<int> all;
  };
  int watch(const std::filesystem::path& folder);  // its descriptor; -1 for a pseudo file system (/proc)
  void tree(const std::filesystem::path& folder, int depth, std::set<int>& into);
  void forget(int wd);  // its records, once inotify dropped it or it was removed
  void refollow();      // watches the followed files' ways as they are now, drops the watches no longer needed
  std::string drain();  // the first counted change among the pending events, or empty

  // Why each watch exists decides what counts in it and when it goes: base_ (the recipe's own folders)
  // stay; ends_ and on_the_way_ are computed again at every refollow and the watches in neither are removed.
  int fd_ = -1;
  std::filesystem::path skip_;
  std::map<int, std::filesystem::path> watched_;              // every watch, by descriptor: its folder
  std::map<std::string, int> real_;                           // the watched folders' canonical paths, their descriptors
  std::set<int> base_;                                        // the folders given and their subfolders: all their files
  std::vector<std::pair<std::string, std::set<int>>> given_;  // each folder given: its canonical path, its tree
  std::map<std::string, End> ends_;                           // by canonical path: the followed ways' end folders
  std::set<int> all_;                                         // base_ and every end's: watched for all their files
  std::map<int, std::set<std::string>> on_the_way_;           // by descriptor: the names on a followed file's way
  // Folders deleted (git checkout may bring them back), and the end they belong to ("" for the given ones).
  std::vector<std::pair<std::filesystem::path, std::string>> lost_;
  // Absolute paths whose ways are followed: the files, and their folders (where require finds modules),
  // which are watched for all their files where they lead now.
  std::vector<std::pair<std::filesystem::path, bool>> followed_;  // true for a folder
};

// Whether an editor's side file (hidden, backup, swap, vim's "4913" probe) rather than a source.
bool side_file(const std::string& name);

}  // namespace selfsim::interp
