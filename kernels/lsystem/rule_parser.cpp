#include "kernels/lsystem/rule_parser.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <set>

#include "kernels/base/text_width.h"
#include "kernels/base/utf8.h"
#include "kernels/lsystem/find_outside.h"

namespace selfsim::lsystem {

namespace {

constexpr std::size_t npos = std::string_view::npos;
// Fixed bounds that let evaluation use stack buffers: no real rule comes near them.
constexpr std::size_t max_params = 16;
constexpr std::size_t max_slots = 48;

bool blank(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

// A module's byte in a message, escaped as the caret line shows it ("\x7f", not "\127" beside "\x7f").
std::string shown(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 33 && u < 127) return std::string(1, c);
  char buf[8];
  std::snprintf(buf, sizeof buf, "\\x%02x", u);
  return buf;
}

// Column of `part` (a view into `whole`) in `whole`.
std::size_t column(std::string_view whole, std::string_view part) {
  return static_cast<std::size_t>(part.data() - whole.data());
}

bool name_start(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool name_char(char c) { return name_start(c) || (c >= '0' && c <= '9'); }

// Calls f(symbol, column of symbol, list of parameter texts) for each module of `part`.
template <class F>
void each_module(std::string_view whole, std::string_view part, F&& f) {
  std::size_t i = 0;
  while (i < part.size()) {
    if (blank(part[i])) {
      ++i;
      continue;
    }
    const char c = part[i];
    const std::size_t at = column(whole, part) + i;
    if (c == '(') throw RuleError("'(' must follow a module's symbol directly, as in A(x)", at);
    if (c == ')' || c == ',') throw RuleError(std::string("unexpected '") + c + "'", at);
    ++i;
    std::vector<std::string_view> params;
    if (i < part.size() && part[i] == '(') {
      int depth = 0;
      std::size_t start = i + 1, j = i;
      for (; j < part.size(); ++j) {
        if (part[j] == '(') ++depth;
        if (part[j] == ')' && --depth == 0) break;
        if (part[j] == ',' && depth == 1) {
          params.push_back(part.substr(start, j - start));
          start = j + 1;
        }
      }
      if (j == part.size()) throw RuleError("missing ')' for the parameters of " + shown(c), column(whole, part) + i);
      params.push_back(part.substr(start, j - start));
      for (std::string_view p : params)
        if (trim(p).empty()) throw RuleError("empty parameter in the parameters of " + shown(c), column(whole, p));
      if (params.size() > max_params)
        throw RuleError("module " + shown(c) + " has " + std::to_string(params.size()) +
                            " parameters, over the limit of " + std::to_string(max_params),
                        at);
      i = j + 1;
    }
    f(static_cast<std::uint8_t>(c), at, params);
  }
}

// Appends the parameter names the patterns bind to `names`, whose first `constants` are the grammar's.
std::vector<Pattern> parse_patterns(std::string_view whole, std::string_view part, std::vector<std::string>& names,
                                    std::size_t constants) {
  std::vector<Pattern> out;
  each_module(whole, part, [&](std::uint8_t s, std::size_t, const std::vector<std::string_view>& params) {
    Pattern p{s, {}};
    for (std::string_view raw : params) {
      const std::string_view name = trim(raw);
      const std::size_t at = column(whole, name);
      if (!name_start(name[0]))
        throw RuleError("a rule's left side names its parameters, e.g. A(x, y); got '" + std::string(name) + "'", at);
      for (char c : name)
        if (!name_char(c))
          throw RuleError("a rule's left side names its parameters, e.g. A(x, y); got '" + std::string(name) + "'", at);
      for (std::size_t k = 0; k < names.size(); ++k)
        if (names[k] == name)
          throw RuleError("parameter name '" + names[k] + "' is " +
                              (k < constants ? "also a constant (option 'define')" : "used twice"),
                          at);
      names.emplace_back(name);
      p.params.emplace_back(name);
    }
    out.push_back(std::move(p));
  });
  if (names.size() - constants > max_slots)
    throw RuleError("the rule binds " + std::to_string(names.size() - constants) + " parameters, over the limit of " +
                        std::to_string(max_slots),
                    column(whole, part));
  return out;
}

std::vector<Call> calls_in(std::string_view whole, std::string_view part, std::span<const std::string> names) {
  std::vector<Call> out;
  // Polygons nest as branches do (the turtle keeps a stack of each): a '}' with no polygon open, or a '{'
  // left open, would draw nothing and say nothing, so each text balances its braces as its brackets.
  int depth = 0, polygons = 0;
  std::array<std::uint32_t, 256> seen{};
  each_module(whole, part, [&](std::uint8_t s, std::size_t at, const std::vector<std::string_view>& params) {
    depth += s == '[' ? 1 : s == ']' ? -1 : 0;
    if (depth < 0) throw RuleError("unbalanced brackets: a ']' without its '['", at);
    polygons += s == '{' ? 1 : s == '}' ? -1 : 0;
    if (polygons < 0) throw RuleError("unbalanced braces: a '}' without its '{' (no polygon is open)", at);
    Call call{s, {}, (std::uint64_t{s} << 32) | seen[s]++};
    for (std::string_view p : params) {
      try {
        call.args.push_back(Expression::compile(p, names));
      } catch (const SyntaxError& e) {
        throw RuleError(e.what(), column(whole, p) + e.column);
      }
    }
    out.push_back(std::move(call));
  });
  if (depth > 0) throw RuleError("unbalanced brackets: a '[' is never closed", column(whole, part) + part.size());
  if (polygons > 0)
    throw RuleError("unbalanced braces: a '{' is never closed (its polygon has no '}')",
                    column(whole, part) + part.size());
  return out;
}

double parse_weight(std::string_view whole, std::string_view part) {
  const std::string_view t = trim(part);
  double w = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), w);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !std::isfinite(w) || w < 0)
    throw RuleError("a stochastic weight after the successor must be a number >= 0, got '" + std::string(t) + "'",
                    column(whole, t.empty() ? part : t));
  return w;
}

}  // namespace

std::vector<Call> parse_calls(std::string_view text, std::span<const std::string> names) {
  return calls_in(text, text, names);
}

bool rule_weight_given(std::string_view text) {
  const std::size_t arrow = find_outside(text, "->");
  return arrow != npos && find_outside(text.substr(arrow + 2), ":") != npos;
}

bool has_module_syntax(std::string_view text) { return text.find('(') != npos || text.find(')') != npos; }

Production parse_rule(std::string_view text, const std::string& where, std::span<const std::string> constants) {
  Production p;
  p.text = std::string(trim(text));
  p.where = where;
  const std::size_t arrow = find_outside(text, "->");
  if (arrow == npos) {
    // An arrow inside parentheses: a '(' before it was never closed.
    if (const std::size_t raw = text.find("->"); raw != npos) {
      std::vector<std::size_t> open;
      for (std::size_t i = 0; i < raw; ++i) {
        if (text[i] == '(') open.push_back(i);
        if (text[i] == ')' && !open.empty()) open.pop_back();
      }
      if (!open.empty()) throw RuleError("a '(' before '->' is never closed", open.back());
    }
    throw RuleError("expected '->' between the rule's left side and its successor", text.size());
  }
  std::string_view left_side = text.substr(0, arrow), succ = text.substr(arrow + 2);
  if (const std::size_t again = find_outside(succ, "->"); again != npos)
    throw RuleError("a rule has one '->' (between its left side and its successor)", arrow + 2 + again);
  if (const std::size_t colon = find_outside(succ, ":", true); colon != npos) {
    const double w = parse_weight(text, succ.substr(colon + 1));
    succ = succ.substr(0, colon);
    p.options.push_back({w, {}});
  } else {
    p.options.push_back({1, {}});
  }
  std::string_view condition;
  bool has_right = false, has_condition = false;
  if (const std::size_t colon = find_outside(left_side, ":"); colon != npos) {
    condition = left_side.substr(colon + 1);
    has_condition = true;
    left_side = left_side.substr(0, colon);
  }
  // left < pred > right
  std::string_view left, pred = left_side, right;
  if (const std::size_t lt = find_outside(pred, "<"); lt != npos) {
    left = pred.substr(0, lt);
    pred = pred.substr(lt + 1);
    if (find_outside(pred, "<") != npos)
      throw RuleError("a rule has at most one '<' (left context < predecessor)",
                      column(text, pred) + find_outside(pred, "<"));
  }
  if (const std::size_t gt = find_outside(pred, ">"); gt != npos) {
    right = pred.substr(gt + 1);
    has_right = true;
    pred = pred.substr(0, gt);
    if (find_outside(right, ">") != npos)
      throw RuleError("a rule has at most one '>' (predecessor > right context)",
                      column(text, right) + find_outside(right, ">"));
  }
  // ABOP writes "*" for "any": no condition, no context on that side.
  if (trim(condition) == "*") {
    condition = {};
    has_condition = false;
  }
  if (trim(left) == "*") left = {};
  if (trim(right) == "*") {
    right = {};
    has_right = false;
  }
  std::vector<std::string> names(constants.begin(), constants.end());
  const std::size_t k = constants.size();
  p.left = parse_patterns(text, left, names, k);
  if (!left.empty() && p.left.empty()) throw RuleError("expected a left context before '<'", column(text, left));
  for (const Pattern& m : p.left)
    if (m.symbol == '[' || m.symbol == ']')
      throw RuleError("a left context cannot hold branches (it skips them itself)", column(text, left));
  const std::vector<Pattern> preds = parse_patterns(text, pred, names, k);
  if (preds.size() != 1)
    throw RuleError(preds.empty() ? "expected a predecessor module before '->'"
                                  : "the predecessor must be one module, got " + std::to_string(preds.size()) +
                                        " (a context goes before '<' or after '>')",
                    column(text, trim(pred).empty() ? pred : trim(pred)));
  p.pred = preds[0];
  if (p.pred.symbol == '[' || p.pred.symbol == ']' || p.pred.symbol == '%')
    throw RuleError("'" + shown(static_cast<char>(p.pred.symbol)) + "' cannot have a rule", column(text, trim(pred)));
  p.right = parse_patterns(text, right, names, k);
  if (has_right && p.right.empty()) throw RuleError("expected a right context after '>'", column(text, right));
  p.slots = static_cast<int>(names.size() - k);
  if (!trim(condition).empty()) {
    try {
      p.condition = Expression::compile(condition, names);
    } catch (const SyntaxError& e) {
      throw RuleError(e.what(), column(text, condition) + e.column);
    }
  } else if (has_condition) {
    throw RuleError("expected a condition after ':'", column(text, condition));
  }
  p.options[0].set_modules(calls_in(text, succ, names));
  return p;
}

std::size_t shown_column(std::string_view text, std::size_t column) {
  return io::shown_characters(text.substr(0, std::min(column, text.size())));
}

std::string caret_lines(std::string_view text, std::size_t column) {
  // The text as a terminal shows it, piece by piece: a character in its display width (io::text_width.h:
  // 2 for a wide one, 0 for a combining mark), a byte that is not UTF-8 in 1 (a replacement character), a
  // blank as a space, a control or format character escaped as Lua writes it ("\x7f", "\u{202e}") in the
  // columns of its escape: shown as itself it would move, hide or reorder what follows. The caret goes under
  // the piece that holds the byte at `column`: a '«' before the fault moves it one column, as it moves the
  // fault, not two.
  struct Piece {
    std::string shown;
    std::size_t columns;
  };
  std::vector<Piece> pieces;
  std::size_t at = npos;  // the piece holding byte `column`
  for (std::size_t i = 0; i < text.size();) {
    const std::size_t length = io::utf8_length(text, i), n = std::max<std::size_t>(length, 1);
    if (at == npos && column < i + n) at = pieces.size();
    const char32_t c = length == 0 ? 0xfffd : io::utf8_code_point(text, i, n);
    if (blank(text[i])) {
      pieces.push_back({" ", 1});
    } else if (io::shown_escaped(c)) {
      const std::string e = io::escaped_character(c);
      pieces.push_back({e, e.size()});
    } else {
      pieces.push_back({std::string(text.substr(i, n)), static_cast<std::size_t>(io::display_columns(c))});
    }
    i += n;
  }
  if (at == npos) at = pieces.size();  // past the end
  // Long text: `width` pieces around the caret.
  constexpr std::size_t width = 100;
  std::size_t begin = 0;
  if (pieces.size() > width && at > width / 2) begin = std::min(at - width / 2, pieces.size() - width);
  const std::size_t end = std::min(begin + width, pieces.size());
  const std::string lead = begin > 0 ? "  ..." : "  ";
  std::string line = lead, under(lead.size(), ' ');
  for (std::size_t k = begin; k < end; ++k) {
    line += pieces[k].shown;
    if (k < at) under.append(pieces[k].columns, ' ');
  }
  return line + "\n" + under + "^";
}

}  // namespace selfsim::lsystem
