#include "kernels/lsystem/cpfg_file.h"

#include <algorithm>
#include <filesystem>
#include <string_view>

#include "kernels/base/error.h"

namespace selfsim::lsystem {

namespace {

struct Expansion {
  const CpfgReader& read;
  CpfgText out;
  std::vector<std::string> stack;  // the files being expanded, outermost first
  std::size_t bytes = 0;
  int includes = 0;
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

std::string where(const std::string& file, std::size_t line) { return file + ":" + std::to_string(line) + ": "; }

// The text without its '/* ... */' comments, each replaced by the newlines it held so lines keep their numbers.
std::string without_comments(const std::string& file, std::string_view text) {
  std::string out;
  out.reserve(text.size());
  std::size_t line = 1;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.compare(i, 2, "/*") == 0) {
      const std::size_t end = text.find("*/", i + 2);
      if (end == std::string_view::npos) throw Error(where(file, line) + "a '/*' comment is never closed");
      const std::size_t newlines = static_cast<std::size_t>(std::count(text.begin() + i, text.begin() + end, '\n'));
      out.append(newlines, '\n');
      out += ' ';
      line += newlines;
      i = end + 1;
      continue;
    }
    if (text[i] == '\n') ++line;
    out += text[i];
  }
  return out;
}

void expand(Expansion& x, const std::string& file, const std::string& from) {
  if (std::find(x.stack.begin(), x.stack.end(), file) != x.stack.end()) {
    std::string chain;
    for (const std::string& f : x.stack) chain += f + " -> ";
    throw Error(from + "#include loop: " + chain + file);
  }
  if (static_cast<int>(x.stack.size()) >= max_cpfg_include_depth)
    throw Error(from + "#include nested over " + std::to_string(max_cpfg_include_depth) + " files deep");
  std::string raw;
  try {
    raw = x.read(file);
  } catch (const Error& e) {
    throw Error(from + e.what());
  }
  x.bytes += raw.size();
  if (x.bytes > max_cpfg_bytes)
    throw Error(from + "the files hold over " + std::to_string(max_cpfg_bytes >> 20) +
                " MiB together: not an L-system");
  if (const std::size_t nul = raw.find('\0'); nul != std::string::npos)
    throw Error(where(file, 1 + static_cast<std::size_t>(std::count(raw.begin(), raw.begin() + nul, '\n'))) +
                "a NUL byte: not a text file");
  x.stack.push_back(file);
  const std::string text = without_comments(file, raw);
  std::size_t line = 0, begin = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == std::string::npos) end = text.size();
    ++line;
    const std::string_view l = std::string_view(text).substr(begin, end - begin);
    begin = end + 1;
    const std::string_view t = trim(l);
    if (t.starts_with("#include")) {
      const std::string_view arg = trim(t.substr(8));
      const char close = arg.starts_with('"') ? '"' : arg.starts_with('<') ? '>' : '\0';
      const std::size_t stop = close ? arg.find(close, 1) : std::string_view::npos;
      if (!close || stop == std::string_view::npos || stop == 1)
        throw Error(where(file, line) + "expected #include \"file.l\" (a file beside this one)");
      const std::filesystem::path rel(std::string(arg.substr(1, stop - 1)));
      if (rel.is_absolute() || std::find(rel.begin(), rel.end(), "..") != rel.end())
        throw Error(where(file, line) + "#include names a file beside this one, without '..' or a leading '/'");
      if (++x.includes > max_cpfg_includes)
        throw Error(where(file, line) + "over " + std::to_string(max_cpfg_includes) + " #include lines");
      expand(x, (std::filesystem::path(file).parent_path() / rel).generic_string(), where(file, line));
      continue;
    }
    x.out.text.append(l);
    x.out.text += '\n';
    x.out.lines.push_back({file, line});
  }
  x.stack.pop_back();
}

}  // namespace

CpfgText expand_cpfg(const std::string& name, const CpfgReader& read) {
  Expansion x{read, {}, {}, 0, 0};
  expand(x, name, "");
  return std::move(x.out);
}

}  // namespace selfsim::lsystem
