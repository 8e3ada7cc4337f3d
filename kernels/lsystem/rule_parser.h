// Rules and module strings in ABOP notation (Prusinkiewicz & Lindenmayer, The Algorithmic Beauty of
// Plants, 1.5-1.10), parsed once into compiled productions:
//   [left <] pred [> right] [: condition] -> successor [: weight]
// e.g. "A(x) : x > 1 -> F(x) [+(30) A(x*0.6)]", "B < A > C -> X", "F -> F[+F]F : 0.3".
// A module is one symbol (any byte but whitespace, '(' ')' ','), followed directly by its parameters in
// parentheses; whitespace between modules is ignored.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernels/base/error.h"
#include "kernels/lsystem/production.h"

namespace selfsim::lsystem {

// A malformed rule or module string: the message and the 0-based column of the problem in its text.
struct RuleError : Error {
  std::size_t column;
  RuleError(const std::string& message, std::size_t column) : Error(message), column(column) {}
};

// One rule. `where` names it in later messages ("rule 3"); `constants` are names every expression may read
// (the grammar's `define`), which take the first slots, before the rule's own parameters. Throws RuleError.
Production parse_rule(std::string_view text, const std::string& where, std::span<const std::string> constants = {});
// Modules whose parameters are expressions over `names` (a successor, or an axiom with no names).
std::vector<Call> parse_calls(std::string_view text, std::span<const std::string> names);
// Whether the rule gives a stochastic weight after its successor (": 0.3").
bool rule_weight_given(std::string_view text);
// Whether text uses anything beyond plain symbols: parameters, context or condition syntax.
bool has_module_syntax(std::string_view text);

// The text on one line and a caret under the character at byte `column` on the next, for messages:
//   "    A(x) : x > -> F\n               ^"
// Placed by the columns a terminal gives the characters before it (base/text_width.h: 2 for a wide one, 0 for a
// combining mark), not by bytes or characters; control and format characters shown escaped ("\u{202e}").
std::string caret_lines(std::string_view text, std::size_t column);
// The column (0-based) of the byte at `column` of text as an editor counts it: the characters before it.
std::size_t shown_column(std::string_view text, std::size_t column);

}  // namespace selfsim::lsystem
