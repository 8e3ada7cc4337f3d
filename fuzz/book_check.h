// Shared by the book and cpfg targets: the book's text through its reader (kernels/lsystem/book_text.h) with
// what the reader promises checked, then through lsystem.book in a sandbox, so the translated rules are
// compiled by lsystem{}'s own reader (frontend/bindings/lsystem_rules.cpp, Grammar::validate) as a recipe's
// would be, and a few levels are rewritten.
#pragma once

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <lua.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "frontend/bindings/bindings.h"
#include "frontend/lua/run_context.h"
#include "frontend/lua/sandbox.h"
#include "fuzz/fuzz_support.h"
#include "kernels/base/error.h"
#include "kernels/lsystem/book_text.h"
#include "kernels/lsystem/rule_parser.h"

namespace selfsim::fuzz {

inline std::size_t line_count(std::string_view text) {
  return 1 + static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

// read_book on `text`: only a BookError may escape, naming a line of the text; what it returns holds rules
// and an axiom that rule_parser reads with the constants in scope ("every rule and the axiom are checked"),
// each rule on a line of the text, finite constants and angle. Returns whether the text was read.
inline bool check_read_book(std::string_view text) {
  lsystem::BookGrammar b;
  const std::size_t lines = line_count(text);
  try {
    b = lsystem::read_book(text);
  } catch (const lsystem::BookError& e) {
    // lsystem.load maps the line back to its file with lines.at(line - 1).
    require(e.line >= 1 && e.line <= lines, "BookError names line " + std::to_string(e.line) + " of a text of " +
                                                std::to_string(lines) + " lines: " + e.what());
    if (env_flag("SELFSIM_FUZZ_VERBOSE")) std::fprintf(stderr, "read_book: line %zu: %s\n", e.line, e.what());
    return false;
  } catch (const Error& e) {
    finding(std::string("read_book threw an Error that is not a BookError (no line): ") + e.what());
  } catch (...) {
    unexpected_exception("read_book");
  }
  std::vector<std::string> constants;
  for (const auto& [name, value] : b.defines) {
    require(std::isfinite(value), "#define " + name + " is not finite");
    constants.push_back(name);
  }
  if (b.angle) require(std::isfinite(*b.angle), "the angle is not finite");
  for (const lsystem::BookRule& r : b.rules) {
    require(r.line >= 1 && r.line <= lines,
            "a rule on line " + std::to_string(r.line) + " of a text of " + std::to_string(lines) + " lines");
    try {
      lsystem::parse_rule(r.text, "rule", constants);
    } catch (const Error& e) {
      finding("read_book returned a rule that rule_parser refuses: \"" + r.text + "\": " + e.what());
    } catch (...) {
      unexpected_exception("parse_rule");
    }
  }
  if (b.axiom) {
    try {
      lsystem::parse_calls(*b.axiom, constants);
    } catch (const Error& e) {
      finding("read_book returned an axiom that rule_parser refuses: \"" + *b.axiom + "\": " + e.what());
    } catch (...) {
      unexpected_exception("parse_calls");
    }
  }
  return true;
}

// lsystem.book(text) in a sandbox as `selfsim run` makes it, then the grammar's string at a level of at most 2.
// Small limits keep each execution short. No C++ exception may escape a binding.
inline void run_lsystem_book(std::string_view text) {
  namespace fs = std::filesystem;
  static const fs::path root = fs::temp_directory_path() / ("selfsim-fuzz-book-" + std::to_string(::getpid()));
  interp::RunConfig config;
  config.recipe = root / "recipe.lua";  // never read: the chunk is given as text
  config.out_dir = root / "out";
  config.max_points = 1e5;
  config.max_memory = 64 << 20;
  config.timeout = 1;
  config.quiet = true;
  try {
    interp::RunContext run(config);
    run.scripts_dir = SELFSIM_SCRIPTS_DIR;
    lua_State* L = interp::new_sandbox(run);
    if (L == nullptr) finding("new_sandbox returned no state");
    interp::open_all(L);
    int status = luaL_loadstring(L,
                                 "local g = lsystem.book(...)\n"
                                 "local ok, s = pcall(g.string, g, 0)\n"
                                 "ok, s = pcall(g.string, g, 2)\n");
    if (status != LUA_OK) finding("the driver chunk does not load");
    lua_pushlstring(L, text.data(), text.size());
    status = lua_pcall(L, 1, 0, 0);
    run.ended = true;
    if (status != LUA_OK && status != LUA_ERRRUN && status != LUA_ERRMEM && status != LUA_ERRERR) {
      const char* message = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "(not a string)";
      finding("lua_pcall returned status " + std::to_string(status) +
              ": a C++ exception escaped lsystem.book; message on the stack: " + message);
    }
    if (env_flag("SELFSIM_FUZZ_VERBOSE"))
      std::fprintf(stderr, "lsystem.book: %s\n",
                   status == LUA_OK                 ? "compiled, levels 0 and 2 rewritten"
                   : lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1)
                                                    : "(an error that is not a string)");
    lua_close(L);
  } catch (...) {
    unexpected_exception("lsystem.book");
  }
  std::error_code ignored;
  if (fs::exists(config.out_dir, ignored)) finding("lsystem.book wrote into the output folder");
}

}  // namespace selfsim::fuzz
