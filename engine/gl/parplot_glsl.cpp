#include "parplot_glsl.h"

#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "core/flame/parplot_formula.h"

namespace voxflame::gl {

namespace {

// A float literal GLSL reads as the nearest float to `value` (infinities through a function, as
// GLSL has no literal for them).
std::string floatLiteral(double value) {
  if (std::isinf(value) || std::abs(value) > static_cast<double>(FLT_MAX))
    return value > 0.0 ? "pp_inf()" : "(-pp_inf())";
  if (std::abs(value) < static_cast<double>(FLT_MIN)) return "0.0";
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  std::string literal = text;
  if (literal.find_first_of(".e") == std::string::npos) literal += ".0";
  return value < 0.0 ? "(" + literal + ")" : literal;
}

// The names a formula may read besides u, v and param_a … param_f: core's parplotConstants, and
// muParser's own (_pi as muParser rounds it).
const std::map<std::string, double, std::less<>>& constants() {
  static const std::map<std::string, double, std::less<>> table = [] {
    std::map<std::string, double, std::less<>> names(core::parplotConstants().begin(), core::parplotConstants().end());
    names["_pi"] = 3.141592653589;
    names["_e"] = std::numbers::e;
    return names;
  }();
  return table;
}

using Args = std::vector<std::string>;

struct Function {
  int arity;  // −1: one or more (min, max, sum, avg)
  std::function<std::string(const Args&)> glsl;
};

// muParser's functions and those parplot_formula.cpp defines, each as GLSL of its (parenthesised)
// arguments.
const std::map<std::string, Function, std::less<>>& functions() {
  const auto call = [](std::string name) {
    return [name](const Args& a) {
      std::string s = name + "(" + a[0];
      for (std::size_t k = 1; k < a.size(); ++k) s += ", " + a[k];
      return s + ")";
    };
  };
  const auto fold = [](std::string name) {  // min(a, b, c) = min(min(a, b), c)
    return [name](const Args& a) {
      std::string s = a[0];
      for (std::size_t k = 1; k < a.size(); ++k) s = name + "(" + s + ", " + a[k] + ")";
      return s;
    };
  };
  static const std::map<std::string, Function, std::less<>> table = {
      {"sin", {1, call("sin")}},
      {"cos", {1, call("cos")}},
      {"tan", {1, call("tan")}},
      {"asin", {1, call("asin")}},
      {"acos", {1, call("acos")}},
      {"atan", {1, call("atan")}},
      {"sinh", {1, call("sinh")}},
      {"cosh", {1, call("cosh")}},
      {"tanh", {1, call("tanh")}},
      {"asinh", {1, call("asinh")}},
      {"acosh", {1, call("acosh")}},
      {"atanh", {1, call("atanh")}},
      {"log2", {1, call("log2")}},
      {"log10", {1, call("pp_log10")}},
      {"log", {1, call("log")}},
      {"ln", {1, call("log")}},
      {"exp", {1, call("exp")}},
      {"sqrt", {1, call("sqrt")}},
      {"sign", {1, call("pp_sign")}},
      {"signum", {1, call("pp_signum")}},
      {"rint", {1, call("roundEven")}},
      {"abs", {1, call("abs")}},
      {"fabs", {1, call("abs")}},
      {"sqr", {1, [](const Args& a) { return "(" + a[0] + " * " + a[0] + ")"; }}},
      {"floor", {1, call("floor")}},
      {"ceil", {1, call("ceil")}},
      {"round", {1, [](const Args& a) { return "floor(" + a[0] + " + 0.5)"; }}},  // Math.round: half up
      {"trunc", {1, call("trunc")}},
      {"frac", {1, [](const Args& a) { return "(" + a[0] + " - trunc(" + a[0] + "))"; }}},
      {"log1p", {1, call("pp_log1p")}},
      {"expm1", {1, call("pp_expm1")}},
      {"cbrt", {1, call("pp_cbrt")}},
      {"erf", {1, call("pp_erf")}},
      {"lgamma", {1, call("pp_lgamma")}},
      {"toRadians", {1, [](const Args& a) { return "(" + a[0] + " * 0.0174532925199433)"; }}},
      {"toDegrees", {1, [](const Args& a) { return "(" + a[0] + " * 57.2957795130823)"; }}},
      {"pow", {2, call("pp_pow")}},
      {"atan2", {2, call("pp_atan2")}},
      {"fmod", {2, call("pp_fmod")}},
      {"hypot", {2, call("pp_hypot")}},
      {"min", {-1, fold("min")}},
      {"max", {-1, fold("max")}},
      {"sum",
       {-1,
        [](const Args& a) {
          std::string s = "(" + a[0];
          for (std::size_t k = 1; k < a.size(); ++k) s += " + " + a[k];
          return s + ")";
        }}},
      {"avg",
       {-1,
        [](const Args& a) {
          std::string s = "((" + a[0];
          for (std::size_t k = 1; k < a.size(); ++k) s += " + " + a[k];
          return s + ") / " + floatLiteral(static_cast<double>(a.size())) + ")";
        }}},
  };
  return table;
}

struct Failure {
  std::string what;
};

// A recursive descent over muParser's grammar. Every node's GLSL is a parenthesised float.
class Translator {
 public:
  explicit Translator(std::string_view text) : text_(text) {}

  std::string formula() {
    Node e = conditional();
    skipSpace();
    if (at_ < text_.size()) fail("'" + std::string(1, text_[at_]) + "' where the formula should end");
    return e.glsl;
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw Failure{what + " (at character " + std::to_string(at_ + 1) + ")"};
  }

 private:
  // A translated part: its GLSL, a parenthesised float, and whether muParser folds it to a constant
  // when it compiles (numbers, constants, and operators and fixed-arity functions of constants; not
  // `?:` nor min, max, sum, avg), which changes what && and || do.
  struct Node {
    std::string glsl;
    bool constant = false;
  };

  void skipSpace() {
    while (at_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[at_])) != 0) ++at_;
  }
  bool take(std::string_view token) {
    skipSpace();
    if (text_.substr(at_).starts_with(token)) {
      at_ += token.size();
      return true;
    }
    return false;
  }
  static std::string truth(const std::string& condition) { return "(" + condition + " ? 1.0 : 0.0)"; }
  static Node binary(const Node& a, const Node& b, std::string glsl) {
    return {std::move(glsl), a.constant && b.constant};
  }

  // Nesting past this is refused, not followed down the stack (muParser's own limit is its memory).
  static constexpr int kMaxDepth = 256;
  struct Deeper {
    Translator& t;
    explicit Deeper(Translator& translator) : t(translator) {
      if (++t.depth_ > kMaxDepth) t.fail("nesting deeper than " + std::to_string(kMaxDepth));
    }
    ~Deeper() { --t.depth_; }
    Deeper(const Deeper&) = delete;
    Deeper& operator=(const Deeper&) = delete;
  };

  // c ? a : b, the lowest, right to left: 0 ? 1 : 0 ? 2 : 3 is 3.
  Node conditional() {
    const Deeper deeper(*this);
    Node condition = logicalOr();
    if (!take("?")) return condition;
    const Node yes = conditional();
    if (!take(":")) fail("a '?' without its ':'");
    const Node no = conditional();
    return {"(" + condition.glsl + " != 0.0 ? " + yes.glsl + " : " + no.glsl + ")", false};
  }
  // && and || as muParser computes them: as C's on doubles (0.5 && 1 is 1), except where it folds
  // two constants when it compiles, which takes their integer parts (0.5 && 1 is 0; a NaN's or an
  // infinity's is INT_MIN, true).
  static std::string truthy(const Node& operand, bool folded) {
    return folded ? "!(abs(" + operand.glsl + ") < 1.0)" : operand.glsl + " != 0.0";
  }
  Node logical(const Node& a, const Node& b, const char* op) {
    const bool folded = a.constant && b.constant;
    return binary(a, b, truth(truthy(a, folded) + op + truthy(b, folded)));
  }
  Node logicalOr() {
    Node left = logicalAnd();
    while (take("||")) left = logical(left, logicalAnd(), " || ");
    return left;
  }
  Node logicalAnd() {
    Node left = comparison();
    while (take("&&")) left = logical(left, comparison(), " && ");
    return left;
  }
  Node comparison() {
    Node left = additive();
    for (;;) {
      std::string op;
      for (const char* candidate : {"<=", ">=", "==", "!=", "<", ">"})
        if (take(candidate)) {
          op = candidate;
          break;
        }
      if (op.empty()) break;
      const Node right = additive();
      left = binary(left, right, truth(left.glsl + " " + op + " " + right.glsl));
    }
    skipSpace();
    if (at_ < text_.size() && text_[at_] == '=') fail("an assignment");
    return left;
  }
  Node additive() {
    Node left = multiplicative();
    for (;;) {
      skipSpace();
      if (at_ >= text_.size() || (text_[at_] != '+' && text_[at_] != '-')) return left;
      const char op = text_[at_++];
      const Node right = multiplicative();
      left = binary(left, right, "(" + left.glsl + " " + op + " " + right.glsl + ")");
    }
  }
  Node multiplicative() {
    Node left = signed_();
    for (;;) {
      skipSpace();
      if (at_ >= text_.size() || (text_[at_] != '*' && text_[at_] != '/' && text_[at_] != '%')) return left;
      const char op = text_[at_++];
      const Node right = signed_();
      left = binary(left, right,
                    op == '%' ? "pp_fmod(" + left.glsl + ", " + right.glsl + ")"
                              : "(" + left.glsl + " " + op + " " + right.glsl + ")");
    }
  }
  // Signs and `!` sit between the products and the power: −u^2 is −(u^2), 2^−u^2 is 2^(−(u^2)).
  Node signed_() {
    const Deeper deeper(*this);
    if (take("-")) {
      const Node operand = signed_();
      return {"(-" + operand.glsl + ")", operand.constant};
    }
    if (take("+")) return signed_();
    skipSpace();
    if (text_.substr(at_).starts_with("!") && !text_.substr(at_).starts_with("!=")) {
      ++at_;
      const Node operand = signed_();
      return {truth(operand.glsl + " == 0.0"), operand.constant};
    }
    return power();
  }
  Node power() {
    const Node base = primary();
    if (!take("^")) return base;
    const Node exponent = signed_();  // right to left: 2^3^2 is 2^9
    return binary(base, exponent, "pp_pow(" + base.glsl + ", " + exponent.glsl + ")");
  }
  Node primary() {
    skipSpace();
    if (at_ >= text_.size()) fail("the formula ends where a value should be");
    const char c = text_[at_];
    if (c == '(') {
      ++at_;
      const Node inner = conditional();
      if (!take(")")) fail("a '(' without its ')'");
      return {"(" + inner.glsl + ")", inner.constant};
    }
    if (std::isdigit(static_cast<unsigned char>(c)) != 0 || c == '.') return number();
    if (std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_') return name();
    fail("'" + std::string(1, c) + "' where a value should be");
  }
  Node number() {
    const std::size_t start = at_;
    const auto digits = [&] {
      while (at_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[at_])) != 0) ++at_;
    };
    digits();
    if (at_ < text_.size() && text_[at_] == '.') {
      ++at_;
      digits();
    }
    if (at_ < text_.size() && (text_[at_] == 'e' || text_[at_] == 'E')) {
      std::size_t k = at_ + 1;
      if (k < text_.size() && (text_[k] == '+' || text_[k] == '-')) ++k;
      if (k < text_.size() && std::isdigit(static_cast<unsigned char>(text_[k])) != 0) {
        at_ = k;
        digits();
      }
    }
    const std::string token(text_.substr(start, at_ - start));
    if (token == ".") fail("a '.' that is no number");
    return {floatLiteral(std::strtod(token.c_str(), nullptr)), true};
  }
  Node name() {
    const std::size_t start = at_;
    while (at_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[at_])) != 0 || text_[at_] == '_'))
      ++at_;
    const std::string_view word = text_.substr(start, at_ - start);
    skipSpace();
    if (at_ < text_.size() && text_[at_] == '(') {
      const auto found = functions().find(word);
      if (found == functions().end()) fail("function '" + std::string(word) + "'");
      ++at_;
      Args args;
      bool constant = true;
      if (!take(")")) {
        do {
          const Node arg = conditional();
          args.push_back(arg.glsl);
          constant = constant && arg.constant;
        } while (take(","));
        if (!take(")")) fail("a call of '" + std::string(word) + "' without its ')'");
      }
      const int arity = found->second.arity;
      if (args.empty() || (arity > 0 && static_cast<int>(args.size()) != arity))
        fail("'" + std::string(word) + "' with " + std::to_string(args.size()) + " arguments");
      return {found->second.glsl(args), constant && arity > 0};  // muParser folds no variadic call
    }
    if (word == "u" || word == "v") return {std::string(word), false};
    if (word == "isosf_z") return {"gParplotThird", false};  // isosfplot3d_wf's z
    if (word.size() == 7 && word.starts_with("param_") && word[6] >= 'a' && word[6] <= 'f')
      return {std::string(word), false};
    if (const auto found = constants().find(word); found != constants().end())
      return {floatLiteral(found->second), true};
    fail("name '" + std::string(word) + "', no variable or constant of parplot2d_wf");
  }

  std::string_view text_;
  std::size_t at_ = 0;
  int depth_ = 0;
};

}  // namespace

ParplotGlsl parplotFormulaGlsl(std::string_view muParserText) {
  ParplotGlsl result;
  Translator translator(muParserText);
  try {
    result.glsl = translator.formula();
  } catch (const Failure& failure) {
    result.error = failure.what;
  }
  return result;
}

}  // namespace voxflame::gl
