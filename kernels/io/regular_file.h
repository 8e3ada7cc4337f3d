// An input file opened for reading only if it is a regular file. It is opened without blocking (opening a
// FIFO for reading would otherwise wait for a writer), checked with fstat (directories, FIFOs, devices such
// as /dev/zero and sockets are refused), and read at most up to the size it had when it was opened, so a
// file that grows while it is read cannot keep a reader busy forever.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace selfsim::io {

class RegularFile {
 public:
  // Throws Error with the reason alone ("no such file or directory", "is a directory", ...). An empty file
  // is refused too, unless `empty_ok`: no data format selfsim reads is empty (an empty Lua file is fine).
  explicit RegularFile(const std::filesystem::path& file, bool empty_ok = false);
  ~RegularFile();
  RegularFile(const RegularFile&) = delete;
  RegularFile& operator=(const RegularFile&) = delete;

  int fd() const { return fd_; }
  // A name that opens the file checked, not whatever `file` names by then: /proc/self/fd/N (which a
  // forked child inherits), or `file` itself where /proc is not mounted.
  std::string reopen_name(const std::filesystem::path& file) const;
  // The size when opened: no read goes past it.
  std::uint64_t size() const { return size_; }
  // Reads min(n, size() - pos) bytes at pos into buffer and returns that count; throws Error when the file
  // shrank meanwhile or the read fails.
  std::size_t read_at(std::uint64_t pos, void* buffer, std::size_t n) const;

 private:
  int fd_ = -1;
  std::uint64_t size_ = 0;
};

// Reads a RegularFile front to back in chunks, never past its size at open.
class ChunkReader {
 public:
  explicit ChunkReader(const RegularFile& file, std::size_t chunk = std::size_t{1} << 20);
  // The next chunk (empty at the end of the file). Valid until the next call.
  std::string_view next();
  // File position of the first byte the next call to next() returns.
  std::uint64_t position() const { return pos_; }

 private:
  const RegularFile& file_;
  std::string buffer_;
  std::uint64_t pos_ = 0;
};

// A file opened inside a folder without following any symbolic link on the way or at its end (each
// component opened with O_NOFOLLOW), and held open, so that readers open it again through /proc/self/fd:
// a name swapped for a link between the check and the read cannot lead them outside.
class FileBeneath {
 public:
  // `rel` is relative without ".."; throws Error naming the link, or a missing or unreadable component.
  FileBeneath(const std::filesystem::path& folder, const std::filesystem::path& rel);
  ~FileBeneath();
  FileBeneath(const FileBeneath&) = delete;
  FileBeneath& operator=(const FileBeneath&) = delete;
  // The name that opens exactly this file.
  std::string name() const { return "/proc/self/fd/" + std::to_string(fd_); }

 private:
  int fd_ = -1;
};

// strerror(code) with a lower-case first letter, for "cannot read 'x': no such file or directory".
std::string error_text(int code);

}  // namespace selfsim::io
