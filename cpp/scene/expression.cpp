#include "scene/expression.hpp"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "common/errors.hpp"

namespace pdesurf {

namespace {

class Parser {
 public:
  Parser(const std::string& text, const ParameterValues& params) : s_(text), params_(params) {}

  double parseAll() {
    if (s_.size() > kMaxExpressionLength)
      throw Error(ErrorCode::ParseError, "expression longer than " + std::to_string(kMaxExpressionLength) + " characters");
    const double v = sum();
    skip();
    if (pos_ < s_.size()) {
      if (s_[pos_] == ')') fail("unbalanced ')'");
      fail(std::string("unexpected '") + s_[pos_] + "'");
    }
    if (!std::isfinite(v)) throw Error(ErrorCode::NonFinite, "expression '" + s_ + "' is not finite");
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

  double sum() {
    double v = product();
    for (;;) {
      if (eat('+')) v += product();
      else if (eat('-')) v -= product();
      else return v;
    }
  }
  double product() {
    double v = unary();
    for (;;) {
      if (eat('*')) v *= unary();
      else if (eat('/')) v /= unary();
      else return v;
    }
  }
  double unary() {
    Depth guard(*this);
    if (eat('-')) return -unary();
    if (eat('+')) return unary();
    return power();
  }
  double power() {
    const double base = primary();
    if (eat('^')) return std::pow(base, unary());
    return base;
  }
  double primary() {
    Depth guard(*this);
    skip();
    if (pos_ >= s_.size()) fail("expression ends too early");
    const char c = s_[pos_];
    if (c == '(') {
      ++pos_;
      const double v = sum();
      if (!eat(')')) fail("unbalanced '(': missing ')'");
      return v;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const char* begin = s_.c_str() + pos_;
      char* end = nullptr;
      const double v = std::strtod(begin, &end);
      if (end == begin) fail("bad number");
      pos_ += static_cast<size_t>(end - begin);
      return v;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const size_t start = pos_;
      while (pos_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[pos_])) || s_[pos_] == '_')) ++pos_;
      const std::string name = s_.substr(start, pos_ - start);
      skip();
      if (pos_ < s_.size() && s_[pos_] == '(') {
        const size_t at = start;
        ++pos_;
        const double arg = sum();
        if (!eat(')')) fail("unbalanced '(': missing ')'");
        return call(name, arg, at);
      }
      const auto it = params_.find(name);
      if (it != params_.end()) return it->second;
      if (name == "pi") return M_PI;
      if (name == "e") return M_E;
      pos_ = start;
      fail("unknown parameter '" + name + "'", ErrorCode::UnknownName);
    }
    if (c == ')') fail("unbalanced ')'");
    fail(std::string("unexpected '") + c + "'");
  }
  double call(const std::string& name, double x, size_t at) {
    using F = double (*)(double);
    static const struct {
      const char* name;
      F fn;
    } table[] = {{"sqrt", [](double a) { return std::sqrt(a); }}, {"exp", [](double a) { return std::exp(a); }},
                 {"log", [](double a) { return std::log(a); }},   {"sin", [](double a) { return std::sin(a); }},
                 {"cos", [](double a) { return std::cos(a); }},   {"tan", [](double a) { return std::tan(a); }},
                 {"asin", [](double a) { return std::asin(a); }}, {"acos", [](double a) { return std::acos(a); }},
                 {"atan", [](double a) { return std::atan(a); }}, {"sinh", [](double a) { return std::sinh(a); }},
                 {"cosh", [](double a) { return std::cosh(a); }}, {"tanh", [](double a) { return std::tanh(a); }},
                 {"abs", [](double a) { return std::abs(a); }}};
    for (const auto& f : table)
      if (name == f.name) {
        const double y = f.fn(x);
        if (!std::isfinite(y)) {
          pos_ = at;
          fail(name + "(" + std::to_string(x) + ") is not finite", ErrorCode::NonFinite);
        }
        return y;
      }
    pos_ = at;
    fail("unknown function '" + name + "'", ErrorCode::UnknownName);
  }

  const std::string& s_;
  const ParameterValues& params_;
  size_t pos_ = 0;
  int depth_ = 0;
};

}  // namespace

double evaluateExpression(const std::string& text, const ParameterValues& parameters) {
  return Parser(text, parameters).parseAll();
}

}  // namespace pdesurf
