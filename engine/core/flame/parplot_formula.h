// JWildfire's parplot2d_wf draws a parametric surface (x, y, z) = (X(u, v), Y(u, v), Z(u, v)) whose
// three formulas are text parameters. JWildfire compiles them as Java expressions (Janino) with
// MathLib's static functions and constants in scope, `pi`, u, v and param_a … param_f; voxflame
// evaluates them with muParser, after rewriting what of Java muParser reads otherwise (parplot_formula.cpp
// says what). A compiled evaluator is not safe to share between threads: each thread compiles its
// own, once per set of formulas (parplotEvaluator), never per point.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace voxflame::core {

// The formula as muParser reads it: Java's qualifiers, literal suffixes and casts rewritten (see
// parplot_formula.cpp); an empty formula is "0". The GPU's kernel generator translates this text.
std::string parplotMuParserText(const std::string& formula);

// The constants a formula may name besides muParser's own (_pi, _e): `pi`, a local of JWildfire's
// generated code, and MathLib's constants (Math.PI and Math.E once their qualifier is dropped).
const std::vector<std::pair<std::string, double>>& parplotConstants();

// JWildfire's polarplot3d_wf draws r(t, u), one formula of t, u and param_a … param_f, in polar
// coordinates. It is evaluated as a parplot surface (r(t, u), 0, 0) of (u, v) = (t, u): its formula
// with t renamed u and u renamed v (and a v, which polarplot3d_wf does not have, renamed so that it
// names nothing), and "0" for Y and Z. An empty formula stays empty: the variation then adds nothing.
std::array<std::string, 3> polarplotSurfaceFormulas(const std::string& formula);
// JWildfire's isosfplot3d_wf draws the points where |F(x, y, z)| is at most a thickness, one formula of x,
// y, z and param_a … param_f. It is evaluated as the surface (F, 0, 0) of (u, v) = (x, y) with z the
// evaluator's third variable, isosf_z (setThird; a parplot formula may read it too, as 0): x renamed u, y
// renamed v, z renamed isosf_z (and a u or v, which isosfplot3d_wf does not have, renamed to name nothing).
std::array<std::string, 3> isosfplotSurfaceFormulas(const std::string& formula);

// Why one formula cannot be evaluated (muParser's message), or nullopt when it can. An empty
// formula is 0, as in JWildfire.
std::optional<std::string> parplotFormulaError(const std::string& formula);

// The three formulas compiled for one thread. Not copyable: muParser holds the addresses of u, v
// and the parameters.
class ParplotEvaluator {
 public:
  ParplotEvaluator(const std::string& x, const std::string& y, const std::string& z);
  ~ParplotEvaluator();
  ParplotEvaluator(const ParplotEvaluator&) = delete;
  ParplotEvaluator& operator=(const ParplotEvaluator&) = delete;

  bool ok() const;  // false when a formula does not compile: it then evaluates to nothing
  bool isFor(const std::string& x, const std::string& y, const std::string& z) const;
  // isosfplot3d_wf's z (isosf_z), read by every evaluation after this; 0 until set.
  void setThird(double z);
  // param_a … param_f, read by every evaluation after this.
  void setParams(const double* sixParams);
  // (X, Y, Z) at (u, v); NaN or infinite where the formulas are (sqrt of a negative, 1/0).
  std::array<double, 3> operator()(double u, double v);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// This thread's evaluator for these formulas: the few it used last are kept compiled. The
// reference holds until this thread's next call.
ParplotEvaluator& parplotEvaluator(const std::string& x, const std::string& y, const std::string& z);

}  // namespace voxflame::core
