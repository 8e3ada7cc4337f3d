// cpfg's L-system files (.l, the program of The Algorithmic Beauty of Plants, in vlab) before they are read:
// its C preprocessor's part that a model uses, '/* ... */' comments and '#include "file"' of a file beside the
// one that includes it, expanded into one text whose every line remembers where it came from. The text is then
// read by the book's reader (book_text.h), which knows cpfg's structure.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace selfsim::lsystem {

struct CpfgText {
  struct Origin {
    std::string file;  // as the recipe names it, "leaves/leaf.l"
    std::size_t line;  // 1-based
  };
  std::string text;
  std::vector<Origin> lines;  // lines[i]: where line i + 1 of text came from
};

// Reads a file by its name relative to the recipe's folder (the caller confines and budgets it); throws Error.
using CpfgReader = std::function<std::string(const std::string& name)>;

// Limits that keep a file's includes small: no real model comes near them.
constexpr std::size_t max_cpfg_bytes = std::size_t{8} << 20;  // all files together
constexpr int max_cpfg_includes = 64;
constexpr int max_cpfg_include_depth = 16;

// Expands `name` and its includes; throws Error naming the file and line: "tree.l:3: #include loop: ...".
CpfgText expand_cpfg(const std::string& name, const CpfgReader& read);

}  // namespace selfsim::lsystem
