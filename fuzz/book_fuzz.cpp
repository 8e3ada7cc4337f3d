// Fuzz target: the book's notation (kernels/lsystem/book_text.h). Input: the text lsystem.book is given,
// ABOP's "ω : A(1,10)", "p1 : A(l,w) : * → F(l)[...]", "#define", "#ignore", "n = 5, δ = 25.7°", and cpfg's
// sections. Checks (book_check.h): read_book lets only a BookError escape, naming a line of the text; the
// rules and axiom it returns parse with rule_parser under the constants it returns, each rule on a line of
// the text, numbers finite; then lsystem.book(text) in a sandbox compiles the translated rules as lsystem{}
// does and rewrites levels 0 and 2: no C++ exception escapes the binding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz/book_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (selfsim::fuzz::check_read_book(text)) selfsim::fuzz::run_lsystem_book(text);
  return 0;
}
