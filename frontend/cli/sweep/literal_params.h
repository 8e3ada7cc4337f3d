// The parameter names a recipe's text declares literally, to tell a misspelt `--set` key from a parameter
// the recipe declares after the point that `selfsim params` reads to (its first heavy step). A sweep whose
// key names no parameter then stops before any run instead of running every combination at the default.
#pragma once

#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>

namespace selfsim::interp {

// Every name given to param() in `text`; nullopt when the text cannot tell: a mention of `param` that is not
// a call whose whole first argument is a plain string literal (an alias, a computed name, a comment that
// names it), or a require of a module other than selfsim's own (a module may declare parameters too).
std::optional<std::set<std::string>> literal_param_names(std::string_view text);

// The same for a recipe file; nullopt too when it cannot be read or is over 16 MiB.
std::optional<std::set<std::string>> recipe_literal_params(const std::filesystem::path& recipe);

}  // namespace selfsim::interp
