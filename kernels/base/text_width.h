// How wide a character shows on a terminal, for a caret placed under a fault in a message: East Asian wide
// and fullwidth characters and emoji take 2 columns, combining marks 0, others 1. Characters a terminal
// would act on or hide rather than show (control characters, C1 controls, format characters such as the
// bidi overrides U+202A-U+202E and U+2066-U+2069, zero-width spaces and joiners, line and paragraph
// separators) are shown escaped instead, so a message cannot reorder or hide the text it quotes.
// A small table of the ranges that matter, not the whole of Unicode: libc's wcwidth() depends on the
// locale (selfsim may run under C) and its Unicode version on the system; this gives the same on every one.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace selfsim::io {

// The code point of the well-formed UTF-8 character of `n` bytes (utf8_length) at s[i].
char32_t utf8_code_point(std::string_view s, std::size_t i, std::size_t n);

// Whether a message shows the character escaped (escaped_character) rather than as itself.
bool shown_escaped(char32_t c);

// The columns a terminal gives the character when shown as itself: 0, 1 or 2.
int display_columns(char32_t c);

// The character written so a terminal shows it and does nothing else: "\x01" and "\x7f" for a control byte
// (as a Lua string writes them), "\u{202e}" for any other character shown_escaped.
std::string escaped_character(char32_t c);

}  // namespace selfsim::io
