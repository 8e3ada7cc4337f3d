// The tokens of an L-system expression (expression.h), for its compiler in expression.cpp: numbers, names,
// operators and parentheses, each with its byte offset for error carets. Internal to kernels/lsystem.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <string>
#include <string_view>

#include "kernels/lsystem/expression.h"

namespace selfsim::lsystem::expression_tokens {

enum class Tok {
  Number,
  Name,
  LParen,
  RParen,
  Comma,
  Plus,
  Minus,
  Star,
  Slash,
  Caret,
  Bang,
  Lt,
  Le,
  Gt,
  Ge,
  EqEq,
  Ne,
  AndAnd,
  OrOr,
  End
};

struct Token {
  Tok kind = Tok::End;
  std::size_t pos = 0;    // byte offset in the text
  std::string_view text;  // as written
  double number = 0;      // the value of a Number
};

// "'x'", or "the end of the expression": the token as an error message names it.
inline std::string describe(const Token& t) {
  return t.kind == Tok::End ? "the end of the expression" : "'" + std::string(t.text) + "'";
}

inline bool is_digit(char c) { return c >= '0' && c <= '9'; }
inline bool starts_name(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
inline bool continues_name(char c) { return starts_name(c) || is_digit(c); }

class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  Token next() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
    const std::size_t start = pos_;
    if (pos_ == text_.size()) return {Tok::End, start, {}};
    const char c = text_[pos_];
    if (is_digit(c) || (c == '.' && is_digit(peek(1)))) return number();
    if (starts_name(c)) {
      while (pos_ < text_.size() && continues_name(text_[pos_])) ++pos_;
      return token(Tok::Name, start);
    }
    struct Pair {
      char first, second;
      Tok kind;
    };
    static constexpr Pair kPairs[] = {{'<', '=', Tok::Le}, {'>', '=', Tok::Ge},     {'=', '=', Tok::EqEq},
                                      {'!', '=', Tok::Ne}, {'&', '&', Tok::AndAnd}, {'|', '|', Tok::OrOr}};
    for (const Pair& p : kPairs) {
      if (c == p.first && peek(1) == p.second) {
        pos_ += 2;
        return token(p.kind, start);
      }
    }
    ++pos_;
    switch (c) {
      case '(':
        return token(Tok::LParen, start);
      case ')':
        return token(Tok::RParen, start);
      case ',':
        return token(Tok::Comma, start);
      case '+':
        return token(Tok::Plus, start);
      case '-':
        return token(Tok::Minus, start);
      case '*':
        return token(Tok::Star, start);
      case '/':
        return token(Tok::Slash, start);
      case '^':
        return token(Tok::Caret, start);
      case '!':
        return token(Tok::Bang, start);
      case '<':
        return token(Tok::Lt, start);
      case '>':
        return token(Tok::Gt, start);
      case '=':
      case '&':
      case '|':  // half of a two-character operator: the usual slip of C programmers and of ABOP readers
        throw SyntaxError(std::string("unexpected '") + c + "': did you mean '" + c + c + "'?", start);
      default:
        break;
    }
    if (c >= ' ' && c <= '~') throw SyntaxError(std::string("unexpected character '") + c + "'", start);
    static constexpr char kHex[] = "0123456789abcdef";
    const auto byte = static_cast<unsigned char>(c);
    throw SyntaxError(std::string("unexpected byte 0x") + kHex[byte >> 4] + kHex[byte & 15], start);
  }

 private:
  char peek(std::size_t ahead) const { return pos_ + ahead < text_.size() ? text_[pos_ + ahead] : '\0'; }
  void skip_digits() {
    while (pos_ < text_.size() && is_digit(text_[pos_])) ++pos_;
  }
  Token token(Tok kind, std::size_t start) const { return {kind, start, text_.substr(start, pos_ - start)}; }

  // digits [. digits] [e [+-] digits], or . digits [...]. The extent is found here so that from_chars, which
  // would stop quietly at a bad exponent, only ever sees a whole, well-formed number.
  Token number() {
    const std::size_t start = pos_;
    skip_digits();
    if (peek(0) == '.') {
      ++pos_;
      skip_digits();
    }
    if (peek(0) == 'e' || peek(0) == 'E') {
      const std::size_t sign = (peek(1) == '+' || peek(1) == '-') ? 1 : 0;
      if (!is_digit(peek(1 + sign))) {
        pos_ += 1 + sign;
        throw SyntaxError("number '" + std::string(text_.substr(start, pos_ - start)) + "' has no exponent digits",
                          start);
      }
      pos_ += 1 + sign;
      skip_digits();
    }
    Token t = token(Tok::Number, start);
    const auto [end, error] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), t.number);
    // The text is well-formed, so the one possible failure is a value beyond double: too large, or too small
    // to be told from 0 (refused too: such a number in a rule is surely a typo).
    if (error != std::errc() || end != t.text.data() + t.text.size())
      throw SyntaxError("number '" + std::string(t.text) + "' is out of range", start);
    return t;
  }

  std::string_view text_;
  std::size_t pos_ = 0;
};

}  // namespace selfsim::lsystem::expression_tokens
