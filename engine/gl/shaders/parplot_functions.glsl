// What parplot2d_wf's formulas call on the GPU (parplot_glsl.cpp translates them): the C library's
// and Java's meanings where GLSL's differ or are undefined, in float.

float pp_inf() { return uintBitsToFloat(0x7F800000u); }
float pp_nan() { return uintBitsToFloat(0x7FC00000u); }
// muParser's sign: −1, 0 or 1 (0 for a NaN); Java's Math.signum keeps ±0 and NaN.
float pp_sign(float a) { return a < 0.0 ? -1.0 : a > 0.0 ? 1.0 : 0.0; }
float pp_signum(float a) { return a < 0.0 ? -1.0 : a > 0.0 ? 1.0 : a; }
float pp_log10(float a) { return log2(a) * 0.301029995663981; }
float pp_log1p(float a) { return abs(a) < 1e-4 ? a - 0.5 * a * a : log(1.0 + a); }
float pp_expm1(float a) { return abs(a) < 1e-4 ? a + 0.5 * a * a : exp(a) - 1.0; }
float pp_cbrt(float a) { return a == 0.0 ? a : sign(a) * pow(abs(a), 1.0 / 3.0); }
// C's pow, where GLSL leaves a negative base, 0 and a 0 exponent undefined: pow(x, ±0) = 1,
// pow(1, y) = 1, a negative base to an integer power signed by its parity, pow(0, y < 0) = ∞.
float pp_pow(float a, float b) {
  if (b == 0.0 || a == 1.0) return 1.0;
  if (a == 0.0) return b > 0.0 ? 0.0 : (b < 0.0 ? pp_inf() : b);
  if (a < 0.0 && b == floor(b) && !isinf(b)) {
    float r = pow(-a, b);
    return mod(b, 2.0) == 1.0 ? -r : r;
  }
  return pow(a, b);
}
// C's atan2, defined at (0, 0) too, and NaN where either is. (The driver may fold 0 · ∞ to 0 and
// so lose a NaN an expression would make: the NaN cases of these functions are spelled out.)
float pp_atan2(float y, float x) {
  if (isnan(x) || isnan(y)) return pp_nan();
  return x == 0.0 && y == 0.0 ? 0.0 : atan(y, x);
}
// C's fmod and Java's %: the remainder of a truncated quotient, with a's sign; NaN for a remainder
// of 0 or of an infinity.
float pp_fmod(float a, float b) {
  if (b == 0.0 || isinf(a) || isnan(a) || isnan(b)) return pp_nan();
  if (isinf(b)) return a;
  return a - b * trunc(a / b);
}
float pp_hypot(float a, float b) {
  float m = max(abs(a), abs(b)), n = min(abs(a), abs(b));
  if (isinf(m)) return pp_inf();
  if (m == 0.0) return 0.0;
  float q = n / m;
  return m * sqrt(1.0 + q * q);
}
// Abramowitz and Stegun 7.1.26: within 1.5e-7 of erf.
float pp_erf(float x) {
  float t = 1.0 / (1.0 + 0.3275911 * abs(x));
  float y = 1.0 - (((((1.061405429 * t - 1.453152027) * t) + 1.421413741) * t - 0.284496736) * t + 0.254829592) * t *
                      exp(-x * x);
  return isnan(x) ? x : sign(x) * y;
}
// ln Γ(x) for x ≥ ½: Stirling's series once x is moved past 7.
float pp_lgammaRight(float x) {
  float shift = 0.0;
  for (int k = 0; k < 8 && x < 7.0; ++k) {
    shift += log(x);
    x += 1.0;
  }
  float z = 1.0 / (x * x);
  float series = (0.0833333333333333 - z * (0.00277777777777778 - z * (0.000793650793650794 - z * 0.000595238095238095))) / x;
  return (x - 0.5) * log(x) - x + 0.918938533204673 + series - shift;
}
// C's lgamma, ln |Γ(x)|: left of ½ by the reflection Γ(x) Γ(1 − x) = π / sin(πx).
float pp_lgamma(float x) {
  if (x < 0.5) return log(3.14159265358979 / abs(sin(3.14159265358979 * x))) - pp_lgammaRight(1.0 - x);
  return pp_lgammaRight(x);
}
