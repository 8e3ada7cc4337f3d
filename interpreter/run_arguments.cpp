// Parsing `selfsim run` arguments: RECIPE.lua [-o DIR] [--set key=value]... [--max-points N]
// [--timeout S] [--seed N] [-q].
#include "interpreter/commands.h"
#include "interpreter/parse_text.h"

namespace selfsim::interp {

double number_argument(const std::string& flag, const std::string& text, double lo) {
  const auto v = parse_text<double>(text);
  if (!v || *v < lo)
    throw UsageError(flag + " expects a number >= " + std::to_string(static_cast<long long>(lo)) + ", got '" + text + "'");
  return *v;
}

RunConfig parse_run_arguments(const std::vector<std::string>& args) {
  RunConfig c;
  bool have_recipe = false;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError(a + " expects a value");
      return args[++i];
    };
    if (a == "-o" || a == "--output") c.out_dir = value();
    else if (a == "--set") {
      const std::string& kv = value();
      const auto eq = kv.find('=');
      if (eq == std::string::npos || eq == 0) throw UsageError("--set expects key=value, got '" + kv + "'");
      c.sets[kv.substr(0, eq)] = kv.substr(eq + 1);
    } else if (a == "--max-points") c.max_points = number_argument(a, value(), 1);
    else if (a == "--timeout") c.timeout = number_argument(a, value(), 0);
    else if (a == "--seed") c.seed = static_cast<long long>(number_argument(a, value(), 0));
    else if (a == "-q" || a == "--quiet") c.quiet = true;
    else if (!a.empty() && a[0] == '-') throw UsageError("unknown option '" + a + "' for run");
    else if (have_recipe) throw UsageError("run takes one recipe, got '" + c.recipe.string() + "' and '" + a + "'");
    else {
      c.recipe = a;
      have_recipe = true;
    }
  }
  if (!have_recipe) throw UsageError("run expects a recipe file");
  return c;
}

}  // namespace selfsim::interp
