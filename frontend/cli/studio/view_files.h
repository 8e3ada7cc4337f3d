// The studio's 3D views, made after each good run beside the preview PNGs: for each 3D output (a mesh, a 3D
// curve, a .vdb as its surface, each step of a .pvd or .series), its geometry payload (geometry_payload.h)
// and a small index the page reads first, in the output folder's .studio/, served as the folder's other
// files are (confined below it). Made in a forked child (ViewChild) under the run's --max-memory and
// --timeout, so a huge mesh never blocks the page's loop nor takes the studio down; a new run stops it.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "frontend/lua/run_context.h"

namespace selfsim::interp {

// The most one step's payload may take: a browser given more would stall long before drawing it.
inline constexpr std::uint64_t view_max_bytes = std::uint64_t{768} << 20;

// Where the view of output `file` (relative to the output folder) goes, relative to the output folder:
// .studio/FILE.3d/ (shortened as a preview's name is when over 255 bytes), holding index.json and 0.bin,
// 1.bin, ... (a step each).
std::string view_folder(const std::string& file);

// Reads root/file (every file on the way opened below root without following a link, as the page's file
// serving does) with the readers `preview` uses, and writes its view into root/folder through the confined
// writer: the steps' payloads, then index.json: {"steps": ["0.bin", ...], "names": [each step's file],
// "bounds": [the union of the steps' bounds], "up": the axis up_axis.h picks for the last step (0, 1, 2),
// "legend": ...} (one colouring and one camera for a whole series, upright as the preview stands it),
// or {"error": "one line"} when it cannot be shown (the page then shows the PNG and says why).
void write_view(const std::filesystem::path& root, const std::string& file, const std::string& folder,
                const RunConfig& limits);

// write_view for each file, in a forked child process (no exec: the studio's own code, its descriptors closed
// at once) with the run's --max-memory added to what it holds and its --timeout once per file.
class ViewChild {
 public:
  ViewChild(const RunConfig& limits, const std::filesystem::path& root, const std::vector<std::string>& files);
  ~ViewChild();  // stops it
  ViewChild(const ViewChild&) = delete;
  ViewChild& operator=(const ViewChild&) = delete;
  // Readable when the child has ended (poll it); -1 once reaped.
  int fd() const { return pidfd_; }
  // True once the child has ended (and is reaped).
  bool finished();

 private:
  pid_t pid_ = -1;
  int pidfd_ = -1;
};

}  // namespace selfsim::interp
