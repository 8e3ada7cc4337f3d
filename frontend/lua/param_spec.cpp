#include "frontend/lua/param_spec.h"

#include <cmath>
#include <map>
#include <set>
#include <string_view>

#include "frontend/lua/options_reader.h"
#include "frontend/lua/parse_text.h"
#include "kernels/base/check.h"
#include "kernels/io/text/json_text.h"

namespace selfsim::interp {

const char* type_name(ParamSpec::Type type) {
  switch (type) {
    case ParamSpec::Type::integer:
      return "integer";
    case ParamSpec::Type::number:
      return "number";
    case ParamSpec::Type::string:
      return "string";
    case ParamSpec::Type::boolean:
      return "boolean";
  }
  return "?";
}

namespace {

bool is_number(ParamSpec::Type t) { return t == ParamSpec::Type::integer || t == ParamSpec::Type::number; }

// "in [0.05, 1]", "at least 0.05", "at most 1".
std::string range_text(const ParamSpec& s) {
  if (s.min && s.max) return "in [" + number_text(*s.min) + ", " + number_text(*s.max) + "]";
  if (s.min) return "at least " + number_text(*s.min);
  return "at most " + number_text(*s.max);
}

// Whether `v` is a value a Lua integer holds exactly: whole, and within [-2^63, 2^63).
bool whole_in_range(double v) {
  constexpr double kLimit = 9223372036854775808.0;  // 2^63
  return std::floor(v) == v && v >= -kLimit && v < kLimit;
}

// "--set level=99999999999999999999" is written as a whole number (digits after an optional minus, the
// form from_chars reads) that is too large for an integer, not a fraction.
bool written_whole(std::string_view text) {
  if (!text.empty() && text.front() == '-') text.remove_prefix(1);
  if (text.empty()) return false;
  for (const char c : text)
    if (c < '0' || c > '9') return false;
  return true;
}

std::string choices_text(const std::vector<std::string>& choices) {
  std::string s;
  for (const std::string& c : choices) s += (s.empty() ? "'" : ", '") + c + "'";
  return s;
}

std::vector<std::string> read_choices(lua_State* L, Options& o, const std::string& name) {
  std::vector<std::string> choices;
  std::set<std::string> seen;
  if (o.push("choices") != LUA_TTABLE) {
    lua_pop(L, 1);
    throw Error("choices of '" + name + "' must be a list of strings, got " + describe(L, -1));
  }
  const lua_Integer n = luaL_len(L, -1);
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, i);
    if (lua_type(L, -1) != LUA_TSTRING)
      throw Error("choices of '" + name + "': entry " + std::to_string(i) + " must be a string, got " +
                  describe(L, -1));
    std::string c = text_value(L, -1, "choice " + std::to_string(i) + " of '" + name + "'");
    if (!seen.insert(c).second) throw Error("choices of '" + name + "' name '" + c + "' twice");
    choices.push_back(std::move(c));
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  if (choices.empty()) throw Error("choices of '" + name + "' must list at least one string");
  return choices;
}

}  // namespace

ParamSpec read_param_spec(lua_State* L, const std::string& name, int def, int opts) {
  ParamSpec s;
  s.name = name;
  switch (lua_type(L, def)) {
    case LUA_TNUMBER:
      if (lua_isinteger(L, def)) {
        s.type = ParamSpec::Type::integer;
        s.default_text = std::to_string(lua_tointeger(L, def));
      } else {
        s.type = ParamSpec::Type::number;
        s.default_text = io::json_number(finite_number(L, def, "the default of '" + name + "'"));
      }
      break;
    case LUA_TSTRING:
      s.type = ParamSpec::Type::string;
      s.default_text = text_value(L, def, "the default of '" + name + "'");
      break;
    case LUA_TBOOLEAN:
      s.type = ParamSpec::Type::boolean;
      s.default_text = lua_toboolean(L, def) ? "true" : "false";
      break;
    default:
      throw Error("default of '" + name + "' must be a number, string or boolean, got " + describe(L, def));
  }
  if (lua_isnoneornil(L, opts)) return s;
  if (!lua_istable(L, opts))
    throw Error("argument 3 of param('" + name + "', ...) must be a table of min, max, step, choices, doc, got " +
                describe(L, opts));
  Options o(L, opts);
  const char* kind = is_number(s.type) ? "a number" : s.type == ParamSpec::Type::string ? "a string" : "a boolean";
  const std::pair<const char*, std::optional<double>*> numbers[] = {
      {"min", &s.min}, {"max", &s.max}, {"step", &s.step}};
  for (const auto& [key, field] : numbers)
    if (o.has(key)) {
      if (!is_number(s.type))
        throw Error(std::string(key) + " is for number parameters; '" + name + "' defaults to " + kind +
                    (s.type == ParamSpec::Type::string ? " (list its values as choices = { ... })" : ""));
      *field = o.number(key, 0);
    }
  if (o.has("choices")) {
    if (s.type != ParamSpec::Type::string)
      throw Error("choices is for string parameters; '" + name + "' defaults to " + kind +
                  (is_number(s.type) ? " (give its range as min and max)" : ""));
    s.choices = read_choices(L, o, name);
  }
  if (o.has("doc")) {
    if (o.push("doc") != LUA_TSTRING) throw Error("doc of '" + name + "' must be a string, got " + describe(L, -1));
    s.doc = text_value(L, -1, "doc of '" + name + "'");
    lua_pop(L, 1);
  }
  o.finish();
  if (s.min && s.max && *s.min > *s.max)
    throw Error("'" + name + "': min " + number_text(*s.min) + " is above max " + number_text(*s.max));
  if (s.step && !(*s.step > 0)) throw Error("'" + name + "': step must be > 0, got " + number_text(*s.step));
  // An integer parameter takes whole numbers only (check_param_value), so a fractional step or bound would
  // make the studio's control offer values (1.5 from min = 0.5) that are then refused: refuse it here.
  if (s.type == ParamSpec::Type::integer)
    for (const auto& [key, field] : numbers)
      if (*field && !whole_in_range(**field))
        throw Error("'" + name + "' is an integer parameter: its " + key + " must be " +
                    (std::floor(**field) == **field ? "within the integer range" : "a whole number") + ", got " +
                    number_text(**field) + " (a default written " + s.default_text + ".0 takes any number)");
  if (is_number(s.type) && (s.min || s.max)) {
    const double v = *parse_text<double>(s.default_text);
    if ((s.min && v < *s.min) || (s.max && v > *s.max))
      throw Error("'" + name + "': the default " + s.default_text + " is outside its range: it must be " +
                  range_text(s));
  }
  if (!s.choices.empty()) {
    bool found = false;
    for (const std::string& c : s.choices) found = found || c == s.default_text;
    if (!found)
      throw Error("'" + name + "': the default '" + s.default_text + "' is not one of its choices " +
                  choices_text(s.choices));
  }
  return s;
}

void check_param_value(const ParamSpec& s, const std::string& text) {
  const std::string set = "--set " + s.name + "=" + text + ": ";
  if (s.type == ParamSpec::Type::boolean) {
    if (text != "true" && text != "false") throw Error(set + "expected true or false");
  } else if (is_number(s.type)) {
    const auto v = parse_text<double>(text);
    if (!v) throw Error(set + "expected a finite number");
    // An integer parameter reaches the recipe as a Lua integer or not at all: 2.5 and 1e1 are refused
    // here, where --set, a sweep's values and the studio's controls all pass, not later at a kernel's line.
    const bool outside = (s.min && *v < *s.min) || (s.max && *v > *s.max);
    if (s.type == ParamSpec::Type::integer && !parse_text<long long>(text)) {
      // A whole number too large for a Lua integer is out of range, not a fraction: its declared range
      // (within the integer range, see read_param_spec) says so where it has one on that side.
      if (!written_whole(text))
        throw Error(set + "'" + s.name + "' is an integer parameter: expected a whole number such as " +
                    s.default_text + " (a default written " + s.default_text + ".0 takes any number)");
      if (!outside)
        throw Error(set + "'" + s.name + "' is an integer parameter: " + text +
                    " is outside the integer range [-9223372036854775808, 9223372036854775807]");
    }
    if (outside) throw Error(set + "'" + s.name + "' must be " + range_text(s));
  } else if (!s.choices.empty()) {
    for (const std::string& c : s.choices)
      if (c == text) return;
    const std::string near = suggestion(text, s.choices);
    throw Error(set + "expected one of " + choices_text(s.choices) +
                (near.empty() ? std::string() : " (did you mean '" + near + "'?)"));
  }
}

void check_distinct_values(const ParamSpec& s, const std::string& set, const std::vector<std::string>& values) {
  if (!is_number(s.type)) return;
  std::map<long double, std::string> seen;  // long double: exact for every 64-bit integer and every double
  for (const std::string& v : values) {
    const auto whole = parse_text<long long>(v);
    const long double x = whole ? static_cast<long double>(*whole) : *parse_text<double>(v);  // checked
    const auto [at, fresh] = seen.emplace(x, v);
    if (!fresh)
      throw Error("--set " + set + ": '" + at->second + "' and '" + v + "' are the same " +
                  (s.type == ParamSpec::Type::integer ? "integer" : "number") + ", listed twice");
  }
}

void push_param_value(lua_State* L, const ParamSpec& s, const std::string& text) {
  check_param_value(s, text);
  if (s.type == ParamSpec::Type::string)
    lua_pushlstring(L, text.data(), text.size());
  else if (s.type == ParamSpec::Type::boolean)
    lua_pushboolean(L, text == "true");
  else if (const auto whole = parse_text<long long>(text))
    lua_pushinteger(L, *whole);  // a number default takes any number: integers stay integers
  else
    lua_pushnumber(L, *parse_text<double>(text));
}

std::string params_json(const std::vector<ParamSpec>& specs) {
  using io::json_string;
  std::string s = "[";
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const ParamSpec& p = specs[i];
    s += i == 0 ? "\n" : ",\n";
    s += "  {\"name\": " + json_string(p.name) + ", \"type\": \"" + type_name(p.type) + "\", \"default\": ";
    s += p.type == ParamSpec::Type::string ? json_string(p.default_text) : p.default_text;
    if (p.min) s += ", \"min\": " + io::json_number(*p.min);
    if (p.max) s += ", \"max\": " + io::json_number(*p.max);
    if (p.step) s += ", \"step\": " + io::json_number(*p.step);
    if (!p.choices.empty()) {
      s += ", \"choices\": [";
      for (std::size_t c = 0; c < p.choices.size(); ++c) s += (c ? ", " : "") + json_string(p.choices[c]);
      s += "]";
    }
    if (!p.doc.empty()) s += ", \"doc\": " + json_string(p.doc);
    s += "}";
  }
  return s + (specs.empty() ? "]" : "\n]");
}

}  // namespace selfsim::interp
