#include "kernels/lsystem/book_text.h"

#include <array>
#include <cctype>
#include <charconv>
#include <cmath>

#include "kernels/lsystem/expression.h"
#include "kernels/lsystem/find_outside.h"
#include "kernels/lsystem/grammar.h"
#include "kernels/lsystem/rule_parser.h"

namespace selfsim::lsystem {

namespace {

constexpr std::size_t npos = std::string_view::npos;
// The book's characters, in UTF-8.
constexpr std::string_view arrow = "\xE2\x86\x92";  // →
constexpr std::string_view wedge = "\xE2\x88\xA7";  // ∧ (pitch up)
constexpr std::string_view minus = "\xE2\x88\x92";  // − (the typeset minus)
constexpr std::string_view quote = "\xE2\x80\x99";  // ’ (the typeset apostrophe: the book's colour index ')
constexpr std::string_view omega = "\xCF\x89";      // ω
constexpr std::string_view delta = "\xCE\xB4";      // δ
constexpr std::string_view degree = "\xC2\xB0";     // °
constexpr std::string_view epsilon = "\xCE\xB5";    // ε (the empty successor)

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && blank(s.front())) s.remove_prefix(1);
  while (!s.empty() && blank(s.back())) s.remove_suffix(1);
  return s;
}

void replace_all(std::string& s, std::string_view from, std::string_view to) {
  for (std::size_t at = s.find(from); at != npos; at = s.find(from, at + to.size())) s.replace(at, from.size(), to);
}

std::optional<double> number(std::string_view t) {
  t = trim(t);
  double v = 0;
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), v);
  if (t.empty() || ec != std::errc() || end != t.data() + t.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// Case-insensitive: whether `s` starts with the word `key` followed (after blanks) by `sep`; the rest after it.
std::optional<std::string_view> keyed(std::string_view s, std::string_view key, char sep) {
  if (s.size() < key.size()) return std::nullopt;
  for (std::size_t i = 0; i < key.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(s[i])) != key[i]) return std::nullopt;
  std::string_view rest = s.substr(key.size());
  while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
  if (rest.empty() || rest.front() != sep) return std::nullopt;
  return trim(rest.substr(1));
}

// The length of a rule label at the start ("p1 :", "p_12:", "P3 :"), or 0.
std::size_t label_length(std::string_view s) {
  std::size_t i = 0;
  if (s.empty() || (s[0] != 'p' && s[0] != 'P')) return 0;
  i = 1;
  if (i < s.size() && s[i] == '_') ++i;
  const std::size_t digits = i;
  while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
  if (i == digits) return 0;
  while (i < s.size() && blank(s[i])) ++i;
  return i < s.size() && s[i] == ':' ? i + 1 : 0;
}

// '=' alone (not '==', '<=', '>=', '!=') as '==': the book writes "t = 0" in a condition.
std::string equality(std::string_view c) {
  std::string out;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const bool alone = c[i] == '=' && (i == 0 || std::string_view("=<>!").find(c[i - 1]) == npos) &&
                       (i + 1 == c.size() || c[i + 1] != '=');
    out += alone ? "==" : std::string(1, c[i]);
  }
  return out;
}

std::string shown_number(double w) {
  char buf[32];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, w);
  return std::string(buf, end);
}

// A value: a number or an expression of the constants so far.
double value_of(std::string_view text, const std::vector<std::pair<std::string, double>>& defines,
                const std::string& what) {
  std::vector<std::string> names;
  std::vector<double> values;
  for (const auto& [n, v] : defines) {
    names.push_back(n);
    values.push_back(v);
  }
  try {
    return Expression::compile(text, names).eval(values);
  } catch (const SyntaxError& e) {
    throw Error(what + ": " + e.what());
  } catch (const EvalError& e) {
    throw Error(what + ": " + e.what());
  }
}

int level_of(std::string_view text, const std::vector<std::pair<std::string, double>>& defines) {
  const double n = value_of(text, defines, "the derivation length");
  if (!(n >= 0 && n <= max_level && std::floor(n) == n))
    throw Error("the derivation length must be a whole number from 0 to " + std::to_string(max_level) + ", got '" +
                std::string(trim(text)) + "'");
  return static_cast<int>(n);
}

double angle_of(std::string_view text, const std::vector<std::pair<std::string, double>>& defines) {
  std::string t(trim(text));
  if (t.ends_with(degree)) t.resize(t.size() - degree.size());
  return value_of(t, defines, "the angle");
}

bool word(std::string_view s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s[0]))) return false;
  for (char c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

void read_define(std::string_view rest, BookGrammar& g) {
  rest = trim(rest);
  std::size_t end = 0;
  while (end < rest.size() && !blank(rest[end])) ++end;
  const std::string name(rest.substr(0, end));
  const std::string_view value = trim(rest.substr(end));
  if (!word(name)) throw Error("#define names a constant (letters, digits, _), got '" + name + "'");
  if (value.empty()) throw Error("#define " + name + ": expected a value after the name");
  for (const auto& [n, v] : g.defines)
    if (n == name) throw Error("#define " + name + " is defined twice");
  if (g.defines.size() >= max_constants)
    throw Error("#define " + name + ": over the limit of " + std::to_string(max_constants) + " constants");
  g.defines.emplace_back(name, value_of(value, g.defines,
                                        "#define " + name +
                                            ": expected a number or an expression of earlier "
                                            "constants"));
}

// "n = 5, δ = 25.7°": whether the line is such a list; read into g.
bool read_settings(std::string_view line, BookGrammar& g) {
  if (line.find("->") != npos || line.find(arrow) != npos || line.find('=') == npos) return false;
  std::size_t begin = 0;
  while (begin <= line.size()) {
    std::size_t end = find_outside(line.substr(begin), ",");
    end = end == npos ? line.size() : begin + end;
    const std::string_view item = trim(line.substr(begin, end - begin));
    const std::size_t eq = item.find('=');
    if (eq == npos) throw Error("expected 'name = value' (n = 5, δ = 25.7°), got '" + std::string(item) + "'");
    const std::string_view name = trim(item.substr(0, eq)), value = item.substr(eq + 1);
    if (name == "n")
      g.level = level_of(value, g.defines);
    else if (name == delta || name == "delta" || name == "angle")
      g.angle = angle_of(value, g.defines);
    else
      throw Error("expected n = (the derivation length) or δ = (the angle), got '" + std::string(name) + " ='");
    begin = end + 1;
  }
  return true;
}

// What cpfg writes that selfsim cannot do, refused by name rather than read as do-nothing symbols.
void refuse_cpfg(std::string_view t) {
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] == '?' && i + 1 < t.size() && (std::isalpha(static_cast<unsigned char>(t[i + 1])) || t[i + 1] == '('))
      throw Error("'?" + std::string(1, t[i + 1]) +
                  "' is one of cpfg's query modules (the environment, the turtle's state): selfsim cannot answer it");
    if (t[i] == '~') throw Error("'~' draws one of cpfg's predefined surfaces (from .s files): selfsim has none");
    if (t[i] == '@') throw Error("'@' starts one of cpfg's drawing commands (@o, @v, @Gs, ...): selfsim has none");
  }
  const std::size_t at = find_outside(t, "->") != npos ? find_outside(t, "->") : t.find(arrow);
  const std::string_view left = t.substr(0, at);
  if (const std::size_t colon = find_outside(left, ":"); colon != npos && left.find('{', colon) != npos)
    throw Error("'{ ... }' in a production's condition holds cpfg's C statements: selfsim cannot run them");
}

void see_symbols(const Production& p, std::array<bool, 256>& seen) {
  for (const auto* side : {&p.left, &p.right})
    for (const Pattern& m : *side) seen[m.symbol] = true;
  seen[p.pred.symbol] = true;
  for (const Successor& o : p.options)
    for (const Call& c : o.modules) seen[c.symbol] = true;
}

}  // namespace

std::string book_symbols(std::string_view text) {
  std::string s(text);
  replace_all(s, wedge, "^");
  replace_all(s, minus, "-");
  replace_all(s, quote, "'");
  replace_all(s, epsilon, "");
  return s;
}

std::string book_rule(std::string_view line) {
  std::string s = book_symbols(line);
  replace_all(s, arrow, "->");
  if (const std::size_t at = find_outside(s, "-->"); at != npos) s.replace(at, 3, "->");
  const std::size_t at = find_outside(s, "->");
  if (at == npos) throw Error("expected a rule, predecessor → successor, or ω:, #define, #ignore, n =, δ =");
  std::string_view left = trim(std::string_view(s).substr(0, at)), right = trim(std::string_view(s).substr(at + 2));
  std::optional<double> weight;
  // "→(0.33) F[+F]F": a successor never starts with '(' (a parameter list follows its module).
  if (right.starts_with('(')) {
    const std::size_t close = right.find(')');
    if (close == npos) throw Error("a '(' after the arrow is never closed");
    weight = number(right.substr(1, close - 1));
    if (!weight || *weight < 0)
      throw Error("after the arrow, '(...)' is a probability, a number >= 0; got '" +
                  std::string(right.substr(0, close + 1)) + "'");
    right = trim(right.substr(close + 1));
  }
  // "F (0.33) -> ...": a number in parentheses is never a predecessor's parameter (those are names).
  if (left.ends_with(')')) {
    const std::size_t open = left.rfind('(');
    if (const auto w = open == npos ? std::nullopt : number(left.substr(open + 1, left.size() - open - 2))) {
      if (weight) throw Error("two probabilities: one before the arrow and one after it");
      if (*w < 0) throw Error("a probability must be >= 0, got " + shown_number(*w));
      weight = w;
      left = trim(left.substr(0, open));
    }
  }
  if (weight && find_outside(right, ":", true) != npos)
    throw Error("two probabilities: one at the arrow and one after the successor (': w')");
  std::string out;
  if (const std::size_t colon = find_outside(left, ":"); colon != npos)
    out = std::string(left.substr(0, colon)) + ":" + equality(left.substr(colon + 1));
  else
    out = std::string(left);
  out += " -> ";
  out += right;
  if (weight) out += " : " + shown_number(*weight);
  return out;
}

BookGrammar read_book(std::string_view text) {
  BookGrammar g;
  RuleSet set = RuleSet::productions;
  bool lsystem_seen = false, ended = false;
  std::optional<std::string> consider;
  std::array<bool, 256> seen{};
  std::size_t line = 0, begin = 0;
  while (begin <= text.size()) {
    std::size_t end = text.find('\n', begin);
    if (end == npos) end = text.size();
    ++line;
    const std::string_view raw = trim(text.substr(begin, end - begin));
    begin = end + 1;
    if (raw.empty()) continue;
    std::vector<std::string> names;
    for (const auto& [n, v] : g.defines) names.push_back(n);
    try {
      if (raw.starts_with('#')) {
        if (raw.substr(1).starts_with("define")) {
          if (raw.size() < 8 || !blank(raw[7])) throw Error("#define needs a name and a value: #define r1 0.9");
          read_define(raw.substr(8), g);
        } else if (raw.substr(1, 6) == "ignore") {
          std::string_view rest = trim(raw.substr(7));
          if (rest.starts_with(':')) rest.remove_prefix(1);
          std::string symbols = book_symbols(rest);
          std::erase_if(symbols, blank);
          if (g.ignore) throw Error("#ignore is given twice");
          g.ignore = symbols;
        } else {
          throw Error("expected #define or #ignore, got '" + std::string(raw.substr(0, raw.find(' '))) + "'");
        }
        continue;
      }
      const std::string_view t = trim(raw.substr(label_length(raw)));
      if (ended) throw Error("text after endlsystem: selfsim reads one L-system a file");
      if (keyed(t, "lsystem", ':')) {
        if (lsystem_seen) throw Error("a second L-system ('Lsystem:'): selfsim reads one a file");
        lsystem_seen = true;
        continue;
      }
      if (lower(t) == "endlsystem") {
        ended = true;
        continue;
      }
      if (lower(t).starts_with("homomorphism") || lower(t).starts_with("decomposition")) {
        set = lower(t).starts_with("homomorphism") ? RuleSet::interpretation : RuleSet::decomposition;
        continue;
      }
      if (const auto d = keyed(t, "maximum depth", ':')) {
        g.max_depth = level_of(*d, g.defines);
        if (*g.max_depth > max_rule_depth)
          throw Error("maximum depth must be at most " + std::to_string(max_rule_depth));
        continue;
      }
      if (const auto i = keyed(t, "ignore", ':')) {
        if (g.ignore) throw Error("ignore: is given twice");
        g.ignore = book_symbols(*i);
        std::erase_if(*g.ignore, blank);
        continue;
      }
      if (const auto c = keyed(t, "consider", ':')) {
        if (consider) throw Error("consider: is given twice");
        consider = book_symbols(*c);
        std::erase_if(*consider, blank);
        continue;
      }
      for (const char* block : {"start", "starteach", "end", "endeach", "define"})
        if (keyed(t, block, ':'))
          throw Error(std::string("cpfg's '") + std::string(t.substr(0, std::string_view(block).size())) +
                      ":' block holds C statements: selfsim cannot run them");
      refuse_cpfg(t);
      std::optional<std::string_view> axiom =
          t.starts_with(omega) ? keyed(t.substr(omega.size()), "", ':') : keyed(t, "axiom", ':');
      if (axiom) {
        if (g.axiom) throw Error("a second axiom: the text gives one, with ω:");
        g.axiom = book_symbols(*axiom);
        if (trim(*g.axiom).empty()) throw Error("the axiom is empty: write the level-0 string after ω:");
        try {
          for (const Call& c : parse_calls(*g.axiom, names)) seen[c.symbol] = true;
        } catch (const RuleError& e) {
          throw Error(std::string("the axiom: ") + e.what());
        }
      } else if (const auto n = keyed(t, "derivation length", ':')) {
        g.level = level_of(*n, g.defines);
      } else if (const auto a = keyed(t, "angle", ':')) {
        g.angle = angle_of(*a, g.defines);
      } else if (!read_settings(book_symbols(t), g)) {
        BookRule r{book_rule(t), line, set};
        try {
          see_symbols(parse_rule(r.text, "line " + std::to_string(line), names), seen);
        } catch (const RuleError& e) {
          throw Error(std::string(e.what()) + ", in '" + r.text + "'");
        }
        g.rules.push_back(std::move(r));
      }
    } catch (const BookError&) {
      throw;
    } catch (const Error& e) {
      throw BookError(e.what(), line);
    }
  }
  // cpfg's consider: contexts see only these symbols (and the branches), so every other one is ignored.
  if (consider) {
    if (g.ignore) throw BookError("both ignore: and consider: are given: keep one", line);
    g.ignore = "";
    for (int c = 1; c < 256; ++c)
      if (seen[c] && c != '[' && c != ']' && consider->find(static_cast<char>(c)) == std::string::npos)
        *g.ignore += static_cast<char>(c);
  }
  return g;
}

std::optional<std::pair<std::string, std::size_t>> book_form_hint(std::string_view text, bool failed) {
  const std::string_view t = trim(text);
  const std::size_t lead = static_cast<std::size_t>(t.data() - text.data());
  if (const std::size_t at = text.find(arrow); at != npos)
    return std::pair{"'→' is the book's arrow: write '->' (or use lsystem.book)", at};
  if (const std::size_t at = text.find(wedge); at != npos)
    return std::pair{"'∧' is the book's pitch up: write '^' (or use lsystem.book)", at};
  if (const std::size_t at = text.find(minus); at != npos)
    return std::pair{"'−' is the book's minus sign: write '-' (or use lsystem.book)", at};
  if (const std::size_t at = text.find(quote); at != npos)
    return std::pair{"'’' is the book's colour index: write \"'\" (or use lsystem.book)", at};
  if (t.starts_with(omega) || (failed && keyed(t, "axiom", ':')))
    return std::pair{"'ω:' is the book's axiom line: give the axiom as option 'axiom' (or use lsystem.book)", lead};
  if (!failed) return std::nullopt;
  if (label_length(t) > 0)
    return std::pair{"'" + std::string(t.substr(0, t.find_first_of(" \t:"))) +
                         ":' is the book's rule label: leave it out (or use lsystem.book)",
                     lead};
  if (const std::size_t at = text.find("-->"); at != npos)
    return std::pair{"'-->' is cpfg's arrow: write '->' (or use lsystem.book)", at};
  if (const std::size_t at = find_outside(text, "->"); at != npos) {
    const std::string_view left = trim(text.substr(0, at)), right = trim(text.substr(at + 2));
    const std::size_t open = left.rfind('(');
    const bool before = left.ends_with(')') && open != npos && number(left.substr(open + 1, left.size() - open - 2));
    const bool after =
        right.starts_with('(') && right.find(')') != npos && number(right.substr(1, right.find(')') - 1));
    if (before || after)
      return std::pair{
          "a probability at the arrow is the book's: write it after the successor, 'F -> F[+F]F : 0.33' (or use "
          "lsystem.book)",
          before ? static_cast<std::size_t>(left.data() - text.data()) + open
                 : static_cast<std::size_t>(right.data() - text.data())};
  }
  return std::nullopt;
}

}  // namespace selfsim::lsystem
