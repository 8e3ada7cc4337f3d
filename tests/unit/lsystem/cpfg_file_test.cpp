// cpfg's files expanded (kernels/lsystem/cpfg_file.h) and read by the book's reader, and both readers fed junk.
#include "kernels/lsystem/cpfg_file.h"

#include <gtest/gtest.h>

#include <map>
#include <random>

#include "kernels/base/error.h"
#include "kernels/lsystem/book_text.h"

namespace selfsim::lsystem {
namespace {

CpfgReader files(std::map<std::string, std::string> m) {
  return [m](const std::string& name) {
    const auto it = m.find(name);
    if (it == m.end()) throw Error("cannot read '" + name + "': no such file");
    return it->second;
  };
}

TEST(CpfgFile, CommentsKeepLineNumbers) {
  const CpfgText t = expand_cpfg("a.l", files({{"a.l", "/* one\ntwo */ Axiom: F\nF --> FF /* x */\n"}}));
  ASSERT_GE(t.lines.size(), 2u);
  EXPECT_EQ(t.lines[1].line, 2u);
  const BookGrammar g = read_book(t.text);
  EXPECT_EQ(*g.axiom, "F");
  ASSERT_EQ(g.rules.size(), 1u);
  EXPECT_EQ(g.rules[0].text, "F -> FF");
}

TEST(CpfgFile, IncludeBesideTheIncludingFile) {
  const CpfgText t =
      expand_cpfg("m/tree.l", files({{"m/tree.l", "#include \"c.l\"\nAxiom: A(k)\n"}, {"m/c.l", "#define k 2\n"}}));
  ASSERT_EQ(t.lines.size(), 4u);  // each file's lines and the empty one after its last newline
  EXPECT_EQ(t.lines[0].file, "m/c.l");
  EXPECT_EQ(t.lines.back().file, "m/tree.l");
  EXPECT_EQ(read_book(t.text).defines[0].second, 2);
}

TEST(CpfgFile, Refusals) {
  EXPECT_THROW(expand_cpfg("a.l", files({{"a.l", "#include \"a.l\"\n"}})), Error);     // a loop
  EXPECT_THROW(expand_cpfg("a.l", files({{"a.l", "#include \"../x.l\"\n"}})), Error);  // outside
  EXPECT_THROW(expand_cpfg("a.l", files({{"a.l", "#include \"gone.l\"\n"}})), Error);  // missing
  EXPECT_THROW(expand_cpfg("a.l", files({{"a.l", std::string("F\0G", 3)}})), Error);   // binary
  EXPECT_THROW(expand_cpfg("a.l", files({{"a.l", "/* open\n"}})), Error);              // comment
  EXPECT_THROW(read_book("Axiom: F\nF --> F ?E(1)\n"), BookError);                     // a query
  EXPECT_THROW(read_book("Axiom: F\nF --> ~l F\n"), BookError);                        // a surface
  EXPECT_THROW(read_book("Axiom: F\nF --> @o(1) F\n"), BookError);                     // a command
  EXPECT_THROW(read_book("Axiom: F\nA(x) : {y=1;} x > 1 --> F\n"), BookError);         // C statements
  EXPECT_THROW(read_book("Lsystem: 1\nLsystem: 2\n"), BookError);                      // two L-systems
}

TEST(CpfgFile, Sections) {
  const BookGrammar g = read_book(
      "Lsystem: 1\nconsider: AB\nAxiom: A+B\nA < B --> C\nhomomorphism\nmaximum depth: 3\nC --> F\n"
      "decomposition\nB --> BF\nendlsystem\n");
  ASSERT_EQ(g.rules.size(), 3u);
  EXPECT_EQ(g.rules[0].set, RuleSet::productions);
  EXPECT_EQ(g.rules[1].set, RuleSet::interpretation);
  EXPECT_EQ(g.rules[2].set, RuleSet::decomposition);
  EXPECT_EQ(g.max_depth, 3);
  EXPECT_EQ(g.ignore, "+CF");  // consider: AB -> everything else written is ignored
}

// Random bytes, and random lines of the notation's own pieces: every reader answers or throws Error, never
// anything else (and never crashes: the sanitizer builds run this too).
TEST(CpfgFile, Fuzz) {
  std::mt19937 rng(39);
  const std::string pieces[] = {"ω : ",
                                "Axiom: ",
                                "#define a ",
                                "#ignore: ",
                                "#include \"a.l\"",
                                "p1 : ",
                                "→",
                                "-->",
                                "->",
                                "(",
                                ")",
                                "F",
                                "A(x)",
                                " : ",
                                "x > 1",
                                "*",
                                "<",
                                ">",
                                "[",
                                "]",
                                "{",
                                "}",
                                "0.5",
                                "δ = ",
                                "n = ",
                                "\n",
                                "/*",
                                "*/",
                                "?E",
                                "~",
                                "@",
                                "∧",
                                "homomorphism\n",
                                "endlsystem\n",
                                "consider: ",
                                "\xff",
                                std::string(1, '\0')};
  for (int round = 0; round < 3000; ++round) {
    std::string text;
    const int n = static_cast<int>(rng() % 40);
    for (int i = 0; i < n; ++i)
      text += round % 2 ? std::string(1, static_cast<char>(rng() % 256)) : pieces[rng() % std::size(pieces)];
    try {
      read_book(text);
    } catch (const Error&) {
    }
    try {
      read_book(expand_cpfg("a.l", files({{"a.l", text}})).text);
    } catch (const Error&) {
    }
  }
}

}  // namespace
}  // namespace selfsim::lsystem
