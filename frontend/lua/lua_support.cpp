#include "frontend/lua/lua_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_set>
#include <vector>

#include "frontend/lua/options_reader.h"
#include "frontend/lua/run_context.h"
#include "kernels/base/check.h"
#include "kernels/io/regular_file.h"

namespace selfsim::interp {

std::string recipe_where(lua_State* L) { return stack_where(L, "@" + RunContext::of(L).scripts_dir.string(), 1); }

int load_lua_file(lua_State* L, const std::filesystem::path& file, const char* what, std::string* text) {
  std::string bytes;
  try {
    const io::RegularFile f(file, true);
    bytes.resize(static_cast<std::size_t>(f.size()));
    f.read_at(0, bytes.data(), bytes.size());
  } catch (const Error& e) {
    const std::string message = std::string("cannot open ") + what + " '" + file.string() + "': " + e.what();
    lua_pushlstring(L, message.data(), message.size());
    return LUA_ERRFILE;
  }
  std::string_view chunk = bytes;
  if (chunk.starts_with("\xEF\xBB\xBF")) chunk.remove_prefix(3);
  if (chunk.starts_with('#')) chunk.remove_prefix(std::min(chunk.find('\n'), chunk.size()));  // its '\n' kept
  const std::string name = "@" + file.string();
  const int status = luaL_loadbufferx(L, chunk.data(), chunk.size(), name.c_str(), "t");
  if (text != nullptr) *text = std::move(bytes);
  return status;
}

std::string stack_where(lua_State* L, const std::string& library, int first_level) {
  std::string first;
  lua_Debug ar;
  for (int level = first_level; lua_getstack(L, level, &ar); ++level) {
    lua_getinfo(L, "Sl", &ar);
    if (ar.currentline <= 0) continue;
    const std::string where = std::string(ar.short_src) + ":" + std::to_string(ar.currentline) + ": ";
    if (first.empty()) first = where;
    if (std::string_view(ar.source).substr(0, library.size()) != library) return where;
  }
  return first;
}

int method_index(lua_State* L) {
  lua_pushvalue(L, 2);
  if (lua_rawget(L, lua_upvalueindex(1)) != LUA_TNIL) return 1;
  std::string message;
  {
    std::vector<std::string> names;
    lua_pushnil(L);
    while (lua_next(L, lua_upvalueindex(1)) != 0) {
      lua_pop(L, 1);
      if (lua_type(L, -1) == LUA_TSTRING) names.emplace_back(lua_tostring(L, -1));
    }
    std::sort(names.begin(), names.end());
    std::string type = lua_tostring(L, lua_upvalueindex(2));
    type = type.substr(type.find('.') + 1);
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    const std::string key = lua_type(L, 2) == LUA_TSTRING ? lua_tostring(L, 2) : "";
    const std::string near = key.empty() ? "" : suggestion(key, names);
    message = recipe_where(L) + type + " has no method " + describe(L, 2) +
              (near.empty() ? "" : " (did you mean '" + near + "'?)") + "; its methods: " + list;
  }
  lua_pushstring(L, message.c_str());
  return lua_error(L);
}

std::string extra_arguments(lua_State* L, int count, const std::string& takes) {
  const int given = lua_gettop(L) - 1;  // after the value itself
  if (given <= count) return {};
  const int first = count + 1;
  const char* const suffix = first == 1 ? "st" : first == 2 ? "nd" : first == 3 ? "rd" : "th";
  return "takes " + takes + ", got " + std::to_string(given) + (given == 1 ? " argument" : " arguments") + " (the " +
         std::to_string(first) + suffix + " is " + describe(L, count + 2) + ")";
}

int checked_method(lua_State* L) {
  bool refused = false;
  {
    const std::string message = extra_arguments(L, static_cast<int>(lua_tointeger(L, lua_upvalueindex(2))),
                                                lua_tostring(L, lua_upvalueindex(3)));
    if (!message.empty()) {
      push_error(L, lua_tostring(L, lua_upvalueindex(4)), message);
      refused = true;
    }
  }  // message freed before the error
  if (refused) return lua_error(L);
  return lua_tocfunction(L, lua_upvalueindex(1))(L);
}

lua_Integer list_length(lua_State* L, int index, const std::string& what, const std::string& hint) {
  index = lua_absindex(L, index);
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, index));
  lua_Integer keys = 0;
  lua_pushnil(L);
  while (lua_next(L, index) != 0) {
    lua_pop(L, 1);
    ++keys;
  }
  if (keys == n) {
    // As many keys as entries 1..n: a list exactly when every entry is there.
    bool whole = true;
    for (lua_Integer i = 1; i <= n && whole; ++i) {
      whole = lua_rawgeti(L, index, i) != LUA_TNIL;
      lua_pop(L, 1);
    }
    if (whole) return n;
  }
  // Something else is there: name it, the same one on every run (keys in their fixed order).
  const int count = push_sorted_keys(L, index);
  for (int k = 1; k <= count; ++k) {
    lua_rawgeti(L, -1, k);
    if (!lua_isinteger(L, -1) || lua_tointeger(L, -1) < 1 || lua_tointeger(L, -1) > n)
      throw Error(what + " must be a list (entries 1, 2, 3, ...), got the key " + describe(L, -1) + hint);
    lua_pop(L, 1);
  }
  for (lua_Integer i = 1; i <= n; ++i)
    if (lua_rawgeti(L, index, i) == LUA_TNIL)
      throw Error(what + " has no entry " + std::to_string(i) + " (a list's entries run 1, 2, 3, ... without holes)");
    else
      lua_pop(L, 1);
  return n;  // not reached: some key was out of place
}

std::string describe(lua_State* L, int index) {
  switch (lua_type(L, index)) {
    case LUA_TNUMBER: {
      if (lua_isinteger(L, index)) return std::to_string(lua_tointeger(L, index));
      return number_text(lua_tonumber(L, index));
    }
    case LUA_TSTRING: {
      std::size_t n = 0;
      const char* text = lua_tolstring(L, index, &n);
      return "'" + shown_text(std::string_view(text, n)) + "'";
    }
    case LUA_TNIL:
      return "nil";
    case LUA_TNONE:
      return "nothing";
    case LUA_TBOOLEAN:
      return lua_toboolean(L, index) ? "true" : "false";
    default: {
      const char* name = luaL_typename(L, index);
      if (luaL_getmetafield(L, index, "__name") == LUA_TSTRING) {
        std::string n = lua_tostring(L, -1);
        lua_pop(L, 1);
        return "a " + n.substr(n.find('.') + 1);
      }
      return std::string("a ") + name;
    }
  }
}

void push_error(lua_State* L, const char* fn, const std::string& message) {
  const std::string where = recipe_where(L);
  lua_pushfstring(L, "%s%s: %s", where.c_str(), fn, message.c_str());
}

namespace {
const char* const detail_key = "selfsim.error_detail";
const char* const detail_for_key = "selfsim.error_detail_for";
}  // namespace

void note_error_detail(lua_State* L, const std::string& detail) {
  lua_pushvalue(L, -1);
  lua_setfield(L, LUA_REGISTRYINDEX, detail_for_key);
  lua_pushlstring(L, detail.data(), detail.size());
  lua_setfield(L, LUA_REGISTRYINDEX, detail_key);
}

std::string error_detail(lua_State* L, int index) {
  index = lua_absindex(L, index);
  lua_getfield(L, LUA_REGISTRYINDEX, detail_for_key);
  const bool same = lua_type(L, index) == LUA_TSTRING && lua_rawequal(L, -1, index);
  lua_pop(L, 1);
  if (!same) return "";
  lua_getfield(L, LUA_REGISTRYINDEX, detail_key);
  std::string detail = lua_type(L, -1) == LUA_TSTRING ? lua_tostring(L, -1) : "";
  lua_pop(L, 1);
  return detail;
}

std::string shown_text(std::string_view text, std::size_t max_bytes) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && out.size() < max_bytes; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '\n')
      out += "\\n";
    else if (c < 32 || c == 127) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", c);
      out += buf;
    } else
      out += static_cast<char>(c);
    if (out.size() >= max_bytes && i + 1 < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
  }
  return out;
}

std::string type_word(const char* type) {
  const std::string t = type;
  return t.substr(t.find('.') + 1);
}

void hold_points(lua_State* L, double points) { RunContext::of(L).held_points += points; }

PointBudget run_budget(lua_State* L) {
  RunContext& run = RunContext::of(L);
  if (run.values.sweep_due) sweep_values(L);
  return run.budget();
}

namespace {

constexpr const char* live_key = "selfsim.live";

// Pushes the registry's table userdata -> id, whose keys are weak. Lua clears a weak key only once its
// object is gone for good, a collection after its finalizer ran or failed (weak values are cleared before
// finalizers run, while a value awaiting one may still be used by another's finalizer).
void push_live_table(lua_State* L) {
  if (lua_getfield(L, LUA_REGISTRYINDEX, live_key) == LUA_TTABLE) return;
  lua_pop(L, 1);
  lua_createtable(L, 0, 0);
  lua_createtable(L, 0, 1);
  lua_pushliteral(L, "k");
  lua_setfield(L, -2, "__mode");
  lua_setmetatable(L, -2);
  lua_pushvalue(L, -1);
  lua_setfield(L, LUA_REGISTRYINDEX, live_key);
}

}  // namespace

std::uint64_t adopt_value(lua_State* L, std::shared_ptr<const void> value, double points, std::size_t bytes) {
  RunContext& run = RunContext::of(L);
  if (run.values.sweep_due) sweep_values(L);
  hold_memory(L, static_cast<double>(bytes));
  return run.values.add({std::move(value), points, bytes});
}

void hold_value(lua_State* L, std::uint64_t id) {
  RunContext& run = RunContext::of(L);
  push_live_table(L);
  lua_pushvalue(L, -2);
  lua_pushinteger(L, static_cast<lua_Integer>(id));
  lua_rawset(L, -3);
  lua_pop(L, 1);
  if (LiveValue* v = run.values.find(id)) {
    v->held = true;
    run.held_points += v->points;
  }
}

std::shared_ptr<const void> live_value(lua_State* L, std::uint64_t id) {
  const LiveValue* v = RunContext::of(L).values.find(id);
  return v ? v->value : nullptr;
}

void release_value(lua_State* L, std::uint64_t id) {
  RunContext& run = RunContext::of(L);
  const LiveValue v = run.values.take(id);
  if (v.held) run.held_points -= v.points;
  hold_external(run.memory, -static_cast<double>(v.bytes));
}

void sweep_values(lua_State* L) {
  RunContext& run = RunContext::of(L);
  run.values.sweep_due = false;
  push_live_table(L);
  std::unordered_set<std::uint64_t> present;
  lua_pushnil(L);
  while (lua_next(L, -2) != 0) {
    present.insert(static_cast<std::uint64_t>(lua_tointeger(L, -1)));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  std::vector<std::uint64_t> gone;
  run.values.each_held([&](std::uint64_t id) {
    if (!present.contains(id)) gone.push_back(id);
  });
  for (const std::uint64_t id : gone) release_value(L, id);
}

void hold_memory(lua_State* L, double bytes) {
  LuaMemory& m = RunContext::of(L).memory;
  if (!hold_external(m, bytes)) throw Error(memory_reason(m));  // call_kernel adds the recipe line
}

bool run_has_ended(lua_State* L) { return RunContext::of(L).ended; }

void end_progress(lua_State* L) noexcept { RunContext::of(L).finish_bar(); }

namespace {

// Keys of a table in the order they are visited: numbers by value, then strings by their bytes, then
// false before true, then every other key in traversal order.
struct KeyOrder {
  int rank;
  bool integer;
  lua_Integer i;
  double x;
  std::string_view text;
  int slot;

  bool operator<(const KeyOrder& o) const {
    if (rank != o.rank) return rank < o.rank;
    if (rank == 0) return integer && o.integer ? i < o.i : x < o.x;
    if (rank == 1) return text < o.text;
    if (rank == 2) return x < o.x;
    return false;
  }
};

}  // namespace

int push_sorted_keys(lua_State* L, int table) {
  table = lua_absindex(L, table);
  lua_newtable(L);  // every key, in traversal order: keeps key strings alive while `order` points at them
  const int found = lua_gettop(L);
  std::vector<KeyOrder> order;
  lua_pushnil(L);
  while (lua_next(L, table) != 0) {
    lua_pop(L, 1);
    const int slot = static_cast<int>(order.size()) + 1;
    lua_pushvalue(L, -1);
    lua_rawseti(L, found, slot);
    KeyOrder k{3, false, 0, 0, {}, slot};
    switch (lua_type(L, -1)) {
      case LUA_TNUMBER:
        k.rank = 0;
        k.integer = lua_isinteger(L, -1);
        k.i = lua_tointeger(L, -1);
        k.x = lua_tonumber(L, -1);
        break;
      case LUA_TSTRING: {
        std::size_t n = 0;
        const char* text = lua_tolstring(L, -1, &n);
        k.rank = 1;
        k.text = std::string_view(text, n);
        break;
      }
      case LUA_TBOOLEAN:
        k.rank = 2;
        k.x = lua_toboolean(L, -1);
        break;
      default:
        break;
    }
    order.push_back(k);
  }
  std::stable_sort(order.begin(), order.end());
  lua_createtable(L, static_cast<int>(order.size()), 0);
  for (std::size_t i = 0; i < order.size(); ++i) {
    lua_rawgeti(L, found, order[i].slot);
    lua_rawseti(L, -2, static_cast<lua_Integer>(i) + 1);
  }
  lua_remove(L, found);
  return static_cast<int>(order.size());
}

std::string cancel_message(lua_State* L) {
  const RunContext& run = RunContext::of(L);
  if (run.config.params_only) return params_stop;
  const std::string reason = run.stop_reason();
  return reason.empty() ? "cancelled" : reason;
}

}  // namespace selfsim::interp
