// The book's notation translated into selfsim's rule syntax (kernels/lsystem/book_text.h), form by form.
#include "kernels/lsystem/book_text.h"

#include <gtest/gtest.h>

namespace selfsim::lsystem {
namespace {

TEST(BookText, Arrows) {
  EXPECT_EQ(book_rule("F \xE2\x86\x92 F[+F]F"), "F -> F[+F]F");
  EXPECT_EQ(book_rule("F --> F[+F]F"), "F -> F[+F]F");
  EXPECT_EQ(book_rule("F -> F"), "F -> F");
  EXPECT_THROW(book_rule("F F[+F]F"), Error);
}

TEST(BookText, SymbolsAndConditions) {
  EXPECT_EQ(book_rule("A \xE2\x86\x92 [\xE2\x88\xA7"
                      "F]\xE2\x88\x92"
                      "F"),
            "A -> [^F]-F");
  EXPECT_EQ(book_rule("A(t) : t = 0 -> B"), "A(t) : t == 0 -> B");
  EXPECT_EQ(book_rule("A(t) : t >= 0 && t != 2 -> B"), "A(t) : t >= 0 && t != 2 -> B");
  EXPECT_EQ(book_rule("A -> \xCE\xB5"), "A -> ");
  // The book's typeset apostrophe (its colour index) is selfsim's ': it was a silent do-nothing symbol.
  EXPECT_EQ(book_rule("A \xE2\x86\x92 F\xE2\x80\x99"
                      "A"),
            "A -> F'A");
}

TEST(BookText, Probabilities) {
  EXPECT_EQ(book_rule("F \xE2\x86\x92(0.33) F[+F]F"), "F -> F[+F]F : 0.33");
  EXPECT_EQ(book_rule("F (0.25) -> F[-F]F"), "F -> F[-F]F : 0.25");
  EXPECT_EQ(book_rule("F -> F : 0.5"), "F -> F : 0.5");
  EXPECT_EQ(book_rule("A(x) -> B(x)"), "A(x) -> B(x)");  // a name in parentheses is a parameter
  EXPECT_THROW(book_rule("F (0.5) -> F : 0.5"), Error);
  EXPECT_THROW(book_rule("F ->(x) F"), Error);
}

TEST(BookText, Grammar) {
  const BookGrammar g = read_book(
      "#define r 0.5\n#define s r*2\n#ignore: + - F\n\xCF\x89 : A(r)\np1 : A(x) : * -> F(x*s) A(x)\n"
      "n = 4, \xCE\xB4 = 25.7\xC2\xB0\n");
  ASSERT_TRUE(g.axiom);
  EXPECT_EQ(*g.axiom, "A(r)");
  ASSERT_EQ(g.defines.size(), 2u);
  EXPECT_EQ(g.defines[1].second, 1.0);
  EXPECT_EQ(g.ignore, "+-F");
  ASSERT_EQ(g.rules.size(), 1u);
  EXPECT_EQ(g.rules[0].text, "A(x) : * -> F(x*s) A(x)");
  EXPECT_EQ(g.rules[0].line, 5u);
  EXPECT_EQ(g.level, 4);
  EXPECT_DOUBLE_EQ(*g.angle, 25.7);
  const BookGrammar h = read_book("axiom: F\nderivation length: 3\nangle: 90\nF -> FF\n");
  EXPECT_EQ(*h.axiom, "F");
  EXPECT_EQ(h.level, 3);
  EXPECT_EQ(*h.angle, 90);
}

TEST(BookText, ErrorsNameTheLine) {
  auto line_of = [](const char* text) -> std::size_t {
    try {
      read_book(text);
    } catch (const BookError& e) {
      return e.line;
    }
    return 0;
  };
  EXPECT_EQ(line_of("\xCF\x89 : F\n\nF -> F[\n"), 3u);     // a rule that does not parse
  EXPECT_EQ(line_of("\xCF\x89 : F\nF -> F(q)\n"), 2u);     // an unknown name
  EXPECT_EQ(line_of("#define a b\n"), 1u);                 // an unknown constant
  EXPECT_EQ(line_of("\xCF\x89 : F\n\xCF\x89 : G\n"), 2u);  // two axioms
  EXPECT_EQ(line_of("\xCF\x89 : F\nn = 1.5\n"), 2u);       // a level that is not whole
  EXPECT_EQ(line_of("\xCF\x89 : F\n#pragma x\n"), 2u);     // an unknown directive
  EXPECT_EQ(line_of("\xCF\x89 : F\nF -> F\n"), 0u);
}

TEST(BookText, HintsInOwnSyntax) {
  EXPECT_TRUE(book_form_hint("F \xE2\x86\x92 F", false));
  EXPECT_TRUE(
      book_form_hint("F -> [\xE2\x88\xA7"
                     "F]",
                     false));
  EXPECT_TRUE(book_form_hint("\xCF\x89 : F", false));
  EXPECT_TRUE(
      book_form_hint("A -> F\xE2\x80\x99"
                     "A",
                     false));
  EXPECT_FALSE(book_form_hint("p1 : F -> F", false));  // only once the parser has refused it
  EXPECT_TRUE(book_form_hint("p1 : F -> F", true));
  EXPECT_TRUE(book_form_hint("F (0.3) -> F", true));
  EXPECT_TRUE(book_form_hint("F -->F", true));
  EXPECT_FALSE(book_form_hint("A(x) : x > 1 -> F(x)", true));
  EXPECT_EQ(book_form_hint("F \xE2\x86\x92 F", false)->second, 2u);
}

}  // namespace
}  // namespace selfsim::lsystem
