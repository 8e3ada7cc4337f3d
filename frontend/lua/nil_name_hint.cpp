#include "frontend/lua/nil_name_hint.h"

#include <cctype>
#include <string_view>
#include <vector>

#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "kernels/io/regular_file.h"

namespace selfsim::interp {

namespace {

// The string keys of the table at the top of the stack whose values are not nil.
std::vector<std::string> string_keys(lua_State* L) {
  std::vector<std::string> keys;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    lua_pop(L, 1);
    if (lua_type(L, -1) == LUA_TSTRING) keys.emplace_back(lua_tostring(L, -1));
  }
  return keys;
}

// Line `line` (from 1) of a Lua file, or empty. The recipe or module that raised was read whole already.
std::string source_line(const std::string& file, int line) {
  const io::RegularFile f(file, true);
  std::string bytes(static_cast<std::size_t>(std::min<std::uint64_t>(f.size(), 64u << 20)), '\0');
  bytes.resize(f.read_at(0, bytes.data(), bytes.size()));
  std::size_t begin = 0;
  for (int i = 1; i < line && begin != std::string::npos; ++i) {
    begin = bytes.find('\n', begin);
    if (begin != std::string::npos) ++begin;
  }
  if (begin == std::string::npos) return "";
  return bytes.substr(begin, bytes.find('\n', begin) - begin);
}

bool is_name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// True when the function at `ar` has an active local named `name` (which would shadow the global).
bool has_local(lua_State* L, const lua_Debug* ar, const std::string& name) {
  for (int n = 1;; ++n) {
    const char* local = lua_getlocal(L, ar, n);
    if (local == nullptr) return false;
    lua_pop(L, 1);
    if (name == local) return true;
  }
}

// For a nil field `field` at the error site: the global table the source line indexes as `T.field` (or
// `T:field`) and the closest key of T, as "T.key"; empty when there is none.
std::string field_meant(lua_State* L, const std::string& field, std::string* table_name) {
  lua_Debug ar;
  if (!lua_getstack(L, 1, &ar) || !lua_getinfo(L, "Sl", &ar) || ar.source[0] != '@' || ar.currentline <= 0) return "";
  const std::string line = source_line(ar.source + 1, ar.currentline);
  for (std::size_t at = line.find(field); at != std::string::npos; at = line.find(field, at + 1)) {
    if (at + field.size() < line.size() && is_name_char(line[at + field.size()])) continue;
    std::size_t i = at;
    while (i > 0 && (line[i - 1] == ' ' || line[i - 1] == '\t')) --i;
    if (i == 0 || (line[i - 1] != '.' && line[i - 1] != ':')) continue;
    const char sep = line[i - 1];
    --i;
    while (i > 0 && (line[i - 1] == ' ' || line[i - 1] == '\t')) --i;
    std::size_t start = i;
    while (start > 0 && is_name_char(line[start - 1])) --start;
    if (start == i || std::isdigit(static_cast<unsigned char>(line[start]))) continue;
    if (start > 0 && (line[start - 1] == '.' || line[start - 1] == ':')) continue;  // a field of a field
    const std::string table = line.substr(start, i - start);
    if (has_local(L, &ar, table)) continue;
    lua_pushglobaltable(L);
    const bool is_table = lua_getfield(L, -1, table.c_str()) == LUA_TTABLE;
    const std::vector<std::string> keys = is_table ? string_keys(L) : std::vector<std::string>{};
    lua_pop(L, 2);
    const std::string near = suggestion(field, keys);
    if (near.empty()) continue;
    *table_name = table + sep;
    return table + sep + near;
  }
  return "";
}

}  // namespace

std::string with_nil_name_hint(lua_State* L, const std::string& message) {
  try {
    // Lua 5.4's words: "attempt to VERB a nil value (KIND 'NAME')" at the end of the message.
    const std::size_t at = message.rfind("attempt to ");
    if (at == std::string::npos || !message.ends_with("')")) return message;
    const std::string_view rest = std::string_view(message).substr(at + 11);
    const std::size_t space = rest.find(' ');
    const std::string verb(rest.substr(0, space));
    if (verb != "call" && verb != "index") return message;
    const std::string_view nil = " a nil value (";
    if (rest.substr(space, nil.size()) != nil) return message;
    const std::string_view kind_name = rest.substr(space + nil.size());
    const std::size_t quote = kind_name.find(" '");
    if (quote == std::string_view::npos) return message;
    const std::string kind(kind_name.substr(0, quote));
    const std::string name(kind_name.substr(quote + 2, kind_name.size() - quote - 4));
    std::string shown = name, near;
    if (kind == "global") {
      lua_pushglobaltable(L);
      const std::vector<std::string> keys = string_keys(L);
      lua_pop(L, 1);
      near = suggestion(name, keys);
    } else if (kind == "field" || kind == "method") {
      std::string table;
      near = field_meant(L, name, &table);
      shown = table + name;
    }
    // A short name is close to many ("nope" to "type"): there only a name with the same first letter is
    // likely, as typos keep it ("lsytem", "exclusio").
    const std::string near_leaf = near.substr(near.find_last_of(".:") + 1);
    if (near.empty() || (name.size() < 6 && near_leaf.front() != name.front())) return message;
    return message.substr(0, at) + "attempt to " + verb + " '" + shown_text(shown) + "': did you mean '" +
           shown_text(near) + "'?";
  } catch (...) {  // out of memory, the file gone: Lua's own message
    return message;
  }
}

}  // namespace selfsim::interp
