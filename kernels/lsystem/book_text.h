// The Algorithmic Beauty of Plants' notation (Prusinkiewicz & Lindenmayer 1990), read as the book prints it and
// translated into the rule strings selfsim's own lsystem{} parses (rule_parser.h), so both share one engine:
//   ω : A(1,10)                      the axiom (also "axiom:")
//   p1 : A(l,w) : l > 1 → F(l) [...] a label, a condition after ':', '→' '-->' or '->' for the arrow
//   p2 : F →(0.33) F[+F]F            a probability after the arrow; also "F (0.33) -> ..." and "... : 0.33"
//   #define r1 0.9                   a constant: a number, or an expression of earlier constants
//   #ignore: + - F                   the symbols a context skips
//   n = 5, δ = 25.7°                 the derivation length (the default level) and the angle; also
//                                    "derivation length: 5", "angle: 25.7"
// '∧' is '^' (pitch up), '−' is '-', and '=' alone in a condition is '=='. cpfg's structure is read too:
// "Lsystem: 1", "Axiom:", "ignore:", "consider:" (every other symbol is ignored), "homomorphism" and
// "decomposition" sections (with "maximum depth:"), "endlsystem". What selfsim cannot do is refused by name:
// cpfg's query modules ('?E'), '~' surfaces, '@' commands, C statements in a production ('{ ... }' before the
// arrow), start:/end: blocks.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "kernels/base/error.h"

namespace selfsim::lsystem {

// A line of the book's text that cannot be read: the message and the 1-based line.
struct BookError : Error {
  std::size_t line;
  BookError(const std::string& message, std::size_t line) : Error(message), line(line) {}
};

// The rule sets of a grammar: its productions, and cpfg's decomposition and homomorphism sections.
enum class RuleSet { productions, decomposition, interpretation };

struct BookRule {
  std::string text;  // in selfsim's syntax: "A(l,w) : l > 1 -> F(l) [...] : 0.33"
  std::size_t line;  // 1-based, in the book's text
  RuleSet set = RuleSet::productions;
};

struct BookGrammar {
  std::optional<std::string> axiom;
  std::vector<BookRule> rules;
  std::vector<std::pair<std::string, double>> defines;  // in the order written
  std::optional<std::string> ignore;                    // the symbols of '#ignore', without blanks
  std::optional<int> level;                             // "derivation length" or "n ="
  std::optional<double> angle;                          // "δ =" or "angle:", in degrees
  std::optional<int> max_depth;                         // cpfg\'s "maximum depth:" of its sections
};

// Reads the text; every rule and the axiom are checked by rule_parser.h with the constants in scope, so a
// mistake names its book line. Throws BookError.
BookGrammar read_book(std::string_view text);

// One line of the book's notation (without its label) in selfsim's syntax; throws Error. For lsystem.load too.
std::string book_rule(std::string_view line);
// The book's symbols in a module string: '∧' -> '^', '−' -> '-'.
std::string book_symbols(std::string_view text);

// Where text written in selfsim's own syntax holds one of the book's forms, a hint naming it and its byte
// column: "'→' is the book's arrow: write '->' (or use lsystem.book)". `failed`: the rule did not parse
// (some forms, such as "-->", are only suspect then).
std::optional<std::pair<std::string, std::size_t>> book_form_hint(std::string_view text, bool failed);

}  // namespace selfsim::lsystem
