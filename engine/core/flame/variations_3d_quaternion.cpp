// Zephyrtronium's quaternion variations (the "Quaternion Apo Plugin Pack", as Fractorium and JWildfire carry them):
// the point read as the quaternion q = x + y i + z j (no k part) and mapped by a function of one quaternion variable.
// For q = x + v with v = (y, z) the vector part and |v| = √(y² + z²), the functions of a quaternion keep the
// direction of v, so each result is (X, K y, K z) with X and K from x and |v| alone (sin q = sin x cosh|v| +
// cos x sinh|v| v/|v|, exp q = eˣ (cos|v| + sin|v| v/|v|), …). The formulas and their guards (Fractorium's Zeps, a
// zero divisor taken as the double's epsilon) follow Fractorium's classes of the same name (Variations04.h).
#include <cmath>
#include <numbers>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// One lane loop: px, py, pz the point, a = |v| and a2 = |v|² in scope; the body sets X and K, and the variation
// adds (X, K y, K z), both already carrying the weight.
#define VOXFLAME_QUATERNION_VARIATION(fn, ...)                                                               \
  VOXFLAME_VARIATION_TARGETS void fn(const VariationInput& in, double* __restrict ox, double* __restrict oy, \
                                     double* __restrict oz) {                                                \
    VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)                                                                 \
    for (std::size_t i = 0; i < n; ++i) {                                                                    \
      const double px = x[i], py = y[i], pz = z[i];                                                          \
      const double a2 = py * py + pz * pz;                                                                   \
      const double a = std::sqrt(a2);                                                                        \
      const double inverseA = 1.0 / fractoriumZeps(a);                                                       \
      double X = 0.0, K = 0.0;                                                                               \
      __VA_ARGS__                                                                                            \
      outX[i] += X;                                                                                          \
      outY[i] += K * py;                                                                                     \
      outZ[i] += K * pz;                                                                                     \
    }                                                                                                        \
  }

// The reciprocals (sec, csc, …) divide by |q|² = x² + |v|², as Fractorium does (the exact reciprocal of cos q
// divides by |cos q|²; the plug-in's shortcut is kept, since flames were made with it).
VOXFLAME_QUATERNION_VARIATION(sinq, {
  X = w * std::sin(px) * std::cosh(a);
  K = w * std::cos(px) * std::sinh(a) * inverseA;
})
VOXFLAME_QUATERNION_VARIATION(cosq, {
  X = w * std::cos(px) * std::cosh(a);
  K = -w * std::sin(px) * std::sinh(a) * inverseA;
})
VOXFLAME_QUATERNION_VARIATION(sinhq, {
  X = w * std::sinh(px) * std::cos(a);
  K = w * std::cosh(px) * std::sin(a) * inverseA;
})
VOXFLAME_QUATERNION_VARIATION(coshq, {
  X = w * std::cosh(px) * std::cos(a);
  K = w * std::sinh(px) * std::sin(a) * inverseA;
})
VOXFLAME_QUATERNION_VARIATION(secq, {
  const double ni = w / fractoriumZeps(px * px + a2);
  X = ni * std::cos(px) * std::cosh(a);
  K = ni * std::sin(px) * std::sinh(a) * inverseA;
})
VOXFLAME_QUATERNION_VARIATION(sechq, {
  const double ni = w / fractoriumZeps(px * px + a2);
  X = ni * std::cosh(px) * std::cos(a);
  K = -ni * std::sinh(px) * std::sin(a) * inverseA;
})
VOXFLAME_QUATERNION_VARIATION(cscq, {
  const double ni = w / fractoriumZeps(px * px + a2);
  X = ni * std::sin(px) * std::cosh(a);
  K = -ni * std::cos(px) * std::sinh(a) * inverseA;
})
VOXFLAME_QUATERNION_VARIATION(cschq, {
  const double ni = w / fractoriumZeps(px * px + a2);
  X = ni * std::sinh(px) * std::cos(a);
  K = -ni * std::cosh(px) * std::sin(a) * inverseA;
})

// tan, cot and their hyperbolic forms: the plug-in's product of the sine-like and cosine-like parts, (S C + D B |v|²,
// (D C − S B)) scaled by n, where the circular forms take S = sin x cosh|v|, C = cos x cosh|v|, D = cos x sinh|v|/|v|,
// B = −sin x sinh|v|/|v|, the hyperbolic ones S = sinh x cos|v|, C = cosh x cos|v|, D = cosh x sin|v|/|v|, B = sinh x
// sin|v|/|v|; n = w/|q|², for cothq w/|q|⁴ (Fractorium's factors, kept as they are).
VOXFLAME_QUATERNION_VARIATION(tanq, {
  const double ni = w / fractoriumZeps(px * px + a2);
  const double s = std::sin(px), c = std::cos(px), sh = std::sinh(a), ch = std::cosh(a);
  const double d = c * sh * inverseA, b = -s * sh * inverseA, S = s * ch, C = c * ch;
  X = (S * C + d * b * a2) * ni;
  K = (d * C - S * b) * ni;
})
VOXFLAME_QUATERNION_VARIATION(cotq, {
  const double ni = w / fractoriumZeps(px * px + a2);
  const double s = std::sin(px), c = std::cos(px), sh = std::sinh(a), ch = std::cosh(a);
  const double d = c * sh * inverseA, b = -s * sh * inverseA, S = s * ch, C = c * ch;
  X = (S * C + d * b * a2) * ni;
  K = -(d * C - S * b) * ni;
})
VOXFLAME_QUATERNION_VARIATION(tanhq, {
  const double ni = w / fractoriumZeps(px * px + a2);
  const double s = std::sin(a), c = std::cos(a), sh = std::sinh(px), ch = std::cosh(px);
  const double d = ch * s * inverseA, b = sh * s * inverseA, S = sh * c, C = ch * c;
  X = (S * C + d * b * a2) * ni;
  K = (d * C - S * b) * ni;
})
VOXFLAME_QUATERNION_VARIATION(cothq, {
  const double q2 = px * px + a2;
  const double ni = w / fractoriumZeps(q2 * q2);
  const double s = std::sin(a), c = std::cos(a), sh = std::sinh(px), ch = std::cosh(px);
  const double d = ch * s * inverseA, b = sh * s * inverseA, S = sh * c, C = ch * c;
  X = (S * C + d * b * a2) * ni;
  K = (d * C - S * b) * ni;
})

// estiq: exp q.
VOXFLAME_QUATERNION_VARIATION(estiq, {
  const double e = std::exp(px);
  X = w * e * std::cos(a);
  K = w * e * std::sin(a) * inverseA;
})

// loq: the logarithm of q to a base, ln|q|/ln base + atan2(|v|, x) v/|v|. Fractorium leaves the weight out of the
// real part; JWildfire (LoqFunc) and the plug-in apply it, and so does this.
VOXFLAME_VARIATION_TARGETS void loq(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                    double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double denominator = 0.5 * w / std::log(P[0]);
  for (std::size_t i = 0; i < n; ++i) {
    const double px = x[i], py = y[i], pz = z[i];
    const double a2 = py * py + pz * pz, a = std::sqrt(a2);
    const double K = w * std::atan2(a, px) / fractoriumZeps(a);
    outX[i] += std::log(px * px + a2) * denominator;
    outY[i] += K * py;
    outZ[i] += K * pz;
  }
}

#undef VOXFLAME_QUATERNION_VARIATION

}  // namespace

void variation_kernels::addQuaternionVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  constexpr bool k3D = CatalogueAdder::k3D, kFixed = CatalogueAdder::kFixed;
  // The notation of the formulas: q = x + v, v = (y, z), a = |v| = √(y² + z²), v̂ = v/a (a taken as the double's
  // epsilon where it is 0), |q|² = x² + a².
  add("sinq", "sin q = (sin x cosh a, cos x sinh a v̂) (zephyrtronium's, Fractorium's)", k3D, kFixed, &sinq);
  add("cosq", "cos q = (cos x cosh a, −sin x sinh a v̂)", k3D, kFixed, &cosq);
  add("tanq",
      "(S C + D B a², (D C − S B) v) / |q|²; S = sin x cosh a, C = cos x cosh a, D = cos x sinh a / a, B = −sin x "
      "sinh a / a (Fractorium's tanq)",
      k3D, kFixed, &tanq);
  add("cotq", "tanq's formula with the vector part negated: (S C + D B a², −(D C − S B) v) / |q|²", k3D, kFixed, &cotq);
  add("secq", "(cos x cosh a, sin x sinh a v̂) / |q|² (Fractorium's)", k3D, kFixed, &secq);
  add("cscq", "(sin x cosh a, −cos x sinh a v̂) / |q|² (Fractorium's)", k3D, kFixed, &cscq);
  add("sinhq", "sinh q = (sinh x cos a, cosh x sin a v̂)", k3D, kFixed, &sinhq);
  add("coshq", "cosh q = (cosh x cos a, sinh x sin a v̂)", k3D, kFixed, &coshq);
  add("tanhq",
      "(S C + D B a², (D C − S B) v) / |q|²; S = sinh x cos a, C = cosh x cos a, D = cosh x sin a / a, B = sinh x "
      "sin a / a (Fractorium's tanhq)",
      k3D, kFixed, &tanhq);
  add("cothq", "tanhq's formula divided by |q|⁴ instead of |q|² (Fractorium's)", k3D, kFixed, &cothq);
  add("sechq", "(cosh x cos a, −sinh x sin a v̂) / |q|² (Fractorium's)", k3D, kFixed, &sechq);
  add("cschq", "(sinh x cos a, −cosh x sin a v̂) / |q|² (Fractorium's)", k3D, kFixed, &cschq);
  add("estiq", "exp q = eˣ (cos a, sin a v̂)", k3D, kFixed, &estiq);
  add("loq", "log_base q = (ln |q|² / (2 ln base), atan2(a, x) v̂)", k3D, kFixed, &loq,
      {{"base", std::numbers::e, 0.1, 10.0}});
}

}  // namespace voxflame::core
