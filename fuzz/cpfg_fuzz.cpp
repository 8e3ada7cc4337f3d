// Fuzz target: cpfg's .l files (kernels/lsystem/cpfg_file.h), then the book's reader on the expanded text.
// Input: the files of a model, in memory. The text up to the first line "@file NAME" is model.l, the file
// expanded; each "@file NAME" line starts the file NAME ("leaf.l", "sub/part.l") that an #include may name.
// Checks:
//   - expand_cpfg lets only a selfsim::Error escape, and asks the reader only for names beside the including
//     file: relative, without "..";
//   - every line of the expanded text has an origin (lines.size() = its newlines), each a file that was read
//     and a line of that file; the text is no larger than the files read (comments only shrink);
//   - then book_check.h on the text: read_book's BookError names a line that lines.at(line - 1) can map back
//     to its file, as lsystem.load does; rules parse; lsystem.book compiles them.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "fuzz/book_check.h"
#include "kernels/lsystem/cpfg_file.h"

namespace {

using namespace selfsim;
using fuzz::require;

std::map<std::string, std::string> split_files(std::string_view in) {
  std::map<std::string, std::string> files;
  std::string name = "model.l";
  std::size_t begin = 0, start = 0;
  while (begin <= in.size()) {
    std::size_t end = in.find('\n', begin);
    if (end == std::string_view::npos) end = in.size();
    const std::string_view line = in.substr(begin, end - begin);
    if (line.starts_with("@file ")) {
      files.emplace(name, std::string(in.substr(start, begin - start)));
      name = std::string(line.substr(6));
      start = std::min(end + 1, in.size());
    }
    begin = end + 1;
  }
  files.emplace(name, std::string(in.substr(start)));
  return files;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::map<std::string, std::string> files = split_files({reinterpret_cast<const char*>(data), size});
  std::map<std::string, std::size_t> read;  // name -> lines
  std::size_t bytes = 0;
  const lsystem::CpfgReader reader = [&](const std::string& name) {
    const std::filesystem::path p(name);
    require(!name.empty() && p.is_relative() && std::find(p.begin(), p.end(), "..") == p.end(),
            "expand_cpfg asked for '" + name + "', not a name beside the including file");
    const auto it = files.find(name);
    if (it == files.end()) throw Error("cannot read '" + name + "': no such file");
    read[name] = fuzz::line_count(it->second);
    bytes += it->second.size();
    return it->second;
  };
  lsystem::CpfgText text;
  try {
    text = lsystem::expand_cpfg("model.l", reader);
  } catch (const Error&) {
    return 0;
  } catch (...) {
    fuzz::unexpected_exception("expand_cpfg");
  }
  const auto newlines = static_cast<std::size_t>(std::count(text.text.begin(), text.text.end(), '\n'));
  require(text.lines.size() == newlines,
          std::to_string(text.lines.size()) + " origins for " + std::to_string(newlines) + " lines of expanded text");
  require(!text.lines.empty(), "an expanded text without lines");
  for (const lsystem::CpfgText::Origin& o : text.lines) {
    const auto it = read.find(o.file);
    require(it != read.end(), "a line from '" + o.file + "', a file never read");
    require(o.line >= 1 && o.line <= it->second, "line " + std::to_string(o.line) + " of '" + o.file + "', a file of " +
                                                     std::to_string(it->second) + " lines");
  }
  require(text.text.size() <= bytes + text.lines.size(), "the expanded text is larger than the files read");
  // lsystem.load maps a BookError's line back with lines.at(min(line, lines.size()) - 1): line 0 would throw.
  if (fuzz::check_read_book(text.text)) fuzz::run_lsystem_book(text.text);
  return 0;
}
