#include "kernels/io/provenance.h"

#include <cstdlib>
#include <fstream>
#include <iterator>

#include "kernels/geom/error.h"
#include "kernels/geom/lower_case.h"
#include "kernels/io/json_text.h"
#include "kernels/io/read.h"
#include "kernels/io/read_error.h"

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

// A reader for exactly the JSON provenance_json writes: an object of strings, one object of strings and
// one whole number. Anything else gives nullopt.
class Parser {
 public:
  explicit Parser(const std::string& text) : t_(text) {}

  std::optional<Provenance> provenance() {
    Provenance p;
    if (!eat('{')) return std::nullopt;
    do {
      std::string key;
      if (!string(key) || !eat(':')) return std::nullopt;
      if (key == "set") {
        if (!eat('{')) return std::nullopt;
        if (!eat('}')) {
          do {
            std::string k, v;
            if (!string(k) || !eat(':') || !string(v)) return std::nullopt;
            p.sets[k] = v;
          } while (eat(','));
          if (!eat('}')) return std::nullopt;
        }
      } else if (key == "seed") {
        skip();
        char* end = nullptr;
        p.seed = std::strtoll(t_.c_str() + i_, &end, 10);
        if (end == t_.c_str() + i_) return std::nullopt;
        i_ = static_cast<std::size_t>(end - t_.c_str());
      } else {
        std::string value;
        if (!string(value)) return std::nullopt;
        if (key == "selfsim")
          p.version = value;
        else if (key == "recipe")
          p.recipe = value;
        else if (key == "sha256")
          p.sha256 = value;
        else if (key == "name")
          p.name = value;
      }
    } while (eat(','));
    if (!eat('}') || p.recipe.empty()) return std::nullopt;
    return p;
  }

 private:
  void skip() {
    while (i_ < t_.size() && (t_[i_] == ' ' || t_[i_] == '\n' || t_[i_] == '\t' || t_[i_] == '\r')) ++i_;
  }
  bool eat(char c) {
    skip();
    if (i_ < t_.size() && t_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  bool string(std::string& out) {
    if (!eat('"')) return false;
    for (; i_ < t_.size(); ++i_) {
      const char c = t_[i_];
      if (c == '"') {
        ++i_;
        return true;
      }
      if (c != '\\') {
        out += c;
        continue;
      }
      if (++i_ >= t_.size()) return false;
      const char e = t_[i_];
      if (e == 'u') {  // only the ASCII escapes json_escaped writes
        if (i_ + 4 >= t_.size()) return false;
        out += static_cast<char>(std::strtol(t_.substr(i_ + 1, 4).c_str(), nullptr, 16));
        i_ += 4;
      } else {
        out += e == 'n' ? '\n' : e == 't' ? '\t' : e;
      }
    }
    return false;
  }

  const std::string& t_;
  std::size_t i_ = 0;
};

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

std::optional<Provenance> parse_provenance(const std::string& json) { return Parser(json).provenance(); }

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
  return parse_provenance(*json);
}

}  // namespace selfsim::io
