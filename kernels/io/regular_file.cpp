#include "kernels/io/regular_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/io/read_error.h"

namespace selfsim::io {

std::string RegularFile::reopen_name(const std::filesystem::path& file) const {
  const std::string name = "/proc/self/fd/" + std::to_string(fd_);
  return ::access(name.c_str(), R_OK) == 0 ? name : file.string();
}

FileBeneath::FileBeneath(const std::filesystem::path& folder, const std::filesystem::path& rel) {
  int dir = ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);  // the user's choice
  if (dir < 0) throw Error(error_text(errno));
  std::vector<std::filesystem::path> parts(rel.begin(), rel.end());
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const bool last = i + 1 == parts.size();
    // O_NONBLOCK: a FIFO opens at once instead of waiting for a writer; RegularFile refuses it later.
    const int flags = O_RDONLY | O_NOFOLLOW | O_CLOEXEC | O_NOCTTY | (last ? O_NONBLOCK : O_DIRECTORY);
    int fd = -1;
    do fd = ::openat(dir, parts[i].c_str(), flags);
    while (fd < 0 && errno == EINTR);
    const int code = errno;
    ::close(dir);
    if (fd < 0) {
      struct stat st {};
      const bool link = code == ELOOP ||
                        (code == ENOTDIR && ::fstatat(AT_FDCWD, (folder / rel).c_str(), &st, AT_SYMLINK_NOFOLLOW) == 0);
      throw Error(link || code == ELOOP ? "'" + rel.string() + "' goes through a symbolic link, which is not followed"
                                        : cannot_read(rel, error_text(code)));
    }
    dir = fd;
  }
  fd_ = dir;
  if (::access(name().c_str(), R_OK) != 0) {
    ::close(fd_);
    throw Error("cannot read files safely here: /proc/self/fd is not available");
  }
}

FileBeneath::~FileBeneath() {
  if (fd_ >= 0) ::close(fd_);
}

std::string error_text(int code) {
  std::string s = std::strerror(code);
  if (!s.empty() && std::isupper(static_cast<unsigned char>(s[0])) &&
      (s.size() < 2 || std::islower(static_cast<unsigned char>(s[1]))))
    s[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(s[0])));
  return s;
}

namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISFIFO(mode)) return "is a FIFO, not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  return "is not a regular file";
}

}  // namespace

RegularFile::RegularFile(const std::filesystem::path& file, bool empty_ok) {
  if (file.empty()) throw Error("empty file name");
  // O_NONBLOCK: a FIFO opens at once instead of waiting for a writer; fstat then refuses it.
  do fd_ = ::open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  while (fd_ < 0 && errno == EINTR);
  if (fd_ < 0) throw Error(error_text(errno));
  struct stat st {};
  if (::fstat(fd_, &st) != 0) {
    const int code = errno;
    ::close(fd_);
    throw Error(error_text(code));
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd_);
    throw Error(kind_of(st.st_mode));
  }
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags >= 0) ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);
  size_ = static_cast<std::uint64_t>(st.st_size);
  if (size_ == 0 && !empty_ok) {
    ::close(fd_);
    throw Error("the file is empty");
  }
}

RegularFile::~RegularFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t RegularFile::read_at(std::uint64_t pos, void* buffer, std::size_t n) const {
  if (pos >= size_) return 0;
  n = static_cast<std::size_t>(std::min<std::uint64_t>(n, size_ - pos));
  std::size_t done = 0;
  while (done < n) {
    const ssize_t r = ::pread(fd_, static_cast<char*>(buffer) + done, n - done, static_cast<off_t>(pos + done));
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) throw Error(error_text(errno));
    if (r == 0) throw Error("the file shrank while it was read");
    done += static_cast<std::size_t>(r);
  }
  return n;
}

ChunkReader::ChunkReader(const RegularFile& file, std::size_t chunk)
    : file_(file), buffer_(static_cast<std::size_t>(std::min<std::uint64_t>(chunk, file.size())), '\0') {}

std::string_view ChunkReader::next() {
  const std::size_t n = file_.read_at(pos_, buffer_.data(), buffer_.size());
  pos_ += n;
  return {buffer_.data(), n};
}

}  // namespace selfsim::io
