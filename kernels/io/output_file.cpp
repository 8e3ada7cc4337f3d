#include "kernels/io/output_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <cstring>
#include <mutex>
#include <vector>

#include "kernels/base/error.h"

namespace selfsim::io {

namespace {

constexpr std::size_t buffer_bytes = std::size_t{1} << 20;

// Named temporaries of open OutputFiles, by folder descriptor and name, for remove_temporaries().
std::mutex temporaries_mutex;
std::vector<std::pair<int, std::string>> temporaries;

void track(int dir, const std::string& name) {
  std::lock_guard lock(temporaries_mutex);
  temporaries.emplace_back(dir, name);
}

void untrack(int dir, const std::string& name) {
  std::lock_guard lock(temporaries_mutex);
  std::erase(temporaries, std::pair{dir, name});
}

std::string system_error() { return std::strerror(errno); }

// A name for a temporary beside `leaf` that no other run or file uses: dot-prefixed, with the process id
// and a counter.
std::string temporary_name(const std::string& leaf) {
  static std::atomic<unsigned> counter{0};
  return "." + leaf.substr(0, 64) + ".part-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
}

}  // namespace

namespace {

std::atomic<bool> root_link_refused{false};  // confine_output_root()

// The output folder opened (and made when missing). Under confine_output_root() its last component is made
// and opened by openat without following a link, so a link planted there after the parent's check is refused.
int open_root(const std::filesystem::path& root) {
  std::error_code ec;
  if (!root_link_refused.load()) {
    std::filesystem::create_directories(root, ec);
    const int dir = ::open(root.c_str(), O_DIRECTORY | O_RDONLY | O_CLOEXEC);
    if (dir < 0)
      throw Error("cannot open the output folder '" + root.string() + "': " + (ec ? ec.message() : system_error()));
    return dir;
  }
  std::filesystem::path r = root.lexically_normal();
  while (!r.has_filename() && r.has_parent_path() && r.parent_path() != r) r = r.parent_path();  // "out/x/"
  const std::filesystem::path up = r.has_parent_path() ? r.parent_path() : std::filesystem::path(".");
  std::filesystem::create_directories(up, ec);
  const int parent = ::open(up.c_str(), O_DIRECTORY | O_RDONLY | O_CLOEXEC);
  if (parent < 0) throw Error("cannot open the output folder '" + up.string() + "': " + system_error());
  const std::string leaf = r.filename().string();
  if (::mkdirat(parent, leaf.c_str(), 0777) != 0 && errno != EEXIST) {
    const std::string why = system_error();
    ::close(parent);
    throw Error("cannot create the output folder '" + root.string() + "': " + why);
  }
  const int dir = ::openat(parent, leaf.c_str(), O_DIRECTORY | O_NOFOLLOW | O_RDONLY | O_CLOEXEC);
  const int err = errno;
  ::close(parent);
  if (dir < 0) {
    if (err == ELOOP || err == ENOTDIR)
      throw Error("'" + root.string() +
                  "' is a symbolic link or not a folder: selfsim writes only inside the output folder");
    throw Error("cannot open the output folder '" + root.string() + "': " + std::strerror(err));
  }
  return dir;
}

}  // namespace

void confine_output_root(bool refuse) { root_link_refused.store(refuse); }

// Opens root/folder for writing, creating the folders on the way one by one and never following a link
// below root.
static int open_folder(const std::filesystem::path& root, const std::filesystem::path& folder) {
  int dir = open_root(root);
  std::filesystem::path walked = root;
  for (const auto& part : folder) {
    walked /= part;
    if (::mkdirat(dir, part.c_str(), 0777) != 0 && errno != EEXIST) {
      ::close(dir);
      throw Error("cannot create folder '" + walked.string() + "': " + system_error());
    }
    const int next = ::openat(dir, part.c_str(), O_DIRECTORY | O_NOFOLLOW | O_RDONLY | O_CLOEXEC);
    const int err = errno;
    ::close(dir);
    if (next < 0) {
      if (err == ELOOP || err == ENOTDIR)
        throw Error("'" + walked.string() +
                    "' is a symbolic link or not a folder: selfsim writes only inside the output folder");
      throw Error("cannot open folder '" + walked.string() + "': " + std::strerror(err));
    }
    dir = next;
  }
  return dir;
}

OutputFile::OutputFile(const std::filesystem::path& root, const std::string& name) {
  const std::filesystem::path rel = std::filesystem::path(name).lexically_normal();
  if (name.empty() || name.find('\0') != std::string::npos || rel.is_absolute() || rel.empty() ||
      *rel.begin() == ".." || !rel.has_filename() || rel.filename() == "." || rel.filename() == "..")
    throw Error("path '" + name + "' is outside the output folder (give a relative file name such as 'curve.vtp')");
  for (unsigned char c : name)
    if (c < 32 || c == 127) throw Error("file names must not contain control characters (a newline, a tab)");
  for (const auto& part : rel)
    if (part.string().size() > NAME_MAX)
      throw Error("name '" + part.string().substr(0, 40) + "...' is longer than " + std::to_string(NAME_MAX) +
                  " bytes");
  leaf_ = rel.filename().string();
  display_ = (root / rel).string();

  dir_ = open_folder(root, rel.parent_path());
  fd_ = ::openat(dir_, ".", O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
  if (fd_ < 0) {  // no O_TMPFILE here: an exclusive named temporary instead
    temporary_ = temporary_name(leaf_);
    fd_ = ::openat(dir_, temporary_.c_str(), O_CREAT | O_EXCL | O_WRONLY | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd_ < 0) {
      const std::string why = system_error();
      temporary_.clear();
      throw Error("cannot write '" + display_ + "': " + why);
    }
    track(dir_, temporary_);
  }
  buffer_.reserve(buffer_bytes);
}

OutputFile::~OutputFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!committed_ && !temporary_.empty()) {
    ::unlinkat(dir_, temporary_.c_str(), 0);
    untrack(dir_, temporary_);
  }
  if (dir_ >= 0) ::close(dir_);
}

void OutputFile::write(std::string_view bytes) {
  if (buffer_.size() + bytes.size() > buffer_bytes) flush();
  if (bytes.size() > buffer_bytes) {
    buffer_ = bytes;  // rare: one piece bigger than the buffer
    flush();
    return;
  }
  buffer_.append(bytes);
}

void OutputFile::flush() {
  const char* p = buffer_.data();
  std::size_t left = buffer_.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      throw Error("cannot write '" + display_ + "': " + (n < 0 ? system_error() : "no progress") + " (disk full?)");
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  buffer_.clear();
}

// Links the anonymous file under `name` in the folder (through /proc, which needs no privilege); fails
// with EEXIST if the name is taken.
bool OutputFile::link_as(const std::string& name) {
  const std::string proc = "/proc/self/fd/" + std::to_string(fd_);
  return ::linkat(AT_FDCWD, proc.c_str(), dir_, name.c_str(), AT_SYMLINK_FOLLOW) == 0;
}

// Gives the anonymous file a fresh name beside the target.
void OutputFile::name_temporary() {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const std::string name = temporary_name(leaf_);
    track(dir_, name);
    if (link_as(name)) {
      temporary_ = name;
      return;
    }
    const int err = errno;
    untrack(dir_, name);
    if (err != EEXIST) throw Error("cannot write '" + display_ + "': " + std::strerror(err));
  }
  throw Error("cannot write '" + display_ + "': no free temporary name");
}

void OutputFile::commit() {
  flush();
  if (temporary_.empty()) {
    // A new file is linked straight under its name: nothing is ever visible but the whole file. Only a file
    // replacing an older one needs a named step (link, then rename over the old one): a SIGKILL in that
    // instant leaves the dot-named temporary.
    if (link_as(leaf_)) {
      committed_ = true;
      return;
    }
    name_temporary();
  }
  if (::renameat(dir_, temporary_.c_str(), dir_, leaf_.c_str()) != 0) {
    const int err = errno;
    throw Error("cannot write '" + display_ + "': " +
                (err == EISDIR || err == ENOTEMPTY || err == EEXIST ? std::string("a folder of that name is in the way")
                                                                    : std::strerror(err)));
  }
  untrack(dir_, temporary_);
  committed_ = true;
}

// A plain file, not a link or folder (asking the folder where the listing cannot tell).
static bool regular(int dir, const dirent& e) {
  if (e.d_type != DT_UNKNOWN) return e.d_type == DT_REG;
  struct stat st {};
  return ::fstatat(dir, e.d_name, &st, AT_SYMLINK_NOFOLLOW) == 0 && S_ISREG(st.st_mode);
}

void remove_files(const std::filesystem::path& root, const std::filesystem::path& folder,
                  const std::function<bool(const std::string&)>& remove) {
  const int dir = open_folder(root, folder);
  const int copy = ::dup(dir);
  DIR* listing = copy >= 0 ? ::fdopendir(copy) : nullptr;
  if (listing == nullptr && copy >= 0) ::close(copy);
  std::vector<std::string> doomed;
  if (listing != nullptr) {
    while (const dirent* e = ::readdir(listing))
      if (regular(dir, *e) && remove(e->d_name)) doomed.emplace_back(e->d_name);
    ::closedir(listing);
  }
  for (const std::string& name : doomed) ::unlinkat(dir, name.c_str(), 0);
  ::close(dir);
}

void rename_file(const std::filesystem::path& root, const std::filesystem::path& folder, const std::string& from,
                 const std::string& to) {
  const int dir = open_folder(root, folder);
  const int result = ::renameat(dir, from.c_str(), dir, to.c_str());
  const int err = errno;
  ::close(dir);
  if (result != 0)
    throw Error(
        "cannot write '" + (root / folder / to).string() + "': " +
        (err == EISDIR || err == ENOTEMPTY ? std::string("a folder of that name is in the way") : std::strerror(err)));
}

// The folder of `rel` (relative, inside root, no '..') opened confined, and its leaf; throws Error.
static std::pair<int, std::string> open_parent(const std::filesystem::path& root, const std::filesystem::path& rel) {
  const std::filesystem::path n = rel.lexically_normal();
  if (n.empty() || n.is_absolute() || *n.begin() == ".." || !n.has_filename() || n.filename() == "..")
    throw Error("path '" + rel.string() + "' is outside the output folder");
  return {open_folder(root, n.parent_path()), n.filename().string()};
}

void move_file(const std::filesystem::path& root, const std::filesystem::path& from, const std::filesystem::path& to) {
  const auto [source, from_leaf] = open_parent(root, from);
  int target = -1;
  try {
    target = open_parent(root, to).first;
  } catch (...) {
    ::close(source);
    throw;
  }
  const int result = ::renameat(source, from_leaf.c_str(), target, to.filename().c_str());
  const int err = errno;
  ::close(source);
  ::close(target);
  if (result != 0)
    throw Error(
        "cannot write '" + (root / to).string() + "': " +
        (err == EISDIR || err == ENOTEMPTY ? std::string("a folder of that name is in the way") : std::strerror(err)));
}

void make_folder(const std::filesystem::path& root, const std::filesystem::path& folder) {
  // The same rule as every name below root: relative, never climbing out ("" or "." is root itself).
  const std::filesystem::path n = folder.lexically_normal();
  if (folder.native().find('\0') != std::string::npos || n.is_absolute() || (!n.empty() && *n.begin() == ".."))
    throw Error("path '" + folder.string() + "' is outside the output folder");
  ::close(open_folder(root, n));
}

int open_log(const std::filesystem::path& root, const std::filesystem::path& name) {
  const auto [dir, leaf] = open_parent(root, name);
  // O_NONBLOCK: a FIFO planted at the log's name must not hold the caller (the studio's loop) until a
  // reader comes; whatever opens is then taken only if it is a regular file.
  const int fd = ::openat(dir, leaf.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC | O_NONBLOCK, 0644);
  const int err = errno;
  ::close(dir);
  if (fd < 0)
    throw Error("cannot write '" + (root / name).string() + "': " +
                (err == ELOOP   ? std::string("it is a symbolic link")
                 : err == ENXIO ? std::string("it is not a regular file")
                                : std::strerror(err)));
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    ::close(fd);
    throw Error("cannot write '" + (root / name).string() + "': it is not a regular file");
  }
  return fd;
}

void remove_temporaries() noexcept {
  std::lock_guard lock(temporaries_mutex);
  for (const auto& [dir, name] : temporaries) ::unlinkat(dir, name.c_str(), 0);
  temporaries.clear();
}

}  // namespace selfsim::io
