// An animated PNG (APNG) from the PNG files of its frames: a growth a person can play in any browser
// (Chromium, Firefox and Safari play APNG; a viewer that does not shows the first frame as a still PNG).
// Frames are whole PNG files of one size and pixel format, as the preview renderer writes them; their
// compressed image data is moved as it is (IDAT becomes fdAT), nothing is decoded or recompressed.
#pragma once

#include <string>
#include <vector>

namespace selfsim::io {

struct ApngFrame {
  std::string png;       // a whole PNG file
  double seconds = 0.5;  // how long it shows, in (0, 655.35]
};

// The APNG file's bytes, playing the frames in order and looping (`plays` times; 0 = forever). Throws Error
// naming the frame when one is not a PNG, its size or pixel format differs from the first's, or a delay is
// out of range; and when there are no frames.
std::string animated_png(const std::vector<ApngFrame>& frames, int plays = 0);

}  // namespace selfsim::io
