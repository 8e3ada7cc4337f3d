#include "kernels/io/provenance/provenance.h"

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "kernels/base/error.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"
#include "kernels/io/text/json_text.h"

namespace selfsim::io {

namespace {

// JSON text with every second '-' of a run written \u002d: the line may sit inside an XML comment.
std::string comment_safe(const std::string& json) {
  std::string s;
  for (char c : json) {
    if (c == '-' && !s.empty() && s.back() == '-')
      s += "\\u002d";
    else
      s += c;
  }
  return s;
}

std::string head_of(const std::filesystem::path& file, std::size_t limit) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(cannot_read(file, "cannot open it"));
  std::string s(limit, '\0');
  in.read(s.data(), static_cast<std::streamsize>(limit));
  s.resize(static_cast<std::size_t>(in.gcount()));
  return s;
}

// The JSON after "selfsim_provenance " on one line (SVG, OBJ, PLY, EPS comments).
std::optional<std::string> marked_line(const std::string& text) {
  const std::string mark = std::string(provenance_key) + " ";
  const std::size_t at = text.find(mark);
  if (at == std::string::npos) return std::nullopt;
  const std::size_t begin = at + mark.size(), end = text.find('\n', begin);
  std::string line = text.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
  if (const std::size_t close = line.rfind(" -->"); close != std::string::npos) line.resize(close);
  return line;
}

// The string of a VTK XML FieldData String array named selfsim_provenance: character codes ending in 0.
std::optional<std::string> vtk_field_string(const std::string& text) {
  const std::size_t name = text.find("Name=\"" + std::string(provenance_key) + "\"");
  if (name == std::string::npos) return std::nullopt;
  const std::size_t open = text.find('>', name);
  if (open == std::string::npos) return std::nullopt;
  std::string s;
  const char* p = text.c_str() + open + 1;
  for (;;) {
    char* end = nullptr;
    const long c = std::strtol(p, &end, 10);
    if (end == p || c < 0 || c > 255) return std::nullopt;
    if (c == 0) return s;
    s += static_cast<char>(c);
    p = end;
  }
}

}  // namespace

std::string provenance_json(const Provenance& p) {
  std::string s = "{\"selfsim\": " + json_string(p.version) + ", \"recipe\": " + json_string(p.recipe) +
                  ", \"sha256\": " + json_string(p.sha256) + ", \"set\": {";
  bool first = true;
  for (const auto& [k, v] : p.sets) {
    s += (first ? "" : ", ") + json_string(k) + ": " + json_string(v);
    first = false;
  }
  s += "}, \"seed\": " + std::to_string(p.seed) + ", \"name\": " + json_string(p.name) + "}";
  return comment_safe(s);
}

bool provenance_beside(const std::string& extension) { return extension == ".stl" || extension == ".vdb"; }

std::optional<Provenance> read_provenance(const std::filesystem::path& file) {
  const std::string ext = lower_case(file.extension().string());
  std::optional<std::string> json;
  if (provenance_beside(ext)) {
    std::error_code ec;
    const std::filesystem::path beside = file.string() + ".json";
    if (!std::filesystem::is_regular_file(beside, ec)) return std::nullopt;
    json = head_of(beside, 1 << 16);
  } else if (ext == ".3mf") {
    json = marked_line(read_dataset(file).provenance);  // its Description, read by lib3mf in a child process
  } else if (ext == ".vtp" || ext == ".vtu") {
    json = vtk_field_string(head_of(file, 1 << 20));
  } else {
    json = marked_line(head_of(file, 1 << 16));
  }
  if (!json) return std::nullopt;
  try {
    return parse_provenance(*json);
  } catch (const Error& e) {  // a malformed field: say which file holds it
    throw Error(cannot_read(file, std::string("its provenance record: ") + e.what()));
  }
}

}  // namespace selfsim::io
