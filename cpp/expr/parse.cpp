#include "expr/parse.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "common/errors.hpp"

namespace pdesurf {

namespace {

class Parser {
 public:
  Parser(const std::string& text, const ParameterValues& params, AllowedVariables allowed)
      : s_(text), params_(params), allowed_(allowed) {}

  Expr parseAll() {
    if (s_.size() > kMaxExpressionLength)
      throw Error(ErrorCode::ParseError, "expression longer than " + std::to_string(kMaxExpressionLength) + " characters");
    const Expr v = sum();
    skip();
    if (pos_ < s_.size()) {
      if (s_[pos_] == ')') fail("unbalanced ')'");
      fail(std::string("unexpected '") + s_[pos_] + "'");
    }
    if (isConstant(v) && !std::isfinite(v->value)) throw Error(ErrorCode::NonFinite, "expression '" + s_ + "' is not finite");
    return v;
  }

 private:
  [[noreturn]] void fail(const std::string& why, ErrorCode code = ErrorCode::ParseError) const {
    throw Error(code, "col " + std::to_string(pos_ + 1) + ": " + why);
  }
  void skip() {
    while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) ++pos_;
  }
  bool eat(char c) {
    skip();
    if (pos_ < s_.size() && s_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  struct Depth {
    explicit Depth(Parser& p) : p_(p) {
      if (++p_.depth_ > kMaxExpressionDepth) p_.fail("expression nested too deeply");
    }
    ~Depth() { --p_.depth_; }
    Parser& p_;
  };

  Expr sum() {
    Expr v = product();
    for (;;) {
      if (eat('+')) v = add(v, product());
      else if (eat('-')) v = subtract(v, product());
      else return v;
    }
  }
  Expr product() {
    Expr v = unary();
    for (;;) {
      if (eat('*')) v = multiply(v, unary());
      else if (eat('/')) v = divide(v, unary());
      else return v;
    }
  }
  Expr unary() {
    Depth guard(*this);
    if (eat('-')) return negate(unary());
    if (eat('+')) return unary();
    return powerExpr();
  }
  Expr powerExpr() {
    const Expr base = primary();
    if (eat('^')) return power(base, unary());
    return base;
  }
  Expr primary() {
    Depth guard(*this);
    skip();
    if (pos_ >= s_.size()) fail("expression ends too early");
    const char c = s_[pos_];
    if (c == '(') {
      ++pos_;
      const Expr v = sum();
      if (!eat(')')) fail("unbalanced '(': missing ')'");
      return v;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      // Decimal only, scanned here: strtod alone would also take 0x10 and 0x1p3.
      const auto digit = [&](size_t k) { return k < s_.size() && std::isdigit(static_cast<unsigned char>(s_[k])); };
      size_t k = pos_;
      while (digit(k)) ++k;
      if (k < s_.size() && s_[k] == '.') ++k;
      while (digit(k)) ++k;
      if (k < s_.size() && (s_[k] == 'e' || s_[k] == 'E')) {
        const size_t e = k + (k + 1 < s_.size() && (s_[k + 1] == '+' || s_[k + 1] == '-') ? 2 : 1);
        if (digit(e)) {
          k = e;
          while (digit(k)) ++k;
        }
      }
      if (k < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[k])) || s_[k] == '_' || s_[k] == '.'))
        fail("bad number: numbers are decimal, such as 16, 0.5 or 1.5e-3");
      const std::string text = s_.substr(pos_, k - pos_);
      char* end = nullptr;
      const double v = std::strtod(text.c_str(), &end);
      if (text == "." || end != text.c_str() + text.size()) fail("bad number");
      pos_ = k;
      return constant(v);
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const size_t start = pos_;
      while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_')) ++pos_;
      const std::string name = s_.substr(start, pos_ - start);
      skip();
      if (pos_ < s_.size() && s_[pos_] == '(') {
        const size_t at = start;
        ++pos_;
        const Expr arg = sum();
        if (!eat(')')) fail("unbalanced '(': missing ')'");
        return callNamed(name, arg, at);
      }
      const auto it = params_.find(name);
      if (it != params_.end()) return constant(it->second);
      if (name == "pi") return constant(M_PI);
      if (name == "e") return constant(M_E);
      if (name == "v" && allowed_.v) return variable(ExprVar::V);
      if (allowed_.u && name == allowed_.uName) return variable(ExprVar::U);
      pos_ = start;
      if (name == "v" || name == "u" || name == "t")
        fail("'" + name + "' cannot be used here" + (allowed_.v ? std::string(": the variables are v") + (allowed_.u ? std::string(" and ") + allowed_.uName : "")
                                                                : std::string(": a number is expected")),
             ErrorCode::UnknownName);
      fail("unknown parameter '" + name + "'", ErrorCode::UnknownName);
    }
    if (c == ')') fail("unbalanced ')'");
    fail(std::string("unexpected '") + c + "'");
  }
  Expr callNamed(const std::string& name, const Expr& x, size_t at) {
    ExprFn f;
    if (!exprFnFromName(name, &f)) {
      pos_ = at;
      fail("unknown function '" + name + "'", ErrorCode::UnknownName);
    }
    const Expr y = call(f, x);
    if (isConstant(y) && !std::isfinite(y->value)) {
      pos_ = at;
      fail(name + "(" + std::to_string(x->value) + ") is not finite", ErrorCode::NonFinite);
    }
    return y;
  }

  const std::string& s_;
  const ParameterValues& params_;
  AllowedVariables allowed_;
  size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

Expr parseExpression(const std::string& text, const ParameterValues& parameters, AllowedVariables allowed) {
  return Parser(text, parameters, allowed).parseAll();
}

}  // namespace pdesurf
