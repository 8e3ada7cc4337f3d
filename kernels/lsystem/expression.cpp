#include "kernels/lsystem/expression.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>

#include "kernels/lsystem/expression_code.h"
#include "kernels/lsystem/expression_tokens.h"

namespace selfsim::lsystem {

using namespace expression_tokens;

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

    // A constant left operand either decides the result, or leaves it to the right one alone. One that is
    // not finite (sqrt(-1), exp(1000)) decides nothing: it stays, for eval to refuse as run refuses it.
    const double left = code_[start].value;
    if (!std::isfinite(left)) return false;
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

}  // namespace selfsim::lsystem
