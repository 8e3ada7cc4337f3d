// VTK reports errors as "ERROR: In .../vtkXMLReader.cxx, line 42\nvtkXMLPolyDataReader (0x55d0): what\n"
// followed by a dump of its pipeline. What a user needs is the first line after the location, without the
// object's name and address; the readers (vtk_read.cpp) and the preview renderer (preview_png.cpp) both
// turn VTK's text into that. No VTK header needed.
#pragma once

#include <string>

namespace selfsim::io {

// The first line of VTK's error text that says what failed, or "" when there is none.
inline std::string vtk_error_line(const std::string& text) {
  std::size_t begin = 0;
  while (begin < text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(begin, end - begin);
    begin = end + 1;
    if (line.empty() || line.rfind("ERROR: In ", 0) == 0) continue;
    if (line.rfind("vtk", 0) == 0)
      if (const std::size_t object = line.find("): "); object != std::string::npos && object < 80)
        line.erase(0, object + 3);
    return line;
  }
  return "";
}

}  // namespace selfsim::io
