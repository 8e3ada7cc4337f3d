#include "frontend/cli/sweep/literal_params.h"

#include <algorithm>
#include <cctype>

#include "kernels/base/error.h"
#include "kernels/io/regular_file.h"

namespace selfsim::interp {

namespace {

bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::size_t skip_space(std::string_view t, std::size_t i) {
  while (i < t.size() && std::isspace(static_cast<unsigned char>(t[i]))) ++i;
  return i;
}

// The literal that is the whole first argument of a call starting at `i` (just after the function's name):
// `("name", ...)`, `("name")` or `"name"`; nullopt for anything else.
std::optional<std::string> literal_argument(std::string_view t, std::size_t i) {
  i = skip_space(t, i);
  const bool paren = i < t.size() && t[i] == '(';
  if (paren) i = skip_space(t, i + 1);
  if (i >= t.size() || (t[i] != '"' && t[i] != '\'')) return std::nullopt;
  const char quote = t[i];
  const std::size_t start = ++i;
  while (i < t.size() && t[i] != quote) {
    if (t[i] == '\\' || t[i] == '\n') return std::nullopt;  // an escape or an unfinished string: not plain
    ++i;
  }
  if (i >= t.size()) return std::nullopt;
  const std::string name(t.substr(start, i - start));
  if (!paren) return name;
  i = skip_space(t, i + 1);
  if (i < t.size() && (t[i] == ',' || t[i] == ')')) return name;
  return std::nullopt;  // "fac" .. "ter": the name is computed
}

// Each mention of `word` as a name of its own, by the position after it; false when `f` says the text
// cannot tell, or at a field `t.word` or method `t:word`.
template <class F>
bool each_mention(std::string_view t, std::string_view word, F&& f) {
  for (std::size_t at = t.find(word); at != std::string_view::npos; at = t.find(word, at + 1)) {
    const std::size_t end = at + word.size();
    if (at > 0 && identifier_char(t[at - 1])) continue;  // part of another name
    if (end < t.size() && identifier_char(t[end])) continue;
    // `_G.param(...)` is the global itself, `t.param` may be anything: neither tells.
    if (at > 0 && (t[at - 1] == '.' || t[at - 1] == ':')) return false;
    if (!f(end)) return false;
  }
  return true;
}

// The level of a long bracket "[==[" starting at i (its count of '='), or -1 when there is none.
int long_bracket(std::string_view t, std::size_t i) {
  if (i >= t.size() || t[i] != '[') return -1;
  std::size_t j = i + 1;
  while (j < t.size() && t[j] == '=') ++j;
  return j < t.size() && t[j] == '[' ? static_cast<int>(j - i - 1) : -1;
}

// Past the long bracket of `level` opened at i: after its "]==]", or the end of the text.
std::size_t past_long_bracket(std::string_view t, std::size_t i, int level) {
  const std::string close = "]" + std::string(static_cast<std::size_t>(level), '=') + "]";
  const std::size_t at = t.find(close, i + static_cast<std::size_t>(level) + 2);
  return at == std::string_view::npos ? t.size() : at + close.size();
}

// The text with its comments blanked out (a comment that names param is no call of it); strings are kept,
// so that a "--" inside one starts no comment.
std::string without_comments(std::string_view t) {
  std::string out(t);
  std::size_t i = 0;
  while (i < t.size()) {
    if (t[i] == '"' || t[i] == '\'') {
      const char quote = t[i++];
      while (i < t.size() && t[i] != quote && t[i] != '\n') i += t[i] == '\\' ? 2 : 1;
      ++i;
    } else if (const int level = long_bracket(t, i); level >= 0) {
      i = past_long_bracket(t, i, level);
    } else if (t.compare(i, 2, "--") == 0) {
      const int level = long_bracket(t, i + 2);
      const std::size_t end = level >= 0 ? past_long_bracket(t, i + 2, level) : std::min(t.find('\n', i), t.size());
      for (std::size_t k = i; k < end && k < out.size(); ++k)
        if (out[k] != '\n') out[k] = ' ';
      i = end;
    } else {
      ++i;
    }
  }
  return out;
}

}  // namespace

std::optional<std::set<std::string>> literal_param_names(std::string_view source) {
  const std::string code = without_comments(source);
  const std::string_view text = code;
  std::set<std::string> names;
  const bool params = each_mention(text, "param", [&](std::size_t end) {
    const std::optional<std::string> name = literal_argument(text, end);
    if (name) names.insert(*name);
    return name.has_value();
  });
  const bool modules = each_mention(text, "require", [&](std::size_t end) {
    const std::optional<std::string> name = literal_argument(text, end);
    return name && name->starts_with("selfsim.");
  });
  if (!params || !modules) return std::nullopt;
  return names;
}

std::optional<std::set<std::string>> recipe_literal_params(const std::filesystem::path& recipe) {
  try {
    const io::RegularFile file(recipe, true);
    if (file.size() > (std::uint64_t{16} << 20)) return std::nullopt;
    std::string text(static_cast<std::size_t>(file.size()), '\0');
    text.resize(file.read_at(0, text.data(), text.size()));
    return literal_param_names(text);
  } catch (const Error&) {
    return std::nullopt;
  }
}

}  // namespace selfsim::interp
