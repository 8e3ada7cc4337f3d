#include "kernels/lsystem/expression.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

namespace selfsim::lsystem {

// Grouped by how many values each operation leaves on the stack, which stack_effect relies on.
enum class Expression::Code : std::uint8_t {
  // push one value
  Const,
  Param,
  // replace the top value
  Neg,
  Not,
  Truth,  // 1 if nonzero, else 0: the result of && and || is always 1 or 0
  Sin,
  Cos,
  Tan,
  Asin,
  Acos,
  Atan,
  Sqrt,
  Abs,
  Floor,
  Ceil,
  Exp,
  Log,
  // replace the two top values by one
  Add,
  Sub,
  Mul,
  Div,
  Pow,
  Eq,
  Ne,
  Lt,
  Le,
  Gt,
  Ge,
  Min,
  Max,
  Atan2,
  // Short circuit: if the top value decides the result (0 for &&, nonzero for ||), it becomes that result (0 or
  // 1) and the right operand is skipped; otherwise it is popped and the right operand follows.
  AndJump,
  OrJump,
};

namespace {

constexpr double kDegreesPerRadian = 180 / std::numbers::pi;

// Angle `degrees` as quadrant * 90 + rest, with rest in radians within +-45 degrees. Reducing in degrees is
// exact, so that multiples of 90 give exact 0 and +-1 below (a turtle that turns by 90 four times comes back
// to the same point) and large angles keep their precision.
struct Reduced {
  int quadrant;
  double rest;
};
Reduced reduce_degrees(double degrees) {
  // exact, within +-180; NaN for inf and NaN. The test skips the slow remainder for the usual small angles.
  const double r = std::fabs(degrees) <= 180 ? degrees : std::remainder(degrees, 360);
  if (std::isnan(r)) return {0, r};  // (casting NaN to int below would be undefined)
  const double quadrant = std::nearbyint(r / 90);
  return {static_cast<int>(quadrant), (r - 90 * quadrant) / kDegreesPerRadian};
}

// sin(rest + quadrant * 90 degrees).
double sin_quadrant(Reduced a) {
  switch (a.quadrant & 3) {  // two's complement: -1 & 3 == 3
    case 0:
      return std::sin(a.rest);
    case 1:
      return std::cos(a.rest);
    case 2:
      return -std::sin(a.rest);
    default:
      return -std::cos(a.rest);
  }
}

double sin_degrees(double degrees) { return sin_quadrant(reduce_degrees(degrees)); }
double cos_degrees(double degrees) {
  Reduced a = reduce_degrees(degrees);
  ++a.quadrant;
  return sin_quadrant(a);
}
double tan_degrees(double degrees) { return sin_degrees(degrees) / cos_degrees(degrees); }

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
std::string describe(const Token& t) {
  return t.kind == Tok::End ? "the end of the expression" : "'" + std::string(t.text) + "'";
}

bool is_digit(char c) { return c >= '0' && c <= '9'; }
bool starts_name(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
bool continues_name(char c) { return starts_name(c) || is_digit(c); }

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

}  // namespace

// Recursive descent straight to bytecode, one function per precedence level. Each parsing function returns
// whether what it emitted is a single Const, which lets its caller fold constant operations as it goes.
class Expression::Compiler {
 public:
  Compiler(std::string_view text, std::span<const std::string> names) : text_(text), lexer_(text), names_(names) {}

  Expression compile() {
    if (text_.size() > kMaxLength)
      throw SyntaxError("expression is longer than " + std::to_string(kMaxLength) + " bytes", kMaxLength);
    advance();
    if (tok_.kind == Tok::End) throw SyntaxError("expected an expression", 0);
    expression();
    if (tok_.kind == Tok::RParen) throw SyntaxError("unexpected ')'", tok_.pos);
    if (tok_.kind != Tok::End) throw SyntaxError("unexpected " + describe(tok_) + " after the expression", tok_.pos);
    check_stack();

    Expression e;
    for (const Op& op : code_) {
      if (op.code != Code::Param) continue;
      e.constant_ = false;
      e.arity_ = std::max<std::size_t>(e.arity_, op.index + 1);
    }
    e.code_ = std::move(code_);
    return e;
  }

 private:
  struct Binary {
    int level;  // precedence, 0 lowest
    Tok tok;
    Code code;
  };
  static constexpr Binary kBinary[] = {
      {0, Tok::OrOr, Code::OrJump}, {1, Tok::AndAnd, Code::AndJump}, {2, Tok::EqEq, Code::Eq},
      {2, Tok::Ne, Code::Ne},       {3, Tok::Lt, Code::Lt},          {3, Tok::Le, Code::Le},
      {3, Tok::Gt, Code::Gt},       {3, Tok::Ge, Code::Ge},          {4, Tok::Plus, Code::Add},
      {4, Tok::Minus, Code::Sub},   {5, Tok::Star, Code::Mul},       {5, Tok::Slash, Code::Div},
  };
  static constexpr int kUnaryLevel = 6;  // above every binary operator but ^

  struct Function {
    std::string_view name;
    Code code;
    int arity;
  };
  static constexpr Function kFunctions[] = {
      {"sin", Code::Sin, 1},   {"cos", Code::Cos, 1},     {"tan", Code::Tan, 1},     {"asin", Code::Asin, 1},
      {"acos", Code::Acos, 1}, {"atan", Code::Atan, 1},   {"atan2", Code::Atan2, 2}, {"sqrt", Code::Sqrt, 1},
      {"abs", Code::Abs, 1},   {"floor", Code::Floor, 1}, {"ceil", Code::Ceil, 1},   {"exp", Code::Exp, 1},
      {"log", Code::Log, 1},   {"min", Code::Min, 2},     {"max", Code::Max, 2},     {"pow", Code::Pow, 2},
  };

  // One level deeper in the recursion. Refusing past kMaxNesting bounds the C++ stack whatever the input.
  class Nest {
   public:
    Nest(int& depth, std::size_t column) : depth_(depth) {
      if (++depth_ > kMaxNesting)
        throw SyntaxError("expression nests too deeply (more than " + std::to_string(kMaxNesting) + " levels)", column);
    }
    ~Nest() { --depth_; }
    Nest(const Nest&) = delete;
    Nest& operator=(const Nest&) = delete;

   private:
    int& depth_;
  };

  bool expression() { return binary(0); }

  // Left-associative operators of precedence `level` and above.
  bool binary(int level) {
    if (level == kUnaryLevel) return unary();
    const std::size_t start = code_.size();
    bool folded = binary(level + 1);
    while (const Binary* op = binary_at(level, tok_.kind)) {
      const std::size_t column = tok_.pos;
      advance();
      if (op->code == Code::AndJump || op->code == Code::OrJump) {
        folded = logic(op->code, level, start, folded, column);
        continue;
      }
      const bool right = binary(level + 1);
      emit(op->code, column);
      folded = folded && right && fold(start);
    }
    return folded;
  }

  static const Binary* binary_at(int level, Tok tok) {
    for (const Binary& b : kBinary)
      if (b.level == level && b.tok == tok) return &b;
    return nullptr;
  }

  // The right operand of && or || (`jump`), after the left one emitted from `start`.
  bool logic(Code jump, int level, std::size_t start, bool left_folded, std::size_t column) {
    const std::size_t at = code_.size();
    emit(jump, column);
    const std::size_t right_start = code_.size();
    bool right_folded = binary(level + 1);
    emit(Code::Truth, column);
    right_folded = right_folded && fold(right_start);
    code_[at].index = static_cast<std::uint32_t>(code_.size() - right_start);
    if (!left_folded) return false;

    // A constant left operand either decides the result, or leaves it to the right one alone.
    const double left = code_[start].value;
    if (jump == Code::AndJump ? left == 0 : left != 0) {
      const std::size_t left_column = columns_[start];
      truncate(start);
      emit(Code::Const, left_column, 0, jump == Code::AndJump ? 0 : 1);
      return true;
    }
    code_.erase(code_.begin() + start, code_.begin() + right_start);  // jumps are relative: still right
    columns_.erase(columns_.begin() + start, columns_.begin() + right_start);
    return right_folded;
  }

  // Prefix - + !, whose operand may itself be prefixed; they bind looser than ^ (-x^2 is -(x^2)).
  bool unary() {
    const Token op = tok_;
    if (op.kind != Tok::Minus && op.kind != Tok::Plus && op.kind != Tok::Bang) return power();
    advance();
    Nest nest(nesting_, op.pos);
    const std::size_t start = code_.size();
    const bool folded = unary();
    if (op.kind == Tok::Plus) return folded;
    emit(op.kind == Tok::Minus ? Code::Neg : Code::Not, op.pos);
    return folded && fold(start);
  }

  // a ^ b, right-associative; b may carry a sign (2^-1).
  bool power() {
    const std::size_t start = code_.size();
    const bool base = primary();
    if (tok_.kind != Tok::Caret) return base;
    const std::size_t column = tok_.pos;
    advance();
    Nest nest(nesting_, column);
    const bool exponent = unary();
    emit(Code::Pow, column);
    return base && exponent && fold(start);
  }

  bool primary() {
    const Token t = tok_;
    switch (t.kind) {
      case Tok::Number:
        advance();
        emit(Code::Const, t.pos, 0, t.number);
        return true;
      case Tok::Name:
        advance();
        return tok_.kind == Tok::LParen ? call(t) : name(t);
      case Tok::LParen: {
        advance();
        Nest nest(nesting_, t.pos);
        const bool folded = expression();
        if (tok_.kind != Tok::RParen) throw missing_paren(t.pos);
        advance();
        return folded;
      }
      default:
        throw SyntaxError("expected a number, a name or '(' at " + describe(t), t.pos);
    }
  }

  SyntaxError missing_paren(std::size_t open) const {
    return SyntaxError("missing ')' to close the '(' at column " + std::to_string(open), tok_.pos);
  }

  bool name(const Token& t) {
    for (std::size_t i = 0; i < names_.size(); ++i) {
      if (names_[i] == t.text) {
        emit(Code::Param, t.pos, static_cast<std::uint32_t>(i));
        return false;
      }
    }
    if (t.text == "pi") {
      emit(Code::Const, t.pos, 0, std::numbers::pi);
      return true;
    }
    std::string list;
    for (const auto& n : names_) list += (list.empty() ? "" : ", ") + n;
    throw SyntaxError("unknown parameter name '" + std::string(t.text) + "' (" +
                          (list.empty() ? "no parameters" : "parameters: " + list) + ")",
                      t.pos);
  }

  // name(arguments), with tok_ at the '('.
  bool call(const Token& name) {
    const Function* f = nullptr;
    for (const Function& candidate : kFunctions)
      if (candidate.name == name.text) f = &candidate;
    if (!f) throw SyntaxError("unknown function '" + std::string(name.text) + "'", name.pos);

    const std::size_t open = tok_.pos;
    advance();
    Nest nest(nesting_, open);
    const std::size_t start = code_.size();
    bool folded = true;
    int count = 0;
    if (tok_.kind != Tok::RParen) {
      for (;;) {
        folded = expression() && folded;
        ++count;
        if (tok_.kind == Tok::Comma) {
          advance();
        } else if (tok_.kind == Tok::RParen) {
          break;
        } else if (tok_.kind == Tok::End) {
          throw missing_paren(open);
        } else {
          throw SyntaxError(
              "expected ',' or ')' after an argument of " + std::string(name.text) + ", found " + describe(tok_),
              tok_.pos);
        }
      }
    }
    advance();
    if (count != f->arity)
      throw SyntaxError(std::string(name.text) + " takes " + std::to_string(f->arity) +
                            (f->arity == 1 ? " argument, got " : " arguments, got ") + std::to_string(count),
                        name.pos);
    emit(f->code, name.pos);
    return folded && fold(start);
  }

  void advance() { tok_ = lexer_.next(); }

  void emit(Code code, std::size_t column, std::uint32_t index = 0, double value = 0) {
    code_.push_back({code, index, value});
    columns_.push_back(column);
  }

  void truncate(std::size_t size) {
    code_.resize(size);
    columns_.resize(size);
  }

  // Replaces the operations from `start` on (which read no parameter, and whose operands are folded already)
  // by the constant they compute, with the very code eval runs. A division by zero is left for eval to report.
  bool fold(std::size_t start) {
    double value;
    try {
      value = run(code_.data() + start, code_.data() + code_.size(), nullptr);
    } catch (const EvalError&) {
      return false;
    }
    const std::size_t column = columns_[start];
    truncate(start);
    emit(Code::Const, column, 0, value);
    return true;
  }

  static int stack_effect(Code code) {
    if (code <= Code::Param) return 1;
    if (code < Code::Add) return 0;
    return -1;  // a binary operation, or a jump not taken (one taken leaves the depth as it is at its target)
  }

  // eval's stack has kMaxStack slots. Jumps only go forward and reach their target with the depth that falling
  // through gives there, so one pass in order finds the deepest point.
  void check_stack() const {
    std::ptrdiff_t depth = 0;
    for (std::size_t i = 0; i < code_.size(); ++i) {
      depth += stack_effect(code_[i].code);
      if (depth > static_cast<std::ptrdiff_t>(kMaxStack))
        throw SyntaxError("expression needs more than " + std::to_string(kMaxStack) +
                              " values at once: split it or add fewer nested operands",
                          columns_[i]);
    }
  }

  std::string_view text_;
  Lexer lexer_;
  Token tok_;
  std::span<const std::string> names_;
  std::vector<Op> code_;
  std::vector<std::size_t> columns_;  // where each operation comes from in the text, for errors
  int nesting_ = 0;
};

Expression Expression::compile(std::string_view text, std::span<const std::string> names) {
  return Compiler(text, names).compile();
}

double Expression::eval(std::span<const double> args) const {
  if (code_.empty()) [[unlikely]]
    throw Error("cannot evaluate an empty expression");
  if (args.size() < arity_) [[unlikely]]
    throw Error("expression reads " + std::to_string(arity_) + " arguments, given " + std::to_string(args.size()));
  // A number or a parameter alone (`30`, `x`), the commonest arguments, without the interpreter loop.
  const Op& first = code_.front();
  const double result = code_.size() == 1 && first.code == Code::Const ? first.value
                        : code_.size() == 1 && first.code == Code::Param
                            ? args[first.index]
                            : run(code_.data(), code_.data() + code_.size(), args.data());
  if (!std::isfinite(result)) [[unlikely]]
    throw EvalError(std::isnan(result) ? "result is not a number" : "result is infinite");
  return result;
}

double Expression::run(const Op* pc, const Op* end, const double* args) {
  // The top value stays in a register; `below` holds the values under it. Its first entry is the dummy `top`
  // pushed down by the first value, so that pushing needs no test for an empty stack.
  double top = 0;
  double below[kMaxStack];
  std::size_t n = 0;  // entries used in `below`
  const auto push = [&](double value) {
    below[n++] = top;
    top = value;
  };
  const auto unary = [&](auto f) { top = f(top); };
  const auto binary = [&](auto f) {
    const double a = below[--n];
    top = f(a, top);
  };
  for (; pc != end; ++pc) {
    switch (pc->code) {
      case Code::Const:
        push(pc->value);
        break;
      case Code::Param:
        push(args[pc->index]);
        break;
      case Code::Neg:
        unary([](double a) { return -a; });
        break;
      case Code::Not:
        unary([](double a) { return a == 0 ? 1.0 : 0.0; });
        break;
      case Code::Truth:
        unary([](double a) { return a != 0 ? 1.0 : 0.0; });
        break;
      case Code::Sin:
        unary(sin_degrees);
        break;
      case Code::Cos:
        unary(cos_degrees);
        break;
      case Code::Tan:
        unary(tan_degrees);
        break;
      case Code::Asin:
        unary([](double a) { return std::asin(a) * kDegreesPerRadian; });
        break;
      case Code::Acos:
        unary([](double a) { return std::acos(a) * kDegreesPerRadian; });
        break;
      case Code::Atan:
        unary([](double a) { return std::atan(a) * kDegreesPerRadian; });
        break;
      case Code::Sqrt:
        unary([](double a) { return std::sqrt(a); });
        break;
      case Code::Abs:
        unary([](double a) { return std::fabs(a); });
        break;
      case Code::Floor:
        unary([](double a) { return std::floor(a); });
        break;
      case Code::Ceil:
        unary([](double a) { return std::ceil(a); });
        break;
      case Code::Exp:
        unary([](double a) { return std::exp(a); });
        break;
      case Code::Log:
        unary([](double a) { return std::log(a); });
        break;
      case Code::Add:
        binary([](double a, double b) { return a + b; });
        break;
      case Code::Sub:
        binary([](double a, double b) { return a - b; });
        break;
      case Code::Mul:
        binary([](double a, double b) { return a * b; });
        break;
      case Code::Div:
        if (top == 0) [[unlikely]]
          throw EvalError("division by zero");
        binary([](double a, double b) { return a / b; });
        break;
      case Code::Pow:
        binary([](double a, double b) { return std::pow(a, b); });
        break;
      case Code::Eq:
        binary([](double a, double b) { return a == b ? 1.0 : 0.0; });
        break;
      case Code::Ne:
        binary([](double a, double b) { return a != b ? 1.0 : 0.0; });
        break;
      case Code::Lt:
        binary([](double a, double b) { return a < b ? 1.0 : 0.0; });
        break;
      case Code::Le:
        binary([](double a, double b) { return a <= b ? 1.0 : 0.0; });
        break;
      case Code::Gt:
        binary([](double a, double b) { return a > b ? 1.0 : 0.0; });
        break;
      case Code::Ge:
        binary([](double a, double b) { return a >= b ? 1.0 : 0.0; });
        break;
      case Code::Min:
        binary([](double a, double b) { return std::fmin(a, b); });
        break;
      case Code::Max:
        binary([](double a, double b) { return std::fmax(a, b); });
        break;
      case Code::Atan2:
        binary([](double y, double x) { return std::atan2(y, x) * kDegreesPerRadian; });
        break;
      case Code::AndJump:
        if (top == 0) {
          top = 0;  // also turns -0 into 0
          pc += pc->index;
        } else {
          top = below[--n];
        }
        break;
      case Code::OrJump:
        if (top != 0) {
          top = 1;
          pc += pc->index;
        } else {
          top = below[--n];
        }
        break;
    }
  }
  return top;
}

}  // namespace selfsim::lsystem
