// A file being written inside an output folder, visible under its name only once complete.
//
// Confinement: the folders on the way are created and opened one by one relative to the output folder,
// never following a symbolic link (O_NOFOLLOW), so a link planted inside the folder cannot lead a write
// outside it. The output folder itself is the user's choice and may be a link (unless confine_output_root).
// Atomicity: the data goes to an anonymous file (O_TMPFILE), which a crash, a SIGKILL or the watchdog
// leaves no trace of; commit() links a new file straight under its name, and to replace an older file links
// it under a fresh dot-name and renames that over the target in one step.
// Where the filesystem has no O_TMPFILE, the temporary is a named file created exclusively (O_EXCL, never
// through a link) and removed on failure and by remove_temporaries().
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace selfsim::io {

class OutputFile {
 public:
  // Opens a temporary for `name` (relative, inside `root`); creates `root` and the folders of `name`.
  // Throws Error for a name that leaves the folder, a link or non-folder on the way, or a failed open.
  OutputFile(const std::filesystem::path& root, const std::string& name);
  ~OutputFile();  // removes the temporary unless committed
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  // Buffered writes; throw Error when the disk refuses them.
  void write(std::string_view bytes);
  void write(const void* data, std::size_t size) { write(std::string_view(static_cast<const char*>(data), size)); }
  // Flushes and puts the file in place under its name, replacing an older file (or link) of that name.
  void commit();
  // root/name, for messages and the run's summary.
  const std::string& path() const { return display_; }
  // The final component of the name ("dragon.svg").
  const std::string& leaf() const { return leaf_; }

 private:
  void flush();
  bool link_as(const std::string& name);
  void name_temporary();

  int dir_ = -1, fd_ = -1;
  std::string leaf_, display_, temporary_;  // temporary_: the named temporary, if there is one
  std::string buffer_;
  bool committed_ = false;
};

// Writes `text` as root/name, atomically and confined as any OutputFile (a sweep's manifest, sheets, job lists).
inline void write_whole(const std::filesystem::path& root, const std::string& name, std::string_view text) {
  OutputFile f(root, name);
  f.write(text);
  f.commit();
}

// Removes the regular files of root/folder (confined as OutputFile's folders are) whose names `remove`
// picks: the step files a series' earlier version named and its new version does not.
void remove_files(const std::filesystem::path& root, const std::filesystem::path& folder,
                  const std::function<bool(const std::string&)>& remove);

// Renames root/folder/from to root/folder/to (confined as OutputFile's folders are), replacing `to`.
void rename_file(const std::filesystem::path& root, const std::filesystem::path& folder, const std::string& from,
                 const std::string& to);

// Moves the file root/from to root/to (both relative, each folder on the way opened as OutputFile's are; the
// folders of `to` are created), replacing `to`: a run's staged files published into the output folder.
void move_file(const std::filesystem::path& root, const std::filesystem::path& from, const std::filesystem::path& to);

// Creates root/folder and the folders on the way as OutputFile does, refusing a link or file among them, and
// a folder that is absolute or climbs out with '..': a sweep's run folders and previews/.
void make_folder(const std::filesystem::path& root, const std::filesystem::path& folder);

// Opens root/name for writing as it goes (created or truncated; a log a child process writes into), its
// folders confined as OutputFile's and the file itself never a link. Returns the descriptor (close-on-exec).
int open_log(const std::filesystem::path& root, const std::filesystem::path& name);

// For a process whose output folder its parent made for it (a sweep's run folder, the studio's staging
// folder, given as -o): from now on every root is opened without following a link at its last component
// (made there when missing), so a link planted in its place after the parent made it is refused, not written
// through. Otherwise the output folder is the user's choice and may be a link.
void confine_output_root(bool refuse = true);

// Removes the named temporaries of every OutputFile still open: for a process ending without unwinding
// (the watchdog). Anonymous temporaries need nothing.
void remove_temporaries() noexcept;

}  // namespace selfsim::io
