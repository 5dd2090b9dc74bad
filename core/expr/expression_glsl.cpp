#include "core/expr/expression_glsl.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <vector>

namespace sandstorm {
namespace {

// muParser's constants, to the digit (its _pi is 3.141592653589).
constexpr const char* kPi = "3.141592653589";
constexpr const char* kE = "2.718281828459045";

const char* const kVariables[] = {"x", "y", "z", "t", "vx", "vy", "vz", "age"};

struct Function {
  const char* name;
  int minArgs, maxArgs;  // maxArgs < 0: any number from minArgs
};
const Function kFunctions[] = {
    {"sin", 1, 1},   {"cos", 1, 1},   {"tan", 1, 1},  {"asin", 1, 1}, {"acos", 1, 1},
    {"atan", 1, 1},  {"sinh", 1, 1},  {"cosh", 1, 1}, {"tanh", 1, 1}, {"asinh", 1, 1},
    {"acosh", 1, 1}, {"atanh", 1, 1}, {"exp", 1, 1},  {"ln", 1, 1},   {"log", 1, 1},
    {"log2", 1, 1},  {"log10", 1, 1}, {"sqrt", 1, 1}, {"abs", 1, 1},  {"sign", 1, 1},
    {"rint", 1, 1},  {"atan2", 2, 2}, {"min", 1, -1}, {"max", 1, -1}, {"sum", 1, -1},
    {"avg", 1, -1},
};

std::string wrap(const std::string& s) {
  return "(" + s + ")";
}

class Translator {
 public:
  explicit Translator(std::string_view text) : s_(text) {}

  std::string run() {
    skip();
    if (at_ == s_.size()) fail("an empty expression; expected a value, e.g. -y");
    std::string out = ternary();
    skip();
    if (at_ < s_.size()) {
      if (s_[at_] == ',') fail("',' outside a function's arguments: one value per component");
      fail("unexpected '" + std::string(1, s_[at_]) + "'; expected an operator or the end");
    }
    return out;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw ExpressionError(at_, what); }

  void skip() {
    while (at_ < s_.size() && (s_[at_] == ' ' || s_[at_] == '\t'))
      ++at_;
  }

  bool take(std::string_view op) {
    skip();
    if (s_.substr(at_, op.size()) != op) return false;
    at_ += op.size();
    return true;
  }

  // A comparison or logical result as muParser gives it: 1.0 or 0.0.
  static std::string truth(const std::string& condition) {
    return "(" + condition + " ? 1.0 : 0.0)";
  }

  std::string ternary() {
    std::string c = logicalOr();
    if (!take("?")) return c;
    std::string a = ternary();
    if (!take(":")) fail("a '?' without its ':'");
    std::string b = ternary();
    return "(" + c + " != 0.0 ? " + a + " : " + b + ")";
  }

  std::string logicalOr() {
    std::string a = logicalAnd();
    while (take("||"))
      a = truth(a + " != 0.0 || " + logicalAnd() + " != 0.0");
    return a;
  }

  std::string logicalAnd() {
    std::string a = comparison();
    while (take("&&"))
      a = truth(a + " != 0.0 && " + comparison() + " != 0.0");
    return a;
  }

  std::string comparison() {
    std::string a = additive();
    for (;;) {
      const char* op = nullptr;
      for (const char* o : {"==", "!=", "<=", ">=", "<", ">"})
        if (take(o)) {
          op = o;
          break;
        }
      if (!op) return a;
      a = truth(a + " " + op + " " + additive());
    }
  }

  // Operands of `next` joined left to right by the one-character operators `ops`.
  template <class Next>
  std::string leftToRight(std::string_view ops, Next next) {
    std::string a = (this->*next)();
    for (;;) {
      skip();
      if (at_ == s_.size() || ops.find(s_[at_]) == std::string_view::npos) return a;
      const char op = s_[at_++];
      a = wrap(a + " " + op + " " + (this->*next)());
    }
  }

  std::string additive() { return leftToRight("+-", &Translator::multiplicative); }
  std::string multiplicative() { return leftToRight("*/", &Translator::unary); }

  std::string unary() {
    skip();
    if (at_ < s_.size() && s_[at_] == '-') {
      ++at_;
      return wrap("-" + unary());
    }
    if (at_ < s_.size() && s_[at_] == '+') {
      ++at_;
      return unary();
    }
    return power();
  }

  std::string power() {
    std::string base = atom();
    if (!take("^")) return base;
    return "e_pow(" + base + ", " + unary() + ")";
  }

  std::string number() {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(s_.data() + at_, s_.data() + s_.size(), value);
    if (ec != std::errc() || !(std::abs(value) <= 3.4e38))
      fail("a number beyond a float's range (the GPU computes in float)");
    at_ = std::size_t(end - s_.data());
    char text[40];
    std::snprintf(text, sizeof text, "%.9g", value);
    std::string out = text;
    if (out.find_first_of(".en") == std::string::npos) out += ".0";
    return out;
  }

  std::string atom() {
    skip();
    if (at_ == s_.size()) fail("the expression ends where a value was expected");
    const char c = s_[at_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return number();
    if (c == '(') {
      ++at_;
      std::string inner = ternary();
      if (!take(")")) fail("a '(' without its ')'");
      return wrap(inner);
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = at_;
      while (at_ < s_.size() &&
             (std::isalnum(static_cast<unsigned char>(s_[at_])) || s_[at_] == '_'))
        ++at_;
      const std::string name(s_.substr(start, at_ - start));
      if (name == "_pi") return kPi;
      if (name == "_e") return kE;
      for (const char* v : kVariables)
        if (name == v) return "e_" + name;
      for (const Function& f : kFunctions)
        if (name == f.name) return call(f, start);
      at_ = start;
      fail("unknown name '" + name +
           "'; expected x, y, z, t, vx, vy, vz, age, _pi, _e or a function (sin, cos, sqrt, "
           "exp, ln, min, max, ...)");
    }
    fail("unexpected '" + std::string(1, c) + "'; expected a value");
  }

  std::string call(const Function& f, std::size_t start) {
    if (!take("(")) fail(std::string("the function ") + f.name + " without its '('");
    std::vector<std::string> args{ternary()};
    while (take(","))
      args.push_back(ternary());
    if (!take(")")) fail(std::string("the function ") + f.name + " without its ')'");
    const int n = int(args.size());
    if (n < f.minArgs || (f.maxArgs >= 0 && n > f.maxArgs)) {
      at_ = start;
      fail(std::string(f.name) + " takes " +
           (f.maxArgs < 0 ? "at least " + std::to_string(f.minArgs) : std::to_string(f.minArgs)) +
           " argument(s), not " + std::to_string(n));
    }
    const std::string name = f.name;
    const auto fold = [&](const char* fn) {
      std::string a = args[0];
      for (std::size_t i = 1; i < args.size(); ++i)
        a = std::string(fn) + "(" + a + ", " + args[i] + ")";
      return a;
    };
    if (name == "ln" || name == "log") return "log(" + args[0] + ")";
    if (name == "log10") return "(log(" + args[0] + ") * 0.434294481903251828)";
    if (name == "rint") return "floor(" + args[0] + " + 0.5)";
    if (name == "atan2") return "atan(" + args[0] + ", " + args[1] + ")";
    if (name == "min" || name == "max") return fold(f.name);
    if (name == "sum" || name == "avg") {
      std::string total = args[0];
      for (std::size_t i = 1; i < args.size(); ++i)
        total += " + " + args[i];
      return name == "sum" ? wrap(total) : "((" + total + ") / " + std::to_string(n) + ".0)";
    }
    return name + "(" + args[0] + ")";
  }

  std::string_view s_;
  std::size_t at_ = 0;
};

}  // namespace

std::string expressionToGlsl(std::string_view source) {
  return Translator(source).run();
}

}  // namespace sandstorm
