#include "frontend/lua/options_reader.h"

#include <algorithm>
#include <cmath>

#include "frontend/lua/curve_value.h"
#include "frontend/lua/lua_support.h"
#include "frontend/lua/option_hints.h"
#include "frontend/lua/point_reader.h"
#include "frontend/lua/value_types.h"
#include "kernels/base/check.h"
#include "kernels/base/error.h"

namespace selfsim::interp {

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string option(const char* key) { return std::string("option '") + key + "'"; }

}  // namespace

std::string suggestion(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  // An abbreviation ("--out" for "--output") is the likeliest meaning, whatever the edit distances say.
  if (word.size() >= 3)
    for (const auto& c : candidates)
      if (c.size() > word.size() && c.compare(0, word.size(), word) == 0 && (best.empty() || c.size() < best.size()))
        best = c;
  if (!best.empty()) return best;
  // A long shared start ("rotation" for "rotate") is a likely meaning too, when the lengths differ much.
  std::size_t best_prefix = 3;
  for (const auto& c : candidates) {
    std::size_t k = 0;
    while (k < word.size() && k < c.size() && word[k] == c[k]) ++k;
    if (k > best_prefix && 2 * k >= word.size() && 2 * k >= c.size()) best_prefix = k, best = c;
  }
  if (!best.empty()) return best;
  std::size_t best_distance = std::max<std::size_t>(2, word.size() / 3) + 1;
  for (const auto& c : candidates) {
    // The distance is at least the difference in length: skip the quadratic work (a 256 MiB name).
    const std::size_t gap = word.size() > c.size() ? word.size() - c.size() : c.size() - word.size();
    if (gap >= best_distance) continue;
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) best_distance = d, best = c;
  }
  return best;
}

std::string text_value(lua_State* L, int index, const std::string& what) {
  if (lua_type(L, index) != LUA_TSTRING) throw Error(what + " must be a string, got " + describe(L, index));
  std::size_t n = 0;
  const char* s = lua_tolstring(L, index, &n);
  std::string v(s, n);
  if (v.find('\0') != std::string::npos) throw Error(what + " must not contain NUL bytes, got " + describe(L, index));
  return v;
}

double finite_number(lua_State* L, int index, const std::string& what) {
  if (lua_type(L, index) != LUA_TNUMBER) throw Error(what + " must be a number, got " + describe(L, index));
  return check_finite(lua_tonumber(L, index), what);
}

Options::Options(lua_State* state, int index) : L(state), index_(lua_absindex(state, index)) {
  const int t = lua_type(L, index_);
  if (t != LUA_TTABLE && t != LUA_TNIL && t != LUA_TNONE)
    throw Error("expected a table of options, got " + describe(L, index_));
}

int Options::push(const char* key) {
  read_.insert(key);
  if (lua_type(L, index_) != LUA_TTABLE) {
    lua_pushnil(L);
    return LUA_TNIL;
  }
  return lua_getfield(L, index_, key);
}

bool Options::has(const char* key) {
  const bool present = push(key) != LUA_TNIL;
  lua_pop(L, 1);
  return present;
}

double Options::number(const char* key, double fallback) {
  if (push(key) == LUA_TNIL) {
    lua_pop(L, 1);
    return fallback;
  }
  const double v = finite_number(L, -1, option(key));
  lua_pop(L, 1);
  return v;
}

long long Options::integer(const char* key, long long fallback, long long lo, long long hi) {
  if (push(key) == LUA_TNIL) {
    lua_pop(L, 1);
    return fallback;
  }
  const std::string range = range_text(lo, hi);
  // Whole floats (3.0) are accepted too: recipes compute levels with arithmetic.
  const bool whole = lua_isinteger(L, -1) ||
                     (lua_type(L, -1) == LUA_TNUMBER && std::floor(lua_tonumber(L, -1)) == lua_tonumber(L, -1) &&
                      std::abs(lua_tonumber(L, -1)) < 1e18);
  if (!whole) throw Error(option(key) + " must be an integer in " + range + ", got " + describe(L, -1));
  const long long v = lua_isinteger(L, -1) ? lua_tointeger(L, -1) : static_cast<long long>(lua_tonumber(L, -1));
  lua_pop(L, 1);
  return check_range(v, lo, hi, option(key));
}

bool Options::boolean(const char* key, bool fallback) {
  const int t = push(key);
  if (t == LUA_TNIL) {
    lua_pop(L, 1);
    return fallback;
  }
  if (t != LUA_TBOOLEAN) throw Error(option(key) + " must be true or false, got " + describe(L, -1));
  const bool v = lua_toboolean(L, -1);
  lua_pop(L, 1);
  return v;
}

std::string Options::string(const char* key, const std::string& fallback) {
  const int t = push(key);
  if (t == LUA_TNIL) {
    lua_pop(L, 1);
    return fallback;
  }
  std::string v = text_value(L, -1, option(key));
  lua_pop(L, 1);
  return v;
}

int enum_index(const std::string& value, const std::vector<std::string>& names, const std::string& what,
               const std::string& detail) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == value) return static_cast<int>(i);
  const std::string near = suggestion(value, names);
  throw Error("invalid " + what + " '" + value + "'" + detail +
              (near.empty() ? "" : " (did you mean '" + near + "'?)") + ", expected one of: " + quoted_list(names));
}

std::vector<std::string> Options::unread() {
  std::vector<std::string> unknown;
  if (lua_type(L, index_) != LUA_TTABLE) return unknown;
  // Keys in a fixed order, so the key reported is the same on every run.
  const int n = push_sorted_keys(L, index_);
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, i);
    if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 && lua_tointeger(L, -1) <= positional_) {
      lua_pop(L, 1);
      continue;
    }
    if (lua_type(L, -1) != LUA_TSTRING)
      throw Error("options must be named (key = value), got a value at key " + describe(L, -1));
    std::size_t len = 0;
    const char* key = lua_tolstring(L, -1, &len);
    if (!read_.contains(std::string(key, len))) unknown.emplace_back(key, len);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return unknown;
}

bool Options::require(const char* key, const std::string& hint) {
  if (has(key)) return true;
  missing_.push_back(option(key) + " is required" + (hint.empty() ? "" : " (" + hint + ")"));
  return false;
}

int Options::enumeration(const char* key, const std::vector<std::string>& names, int fallback) {
  if (push(key) == LUA_TNIL) {
    lua_pop(L, 1);
    return fallback;
  }
  const std::string value = text_value(L, -1, option(key));
  lua_pop(L, 1);
  return enum_index(shown_text(value), names, option(key) + " value");
}

std::vector<double> Options::numbers(const char* key) {
  std::vector<double> out;
  if (push(key) == LUA_TNIL) {
    lua_pop(L, 1);
    return out;
  }
  if (lua_type(L, -1) != LUA_TTABLE) throw Error(option(key) + " must be a list of numbers, got " + describe(L, -1));
  const lua_Integer n = list_length(L, -1, option(key));
  check_run_budget(L, static_cast<double>(n), option(key));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, i);
    out.push_back(finite_number(L, -1, option(key) + " entry " + std::to_string(i)));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  return out;
}

template <class V, class Read>
std::optional<V> read_optional(Options& o, lua_State* L, const char* key, Read read) {
  if (o.push(key) == LUA_TNIL) {
    lua_pop(L, 1);
    return std::nullopt;
  }
  const V v = read(L, -1, option(key));
  lua_pop(L, 1);
  return v;
}

std::optional<Vec2> Options::point2(const char* key) { return read_optional<Vec2>(*this, L, key, read_point2); }
std::optional<Vec3> Options::point3(const char* key) { return read_optional<Vec3>(*this, L, key, read_point3); }
std::vector<Vec2> Options::points2(const char* key) {
  return read_optional<std::vector<Vec2>>(*this, L, key, read_point_list<Vec2>).value_or(std::vector<Vec2>{});
}
std::vector<Vec3> Options::points3(const char* key) {
  return read_optional<std::vector<Vec3>>(*this, L, key, read_point_list<Vec3>).value_or(std::vector<Vec3>{});
}
Polyline Options::curve(const char* key) {
  return read_optional<Polyline>(*this, L, key, to_polyline).value_or(Polyline{});
}
Held<Mesh> Options::mesh(const char* key) {
  if (push(key) == LUA_TNIL) {
    lua_pop(L, 1);
    return nullptr;
  }
  Held<Mesh> m = test_geometry<Mesh>(L, -1);
  if (!m) throw Error(option(key) + " must be a mesh (from mesh{} or load()), got " + describe(L, -1));
  lua_pop(L, 1);
  return m;
}

void Options::finish() {
  const std::vector<std::string> unknown = unread();
  if (unknown.empty()) {
    if (!missing_.empty()) throw Error(missing_.front());
    return;
  }
  const std::vector<std::string> known(read_.begin(), read_.end());
  // A name known from elsewhere for one of these options ("elasticity" for tropism) says how it is written.
  std::string value;
  lua_pushlstring(L, unknown.front().data(), unknown.front().size());
  if (lua_rawget(L, index_) == LUA_TNUMBER) value = number_text(lua_tonumber(L, -1));
  lua_pop(L, 1);
  if (const std::string hint = option_hint(unknown.front(), known, value); !hint.empty())
    throw Error("unknown option '" + shown_text(unknown.front()) + "': " + hint);
  const std::string near = suggestion(unknown.front(), known);
  // Without a likely meaning, the valid options themselves (a short list: every binding reads few, lsystem{} the most,
  // 17).
  const std::string hint = !near.empty()        ? " (did you mean '" + near + "'?)"
                           : known.empty()      ? " (it takes no options)"
                           : known.size() <= 20 ? " (valid options: " + quoted_list(known) + ")"
                                                : "";
  throw Error("unknown option '" + shown_text(unknown.front()) + "'" + hint +
              (unknown.size() > 1 ? " (and " + std::to_string(unknown.size() - 1) + " more unknown)" : ""));
}

}  // namespace selfsim::interp
