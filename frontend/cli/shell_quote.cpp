#include "frontend/cli/shell_quote.h"

#include <algorithm>
#include <cctype>

#include "frontend/cli/commands.h"
#include "frontend/lua/lua_support.h"

namespace selfsim::interp {

std::string shell_word(std::string_view a) {
  const bool plain = !a.empty() && std::all_of(a.begin(), a.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) ||
           std::string_view("_-.,/=:+@%").find(c) != std::string_view::npos;
  });
  if (plain) return std::string(a);
  std::string word = "'";
  for (char c : a) word += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return word + "'";
}

std::string shell_command(const std::vector<std::string>& args) {
  std::string line = "selfsim";
  for (const std::string& a : args) line += " " + shell_word(a);
  return line;
}

std::string script_word(std::string_view word, const std::string& what) {
  if (word.find_first_of("\n\r") != std::string_view::npos)
    throw UsageError(what + " '" + shown_text(word, 200) +
                     "' holds a line break, which cannot go on a line of a job list or script (a sweep run here, "
                     "without --jobs-file or --slurm, takes it)");
  return shell_word(word);
}

std::string script_comment(std::string_view text) {
  std::string s;
  for (unsigned char c : text) s += c < 32 || c == 127 ? '?' : static_cast<char>(c);
  return s;
}

}  // namespace selfsim::interp
