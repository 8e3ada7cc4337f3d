// lsystem.load("tree.l" [, options]): a grammar from cpfg's file format (vlab's L-system files), its includes
// expanded (kernels/lsystem/cpfg_file.h), read by the book's reader (book_text.h) and made through lsystem{}'s
// own. Files are confined to the recipe's folder as load()'s are: a relative name without '..', opened
// without following a link, read at most up to a size fixed when it is opened.
#include <filesystem>
#include <string>

#include "frontend/bindings/lsystem_value.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "kernels/base/error.h"
#include "kernels/base/lower_case.h"
#include "kernels/io/regular_file.h"
#include "kernels/lsystem/cpfg_file.h"

namespace selfsim::interp {

namespace {

// One file of the model, relative to the recipe's folder.
std::string read_model_file(const std::filesystem::path& folder, const std::string& name) {
  const std::filesystem::path rel(name);
  if (name.empty() || rel.is_absolute())
    throw Error("'" + shown_text(name) + "' must be a file name relative to the recipe's folder");
  for (const auto& part : rel)
    if (part == "..") throw Error("'" + shown_text(name) + "' leads outside the recipe's folder ('..' is not allowed)");
  std::string text;
  const io::FileBeneath file(folder, rel);  // its errors name the file already
  try {
    const io::RegularFile f(file.name());
    if (f.size() > lsystem::max_cpfg_bytes)
      throw Error("over " + std::to_string(lsystem::max_cpfg_bytes >> 20) + " MiB: not an L-system file");
    text.resize(static_cast<std::size_t>(f.size()));
    if (f.read_at(0, text.data(), text.size()) != text.size()) throw Error("the file shrank while it was read");
  } catch (const Error& e) {
    throw Error("cannot read '" + shown_text(name) + "': " + e.what());
  }
  return text;
}

// A message on one line whatever the file held: control bytes escaped.
std::string one_line(const std::string& message) {
  std::string out;
  for (char c : message) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) {
      static const char hex[] = "0123456789abcdef";
      out += "\\x";
      out += hex[u >> 4];
      out += hex[u & 15];
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

int lsystem_load(lua_State* L) {
  return call_kernel(L, "lsystem.load", [&] {
    const int top = lua_gettop(L);
    const std::string name = text_value(L, 1, "argument 1 (the .l file's name)");
    if (top > 2) throw Error("takes the file's name and a table of options, lsystem.load(\"tree.l\", { angle = 30 })");
    if (top == 2 && lua_type(L, 2) != LUA_TTABLE && lua_type(L, 2) != LUA_TNIL)
      throw Error("argument 2 must be a table of options, got " + describe(L, 2));
    if (lower_case(std::filesystem::path(name).extension().string()) != ".l")
      throw Error("cannot load '" + shown_text(name) + "': expected cpfg's L-system file, 'name.l'");
    const std::filesystem::path folder = RunContext::of(L).config.recipe.parent_path();
    lsystem::CpfgText text;
    lsystem::BookGrammar b;
    try {
      text = lsystem::expand_cpfg(name, [&](const std::string& file) { return read_model_file(folder, file); });
      b = lsystem::read_book(text.text);
    } catch (const lsystem::BookError& e) {
      const lsystem::CpfgText::Origin& at = text.lines.at(std::min(e.line, text.lines.size()) - 1);
      throw Error(one_line(shown_text(at.file) + ":" + std::to_string(at.line) + ": " + e.what()));
    } catch (const Error& e) {
      throw Error(one_line(e.what()));
    }
    const bool table = top == 2 && lua_type(L, 2) == LUA_TTABLE;
    if (!b.axiom && !(table && lua_getfield(L, 2, "axiom") != LUA_TNIL))
      throw Error("'" + shown_text(name) + "' has no axiom: cpfg writes it as 'Axiom: F'");
    push_book_options(L, b, table ? 2 : 0);
    return push_lsystem(L, lua_gettop(L));
  });
}

}  // namespace selfsim::interp
