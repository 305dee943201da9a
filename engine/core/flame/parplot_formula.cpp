#include "core/flame/parplot_formula.h"

#include <muParser.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <string_view>
#include <utility>
#include <vector>

namespace voxflame::core {

namespace {

bool identifierChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool digit(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

// What of Java muParser would read otherwise, or not at all, rewritten: the qualifiers of
// `Math.sin(u)` and `MathLib.M_PI` dropped (the functions and constants are defined under their bare
// names below), the type suffixes of literals such as `2.0f` and `3d` dropped, and the casts
// `(double)` and `(float)` dropped, which change no value of a double expression. Everything else
// is passed as it is; what muParser then cannot read (an `(int)` cast, a string) is reported as
// muParser words it.
std::string fromJava(std::string_view java) {
  std::string out;
  out.reserve(java.size());
  std::size_t i = 0;
  const std::size_t n = java.size();
  while (i < n) {
    const char c = java[i];
    if (std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_') {
      std::size_t j = i;
      while (j < n && identifierChar(java[j])) ++j;
      const std::string_view word = java.substr(i, j - i);
      if ((word == "Math" || word == "MathLib" || word == "StrictMath") && j < n && java[j] == '.') {
        i = j + 1;
        continue;
      }
      out += word;
      i = j;
      continue;
    }
    if (digit(c) || (c == '.' && i + 1 < n && digit(java[i + 1]))) {
      std::size_t j = i;
      while (j < n && digit(java[j])) ++j;
      if (j < n && java[j] == '.') ++j;
      while (j < n && digit(java[j])) ++j;
      if (j < n && (java[j] == 'e' || java[j] == 'E')) {
        std::size_t k = j + 1;
        if (k < n && (java[k] == '+' || java[k] == '-')) ++k;
        if (k < n && digit(java[k])) {
          j = k;
          while (j < n && digit(java[j])) ++j;
        }
      }
      out += java.substr(i, j - i);
      if (j < n && std::string_view("fFdDlL").find(java[j]) != std::string_view::npos &&
          (j + 1 == n || !identifierChar(java[j + 1])))
        ++j;
      i = j;
      continue;
    }
    if (c == '(') {
      std::size_t j = i + 1;
      while (j < n && java[j] == ' ') ++j;
      std::size_t k = j;
      while (k < n && identifierChar(java[k])) ++k;
      const std::string_view word = java.substr(j, k - j);
      while (k < n && java[k] == ' ') ++k;
      if ((word == "double" || word == "float") && k < n && java[k] == ')') {
        out += ' ';
        i = k + 1;
        continue;
      }
    }
    out += c;
    ++i;
  }
  return out;
}

// JWildfire's functions: MathLib's (statically imported there) and java.lang.Math's that take and
// give doubles. muParser has sin … atanh, exp, sqrt, abs, sign, min and max of its own, which agree
// with them; log and rint are defined here all the same, as muParser's meaning of log changed
// between its versions and its rint rounds halves up where Java's goes to the even neighbour.
double javaRemainder(double a, double b) {
  return std::fmod(a, b);  // Java's % on doubles
}
double sqr(double a) {
  return a * a;
}
double javaRound(double a) {
  return std::floor(a + 0.5);  // Math.round: half up
}
double frac(double a) {
  return a - std::trunc(a);
}
double signum(double a) {
  return a > 0.0 ? 1.0 : a < 0.0 ? -1.0 : a;  // Math.signum: ±0 and NaN as they are
}
double toRadians(double a) {
  return a * (std::numbers::pi / 180.0);
}
double toDegrees(double a) {
  return a * (180.0 / std::numbers::pi);
}
double logicalNot(double a) {
  return a == 0.0 ? 1.0 : 0.0;
}

void defineJwildfireNames(mu::Parser& p) {
  using F1 = double (*)(double);
  using F2 = double (*)(double, double);
  const std::pair<const char*, F1> one[] = {
      {"fabs", [](double a) { return std::fabs(a); }},
      {"sqr", &sqr},
      {"floor", [](double a) { return std::floor(a); }},
      {"ceil", [](double a) { return std::ceil(a); }},
      {"round", &javaRound},
      {"rint", [](double a) { return std::nearbyint(a); }},
      {"trunc", [](double a) { return std::trunc(a); }},
      {"frac", &frac},
      {"log", [](double a) { return std::log(a); }},
      {"log10", [](double a) { return std::log10(a); }},
      {"log1p", [](double a) { return std::log1p(a); }},
      {"expm1", [](double a) { return std::expm1(a); }},
      {"cbrt", [](double a) { return std::cbrt(a); }},
      {"erf", [](double a) { return std::erf(a); }},
      {"lgamma", [](double a) { return std::lgamma(a); }},
      {"signum", &signum},
      {"toRadians", &toRadians},
      {"toDegrees", &toDegrees},
  };
  for (const auto& [name, fn] : one) p.DefineFun(name, fn);
  const std::pair<const char*, F2> two[] = {
      {"pow", [](double a, double b) { return std::pow(a, b); }},
      {"atan2", [](double y, double x) { return std::atan2(y, x); }},
      {"fmod", &javaRemainder},
      {"hypot", [](double a, double b) { return std::hypot(a, b); }},
  };
  for (const auto& [name, fn] : two) p.DefineFun(name, fn);
  p.DefineOprt("%", &javaRemainder, mu::prMUL_DIV, mu::oaLEFT, true);
  p.DefineInfixOprt("!", &logicalNot);
  // A bare `e` is none of the constants: JWildfire rejects it.
  for (const auto& [name, value] : parplotConstants()) p.DefineConst(name, value);
}

// The values a formula reads; muParser keeps their addresses.
struct Variables {
  double u = 0.0, v = 0.0, z = 0.0;  // z: isosfplot3d_wf's third variable
  double params[6] = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
};

void bind(mu::Parser& p, Variables& vars) {
  defineJwildfireNames(p);
  p.DefineVar("u", &vars.u);
  p.DefineVar("v", &vars.v);
  p.DefineVar("isosf_z", &vars.z);
  const char* names[6] = {"param_a", "param_b", "param_c", "param_d", "param_e", "param_f"};
  for (int k = 0; k < 6; ++k) p.DefineVar(names[k], &vars.params[k]);
}

// Compiles `formula` into p (bound already); the reason when it cannot be.
std::optional<std::string> compile(mu::Parser& p, const std::string& formula) {
  try {
    // JWildfire's empty formula is 0.0; one of blanks alone is a Java syntax error, which muParser
    // reports as an empty expression.
    p.SetExpr(parplotMuParserText(formula));
    p.Eval();  // muParser parses on the first evaluation
    if (p.GetNumResults() != 1) return "it gives " + std::to_string(p.GetNumResults()) + " values, not one";
    return std::nullopt;
  } catch (const mu::Parser::exception_type& e) {
    return e.GetMsg();
  } catch (const std::exception& e) {
    return e.what();
  }
}

}  // namespace

const std::vector<std::pair<std::string, double>>& parplotConstants() {
  constexpr double kPi = std::numbers::pi;
  static const std::vector<std::pair<std::string, double>> constants = {
      {"pi", kPi},
      {"PI", kPi},
      {"E", std::numbers::e},
      {"M_PI", kPi},
      {"M_PI_2", kPi * 0.5},
      {"M_PI_4", kPi * 0.25},
      {"M_1_PI", 1.0 / kPi},
      {"M_2_PI", 2.0 / kPi},
      {"M_2PI", 2.0 * kPi},
      {"M_1_2PI", 1.0 / kPi / 2.0},
      {"M_SQRT2", std::numbers::sqrt2},
      {"M_E", std::numbers::e},
      {"M_LOG2E", std::numbers::log2e},
      {"EPSILON", 1e-8},
      {"SMALL_EPSILON", 1e-300},
      {"C_255", 255.0},
      {"TRUE", 1.0},
      {"FALSE", 0.0},
  };
  return constants;
}

std::string parplotMuParserText(const std::string& formula) {
  return formula.empty() ? std::string("0") : fromJava(formula);
}

namespace {

// `formula` with its variables (whole names, not a member's `Math.u`, not a literal's suffix) renamed:
// each of `from` to the same place of `to`.
std::string renamedVariables(const std::string& formula, std::initializer_list<std::string_view> from,
                             std::initializer_list<std::string_view> to) {
  std::string out;
  out.reserve(formula.size() + 8);
  std::size_t i = 0;
  const std::size_t n = formula.size();
  while (i < n) {
    const char c = formula[i];
    if (std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_') {
      std::size_t j = i;
      while (j < n && identifierChar(formula[j])) ++j;
      const std::string_view word = std::string_view(formula).substr(i, j - i);
      const bool member = i > 0 && formula[i - 1] == '.';
      const auto found = std::find(from.begin(), from.end(), word);
      if (!member && found != from.end())
        out += *(to.begin() + (found - from.begin()));
      else
        out += word;
      i = j;
      continue;
    }
    if (digit(c)) {  // a literal with its suffix or exponent letter, which names nothing
      std::size_t j = i;
      while (j < n && (identifierChar(formula[j]) || formula[j] == '.')) ++j;
      out.append(formula, i, j - i);
      i = j;
      continue;
    }
    out += c;
    ++i;
  }
  return out;
}

}  // namespace

std::array<std::string, 3> polarplotSurfaceFormulas(const std::string& formula) {
  return {renamedVariables(formula, {"t", "u", "v"}, {"u", "v", "polarplot3d_wf_has_no_v"}), "0", "0"};
}

std::array<std::string, 3> isosfplotSurfaceFormulas(const std::string& formula) {
  return {renamedVariables(formula, {"x", "y", "z", "u", "v"},
                           {"u", "v", "isosf_z", "isosfplot3d_wf_has_no_u", "isosfplot3d_wf_has_no_v"}),
          "0", "0"};
}

std::optional<std::string> parplotFormulaError(const std::string& formula) {
  mu::Parser p;
  Variables vars;
  bind(p, vars);
  return compile(p, formula);
}

struct ParplotEvaluator::Impl {
  std::string sources[3];
  Variables vars;
  mu::Parser parsers[3];
  bool ok = true;
};

ParplotEvaluator::ParplotEvaluator(const std::string& x, const std::string& y, const std::string& z)
    : impl_(std::make_unique<Impl>()) {
  impl_->sources[0] = x;
  impl_->sources[1] = y;
  impl_->sources[2] = z;
  for (int k = 0; k < 3; ++k) {
    bind(impl_->parsers[k], impl_->vars);
    if (compile(impl_->parsers[k], impl_->sources[k])) impl_->ok = false;
  }
}

ParplotEvaluator::~ParplotEvaluator() = default;

bool ParplotEvaluator::ok() const {
  return impl_->ok;
}

bool ParplotEvaluator::isFor(const std::string& x, const std::string& y, const std::string& z) const {
  return impl_->sources[0] == x && impl_->sources[1] == y && impl_->sources[2] == z;
}

void ParplotEvaluator::setThird(double z) {
  impl_->vars.z = z;
}

void ParplotEvaluator::setParams(const double* sixParams) {
  std::copy(sixParams, sixParams + 6, impl_->vars.params);
}

// One Eval per formula and point, not muParser's bulk mode: Debian builds muParser with OpenMP, and
// its bulk mode would start OpenMP's threads inside the chaos game's own workers.
std::array<double, 3> ParplotEvaluator::operator()(double u, double v) {
  if (!impl_->ok) {
    constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    return {kNaN, kNaN, kNaN};
  }
  impl_->vars.u = u;
  impl_->vars.v = v;
  return {impl_->parsers[0].Eval(), impl_->parsers[1].Eval(), impl_->parsers[2].Eval()};
}

ParplotEvaluator& parplotEvaluator(const std::string& x, const std::string& y, const std::string& z) {
  // Most recent first. A render has a handful of parplot2d_wf terms at most; an animation changes
  // the parameters (read at each call), not the formulas, so a few kept cover both.
  constexpr std::size_t kKept = 8;
  thread_local std::vector<std::unique_ptr<ParplotEvaluator>> recent;
  for (std::size_t k = 0; k < recent.size(); ++k)
    if (recent[k]->isFor(x, y, z)) {
      std::rotate(recent.begin(), recent.begin() + static_cast<std::ptrdiff_t>(k),
                  recent.begin() + static_cast<std::ptrdiff_t>(k) + 1);
      return *recent.front();
    }
  if (recent.size() >= kKept) recent.pop_back();
  recent.insert(recent.begin(), std::make_unique<ParplotEvaluator>(x, y, z));
  return *recent.front();
}

}  // namespace voxflame::core
