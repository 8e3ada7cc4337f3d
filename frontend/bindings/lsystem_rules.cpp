#include "frontend/bindings/lsystem_rules.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "frontend/lua/lua_support.h"
#include "frontend/lua/options_reader.h"
#include "kernels/base/error.h"
#include "kernels/lsystem/book_text.h"
#include "kernels/lsystem/rule_parser.h"

namespace selfsim::interp {

namespace {

using lsystem::Production;

[[noreturn]] void rule_error(const lsystem::RuleError& e, const std::string& where, std::string_view text) {
  // Columns count characters, as the caret line shows them, not bytes.
  throw DetailedError(
      where + ": " + e.what() + " (column " + std::to_string(lsystem::shown_column(text, e.column) + 1) + ")",
      lsystem::caret_lines(text, e.column));
}

// The names of the grammar's constants, which every expression may read.
std::vector<std::string> constant_names(const lsystem::Grammar& g) {
  std::vector<std::string> names;
  for (const auto& [name, value] : g.constants) names.push_back(name);
  return names;
}

// A rule in the book's notation ('→', 'p1:', a probability at the arrow, ...) is named as the book's, with the
// way to write it here: the parser's own message would not say why the book's form fails.
Production parse(const std::string& text, const std::string& where, const std::vector<std::string>& constants) {
  if (const auto hint = lsystem::book_form_hint(text, false))
    rule_error(lsystem::RuleError(hint->first, hint->second), where, text);
  try {
    return lsystem::parse_rule(text, where, constants);
  } catch (const lsystem::RuleError& e) {
    if (const auto hint = lsystem::book_form_hint(text, true))
      rule_error(lsystem::RuleError(hint->first, hint->second), where, text);
    rule_error(e, where, text);
  }
}

// The left side of a rule as written, without whitespace: rules whose left sides agree and that carry a
// weight are the choices of one stochastic rule.
std::string left_side(const std::string& text) {
  std::string out = text.substr(0, text.find("->"));
  out.erase(std::remove_if(out.begin(), out.end(), [](char c) { return c == ' ' || c == '\t'; }), out.end());
  return out;
}

struct Read {
  std::string option = "option 'rules'";  // names the option in messages
  std::vector<std::string> constants;
  std::vector<Production> rules;
  std::map<std::string, std::size_t> weighted;  // a weighted rule's left side -> its place in `rules`
  std::map<char, std::string> plain;
};

void add_text_rule(Read& r, const std::string& text, const std::string& where) {
  Production p = parse(text, where, r.constants);
  if (lsystem::rule_weight_given(text)) {
    const auto [it, added] = r.weighted.emplace(left_side(p.text), r.rules.size());
    if (!added) {
      r.rules[it->second].options.push_back(std::move(p.options[0]));
      return;
    }
  }
  r.rules.push_back(std::move(p));
}

void read_block(Read& r, std::string_view block) {
  std::size_t line = 0, begin = 0;
  while (begin <= block.size()) {
    std::size_t end = block.find('\n', begin);
    if (end == std::string_view::npos) end = block.size();
    ++line;
    const std::string text(block.substr(begin, end - begin));
    const std::size_t first = text.find_first_not_of(" \t\r");
    // '#' starts a comment, but the book's '#define' and '#ignore' are never one: read as comments they
    // would silently leave the constants undefined and the contexts unchanged.
    if (first != std::string::npos && text[first] == '#') {
      const std::string_view word = std::string_view(text).substr(first + 1, 6);
      if (word == "define" || word == "ignore")
        throw Error(r.option + " line " + std::to_string(line) + ": '#" + std::string(word) + "' is the book's: " +
                    (word == "define" ? "give the constants as option 'define', { r1 = 0.9 }"
                                      : "give the symbols as option 'ignore', \"+-F\"") +
                    " (or use lsystem.book)");
    }
    if (first != std::string::npos && text[first] != '#')
      add_text_rule(r, text, r.option + " line " + std::to_string(line));
    begin = end + 1;
  }
}

// A weighted list { { weight, successor }, ... } for the rule whose left side is `key`.
void read_choices(lua_State* L, Read& r, const std::string& key) {
  const std::string what = r.option + ": rule for '" + key + "'";
  const lua_Integer n = list_length(L, -1, what, "write a list of { weight, successor } pairs");
  if (n == 0) throw Error(what + " has an empty list of choices");
  Production rule;
  for (lua_Integer i = 1; i <= n; ++i) {
    const std::string choice = what + ", choice " + std::to_string(i);
    lua_rawgeti(L, -1, i);
    if (lua_type(L, -1) != LUA_TTABLE || list_length(L, -1, choice) != 2)
      throw Error(choice + " must be a { weight, successor } pair, got " + describe(L, -1));
    lua_rawgeti(L, -1, 1);
    if (lua_type(L, -1) != LUA_TNUMBER)
      throw Error(choice + ": the weight must be a number >= 0, got " + describe(L, -1));
    const double weight = lua_tonumber(L, -1);
    if (!(weight >= 0) || !std::isfinite(weight))
      throw Error(choice + ": the weight must be a finite number >= 0, got " + describe(L, -1));
    lua_rawgeti(L, -2, 2);
    const std::string successor = text_value(L, -1, choice + ": the successor");
    lua_pop(L, 3);
    Production p = parse(key + " -> " + successor, choice, r.constants);
    p.options[0].weight = weight;
    if (i == 1) {
      rule = std::move(p);
      rule.where = what;
    } else {
      rule.options.push_back(std::move(p.options[0]));
    }
  }
  r.rules.push_back(std::move(rule));
}

void read_table(lua_State* L, Read& r) {
  const lua_Integer n = static_cast<lua_Integer>(lua_rawlen(L, -1));
  for (lua_Integer i = 1; i <= n; ++i) {
    lua_rawgeti(L, -1, i);
    const std::string where = r.option + " entry " + std::to_string(i);
    add_text_rule(r, text_value(L, -1, where), where);
    lua_pop(L, 1);
  }
  const int keys = push_sorted_keys(L, -1);
  for (int k = 1; k <= keys; ++k) {
    lua_rawgeti(L, -1, k);
    if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 && lua_tointeger(L, -1) <= n) {
      lua_pop(L, 1);
      continue;
    }
    if (lua_type(L, -1) != LUA_TSTRING || lua_rawlen(L, -1) == 0 || lua_tostring(L, -1)[0] == '\0')
      throw Error(r.option + " keys must be symbols or rule left sides (\"A(x) : x > 1\"), got " + describe(L, -1));
    const std::string key = text_value(L, -1, r.option + " key");
    if (key.find("->") != std::string::npos)
      throw Error(r.option + ": the key " + describe(L, -1) +
                  " holds '->': a key is the rule's left side, its value the successor");
    lua_rawget(L, -3);
    if (lua_type(L, -1) == LUA_TTABLE) {
      read_choices(L, r, key);
    } else {
      const std::string value = text_value(L, -1, r.option + ": rule for '" + key + "'");
      if (key.size() == 1 && !lsystem::has_module_syntax(value) && !r.plain.contains(key[0]))
        r.plain[key[0]] = value;
      else
        add_text_rule(r, key + " -> " + value, r.option + ": rule for '" + key + "'");
    }
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
}

// A production that a plain byte rule says as well: no parameters, context, condition or choice.
bool plain_rule(const Production& p) {
  if (p.context() || !p.condition.empty() || p.options.size() != 1 || !p.pred.params.empty()) return false;
  for (const lsystem::Call& c : p.options[0].modules)
    if (!c.args.empty() || c.symbol == '%') return false;
  return true;
}

// Reads the rules value at `index` in any of its forms.
Read read_any(lua_State* L, int index, const lsystem::Grammar& g, const std::string& option) {
  Read r;
  r.option = option;
  r.constants = constant_names(g);
  const int t = lua_type(L, index);
  lua_pushvalue(L, index);
  if (t == LUA_TSTRING) {
    read_block(r, text_value(L, -1, option));
    lua_pop(L, 1);
  } else if (t == LUA_TTABLE) {
    read_table(L, r);
  } else if (t == LUA_TNIL) {
    lua_pop(L, 1);
  } else {
    throw Error(option + " must be a table of rules or a string of ABOP rules, got " + describe(L, index));
  }
  return r;
}

}  // namespace

std::vector<Production> read_rule_set(lua_State* L, int index, const lsystem::Grammar& g, const char* name) {
  Read r = read_any(L, index, g, std::string("option '") + name + "'");
  for (const auto& [symbol, value] : r.plain)
    r.rules.push_back(parse(std::string(1, symbol) + " -> " + value,
                            r.option + ": rule for '" + std::string(1, symbol) + "'", r.constants));
  return std::move(r.rules);
}

void read_rules(lua_State* L, int index, lsystem::Grammar& g) {
  Read r = read_any(L, index, g, "option 'rules'");
  const bool module_axiom = lsystem::has_module_syntax(g.axiom) || g.axiom.find('%') != std::string::npos;
  bool plain = !module_axiom;
  std::vector<bool> seen(256, false);
  for (const Production& p : r.rules) {
    plain = plain && plain_rule(p) && !seen[p.pred.symbol] && !r.plain.contains(static_cast<char>(p.pred.symbol));
    seen[p.pred.symbol] = true;
  }
  for (const auto& [symbol, value] : r.plain) plain = plain && value.find('%') == std::string::npos;
  if (plain) {  // the byte kernel: fastest, and exactly what plain recipes have always drawn
    g.rules = std::move(r.plain);
    for (const Production& p : r.rules) {
      std::string& value = g.rules[static_cast<char>(p.pred.symbol)];
      for (const lsystem::Call& c : p.options[0].modules) value += static_cast<char>(c.symbol);
    }
    return;
  }
  g.rules = std::move(r.plain);
  g.productions = std::move(r.rules);
  to_modules(g);
}

void to_modules(lsystem::Grammar& g) {
  const std::vector<std::string> constants = constant_names(g);
  for (const auto& [symbol, value] : g.rules)
    g.productions.push_back(parse(std::string(1, symbol) + " -> " + value,
                                  "option 'rules': rule for '" + std::string(1, symbol) + "'", constants));
  g.rules.clear();
  try {
    g.start = lsystem::parse_calls(g.axiom, constants);
  } catch (const lsystem::RuleError& e) {
    rule_error(e, "option 'axiom'", g.axiom);
  }
  if (g.start.empty()) throw Error("option 'axiom' must hold at least one module");
}

}  // namespace selfsim::interp
