// Flame variations for the GPU backend's chaos game (flame_kernel.h generates the code that calls
// them, per genome). Each is the CPU catalogue's kernel of the same name (core/flame/variations_*.cpp,
// which stays the reference; variations.h has the notation) in float: V_<name>(p, w, P, A) returns
// w · V(p), with the term's parameters at flameData[P...] and its transform's pre-affine (row-major
// 3×4) at flameData[A...]. A 2D variation carries w · z into z, as on the CPU. Ψ draws from the
// orbit's own chaos stream (psi), in the CPU kernel's order.

layout(std430, binding = 8) readonly buffer FlameData { float flameData[]; };
layout(std430, binding = 9) readonly buffer FlamePick { uint flamePick[]; };

uint gChaosRandom;  // the orbit's chaos stream (xorshift32, never 0), as core::laneUniform draws it
// The point's colour index as its transform's blend left it, for the direct-colour variations
// (VariationInfo::directColour), which read and may set it: core's VariationInput::colour.
float gColour;
// What of core's VariationInput the flagged variations (VariationInfo) read or set besides the point:
// - readsSum: gSum is the sum of the ordinary terms before the term (0 in a pre_ or post_ term), and
//   the variation returns the new sum, where every other one returns what it adds to it;
// - paintsRgb: gRgb is the point's true colour as VariationInput::rgb holds it (kRgbPainted set; 0 at
//   the start of the transform: none painted);
// - hidesPoints: gHidden is JWildfire's doHide, kept per orbit from step to step;
// - laneState: gLane holds every such term's memory per orbit, kept from step to step; a term's
//   first index in it follows its parameters in flameData: int(flameData[P + its parameter count]);
// - paintsRgb: after that index, where the palette it compares painted colours with starts in
//   flameData (VariationInput::palette, the file's colours in sRGB bytes): 3 floats (red, green,
//   blue, 0–255) a colour, 256 colours (variationPalette);
// - a table (VariationInfo::table: svg_wf's pixels, hopalong's orbit, a mesh's faces): after the
//   parameters (and the two numbers above, for one that has them), where its numbers start in
//   flameData and how many there are (tableAt, tableSize);
// - and last, for the variations gpuVariationReadsDoubles names, every parameter in double (paramDouble).
// And every variation may read gStage, its term's stage (VariationInput::stage: 0 pre_, 1 ordinary,
// 2 post_), for those that work otherwise as pre_ or post_ terms (extrude, cubic3D, dc_bubble).
vec3 gSum;
int gStage;
uint gRgb;
bool gHidden;
const uint kRgbPainted = 1u << 24;
#ifdef LANE_MEMORY
double gLane[LANE_MEMORY];
#endif
#ifdef FIELD_BLOCK
// A term whose parameters a weighting field moves per point (core::WeightFieldTerm) reads them from
// here: the kernel copies the term's numbers (flameData[P...], everything a variation reads relative
// to P) in, scales them, and calls the variation with P = kFieldBlock.
float gFieldBlock[FIELD_BLOCK];
const int kFieldBlock = -(1 << 24);
#endif
// The term's number i of those that start at `base`: every read relative to P goes through here.
float P_(int base, int i) {
#ifdef FIELD_BLOCK
  if (base + i < 0) return gFieldBlock[base + i - kFieldBlock];
#endif
  return flameData[base + i];
}
// Where the table of the term whose N parameters are at P starts, and how many numbers it holds.
int tableAt(int P, int N) { return int(P_(P, N)); }
int tableSize(int P, int N) { return int(P_(P, N + 1)); }
// Parameter i in double, of those that start at `at` (a double's bits in two floats).
double paramDouble(int at, int i) {
  return packDouble2x32(uvec2(floatBitsToUint(flameData[at + 2 * i]), floatBitsToUint(flameData[at + 2 * i + 1])));
}
// Point k of such a table of (x, y) pairs.
vec2 tablePoint(int P, int N, int k) {
  int at = tableAt(P, N) + 2 * k;
  return vec2(flameData[at], flameData[at + 1]);
}
// Which of a table's `count` points a draw picks: ⌊Ψ count⌋ in double, as the CPU's index.
int tableIndex(float draw, int count) { return min(int(floor(double(draw) * double(count))), count - 1); }
// Palette entry i (0–255) as VariationInput::palette packs it; `at`: where the palette starts.
uint variationPalette(int at, int i) {
  int e = at + 3 * clamp(i, 0, 255);
  return uint(flameData[e]) | uint(flameData[e + 1]) << 8 | uint(flameData[e + 2]) << 16;
}

float psi() {
  gChaosRandom ^= gChaosRandom << 13;
  gChaosRandom ^= gChaosRandom >> 17;
  gChaosRandom ^= gChaosRandom << 5;
  return float(gChaosRandom >> 8) * (1.0 / 16777216.0);
}
float gaussPsi() {
  float a = psi(), b = psi(), c = psi(), d = psi();
  return a + b + c + d - 2.0;
}

const float kPi = 3.14159265358979;
const float kTwoPi = 6.28318530717959;
// The CPU's 1e-300 guard is 0 in float: the smallest normal float's order keeps 0/0 away as well.
const float kEpsilon = 1e-30;
const float kFlam3Eps = 1e-10;

// atan2 as C has it at the origin (GLSL leaves atan(0, 0) undefined).
float atan2c(float a, float b) { return (a == 0.0 && b == 0.0) ? 0.0 : atan(a, b); }
float fmodc(float a, float m) {  // C's fmod: the sign of a (core's laneFmod)
  float am = abs(m);
  float r = a - trunc(a / m) * m;
  r = a >= 0.0 ? (r < 0.0 ? r + am : r) : (r > 0.0 ? r - am : r);
  return a >= 0.0 ? (r >= am ? r - am : r) : (r <= -am ? r + am : r);
}
float flam3Count(float v) { return v == 0.0 ? 1.0 : v; }
float countParam(float v) {
  float r = sign(v) * floor(abs(v) + 0.5);  // std::round: half away from zero
  return r == 0.0 ? 1.0 : r;
}
float roundHalfAway(float v) { return sign(v) * floor(abs(v) + 0.5); }  // std::round
// Fractorium's integer parameter: ⌊v + ½⌋ clamped to [lo, hi].
float fractoriumInteger(float v, float lo, float hi) { return clamp(floor(v + 0.5), lo, hi); }
// sin and cos in double (GLSL has no double trig): Cody–Waite reduction by π/2 and Taylor series on
// [−π/4, π/4], within an ulp, the series' first terms added last (small arguments' sines come out
// right). The hashes multiply a sine by 43758.5453 and keep the fraction, which float's sin cannot give.
dvec2 dsinCos(double v) {
  double q = floor(v * 0.63661977236758134lf + 0.5lf);
  precise double r = fma(-q, 1.5707963267948966lf, v) - q * 6.123233995736766e-17lf;
  precise double r2 = r * r;
  precise double ps = -8.22063524662433e-18lf;
  ps = ps * r2 + 2.8114572543455206e-15lf;
  ps = ps * r2 - 7.647163731819816e-13lf;
  ps = ps * r2 + 1.6059043836821613e-10lf;
  ps = ps * r2 - 2.505210838544172e-8lf;
  ps = ps * r2 + 2.7557319223985893e-6lf;
  ps = ps * r2 - 1.984126984126984e-4lf;
  ps = ps * r2 + 8.333333333333333e-3lf;
  ps = ps * r2 - 1.6666666666666666e-1lf;
  precise double s = r + r * (r2 * ps);
  precise double pc = -1.5619206968586225e-16lf;
  pc = pc * r2 + 4.779477332387385e-14lf;
  pc = pc * r2 - 1.1470745597729725e-11lf;
  pc = pc * r2 + 2.08767569878681e-9lf;
  pc = pc * r2 - 2.755731922398589e-7lf;
  pc = pc * r2 + 2.48015873015873e-5lf;
  pc = pc * r2 - 1.388888888888889e-3lf;
  pc = pc * r2 + 4.1666666666666664e-2lf;
  precise double hz = 0.5lf * r2;
  precise double h = 1.0lf - hz;
  precise double c = h + (((1.0lf - h) - hz) + r2 * r2 * pc);
  int n = int(q) & 3;
  return n == 0 ? dvec2(s, c) : (n == 1 ? dvec2(c, -s) : (n == 2 ? dvec2(-s, -c) : dvec2(-c, s)));
}
double dsin(double v) { return dsinCos(v).x; }
double dcos(double v) { return dsinCos(v).y; }
// Fractorium's HashShadertoy, fract(43758.5453 sin(12.9898 a + 78.233 b + seed)), in double: float's
// sin of its argument is far too coarse for the fraction.
double hashShadertoyD(double a, double b, double seed) {
  precise double v = dsin(a * 12.9898lf + b * 78.233lf + seed) * 43758.5453lf;
  return v - floor(v);
}
float hashShadertoy(double a, double b, double seed) { return float(hashShadertoyD(a, b, seed)); }
// sn, cn, dn of u for the parameter 1 − emmc (Numerical Recipes' sncndn, accuracy 0.0003), as the CPU.
vec3 jacobiSnCnDn(float u, float emmc) {
  const float kAccuracy = 0.0003;
  float emc = emmc;
  if (emc == 0.0) {
    float c = 1.0 / cosh(u);
    return vec3(tanh(clamp(u, -20.0, 20.0)), c, c);  // GLSL's tanh may give NaN far out
  }
  bool negative = emc < 0.0;
  float d = 1.0;
  if (negative) {
    d = 1.0 - emc;
    emc = -emc / d;
    d = sqrt(d);
    u = d * u;
  }
  float em[8], en[8];
  float a = 1.0, c = 0.0, dn = 1.0;
  int last = 0;
  for (int i = 0; i < 8; ++i) {
    last = i;
    em[i] = a;
    emc = sqrt(emc);
    en[i] = emc;
    c = 0.5 * (a + emc);
    if (abs(a - emc) <= kAccuracy * a) break;
    emc = a * emc;
    a = c;
  }
  u = c * u;
  float sn = sin(u), cn = cos(u);
  if (sn != 0.0) {
    a = cn / sn;
    c = a * c;
    for (int k = last; k >= 0; --k) {
      float b = em[k];
      a = c * a;
      c = dn * c;
      dn = (en[k] + a) / (b + a);
      a = c / b;
    }
    a = 1.0 / (abs(c) > 1e15 ? abs(c) : sqrt(c * c + 1.0));  // c² would overflow float
    sn = sn < 0.0 ? -a : a;
    cn = c * sn;
  }
  if (negative) {
    a = dn;
    dn = cn;
    cn = a;
    sn = sn / d;
  }
  return vec3(sn, cn, dn);
}

// ---- flam3's classics (variations_flam3_classic.cpp) ----------------------------------------

vec3 V_linear(vec3 p, float w, int P, int A) { return w * p; }
vec3 V_sinusoidal(vec3 p, float w, int P, int A) { return w * vec3(sin(p.x), sin(p.y), p.z); }
vec3 V_spherical(vec3 p, float w, int P, int A) {
  float s = w / (p.x * p.x + p.y * p.y + kEpsilon);
  return vec3(s * p.x, s * p.y, w * p.z);
}
vec3 V_swirl(vec3 p, float w, int P, int A) {
  float r2 = p.x * p.x + p.y * p.y;
  float s = sin(r2), c = cos(r2);
  return w * vec3(p.x * s - p.y * c, p.x * c + p.y * s, p.z);
}
vec3 V_horseshoe(vec3 p, float w, int P, int A) {
  float s = w / (sqrt(p.x * p.x + p.y * p.y) + kFlam3Eps);
  return vec3(s * (p.x - p.y) * (p.x + p.y), s * 2.0 * p.x * p.y, w * p.z);
}
vec3 V_polar(vec3 p, float w, int P, int A) {
  return w * vec3(atan2c(p.x, p.y) / kPi, sqrt(p.x * p.x + p.y * p.y) - 1.0, p.z);
}
vec3 V_handkerchief(vec3 p, float w, int P, int A) {
  float theta = atan2c(p.x, p.y), r = sqrt(p.x * p.x + p.y * p.y);
  return w * vec3(r * sin(theta + r), r * cos(theta - r), p.z);
}
vec3 V_heart(vec3 p, float w, int P, int A) {
  float r = sqrt(p.x * p.x + p.y * p.y);
  float a = r * atan2c(p.x, p.y);
  return w * vec3(r * sin(a), -r * cos(a), p.z);
}
vec3 V_disc(vec3 p, float w, int P, int A) {
  float a = atan2c(p.x, p.y) / kPi;
  float r = kPi * sqrt(p.x * p.x + p.y * p.y);
  return w * vec3(sin(r) * a, cos(r) * a, p.z);
}
vec3 V_spiral(vec3 p, float w, int P, int A) {
  float rawR = sqrt(p.x * p.x + p.y * p.y);
  float sinTheta = p.x / (rawR + kEpsilon), cosTheta = p.y / (rawR + kEpsilon);
  float r = rawR + kFlam3Eps;
  float s = w / r;
  return vec3(s * (cosTheta + sin(r)), s * (sinTheta - cos(r)), w * p.z);
}
vec3 V_hyperbolic(vec3 p, float w, int P, int A) {
  float rawR = sqrt(p.x * p.x + p.y * p.y);
  float sinTheta = p.x / (rawR + kEpsilon), cosTheta = p.y / (rawR + kEpsilon);
  float r = rawR + kFlam3Eps;
  return vec3(w * sinTheta / r, w * cosTheta * r, w * p.z);
}
vec3 V_diamond(vec3 p, float w, int P, int A) {
  float r = sqrt(p.x * p.x + p.y * p.y);
  float sinTheta = p.x / (r + kEpsilon), cosTheta = p.y / (r + kEpsilon);
  return w * vec3(sinTheta * cos(r), cosTheta * sin(r), p.z);
}
vec3 V_ex(vec3 p, float w, int P, int A) {
  float theta = atan2c(p.x, p.y), r = sqrt(p.x * p.x + p.y * p.y);
  float n0 = sin(theta + r), n1 = cos(theta - r);
  float m0 = n0 * n0 * n0 * r, m1 = n1 * n1 * n1 * r;
  return w * vec3(m0 + m1, m0 - m1, p.z);
}
vec3 V_julia(vec3 p, float w, int P, int A) {
  float angle = 0.5 * atan2c(p.x, p.y) + (psi() < 0.5 ? 0.0 : kPi);
  float r = w * sqrt(sqrt(p.x * p.x + p.y * p.y));
  return vec3(r * cos(angle), r * sin(angle), w * p.z);
}
vec3 V_bent(vec3 p, float w, int P, int A) {
  return w * vec3(p.x < 0.0 ? 2.0 * p.x : p.x, p.y < 0.0 ? 0.5 * p.y : p.y, p.z);
}
vec3 V_waves(vec3 p, float w, int P, int A) {
  float b = flameData[A + 1], c = flameData[A + 3], e = flameData[A + 5], f = flameData[A + 7];
  float dx2 = 1.0 / (c * c + kFlam3Eps), dy2 = 1.0 / (f * f + kFlam3Eps);
  return w * vec3(p.x + b * sin(p.y * dx2), p.y + e * sin(p.x * dy2), p.z);
}
vec3 V_fisheye(vec3 p, float w, int P, int A) {
  float s = 2.0 * w / (sqrt(p.x * p.x + p.y * p.y) + 1.0);
  return vec3(s * p.y, s * p.x, w * p.z);  // swapped, as flam3 draws it
}
vec3 V_popcorn(vec3 p, float w, int P, int A) {
  float c = flameData[A + 3], f = flameData[A + 7];
  return w * vec3(p.x + c * sin(tan(3.0 * p.y)), p.y + f * sin(tan(3.0 * p.x)), p.z);
}
vec3 V_exponential(vec3 p, float w, int P, int A) {
  float d = w * exp(p.x - 1.0), a = kPi * p.y;
  return vec3(d * cos(a), d * sin(a), w * p.z);
}
vec3 V_power(vec3 p, float w, int P, int A) {
  float r = sqrt(p.x * p.x + p.y * p.y);
  float sinTheta = p.x / (r + kEpsilon), cosTheta = p.y / (r + kEpsilon);
  float s = w * pow(r, sinTheta);
  return vec3(s * cosTheta, s * sinTheta, w * p.z);
}
vec3 V_cosine(vec3 p, float w, int P, int A) {
  float a = kPi * p.x;
  return vec3(w * cos(a) * cosh(p.y), -w * sin(a) * sinh(p.y), w * p.z);
}
vec3 V_rings(vec3 p, float w, int P, int A) {
  float c = flameData[A + 3];
  float dx = c * c + kFlam3Eps;
  float r = sqrt(p.x * p.x + p.y * p.y);
  float sinTheta = p.x / (r + kEpsilon), cosTheta = p.y / (r + kEpsilon);
  float s = w * (fmodc(r + dx, 2.0 * dx) - dx + r * (1.0 - dx));
  return vec3(s * cosTheta, s * sinTheta, w * p.z);
}
vec3 V_fan(vec3 p, float w, int P, int A) {
  float c = flameData[A + 3], f = flameData[A + 7];
  float dx = kPi * (c * c + kFlam3Eps), half_ = 0.5 * dx;
  float theta = atan2c(p.x, p.y);
  float a = theta + (fmodc(theta + f, dx) > half_ ? -half_ : half_);
  float r = w * sqrt(p.x * p.x + p.y * p.y);
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_blob(vec3 p, float w, int P, int A) {
  float low = P_(P, 0), high = P_(P, 1), waves = P_(P, 2);
  float rawR = sqrt(p.x * p.x + p.y * p.y);
  float theta = atan2c(p.x, p.y);
  float sinTheta = p.x / (rawR + kEpsilon), cosTheta = p.y / (rawR + kEpsilon);
  float r = rawR * (low + (high - low) * (0.5 + 0.5 * sin(waves * theta)));
  return w * vec3(sinTheta * r, cosTheta * r, p.z);
}
vec3 V_pdj(vec3 p, float w, int P, int A) {
  float a = P_(P, 0), b = P_(P, 1), c = P_(P, 2), d = P_(P, 3);
  return w * vec3(sin(a * p.y) - cos(b * p.x), sin(c * p.x) - cos(d * p.y), p.z);
}
vec3 V_fan2(vec3 p, float w, int P, int A) {
  float dy = P_(P, 1);
  float dx = kPi * (P_(P, 0) * P_(P, 0) + kFlam3Eps), half_ = 0.5 * dx;
  float theta = atan2c(p.x, p.y);
  float t = theta + dy - dx * trunc((theta + dy) / dx);
  float a = t > half_ ? theta - half_ : theta + half_;
  float r = w * sqrt(p.x * p.x + p.y * p.y);
  return vec3(r * sin(a), r * cos(a), w * p.z);
}
vec3 V_rings2(vec3 p, float w, int P, int A) {
  float dx = P_(P, 0) * P_(P, 0) + kFlam3Eps;
  float rawR = sqrt(p.x * p.x + p.y * p.y);
  float sinTheta = p.x / (rawR + kEpsilon), cosTheta = p.y / (rawR + kEpsilon);
  float r = rawR - 2.0 * dx * trunc((rawR + dx) / (2.0 * dx)) + rawR * (1.0 - dx);
  return w * vec3(sinTheta * r, cosTheta * r, p.z);
}
vec3 V_eyefish(vec3 p, float w, int P, int A) {
  float s = 2.0 * w / (sqrt(p.x * p.x + p.y * p.y) + 1.0);
  return vec3(s * p.x, s * p.y, w * p.z);
}
vec3 V_bubble(vec3 p, float w, int P, int A) {
  float s = w / (0.25 * (p.x * p.x + p.y * p.y) + 1.0);
  return vec3(s * p.x, s * p.y, w * p.z);
}
vec3 V_cylinder(vec3 p, float w, int P, int A) { return w * vec3(sin(p.x), p.y, p.z); }
vec3 V_perspective(vec3 p, float w, int P, int A) {
  float angle = P_(P, 0) * kPi / 2.0, dist = P_(P, 1);
  float vsin = sin(angle), vfcos = dist * cos(angle);
  float t = 1.0 / (dist - p.y * vsin);
  return vec3(w * dist * p.x * t, w * vfcos * p.y * t, w * p.z);
}
vec3 V_noise(vec3 p, float w, int P, int A) {
  float a = kTwoPi * psi();
  float s = w * psi();
  return vec3(p.x * s * cos(a), p.y * s * sin(a), w * p.z);
}
vec3 V_julian(vec3 p, float w, int P, int A) {
  float powerN = flam3Count(P_(P, 0));
  float exponent = P_(P, 1) / powerN / 2.0;
  float root = trunc(abs(powerN) * psi());
  float a = (atan2c(p.y, p.x) + kTwoPi * root) / powerN;
  float r = w * pow(p.x * p.x + p.y * p.y, exponent);
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_juliascope(vec3 p, float w, int P, int A) {
  float powerN = flam3Count(P_(P, 0));
  float exponent = P_(P, 1) / powerN / 2.0;
  float root = trunc(abs(powerN) * psi());
  float phi = atan2c(p.y, p.x);
  bool odd = root - 2.0 * floor(0.5 * root) != 0.0;
  float a = (kTwoPi * root + (odd ? -phi : phi)) / powerN;
  float r = w * pow(p.x * p.x + p.y * p.y, exponent);
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_blur(vec3 p, float w, int P, int A) {
  float a = kTwoPi * psi();
  float r = w * psi();
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_gaussian_blur(vec3 p, float w, int P, int A) {
  float a = kTwoPi * psi();
  float r = w * gaussPsi();
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_radial_blur(vec3 p, float w, int P, int A) {
  float angle = P_(P, 0) * kPi / 2.0;
  float spin = sin(angle), zoom = cos(angle);
  float g = w * gaussPsi();
  float r = sqrt(p.x * p.x + p.y * p.y);
  float a = atan2c(p.y, p.x) + spin * g;
  float rz = zoom * g - 1.0;
  return vec3(r * cos(a) + rz * p.x, r * sin(a) + rz * p.y, w * p.z);
}
vec3 V_pie(vec3 p, float w, int P, int A) {
  float slices = flam3Count(P_(P, 0)), rotation = P_(P, 1), thickness = P_(P, 2);
  float slice = trunc(psi() * slices + 0.5);
  float a = rotation + kTwoPi * (slice + psi() * thickness) / slices;
  float r = w * psi();
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_ngon(vec3 p, float w, int P, int A) {
  float sides = flam3Count(P_(P, 0)), halfPower = P_(P, 1) / 2.0, circle = P_(P, 2), corners = P_(P, 3);
  float b = kTwoPi / sides;
  float rFactor = pow(p.x * p.x + p.y * p.y, halfPower);
  float phi = atan2c(p.y, p.x);
  float wedge = phi - b * floor(phi / b);
  wedge = wedge > 0.5 * b ? wedge - b : wedge;
  float amp = (corners * (1.0 / (cos(wedge) + kFlam3Eps) - 1.0) + circle) / (rFactor + kFlam3Eps);
  return vec3(w * p.x * amp, w * p.y * amp, w * p.z);
}
vec3 V_curl(vec3 p, float w, int P, int A) {
  float c1 = P_(P, 0), c2 = P_(P, 1);
  float re = 1.0 + c1 * p.x + c2 * (p.x * p.x - p.y * p.y);
  float im = c1 * p.y + 2.0 * c2 * p.x * p.y;
  float s = w / (re * re + im * im);
  return vec3((p.x * re + p.y * im) * s, (p.y * re - p.x * im) * s, w * p.z);
}
vec3 V_rectangles(vec3 p, float w, int P, int A) {
  float rx = P_(P, 0), ry = P_(P, 1);
  float safeX = rx == 0.0 ? 1.0 : rx, safeY = ry == 0.0 ? 1.0 : ry;
  float cellX = (2.0 * floor(p.x / safeX) + 1.0) * safeX - p.x;
  float cellY = (2.0 * floor(p.y / safeY) + 1.0) * safeY - p.y;
  return w * vec3(rx == 0.0 ? p.x : cellX, ry == 0.0 ? p.y : cellY, p.z);
}

// ---- 3D variations (variations_3d.cpp) --------------------------------------------------------

vec3 V_linear3D(vec3 p, float w, int P, int A) { return w * p; }
vec3 V_spherical3D(vec3 p, float w, int P, int A) { return p * (w / (dot(p, p) + kEpsilon)); }
vec3 V_julia3D(vec3 p, float w, int P, int A) {
  float powerN = countParam(P_(P, 0));
  float absPower = abs(powerN);
  float exponent = (1.0 / powerN - 1.0) * 0.5;
  float ySign = powerN == -1.0 ? -1.0 : 1.0;
  float zs = p.z / absPower;
  float r2d = p.x * p.x + p.y * p.y;
  float r = w * pow(r2d + zs * zs + kEpsilon, exponent);
  float r2 = r * sqrt(r2d);
  float root = trunc(psi() * absPower);
  float a = (atan2c(p.y, p.x) + kTwoPi * root) / powerN;
  return vec3(r2 * cos(a), ySign * r2 * sin(a), r * zs);
}
vec3 V_julia3Dz(vec3 p, float w, int P, int A) {
  float powerN = countParam(P_(P, 0));
  float absPower = abs(powerN);
  float exponent = 0.5 / powerN;
  float ySign = powerN == -1.0 ? -1.0 : 1.0;
  float quirk = absPower == 2.0 ? 1.0 : 0.0;
  float r2d = p.x * p.x + p.y * p.y + kEpsilon;
  float rho = sqrt(r2d);
  float r = w * pow(r2d, exponent);
  float root = trunc(psi() * absPower);
  float a = (atan2c(p.y, p.x) + kTwoPi * root) / powerN;
  return vec3(r * cos(a), ySign * r * sin(a), r * p.z / (rho * absPower) + quirk * r * p.z / (2.0 * sqrt(rho)));
}
vec3 V_bubble3D(vec3 p, float w, int P, int A) {
  float d = 0.25 * (p.x * p.x + p.y * p.y) + 1.0;
  float s = w / d;
  return vec3(s * p.x, s * p.y, w * (2.0 / d - 1.0));
}
vec3 V_hemisphere(vec3 p, float w, int P, int A) {
  float s = w / sqrt(p.x * p.x + p.y * p.y + 1.0);
  return vec3(s * p.x, s * p.y, s);
}
vec3 V_cylinder3D(vec3 p, float w, int P, int A) {
  float radius = clamp(P_(P, 0), 0.0, 0.5), halfHeight = clamp(P_(P, 1), 0.0, 0.5);
  float a = kTwoPi * psi();
  float rho = radius * sqrt(psi());
  float h = halfHeight * (2.0 * psi() - 1.0);
  return w * vec3(rho * cos(a), h, rho * sin(a));
}
vec3 V_sinusoidal3D(vec3 p, float w, int P, int A) {
  return w * vec3(sin(p.x), sin(p.y), atan2c(p.x * p.x, p.y * p.y) * cos(p.z));
}
vec3 V_swirl3D(vec3 p, float w, int P, int A) {
  float r2 = dot(p, p);
  float s = sin(r2), c = cos(r2);
  return w * vec3(p.x * s - p.y * c, p.x * c + p.y * s, p.z);
}
vec3 V_curl3D(vec3 p, float w, int P, int A) {
  float cx = P_(P, 0), cy = P_(P, 1), cz = P_(P, 2);
  float c2 = cx * cx + cy * cy + cz * cz;
  float r2 = dot(p, p);
  float s = w / (r2 * c2 + 2.0 * cx * p.x - 2.0 * cy * p.y + 2.0 * cz * p.z + 1.0);
  return s * vec3(p.x + cx * r2, p.y - cy * r2, p.z + cz * r2);
}
vec3 V_pie3D(vec3 p, float w, int P, int A) {
  float slices = countParam(P_(P, 0)), rotation = P_(P, 1), thickness = P_(P, 2);
  float slice = trunc(psi() * slices + 0.5);
  float a = rotation + kTwoPi * (slice + psi() * thickness) / slices;
  float r = w * psi();
  return vec3(r * cos(a), r * sin(a), r * sin(r));
}
vec3 V_blur3D(vec3 p, float w, int P, int A) {
  float a = kTwoPi * psi();
  float b = kPi * psi();
  float r = w * gaussPsi();
  return vec3(r * sin(b) * cos(a), r * sin(b) * sin(a), r * cos(b));
}
vec3 V_zblur(vec3 p, float w, int P, int A) { return vec3(0.0, 0.0, w * gaussPsi()); }
vec3 V_zscale(vec3 p, float w, int P, int A) { return vec3(0.0, 0.0, w * p.z); }
vec3 V_ztranslate(vec3 p, float w, int P, int A) { return vec3(0.0, 0.0, w); }
vec3 V_zcone(vec3 p, float w, int P, int A) { return vec3(0.0, 0.0, w * sqrt(p.x * p.x + p.y * p.y)); }

// ---- the rest of flam3's (variations_flam3.cpp) -----------------------------------------------

// flatten adds nothing: the chaos step sets z to 0 after the stage it is in (flame_kernel.cpp).
vec3 V_flatten(vec3 p, float w, int P, int A) { return vec3(0.0); }
vec3 V_arch(vec3 p, float w, int P, int A) {
  float a = psi() * w * kPi;
  float s = sin(a), c = cos(a);
  return vec3(w * s, w * s * s / (c == 0.0 ? kEpsilon : c), w * p.z);
}
vec3 V_tangent(vec3 p, float w, int P, int A) { return w * vec3(sin(p.x) / cos(p.y), tan(p.y), p.z); }
vec3 V_square(vec3 p, float w, int P, int A) {
  float a = psi(), b = psi();
  return w * vec3(a - 0.5, b - 0.5, p.z);
}
vec3 V_rays(vec3 p, float w, int P, int A) {
  float a = w * psi() * kPi;
  float r = w / (p.x * p.x + p.y * p.y + kFlam3Eps);
  float t = w * tan(a) * r;
  return vec3(t * cos(p.x), t * sin(p.y), w * p.z);
}
vec3 V_blade(vec3 p, float w, int P, int A) {
  float r = psi() * w * sqrt(p.x * p.x + p.y * p.y);
  float s = sin(r), c = cos(r);
  return vec3(w * p.x * (c + s), w * p.x * (c - s), w * p.z);
}
vec3 V_secant2(vec3 p, float w, int P, int A) {
  float r = w * sqrt(p.x * p.x + p.y * p.y);
  float c = cos(r), ic = 1.0 / c;
  return vec3(w * p.x, c < 0.0 ? w * (ic + 1.0) : w * (ic - 1.0), w * p.z);
}
vec3 V_twintrian(vec3 p, float w, int P, int A) {
  float r = psi() * w * sqrt(p.x * p.x + p.y * p.y);
  float s = sin(r), c = cos(r);
  float diff = log(s * s) * 0.43429448190325176 + c;
  if (isinf(diff) || isnan(diff)) diff = -30.0;
  return vec3(w * p.x * diff, w * p.x * (diff - s * kPi), w * p.z);
}
vec3 V_cross(vec3 p, float w, int P, int A) {
  float s = p.x * p.x - p.y * p.y;
  float r = w * sqrt(1.0 / (s * s + kFlam3Eps));
  return vec3(p.x * r, p.y * r, w * p.z);
}
vec3 V_disc2(vec3 p, float w, int P, int A) {
  float rot = P_(P, 0), twist = P_(P, 1);
  float timesPi = rot * kPi;
  float sinAdd = sin(twist), cosAdd = cos(twist) - 1.0;
  if (twist > kTwoPi) {
    float k = 1.0 + twist - kTwoPi;
    cosAdd *= k;
    sinAdd *= k;
  }
  if (twist < -kTwoPi) {
    float k = 1.0 + twist + kTwoPi;
    cosAdd *= k;
    sinAdd *= k;
  }
  float t = timesPi * (p.x + p.y);
  float r = w * atan2c(p.x, p.y) / kPi;
  return vec3((sin(t) + cosAdd) * r, (cos(t) + sinAdd) * r, w * p.z);
}
vec3 V_super_shape(vec3 p, float w, int P, int A) {
  float rndMix = P_(P, 0), m4 = P_(P, 1) / 4.0, n1 = P_(P, 2), n2 = P_(P, 3), n3 = P_(P, 4), holes = P_(P, 5);
  float negInvN1 = -1.0 / (n1 == 0.0 ? kFlam3Eps : n1);
  float rr = sqrt(p.x * p.x + p.y * p.y);
  float theta = m4 * atan2c(p.y, p.x) + kPi / 4.0;
  float t1 = pow(abs(cos(theta)), n2);
  float t2 = pow(abs(sin(theta)), n3);
  float r = w * ((rndMix * psi() + (1.0 - rndMix) * rr - holes) * pow(t1 + t2, negInvN1)) / (rr + kEpsilon);
  return vec3(r * p.x, r * p.y, w * p.z);
}
vec3 V_flower(vec3 p, float w, int P, int A) {
  float petals = P_(P, 0), holes = P_(P, 1);
  float theta = atan2c(p.y, p.x);
  float r = w * (psi() - holes) * cos(petals * theta) / (sqrt(p.x * p.x + p.y * p.y) + kEpsilon);
  return vec3(r * p.x, r * p.y, w * p.z);
}
vec3 V_conic(vec3 p, float w, int P, int A) {
  float e = P_(P, 0), holes = P_(P, 1);
  float rr = sqrt(p.x * p.x + p.y * p.y) + kEpsilon;
  float ct = p.x / rr;
  float r = w * (psi() - holes) * e / (1.0 + e * ct) / rr;
  return vec3(r * p.x, r * p.y, w * p.z);
}
vec3 V_parabola(vec3 p, float w, int P, int A) {
  float height = P_(P, 0), width = P_(P, 1);
  float r = sqrt(p.x * p.x + p.y * p.y);
  float s = sin(r), c = cos(r);
  float a = psi(), b = psi();
  return vec3(height * w * s * s * a, width * w * c * b, w * p.z);
}
vec3 V_bent2(vec3 p, float w, int P, int A) {
  float bx = P_(P, 0), by = P_(P, 1);
  return w * vec3(p.x < 0.0 ? p.x * bx : p.x, p.y < 0.0 ? p.y * by : p.y, p.z);
}
vec3 V_bipolar(vec3 p, float w, int P, int A) {
  float shift = -kPi / 2.0 * P_(P, 0);
  float r2 = p.x * p.x + p.y * p.y;
  float t = r2 + 1.0, x2 = 2.0 * p.x;
  float v = 0.5 * atan2c(2.0 * p.y, r2 - 1.0) + shift;
  if (v > kPi / 2.0)
    v = -kPi / 2.0 + fmodc(v + kPi / 2.0, kPi);
  else if (v < -kPi / 2.0)
    v = kPi / 2.0 - fmodc(kPi / 2.0 - v, kPi);
  float f = t + x2, g = t - x2;
  bool defined = g != 0.0 && f / g > 0.0;
  return vec3(defined ? w * 0.25 * (2.0 / kPi) * log(f / g) : 0.0, defined ? w * (2.0 / kPi) * v : 0.0, w * p.z);
}
vec3 V_boarders(vec3 p, float w, int P, int A) {
  float rx = roundEven(p.x), ry = roundEven(p.y);
  float dx = p.x - rx, dy = p.y - ry;
  float px, py;
  if (psi() >= 0.75) {
    px = dx * 0.5 + rx;
    py = dy * 0.5 + ry;
  } else if (abs(dx) >= abs(dy)) {
    float side = dx >= 0.0 ? 0.25 : -0.25;
    px = dx * 0.5 + rx + side;
    py = dy * 0.5 + ry + side * dy / (dx == 0.0 ? kEpsilon : dx);
  } else {
    float side = dy >= 0.0 ? 0.25 : -0.25;
    py = dy * 0.5 + ry + side;
    px = dx * 0.5 + rx + side * dx / (dy == 0.0 ? kEpsilon : dy);
  }
  return w * vec3(px, py, p.z);
}
vec3 V_butterfly(vec3 p, float w, int P, int A) {
  float wx = w * 1.3029400317411198;
  float y2 = 2.0 * p.y;
  float r = wx * sqrt(abs(p.y * p.x) / (kFlam3Eps + p.x * p.x + y2 * y2));
  return vec3(r * p.x, r * y2, w * p.z);
}
vec3 V_cell(vec3 p, float w, int P, int A) {
  float size = P_(P, 0) == 0.0 ? kFlam3Eps : P_(P, 0);
  float inv = 1.0 / size;
  float cx = floor(p.x * inv), cy = floor(p.y * inv);
  float dx = p.x - cx * size, dy = p.y - cy * size;
  cy = cy >= 0.0 ? 2.0 * cy : -(2.0 * cy + 1.0);
  cx = cx >= 0.0 ? 2.0 * cx : -(2.0 * cx + 1.0);
  return vec3(w * (dx + cx * size), -w * (dy + cy * size), w * p.z);
}
vec3 V_cpow(vec3 p, float w, int P, int A) {
  float power = P_(P, 2) == 0.0 ? 1.0 : P_(P, 2);
  float va = kTwoPi / power, vc = P_(P, 0) / power, vd = P_(P, 1) / power;
  float a = atan2c(p.y, p.x);
  float lnr = 0.5 * log(p.x * p.x + p.y * p.y);
  float angle = vc * a + vd * lnr + va * floor(power * psi());
  float m = w * exp(vc * lnr - vd * a);
  return vec3(m * cos(angle), m * sin(angle), w * p.z);
}
vec3 V_curve(vec3 p, float w, int P, int A) {
  float xamp = P_(P, 0), yamp = P_(P, 1);
  float xlen = max(P_(P, 2) * P_(P, 2), 1e-20), ylen = max(P_(P, 3) * P_(P, 3), 1e-20);
  return w * vec3(p.x + xamp * exp(-p.y * p.y / xlen), p.y + yamp * exp(-p.x * p.x / ylen), p.z);
}
vec3 V_edisc(vec3 p, float w, int P, int A) {
  float t = p.x * p.x + p.y * p.y + 1.0, x2 = 2.0 * p.x;
  float xmax = 0.5 * (sqrt(t + x2) + sqrt(t - x2));
  float a1 = log(xmax + sqrt(xmax - 1.0));
  float a2 = -acos(clamp(p.x / xmax, -1.0, 1.0));
  float ww = w / 11.57034632;
  float snv = p.y > 0.0 ? -sin(a1) : sin(a1);
  return vec3(ww * cosh(a2) * cos(a1), ww * sinh(a2) * snv, w * p.z);
}
float sqrt1pm1(float v) {
  if (-0.0625 < v && v < 0.0625) {
    float num = (((1.0 / 32.0 * v + 5.0 / 16.0) * v + 3.0 / 4.0) * v + 1.0 / 2.0) * v;
    float den = (((1.0 / 256.0 * v + 5.0 / 32.0) * v + 15.0 / 16.0) * v + 7.0 / 4.0) * v + 1.0;
    return num / den;
  }
  return sqrt(1.0 + v) - 1.0;
}
vec3 V_elliptic(vec3 p, float w, int P, int A) {
  float mode = sign(P_(P, 0)) * floor(abs(P_(P, 0)) + 0.5);
  float ww = w / (kPi / 2.0);
  float sq = p.x * p.x + p.y * p.y, x2 = 2.0 * p.x;
  vec3 o;
  if (mode == 2.0) {
    float xmaxm1 = 0.5 * (sqrt1pm1(sq + x2) + sqrt1pm1(sq - x2));
    float ssx = xmaxm1 < 0.0 ? 0.0 : sqrt(xmaxm1);
    float a = p.x / (1.0 + xmaxm1);
    o.x = ww * asin(clamp(a, -1.0, 1.0));
    o.y = (p.y > 0.0 ? ww : -ww) * log(1.0 + xmaxm1 + ssx);
  } else {
    float t = sq + 1.0;
    float xmax = 0.5 * (sqrt(t + x2) + sqrt(t - x2));
    float a = p.x / xmax;
    float b = sqrt(max(0.0, 1.0 - a * a));
    float ssx = sqrt(max(0.0, xmax - 1.0));
    bool up = mode == 1.0 ? psi() < 0.5 : p.y > 0.0;
    o.x = ww * atan2c(a, b);
    o.y = (up ? ww : -ww) * log(xmax + ssx);
  }
  o.z = w * p.z;
  return o;
}
vec3 V_escher(vec3 p, float w, int P, int A) {
  float vc = 0.5 * (1.0 + cos(P_(P, 0))), vd = 0.5 * sin(P_(P, 0));
  float a = atan2c(p.y, p.x);
  float lnr = 0.5 * log(p.x * p.x + p.y * p.y);
  float m = w * exp(vc * lnr - vd * a);
  float angle = vc * a + vd * lnr;
  return vec3(m * cos(angle), m * sin(angle), w * p.z);
}
vec3 V_foci(vec3 p, float w, int P, int A) {
  float ex = 0.5 * exp(p.x);
  float enx = 0.25 / ex;
  float t = w / (ex + enx - cos(p.y));
  return vec3(t * (ex - enx), t * sin(p.y), w * p.z);
}
vec3 V_lazysusan(vec3 p, float w, int P, int A) {
  float spin = P_(P, 0), space = P_(P, 1), twist = P_(P, 2), cx = P_(P, 3), cy = P_(P, 4);
  float px = p.x - cx, py = p.y + cy;
  float r = sqrt(px * px + py * py);
  vec3 o;
  if (r < w) {
    float a = atan2c(py, px) + spin + twist * (w - r);
    o.xy = vec2(w * r * cos(a) + cx, w * r * sin(a) - cy);
  } else {
    float s = w * (1.0 + space / (r + kEpsilon));
    o.xy = vec2(s * px + cx, s * py - cy);
  }
  o.z = w * p.z;
  return o;
}
vec3 V_loonie(vec3 p, float w, int P, int A) {
  float r2 = p.x * p.x + p.y * p.y, w2 = w * w;
  float s = r2 < w2 ? w * sqrt(w2 / (r2 + kEpsilon) - 1.0) : w;
  return vec3(s * p.x, s * p.y, w * p.z);
}
vec3 V_modulus(vec3 p, float w, int P, int A) {
  float mx = P_(P, 0), my = P_(P, 1);
  float xr = 2.0 * mx == 0.0 ? kEpsilon : 2.0 * mx, yr = 2.0 * my == 0.0 ? kEpsilon : 2.0 * my;
  float px = p.x > mx ? -mx + fmodc(p.x + mx, xr) : p.x < -mx ? mx - fmodc(mx - p.x, xr) : p.x;
  float py = p.y > my ? -my + fmodc(p.y + my, yr) : p.y < -my ? my - fmodc(my - p.y, yr) : p.y;
  return w * vec3(px, py, p.z);
}
vec3 V_oscilloscope(vec3 p, float w, int P, int A) {
  float separation = P_(P, 0), tpf = kTwoPi * P_(P, 1), amplitude = P_(P, 2), damping = P_(P, 3);
  float t = damping == 0.0 ? amplitude * cos(tpf * p.x) + separation
                           : amplitude * exp(-abs(p.x) * damping) * cos(tpf * p.x) + separation;
  return vec3(w * p.x, abs(p.y) <= t ? -w * p.y : w * p.y, w * p.z);
}
vec3 V_polar2(vec3 p, float w, int P, int A) {
  float q = w / kPi;
  return vec3(q * atan2c(p.x, p.y), 0.5 * q * log(p.x * p.x + p.y * p.y), w * p.z);
}
vec3 V_popcorn2(vec3 p, float w, int P, int A) {
  float px = P_(P, 0), py = P_(P, 1), c = P_(P, 2);
  return w * vec3(p.x + px * sin(tan(p.y * c)), p.y + py * sin(tan(p.x * c)), p.z);
}
vec3 V_scry(vec3 p, float w, int P, int A) {
  float t = p.x * p.x + p.y * p.y;
  float r = 1.0 / (sqrt(t) * (t + 1.0 / (w + kFlam3Eps)) + kEpsilon);
  return vec3(p.x * r, p.y * r, w * p.z);
}
vec3 V_separation(vec3 p, float w, int P, int A) {
  float sx2 = P_(P, 0) * P_(P, 0), xin = P_(P, 1), sy2 = P_(P, 2) * P_(P, 2), yin = P_(P, 3);
  float rx = sqrt(p.x * p.x + sx2), ry = sqrt(p.y * p.y + sy2);
  return vec3(p.x > 0.0 ? w * (rx - p.x * xin) : -w * (rx + p.x * xin),
              p.y > 0.0 ? w * (ry - p.y * yin) : -w * (ry + p.y * yin), w * p.z);
}
vec3 V_split(vec3 p, float w, int P, int A) {
  float sx = P_(P, 0) * kPi, sy = P_(P, 1) * kPi;
  return vec3(cos(p.y * sy) >= 0.0 ? w * p.x : -w * p.x, cos(p.x * sx) >= 0.0 ? w * p.y : -w * p.y, w * p.z);
}
vec3 V_splits(vec3 p, float w, int P, int A) {
  float sx = P_(P, 0), sy = P_(P, 1);
  float lshear = P_(P, 2), rshear = P_(P, 3), ushear = P_(P, 4), dshear = P_(P, 5);
  return w * vec3((p.x >= 0.0 ? p.x + sx : p.x - sx) + (p.y >= 0.0 ? ushear : -dshear),
                  (p.y >= 0.0 ? p.y + sy : p.y - sy) + (p.x >= 0.0 ? rshear : -lshear), p.z);
}
vec3 V_stripes(vec3 p, float w, int P, int A) {
  float space = P_(P, 0), warp = P_(P, 1);
  float rx = floor(p.x + 0.5), dx = p.x - rx;
  return w * vec3(dx * (1.0 - space) + rx, p.y + dx * dx * warp, p.z);
}
vec3 V_wedge(vec3 p, float w, int P, int A) {
  float angle = P_(P, 0), hole = P_(P, 1), count = P_(P, 2), swirlAmount = P_(P, 3);
  float compression = 1.0 - angle * count / kPi * 0.5;
  float r = sqrt(p.x * p.x + p.y * p.y);
  float a = atan2c(p.y, p.x) + swirlAmount * r;
  float c = floor((count * a + kPi) / kPi * 0.5);
  a = a * compression + c * angle;
  return vec3(w * (r + hole) * cos(a), w * (r + hole) * sin(a), w * p.z);
}
vec3 V_wedge_julia(vec3 p, float w, int P, int A) {
  float angle = P_(P, 0), count = P_(P, 1), powerN = P_(P, 2) == 0.0 ? 1.0 : P_(P, 2), dist = P_(P, 3);
  float cn = dist / powerN / 2.0, rootCount = abs(powerN);
  float compression = 1.0 - angle * count / kPi * 0.5;
  float r = w * pow(p.x * p.x + p.y * p.y, cn);
  float root = trunc(rootCount * psi());
  float a = (atan2c(p.y, p.x) + kTwoPi * root) / powerN;
  float c = floor((count * a + kPi) / kPi * 0.5);
  a = a * compression + c * angle;
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_wedge_sph(vec3 p, float w, int P, int A) {
  float angle = P_(P, 0), count = P_(P, 1), hole = P_(P, 2), swirlAmount = P_(P, 3);
  float compression = 1.0 - angle * count / kPi * 0.5;
  float r = 1.0 / (sqrt(p.x * p.x + p.y * p.y) + kFlam3Eps);
  float a = atan2c(p.y, p.x) + swirlAmount * r;
  float c = floor((count * a + kPi) / kPi * 0.5);
  a = a * compression + c * angle;
  return vec3(w * (r + hole) * cos(a), w * (r + hole) * sin(a), w * p.z);
}
vec3 V_whorl(vec3 p, float w, int P, int A) {
  float inside = P_(P, 0), outside = P_(P, 1);
  float r = sqrt(p.x * p.x + p.y * p.y);
  float d = w - r == 0.0 ? kEpsilon : w - r;
  float a = atan2c(p.y, p.x) + (r < w ? inside : outside) / d;
  return vec3(w * r * cos(a), w * r * sin(a), w * p.z);
}
vec3 V_waves2(vec3 p, float w, int P, int A) {
  float freqX = P_(P, 0), scaleX = P_(P, 1), freqY = P_(P, 2), scaleY = P_(P, 3), freqZ = P_(P, 4),
        scaleZ = P_(P, 5);
  return w * vec3(p.x + scaleX * sin(p.y * freqX), p.y + scaleY * sin(p.x * freqY),
                  p.z + scaleZ * sin(sqrt(p.x * p.x + p.y * p.y) * freqZ));
}
vec3 V_exp(vec3 p, float w, int P, int A) {
  float e = w * exp(p.x);
  return vec3(e * cos(p.y), e * sin(p.y), w * p.z);
}
vec3 V_log(vec3 p, float w, int P, int A) {
  float lnBase = log(P_(P, 0));
  float scale = 0.5 / (lnBase == 0.0 ? kEpsilon : lnBase);
  return vec3(w * scale * log(p.x * p.x + p.y * p.y), w * atan2c(p.y, p.x), w * p.z);
}
vec3 V_sin(vec3 p, float w, int P, int A) { return w * vec3(sin(p.x) * cosh(p.y), cos(p.x) * sinh(p.y), p.z); }
vec3 V_cos(vec3 p, float w, int P, int A) { return w * vec3(cos(p.x) * cosh(p.y), -sin(p.x) * sinh(p.y), p.z); }
vec3 V_tan(vec3 p, float w, int P, int A) {
  float d = w / (cos(2.0 * p.x) + cosh(2.0 * p.y));
  return vec3(d * sin(2.0 * p.x), d * sinh(2.0 * p.y), w * p.z);
}
vec3 V_sec(vec3 p, float w, int P, int A) {
  float d = 2.0 * w / (cos(2.0 * p.x) + cosh(2.0 * p.y));
  return vec3(d * cos(p.x) * cosh(p.y), d * sin(p.x) * sinh(p.y), w * p.z);
}
vec3 V_csc(vec3 p, float w, int P, int A) {
  float d = 2.0 * w / (cosh(2.0 * p.y) - cos(2.0 * p.x));
  return vec3(d * sin(p.x) * cosh(p.y), -d * cos(p.x) * sinh(p.y), w * p.z);
}
vec3 V_cot(vec3 p, float w, int P, int A) {
  float d = w / (cosh(2.0 * p.y) - cos(2.0 * p.x));
  return vec3(d * sin(2.0 * p.x), -d * sinh(2.0 * p.y), w * p.z);
}
vec3 V_sinh(vec3 p, float w, int P, int A) { return w * vec3(sinh(p.x) * cos(p.y), cosh(p.x) * sin(p.y), p.z); }
vec3 V_cosh(vec3 p, float w, int P, int A) { return w * vec3(cosh(p.x) * cos(p.y), sinh(p.x) * sin(p.y), p.z); }
vec3 V_tanh(vec3 p, float w, int P, int A) {
  float d = w / (cos(2.0 * p.y) + cosh(2.0 * p.x));
  return vec3(d * sinh(2.0 * p.x), d * sin(2.0 * p.y), w * p.z);
}
vec3 V_sech(vec3 p, float w, int P, int A) {
  float d = 2.0 * w / (cos(2.0 * p.y) + cosh(2.0 * p.x));
  return vec3(d * cos(p.y) * cosh(p.x), -d * sin(p.y) * sinh(p.x), w * p.z);
}
vec3 V_csch(vec3 p, float w, int P, int A) {
  float d = 2.0 * w / (cosh(2.0 * p.x) - cos(2.0 * p.y));
  return vec3(d * sinh(p.x) * cos(p.y), -d * cosh(p.x) * sin(p.y), w * p.z);
}
vec3 V_coth(vec3 p, float w, int P, int A) {
  float d = w / (cosh(2.0 * p.x) - cos(2.0 * p.y));
  return vec3(d * sinh(2.0 * p.x), d * sin(2.0 * p.y), w * p.z);
}
vec3 V_auger(vec3 p, float w, int P, int A) {
  float freq = P_(P, 0), augerWeight = P_(P, 1), sym = P_(P, 2), scale = P_(P, 3);
  float s = sin(freq * p.x), t = sin(freq * p.y);
  float dy = p.y + augerWeight * (scale * s / 2.0 + abs(p.y) * s);
  float dx = p.x + augerWeight * (scale * t / 2.0 + abs(p.x) * t);
  return vec3(w * (p.x + sym * (dx - p.x)), w * dy, w * p.z);
}

// ---- the plugins flames use most (variations_apophysis.cpp, variations_plugins.cpp, ...) --------

// The transform's point after its affine map and pre_ terms, which its ordinary terms map (core's
// VariationInput::tx): the point itself for a pre_ or ordinary term, the point the sum came from
// for a post_ one. Only depth reads it; flame_kernel.cpp sets it where a transform has depth.
vec3 gVariationT;

// flam3's own pre_blur: a Gaussian blur the transform adds to its point before the other terms.
vec3 V_pre_blur(vec3 p, float w, int P, int A) {
  float g = w * gaussPsi();
  float a = kTwoPi * psi();
  return vec3(g * cos(a), g * sin(a), w * p.z);
}
vec3 V_mobius(vec3 p, float w, int P, int A) {
  float reA = P_(P, 0), imA = P_(P, 1), reB = P_(P, 2), imB = P_(P, 3);
  float reC = P_(P, 4), imC = P_(P, 5), reD = P_(P, 6), imD = P_(P, 7);
  float reU = reA * p.x - imA * p.y + reB, imU = reA * p.y + imA * p.x + imB;
  float reV = reC * p.x - imC * p.y + reD, imV = reC * p.y + imC * p.x + imD;
  float s = w / (reV * reV + imV * imV + kEpsilon);
  return vec3(s * (reU * reV + imU * imV), s * (imU * reV - reU * imV), w * p.z);
}
vec3 V_unpolar(vec3 p, float w, int P, int A) {
  float r = w / kPi * 0.5 * exp(p.y);
  return vec3(r * sin(p.x), r * cos(p.x), w * p.z);
}
vec3 V_sineblur(vec3 p, float w, int P, int A) {
  float powerP = max(0.0, P_(P, 0));
  float a = kTwoPi * psi();
  float u = psi();
  float r = w * (powerP == 1.0 ? acos(u * 2.0 - 1.0) : acos(exp(log(u) * powerP) * 2.0 - 1.0)) / kPi;
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
// A point where a root is 0 is carried through unmapped, as on the CPU.
vec3 V_glynnia(vec3 p, float w, int P, int A) {
  float half_ = w * sqrt(2.0) / 2.0;
  float r = sqrt(p.x * p.x + p.y * p.y);
  float side = r >= 1.0 ? 1.0 : -1.0;
  vec3 o = vec3(0.0, 0.0, w * p.z);
  if (psi() > 0.5) {
    float d = sqrt(r + p.x);
    if (d != 0.0) o.xy = vec2(side * half_ * d, -half_ / d * p.y);
  } else {
    float d = r + p.x;
    float dx = sqrt(r * (p.y * p.y + d * d));
    if (dx != 0.0) o.xy = vec2(side * w / dx * d, w / dx * p.y);
  }
  return o;
}
vec3 V_epispiral(vec3 p, float w, int P, int A) {
  float waves = P_(P, 0), thickness = P_(P, 1), holes = P_(P, 2);
  float theta = atan2c(p.y, p.x);
  float c = cos(waves * theta);
  float t = psi() * thickness / (c == 0.0 ? kEpsilon : c) - holes;
  return vec3(w * t * cos(theta), w * t * sin(theta), w * p.z);
}
vec3 V_crop(vec3 p, float w, int P, int A) {
  float x0 = min(P_(P, 0), P_(P, 2)), x1 = max(P_(P, 0), P_(P, 2));
  float y0 = min(P_(P, 1), P_(P, 3)), y1 = max(P_(P, 1), P_(P, 3));
  float scatter = clamp(P_(P, 4), -1.0, 1.0);
  float bandX = (x1 - x0) * 0.5 * scatter, bandY = (y1 - y0) * 0.5 * scatter;
  bool zero = sign(P_(P, 5)) * floor(abs(P_(P, 5)) + 0.5) >= 1.0;
  float a = psi(), b = psi();
  bool outside = p.x < x0 || p.x > x1 || p.y < y0 || p.y > y1;
  float px = p.x < x0 ? x0 + a * bandX : p.x > x1 ? x1 - a * bandX : p.x;
  float py = p.y < y0 ? y0 + b * bandY : p.y > y1 ? y1 - b * bandY : p.y;
  if (outside && zero) px = py = 0.0;
  return w * vec3(px, py, p.z);
}
vec3 V_julian2(vec3 p, float w, int P, int A) {
  float powerN = countParam(P_(P, 0)), exponent = P_(P, 1) / powerN * 0.5, rootCount = abs(powerN);
  float a = P_(P, 2), b = P_(P, 3), c = P_(P, 4), d = P_(P, 5), e = P_(P, 6), f = P_(P, 7);
  float px = a * p.x + b * p.y + e, py = c * p.x + d * p.y + f;
  float root = trunc(rootCount * psi());
  float angle = (atan2c(py, px) + kTwoPi * root) / powerN;
  float r = w * pow(px * px + py * py, exponent);
  return vec3(r * cos(angle), r * sin(angle), w * p.z);
}
vec3 V_stun(vec3 p, float w, int P, int A) {
  float power = abs(clamp(P_(P, 0), 0.0, 3.4e38)), rMin = clamp(P_(P, 1), 0.0, 3.4e38);
  float rMax = clamp(P_(P, 2), 0.0, 3.4e38);
  float low = rMin < rMax ? rMin : rMax, high = rMin > rMax ? rMin : rMax;
  float w3 = 3.0 * w, w1 = w3 / kPi, w2 = 0.5 * w1;
  vec2 q = p.xy;
  float r2 = q.x * q.x + q.y * q.y;
  if (r2 > low) {
    float r = sqrt(r2);
    float reach = r + abs(power * r * psi());
    float m = reach * reach > high ? reach * reach : r2;
    q *= 1.0 / m - 1.0;
  }
  return vec3(w1 * atan2c(q.x, q.y), w2 * log(q.x * q.x + q.y * q.y), w3 * p.z);
}
vec3 V_epispiral_wf(vec3 p, float w, int P, int A) {
  float theta = atan2c(p.x, p.y);
  float d = cos(P_(P, 0) * theta);
  vec3 o = vec3(0.0, 0.0, w * p.z);
  if (d != 0.0) o.xy = w * (0.5 / d) * vec2(sin(theta), cos(theta));  // JWildfire skips the point there
  return o;
}
vec3 V_blur_circle(vec3 p, float w, int P, int A) {
  float sx = 2.0 * psi() - 1.0, sy = 2.0 * psi() - 1.0;
  float ax = abs(sx), ay = abs(sy);
  float perimeter, side;
  if (ax >= ay) {
    perimeter = sx >= ay ? ax + sy : 5.0 * ax - sy;
    side = ax;
  } else {
    perimeter = sy >= ax ? 3.0 * ay - sx : 7.0 * ay + sx;
    side = ay;
  }
  float a = kPi / 4.0 * perimeter / side - kPi / 4.0;
  return vec3(w * side * cos(a), w * side * sin(a), w * p.z);
}
vec3 V_blur_linear(vec3 p, float w, int P, int A) {
  float r = P_(P, 0) * psi();
  return w * vec3(p.x + r * cos(P_(P, 1)), p.y + r * sin(P_(P, 1)), p.z);
}
vec3 V_exblur(vec3 p, float w, int P, int A) {
  float dist = P_(P, 0), spread = P_(P, 1);
  vec3 d = vec3(p.x - P_(P, 2), p.y + P_(P, 3), p.z - P_(P, 4));  // y's origin added, as JWildfire has it
  float n2 = dot(d, d);
  float u = psi() * kTwoPi, v = psi() * kTwoPi;
  float rr = w * pow(n2, dist) * gaussPsi();
  float theta = atan2c(d.y, d.x), phi = acos(d.z / sqrt(n2));
  float sv = sin(phi), rsv = spread * sin(v);
  return rr * vec3(sv * cos(theta) + rsv * cos(u), sv * sin(theta) + rsv * sin(u), cos(phi) + spread * cos(v));
}
vec3 V_twoface(vec3 p, float w, int P, int A) {
  float r = p.x > 0.0 ? w / (p.x * p.x + p.y * p.y) : w;
  return vec3(r * p.x, r * p.y, w * p.z);
}
// Fractorium's Zeps(): a zero divisor becomes the double's machine epsilon, a normal float too.
const float kFractoriumEps = 2.220446049250313e-16;
float fractoriumZeps(float v) { return v == 0.0 ? kFractoriumEps : v; }
// Zueuk's hyperbolic tilings (variations_plugins.cpp): p and q any real number, 0 as Fractorium's
// epsilon.
float hypertileDistance(float p, float q) {
  float cp = cos(kTwoPi / p);
  float r2 = 1.0 - (cp - 1.0) / (cp + cos(kTwoPi / q));
  return r2 > 0.0 ? 1.0 / sqrt(r2) : 1.0;
}
float tilingTurn(float u, float p) { return p == roundEven(p) ? trunc(u * abs(p)) * kTwoPi / p : kTwoPi * u; }
vec2 hypertileMap(vec2 p, float re, float im, float w) {
  float a = p.x + re, b = p.y - im;
  float c = re * p.x - im * p.y + 1.0, d = re * p.y + im * p.x;
  float vr = w / (c * c + d * d);
  return vr * vec2(a * c + b * d, b * c - a * d);
}
vec3 V_hypertile(vec3 p, float w, int P, int A) {
  float pp = fractoriumZeps(P_(P, 0)), q = fractoriumZeps(P_(P, 1));
  float a = P_(P, 2) * kTwoPi / pp, r = hypertileDistance(pp, q);
  return vec3(hypertileMap(p.xy, r * cos(a), r * sin(a), w), w * p.z);
}
vec3 V_hypertile1(vec3 p, float w, int P, int A) {
  float pp = fractoriumZeps(P_(P, 0)), q = fractoriumZeps(P_(P, 1));
  float r = hypertileDistance(pp, q);
  float a = floor(psi() * trunc(pp)) * kTwoPi / pp;
  return vec3(hypertileMap(p.xy, r * cos(a), r * sin(a), w), w * p.z);
}
vec3 V_hypertile2(vec3 p, float w, int P, int A) {
  float pp = fractoriumZeps(P_(P, 0)), q = fractoriumZeps(P_(P, 1));
  float r = hypertileDistance(pp, q);
  float a = p.x + r, b = p.y;
  float c = r * p.x + 1.0, d = r * p.y;
  float mx = a * c + b * d, my = b * c - a * d;
  float vr = w / (c * c + d * d);
  float turn = tilingTurn(psi(), pp);
  float s = sin(turn), co = cos(turn);
  return vec3(vr * (mx * co + my * s), vr * (my * co - mx * s), w * p.z);
}
// The weight is the angle: these return the turned point itself (variations_plugins.cpp).
vec3 V_rotate_x(vec3 p, float w, int P, int A) {
  float s = sin(w * kPi / 2.0), c = cos(w * kPi / 2.0);
  return vec3(p.x, s * p.z + c * p.y, c * p.z - s * p.y);
}
vec3 V_rotate_y(vec3 p, float w, int P, int A) {
  float s = sin(w * kPi / 2.0), c = cos(w * kPi / 2.0);
  return vec3(c * p.x - s * p.z, p.y, s * p.x + c * p.z);
}
vec3 V_rotate_z(vec3 p, float w, int P, int A) {
  float s = sin(w * kPi / 2.0), c = cos(w * kPi / 2.0);
  return vec3(s * p.y + c * p.x, c * p.y - s * p.x, p.z);
}
vec3 V_foci_3D(vec3 p, float w, int P, int A) {
  float expx = exp(p.x) * 0.5, expnx = 0.25 / expx;
  float boot = p.z == 0.0 ? atan2c(p.y, p.x) : p.z;
  float t = w / (expx + expnx - cos(p.y) * cos(boot));
  return t * vec3(expx - expnx, sin(p.y), sin(boot));
}
vec3 V_circlecrop(vec3 p, float w, int P, int A) {
  float radius = P_(P, 0), x0 = P_(P, 1), y0 = P_(P, 2), scatter = clamp(P_(P, 3), -1.0, 1.0);
  bool zero = sign(P_(P, 4)) * floor(abs(P_(P, 4)) + 0.5) == 1.0;
  float dx = p.x - x0, dy = p.y - y0;
  float edge = radius + psi() * 0.5 * scatter;
  vec3 o = vec3(0.0, 0.0, w * p.z);
  if (sqrt(dx * dx + dy * dy) > radius) {
    if (!zero) {
      float a = atan2c(dy, dx);
      o.xy = vec2(w * edge * cos(a) + x0, w * edge * sin(a) + y0);
    }
  } else {
    o.xy = vec2(w * dx + x0, w * dy + y0);
  }
  return o;
}
vec3 V_bwraps(vec3 p, float w, int P, int A) {
  float cellsize = P_(P, 0), space = P_(P, 1), gain = P_(P, 2), innerTwist = P_(P, 3), outerTwist = P_(P, 4);
  float radius = 0.5 * (cellsize / (1.0 + space * space));
  float g2 = gain * gain + 1e-6;
  float maxBubble = g2 * radius;
  maxBubble = maxBubble > 2.0 ? 1.0 : maxBubble / (maxBubble * maxBubble / 4.0 + 1.0);
  float r2 = radius * radius == 0.0 ? kFractoriumEps : radius * radius;
  float rfactor = radius / maxBubble;
  vec2 q = p.xy;
  if (cellsize != 0.0) {
    vec2 centre = (floor(p.xy / cellsize) + 0.5) * cellsize;
    vec2 l = p.xy - centre;
    if (dot(l, l) <= r2) {
      l *= g2;
      float d = dot(l, l) / 4.0 + 1.0;
      l *= rfactor / (d == 0.0 ? kFractoriumEps : d);
      float t = dot(l, l) / r2;
      float theta = innerTwist * (1.0 - t) + outerTwist * t;
      float s = sin(theta), c = cos(theta);
      q = vec2(centre.x + c * l.x + s * l.y, centre.y - s * l.x + c * l.y);
    }
  }
  return w * vec3(q, p.z);
}
// The root is drawn at every point, used or not, as on the CPU.
vec3 V_juni(vec3 p, float w, int P, int A) {
  float power = countParam(P_(P, 0)), absn = abs(power);
  bool invert = sign(P_(P, 1)) * floor(abs(P_(P, 1)) + 0.5) >= 1.0;
  float cn = (P_(P, 2) / power - 1.0) / 2.0;
  float a = flameData[A], b = flameData[A + 1], c = flameData[A + 3];
  float d = flameData[A + 4], e = flameData[A + 5], f = flameData[A + 7];
  float zz = p.z / absn;
  float r2 = p.x * p.x + p.y * p.y;
  float r = w * pow(r2 + zz * zz, cn);
  float root = trunc(psi() * absn);
  bool plain = invert ? (r2 < w * w && r2 != 0.0) : (r2 > w * w || r2 == 0.0);
  if (plain) return vec3(w * p.x, w * p.y, r * zz);
  float xx = a * p.x + b * p.y + c, yy = d * p.x + e * p.y + f;
  float alpha = (atan2c(yy, xx) + kTwoPi * root) / power;
  float gamma = r * sqrt(r2);
  return vec3(gamma * cos(alpha), gamma * sin(alpha), r * zz);
}
vec3 V_blur_zoom(vec3 p, float w, int P, int A) {
  float cx = P_(P, 1), cy = P_(P, 2);
  float zoom = 1.0 + P_(P, 0) * psi();
  return w * vec3((p.x - cx) * zoom + cx, (p.y + cy) * zoom - cy, p.z);
}
// Michael Faber's elliptic coordinates (μ, ν) of p, as variations_plugins.cpp's toElliptic.
vec2 toElliptic(float x, float y, float r2) {
  float t = r2 + 1.0, x2 = 2.0 * x;
  float xmax = max(1.0, (sqrt(max(t + x2, 0.0)) + sqrt(max(t - x2, 0.0))) * 0.5);
  float mu = log(sqrt(xmax * xmax - 1.0) + xmax);
  float nu = acos(clamp(x / xmax, -1.0, 1.0));
  return vec2(mu, y < 0.0 ? -nu : nu);
}
vec3 V_eJulia(vec3 p, float w, int P, int A) {
  float power = countParam(P_(P, 0));
  float r2 = p.x * p.x + p.y * p.y, px = p.x;
  if (power < 0.0) {
    r2 = 1.0 / r2;
    px = p.x * r2;
  }
  vec2 e = toElliptic(px, p.y, r2);
  e.y = e.y / power + kTwoPi / power * floor(psi() * power);
  e.x /= power;
  return vec3(w * cosh(e.x) * cos(e.y), w * sinh(e.x) * sin(e.y), w * p.z);
}
vec3 V_eMotion(vec3 p, float w, int P, int A) {
  float move = P_(P, 0), rotate = P_(P, 1);
  vec2 e = toElliptic(p.x, p.y, p.x * p.x + p.y * p.y);
  e.x += e.y < 0.0 ? move : -move;
  if (e.x <= 0.0) e = -e;
  e.y += rotate;
  return vec3(w * cosh(e.x) * cos(e.y), w * sinh(e.x) * sin(e.y), w * p.z);
}
// Fractorium's depth: t + p |z|^power, t the transform's point (gVariationT).
vec3 V_depth(vec3 p, float w, int P, int A) {
  float power = P_(P, 0);
  float coeff = abs(p.z);
  if (coeff != 0.0 && power != 1.0) coeff = exp(log(coeff) * power);
  return w * (gVariationT + p * coeff);
}

// core's simplexNoise3D (flame/noise.cpp) with its tables in flameData at N: the hash (1024
// permutation entries) and then the gradients (1024 unit vectors, three numbers each). Which
// simplex a point lies in is worked out in double, as the CPU does: 3D simplex noise with the
// plugin's falloff radius (0.6) jumps where the simplex changes, and crackle asks for it at half
// and whole numbers, on those very boundaries, where a float's rounding would tip the choice.
float simplexNoise3D(int N, dvec3 v) {
  precise double skew = (v.x + v.y + v.z) * (1.0lf / 3.0lf);
  ivec3 cell = ivec3(floor(v + skew));
  precise double t = double(cell.x + cell.y + cell.z) * (1.0lf / 6.0lf);
  precise dvec3 offset = v - (dvec3(cell) - t);
  ivec3 s1, s2;
  if (offset.x >= offset.y) {
    if (offset.y >= offset.z) {
      s1 = ivec3(1, 0, 0);
      s2 = ivec3(1, 1, 0);
    } else if (offset.x >= offset.z) {
      s1 = ivec3(1, 0, 0);
      s2 = ivec3(1, 0, 1);
    } else {
      s1 = ivec3(0, 0, 1);
      s2 = ivec3(1, 0, 1);
    }
  } else if (offset.y < offset.z) {
    s1 = ivec3(0, 0, 1);
    s2 = ivec3(0, 1, 1);
  } else if (offset.x < offset.z) {
    s1 = ivec3(0, 1, 0);
    s2 = ivec3(0, 1, 1);
  } else {
    s1 = ivec3(0, 1, 0);
    s2 = ivec3(1, 1, 0);
  }
  // The value itself is continuous in the offsets: float from here on.
  const float kUnskew = 1.0 / 6.0;
  vec3 c0 = vec3(offset);
  float total = 0.0;
  for (int c = 0; c < 4; ++c) {
    ivec3 s = c == 0 ? ivec3(0) : c == 1 ? s1 : c == 2 ? s2 : ivec3(1);
    vec3 corner = c0 - vec3(s) + float(c) * kUnskew;
    int h = int(flameData[N + (((cell.z & 1023) + s.z) & 1023)]);
    h = int(flameData[N + (((cell.y & 1023) + s.y + h) & 1023)]);
    int g = N + 1024 + 3 * int(flameData[N + (((cell.x & 1023) + s.x + h) & 1023)]);
    float falloff = 0.6 - dot(corner, corner);
    if (falloff > 0.0) {
      falloff *= falloff;
      total += falloff * falloff * dot(vec3(flameData[g], flameData[g + 1], flameData[g + 2]), corner);
    }
  }
  return 32.0 * total;
}
// Java's (int) floor(v), which saturates (NaN as 0), as a float.
float javaFloorToInt(float v) {
  float f = floor(v);
  return isnan(f) ? 0.0 : clamp(f, -2147483648.0, 2147483647.0);
}
// The centre of crackle's cell (cx, cy), moved by distort · noise (none without distort, which
// spares the noise: it is finite, so 0 · noise is 0 on the CPU too).
// The noise's arguments are the CPU's to the last bit: whole cell numbers, and the slice in double.
// The two noises come from one call in a loop, and so do the cells of V_crackle below, without
// arrays: a compiler unrolls a loop that indexes an array by its counter, and the noise copied into
// every unrolled step made a crackle flame's program take most of a minute to build on llvmpipe.
vec2 crackleCentre(int N, vec2 cell, float halfSize, float distort, double slice) {
  if (distort == 0.0) return cell * halfSize;
  precise dvec2 c = dvec2(cell) * 2.5lf;
  precise double z = slice * 2.5lf;
  // Cross-over of x and y for the second, as in the plugin, so the two noises do not correlate.
  precise dvec3 crossed = dvec3(c.y + 30.2lf, c.x - 12.1lf, z + 19.8lf);
  vec2 noise;
  for (int axis = 0; axis < 2; ++axis) {
    float n = simplexNoise3D(N, axis == 0 ? dvec3(c.x, c.y, z) : crossed);
    if (axis == 0)
      noise.x = n;
    else
      noise.y = n;
  }
  return (cell + distort * noise) * halfSize;
}
// slobo777's crackle as variations_plugins.cpp has it. After its parameters (flame_kernel.cpp puts
// them there): its slice z as a double's two halves, then the noise tables' place in flameData.
// The crackle cell u lies in: its centre (xy), the one nearest u among the 3×3 block around u's
// square (the first of equals, as the CPU takes it), and u's Voronoi distance from it (z), the
// largest ratio over its neighbours (1 on a shared edge); crackle's and dc_crackle_wf's.
vec3 crackleCell(vec2 u, float halfSize, float distort, double slice, int N) {
  vec2 cell = vec2(javaFloorToInt(u.x / halfSize), javaFloorToInt(u.y / halfSize));
  int nearest = 0;
  float nearestD2 = 3.0e38;
  vec2 centre = vec2(0.0);
  for (int k = 0; k < 9; ++k) {
    vec2 at = crackleCentre(N, cell + vec2(k / 3 - 1, k % 3 - 1), halfSize, distort, slice);
    float d2 = dot(at - u, at - u);
    if (d2 < nearestD2) {
      nearestD2 = d2;
      nearest = k;
      centre = at;
    }
  }
  cell += vec2(nearest / 3 - 1, nearest % 3 - 1);  // re-centred: the nearest's cell has neighbours all round
  float distance = -3.0e38;
  for (int k = 0; k < 9; ++k) {
    if (k == 4) continue;
    vec2 q = crackleCentre(N, cell + vec2(k / 3 - 1, k % 3 - 1), halfSize, distort, slice) - centre;
    float ratio = q == vec2(0.0) ? 1.0 : 2.0 * dot(u - centre, q) / dot(q, q);
    distance = max(distance, ratio);
  }
  return vec3(centre, distance);
}
vec3 V_crackle(vec3 p, float w, int P, int A) {
  float cellsize = P_(P, 0), power = P_(P, 1), distort = P_(P, 2), scale = P_(P, 3);
  double slice = packDouble2x32(uvec2(floatBitsToUint(P_(P, 5)), floatBitsToUint(P_(P, 6))));
  int N = int(P_(P, 7));
  vec3 o = vec3(0.0, 0.0, w * p.z);
  if (cellsize == 0.0) return o;  // the plugin's guard: no cells, nothing drawn
  float halfSize = cellsize / 2.0;
  float a = psi(), b = psi(), c = psi();
  float blurred = (a + b) / 2.0 + (c - 0.5) / 4.0;
  float theta = kTwoPi * psi();
  vec2 u = blurred * vec2(sin(theta), cos(theta));
  vec3 cell = crackleCell(u, halfSize, distort, slice, N);
  vec2 centre = cell.xy;
  float distance = cell.z;
  // The CPU's 1e-100 guard is 0 in float; 1e-30 keeps 0/0 away as it does.
  float pull = pow(distance + 1e-30, power) * scale / (distance + 1e-30);
  o.xy = w * ((u - centre) * pull + centre);
  return o;
}

// ---- more plugins (variations_plugins.cpp, variations_fractorium.cpp, ...) -----------------------

vec3 V_julian3Dx(vec3 p, float w, int P, int A) {
  float power = countParam(P_(P, 1)), absn = abs(power), cn = (P_(P, 0) / power - 1.0) / 2.0;
  float a = P_(P, 2), b = P_(P, 3), c = P_(P, 4), d = P_(P, 5), e = P_(P, 6), f = P_(P, 7);
  float zz = p.z / absn;
  float r2 = p.x * p.x + p.y * p.y;
  float radius = w * pow(r2 + zz * zz, cn);
  float px = a * p.x + b * p.y + e, py = c * p.x + d * p.y + f;
  float root = trunc(psi() * absn);
  float alpha = (atan2c(py, px) + kTwoPi * root) / power;
  float gamma = radius * sqrt(r2);
  return vec3(gamma * cos(alpha), gamma * sin(alpha), radius * zz);
}
// Adds to z alone (the catalogue's mapsXY is false for it).
vec3 V_inflateZ_3(vec3 p, float w, int P, int A) {
  float angle = atan2c(p.y, p.x);
  return vec3(0.0, 0.0, w * 0.2 * (kPi - angle) * cos(3.0 * angle + (p.y - p.x)));
}
vec3 V_bi_linear(vec3 p, float w, int P, int A) { return w * vec3(p.y, p.x, p.z); }
// JWildfire's complex helpers: 1/|q|² with |q|² < 1e-100 taken as 1 (below float's range: 0 there).
float guardedInverseNorm(float re, float im) {
  float m2 = re * re + im * im;
  return m2 == 0.0 ? 1.0 : 1.0 / m2;
}
vec3 V_acoth(vec3 p, float w, int P, int A) {
  float inv = guardedInverseNorm(p.x, p.y);
  float re = p.x * inv, im = -p.y * inv;
  float nre = re + 1.0, nim = im, dre = -(re - 1.0), dim = -im;
  float dinv = guardedInverseNorm(dre, dim);
  float qre = (nim * dim + nre * dre) * dinv, qim = (nim * dre - nre * dim) * dinv;
  float logRe = 0.5 * log(qre * qre + qim * qim + 1e-20), logIm = atan2c(qim, qre);
  float s = w * 2.0 / kPi * 0.5;
  return vec3(s * logIm, s * logRe, w * p.z);
}
vec3 V_acosh(vec3 p, float w, int P, int A) {
  float dr = p.x * p.x - p.y * p.y - 1.0, di = 2.0 * p.x * p.y;
  float radius = length(vec2(dr, di));
  float sr = sqrt(max(0.0, 0.5 * (radius + dr))), si = (di < 0.0 ? -1.0 : 1.0) * sqrt(max(0.0, 0.5 * (radius - dr)));
  float ar = p.x + sr, ai = p.y + si;
  float re = 0.5 * log(ar * ar + ai * ai + 1e-20), im = atan2c(ai, ar);
  float s = psi() < 0.5 ? w * 2.0 / kPi : -w * 2.0 / kPi;
  return vec3(s * re, s * im, w * p.z);
}
// All three numbers drawn at every point, as on the CPU.
vec3 V_glynnSim1(vec3 p, float w, int P, int A) {
  float radius = P_(P, 0), radius1 = P_(P, 1), thickness = P_(P, 3), absPow = abs(P_(P, 4)), contrast = P_(P, 5);
  float phi1 = kPi * P_(P, 2) / 180.0;
  float x1 = radius * cos(phi1), y1 = radius * sin(phi1);
  float pick = psi(), ringU = psi(), ringA = psi();
  float r = sqrt(p.x * p.x + p.y * p.y);
  float alpha = radius / r;
  bool onRing = r < radius;
  vec2 q = p.xy;
  float u = pick, a = ringU;
  if (!onRing) {
    if (pick <= contrast * pow(alpha, absPow)) q = alpha * alpha * p.xy;
    onRing = (q.x - x1) * (q.x - x1) + (q.y - y1) * (q.y - y1) < radius1 * radius1;
    u = ringU;
    a = ringA;
  }
  if (onRing) {
    float ring = radius1 * (thickness + (1.0 - thickness) * u);
    q = vec2(ring * cos(kTwoPi * a) + x1, ring * sin(kTwoPi * a) + y1);
  }
  return w * vec3(q, p.z);
}
vec3 V_hypertile3D1(vec3 p, float w, int P, int A) {
  float pp = fractoriumZeps(P_(P, 0)), q = fractoriumZeps(P_(P, 1));
  float pa = kTwoPi / pp, qa = kTwoPi / q;
  float t = -(cos(pa) - 1.0) / (cos(pa) + cos(qa));
  float r = t > 0.0 ? 1.0 / sqrt(1.0 + t) : 1.0;
  float r2c = r * r, sz = 1.0 - r2c;
  float turn = tilingTurn(psi(), pp);
  float cx = r * cos(turn), cy = r * sin(turn);
  float sx = 1.0 + cx * cx - cy * cy, sy = 1.0 + cy * cy - cx * cx;
  float r2 = dot(p, p);
  float tx = 2.0 * cx * p.x, ty = 2.0 * cy * p.y;
  float d = w / fractoriumZeps(r2c * r2 + tx - ty + 1.0);
  return d * vec3(p.x * sx - cx * (ty - r2 - 1.0), p.y * sy + cy * (-tx - r2 - 1.0), p.z * sz);
}
vec3 V_hypertile3D2(vec3 p, float w, int P, int A) {
  float pp = fractoriumZeps(P_(P, 0)), q = fractoriumZeps(P_(P, 1));
  float pa = kTwoPi / pp, qa = kTwoPi / q;
  float t = -(cos(pa) - 1.0) / (cos(pa) + cos(qa));
  float cx = t > 0.0 ? 1.0 / sqrt(1.0 + t) : 1.0;
  float c2 = cx * cx, sx = 1.0 + c2, sy = 1.0 - c2;
  float r2 = dot(p, p);
  float mx = p.x * sx - cx * (-r2 - 1.0), my = p.y * sy;
  float vr = w / (c2 * r2 + 2.0 * cx * p.x + 1.0);
  float turn = tilingTurn(psi(), pp);
  float s = sin(turn), co = cos(turn);
  return vec3(vr * (mx * co + my * s), vr * (my * co - mx * s), vr * p.z * sy);
}
vec3 V_cropn(vec3 p, float w, int P, int A) {
  float power = P_(P, 0), radius = P_(P, 1), scatter = P_(P, 2);
  bool zero = P_(P, 3) == 0.0;
  float alpha = kTwoPi / max(2.0, abs(power)), half_ = alpha / 2.0;
  float u = psi();
  float r2 = p.x * p.x + p.y * p.y;
  float around = fmodc(atan2c(p.y, p.x) + kPi, alpha);
  float c = cos(around < half_ ? around : alpha - around);
  float reach = c > 0.0 ? radius / c : 1.0;
  float s = w;
  if ((r2 > reach * reach) == (power > 0.0)) {
    float r = sqrt(r2);
    s = zero ? 0.0 : (reach + u * scatter) * w / (r == 0.0 ? kFractoriumEps : r);
  }
  return vec3(s * p.x, s * p.y, w * p.z);
}
// slobo777's plugins' Voronoi distance of u from centres[q]: the largest ratio over the others.
float voronoiDistance7(vec2 centres[7], vec2 u) {
  float distance = -3.0e38;
  for (int k = 1; k < 7; ++k) {
    vec2 q = centres[k] - centres[0];
    float ratio = q == vec2(0.0) ? 1.0 : 2.0 * dot(u - centres[0], q) / dot(q, q);
    distance = max(distance, ratio);
  }
  return distance;
}
vec2 hexCentre(float hx, float hy, float s) {
  return vec2(1.5 * hx - 1.5 * hy, 1.7320508075688772 / 2.0 * (hx + hy)) * s;
}
vec3 V_hexes(vec3 p, float w, int P, int A) {
  float s = P_(P, 0), power = P_(P, 1), scale = P_(P, 3);
  float rotSin = sin(P_(P, 2) * kTwoPi), rotCos = cos(P_(P, 2) * kTwoPi);
  const float kRoot3 = 1.7320508075688772;
  vec3 o = vec3(0.0, 0.0, w * p.z);
  if (s == 0.0) return o;  // the plugin's guard
  vec2 u = p.xy;
  float hx = javaFloorToInt((u.x / 3.0 + kRoot3 / 3.0 * u.y) / s);
  float hy = javaFloorToInt((-u.x / 3.0 + kRoot3 / 3.0 * u.y) / s);
  int nearest = 0;
  float nearestD2 = 3.0e38;
  for (int k = 0; k < 9; ++k) {
    vec2 d = hexCentre(hx + float(k / 3 - 1), hy + float(k % 3 - 1), s) - u;
    if (dot(d, d) < nearestD2) {
      nearestD2 = dot(d, d);
      nearest = k;
    }
  }
  hx += float(nearest / 3 - 1);
  hy += float(nearest % 3 - 1);
  // The chosen hexagon first, then its six neighbours.
  const vec2 around[7] = vec2[](vec2(0, 0), vec2(0, 1), vec2(1, 1), vec2(1, 0), vec2(0, -1), vec2(-1, -1), vec2(-1, 0));
  vec2 centres[7];
  for (int k = 0; k < 7; ++k) centres[k] = hexCentre(hx + around[k].x, hy + around[k].y, s);
  float l1 = voronoiDistance7(centres, u);
  vec2 d = u - centres[0];
  float target = pow(l1 + 1e-30, power) * scale;
  vec2 v = vec2(d.x * rotCos + d.y * rotSin, -d.x * rotSin + d.y * rotCos);
  float l2 = voronoiDistance7(centres, v + centres[0]);
  float l = max(l1, l2);
  float r = l < 0.5 ? target / l1 : l > 0.8 ? target / l2 : ((target / l1) * (0.8 - l) + (target / l2) * (l - 0.5)) / 0.3;
  o.xy = w * (v * r + centres[0]);
  return o;
}
vec3 V_octagon(vec3 p, float w, int P, int A) {
  vec3 off = vec3(P_(P, 0), P_(P, 1), P_(P, 2));
  vec3 q2 = p * p;
  float r = w / (q2.x * q2.x + q2.z + q2.y * q2.y + q2.z + 1e-8);
  vec3 o = (r < 2.0 ? r : w) * p;
  float rootZ = sqrt(max(p.z, 0.0));
  float t = w / (abs(p.x) + rootZ + abs(p.y) + rootZ + 1e-8);
  o += (r >= 0.0 ? t : w) * p;
  o += w * vec3(p.x >= 0.0 ? p.x + off.x : p.x - off.x, p.y >= 0.0 ? p.y + off.y : p.y - off.y,
                p.z >= 0.0 ? p.z + off.z : p.z - off.z);
  return o;
}
vec3 V_bcircle(vec3 p, float w, int P, int A) {
  float scale = P_(P, 0), border = abs(P_(P, 1));
  float u = psi();
  vec2 s = p.xy * scale;
  float r = length(s);
  vec2 q = vec2(0.0);
  if (r <= 1.0) {
    q = s;
  } else if (border != 0.0) {
    float a = atan2c(s.y, s.x), radius = 0.2 * border * u + 1.0;
    q = radius * vec2(cos(a), sin(a));
  }
  return w * vec3(q, p.z);
}
vec3 V_waves23(vec3 p, float w, int P, int A) {
  float scaleX = P_(P, 0), scaleY = P_(P, 1), freqX = P_(P, 2), freqY = P_(P, 3);
  float mx = p.y * freqX / kTwoPi, my = p.x * freqY / kTwoPi;
  float fx = mx - floor(mx), fy = my - floor(my);
  if (fx > 0.5) fx = 0.5 - fx;
  if (fy > 0.5) fy = 0.5 - fy;
  return w * vec3(p.x + fx * scaleX, p.y + fy * scaleY, p.z);
}
vec3 V_wdisc(vec3 p, float w, int P, int A) {
  float a = kPi / (sqrt(p.x * p.x + p.y * p.y) + 1.0);
  float r = atan2c(p.y, p.x) / kPi;
  if (r > 0.0) a = kPi - a;
  return vec3(w * r * cos(a), w * r * sin(a), w * p.z);
}
vec3 V_waves4_wf(vec3 p, float w, int P, int A) {
  float scaleX = P_(P, 0), scaleY = P_(P, 1), freqX = P_(P, 2), freqY = P_(P, 3);
  bool cosX = sign(P_(P, 4)) * floor(abs(P_(P, 4)) + 0.5) == 1.0;
  bool cosY = sign(P_(P, 5)) * floor(abs(P_(P, 5)) + 0.5) == 1.0;
  float dampX = abs(P_(P, 6)) < 1e-8 ? 1.0 : exp(P_(P, 6));
  float dampY = abs(P_(P, 7)) < 1e-8 ? 1.0 : exp(P_(P, 7));
  float sx = sin(p.y * freqX), cx = cos(p.y * freqX);
  float sy = sin(p.x * freqY), cy = cos(p.x * freqY);
  float waveX = cosX ? cx * sx * cx : sx * cx * sx, waveY = cosY ? cy * sy * cy : sy * cy * sy;
  return vec3(w * (p.x + dampX * scaleX * waveX) * dampX, w * (p.y + dampY * scaleY * waveY) * dampY, w * p.z);
}
vec3 V_rblur(vec3 p, float w, int P, int A) {
  float s2 = 2.0 * P_(P, 0), offset = P_(P, 1), cx = P_(P, 2), cy = P_(P, 3);
  float r = length(vec2(p.x - cx, p.y - cy)) - offset;
  r = (r < 0.0 ? 0.0 : r) * s2;
  float a = psi(), b = psi();
  return w * vec3(p.x + (a - 0.5) * r, p.y + (b - 0.5) * r, p.z);
}
// Maps z alone (the catalogue's mapsXY is false for it).
vec3 V_zscale_wf(vec3 p, float w, int P, int A) { return vec3(0.0, 0.0, w * p.z + P_(P, 0)); }
vec3 V_lazyTravis(vec3 p, float w, int P, int A) {
  float spinIn = 4.0 * P_(P, 0), spinOut = 4.0 * P_(P, 1), space = P_(P, 2);
  float ax = abs(p.x), ay = abs(p.y);
  bool outside = ax > w || ay > w;
  float spin = outside ? spinOut : spinIn;
  float s, q;
  if (ax > ay) {
    s = ax;
    q = p.x > 0.0 ? s + p.y + s * spin : 5.0 * s - p.y + s * spin;
  } else {
    s = ay;
    q = p.y > 0.0 ? 3.0 * s - p.x + s * spin : 7.0 * s + p.x + s * spin;
  }
  q = fmodc(q, s * 8.0);
  float px, py;
  if (outside) {
    if (q <= 2.0 * s) {
      px = s + space;
      py = -(s - q);
      py = py + py / s * space;
    } else if (q <= 4.0 * s) {
      py = s + space;
      px = 3.0 * s - q;
      px = px + px / s * space;
    } else if (q <= 6.0 * s) {
      px = -(s + space);
      py = 5.0 * s - q;
      py = py + py / s * space;
    } else {
      py = -(s + space);
      px = -(7.0 * s - q);
      px = px + px / s * space;
    }
  } else if (q <= 2.0 * s) {
    px = s;
    py = -(s - q);
  } else if (q <= 4.0 * s) {
    px = 3.0 * s - q;
    py = s;
  } else if (q <= 6.0 * s) {
    px = -s;
    py = 5.0 * s - q;
  } else {
    px = -(7.0 * s - q);
    py = -s;
  }
  return vec3(w * px, w * py, w * p.z);
}

// ---- points from a table the CPU's kernel builds (VariationInfo::table) ----------------------------

// A table's point picked by Ψ₁, moved by the blur (e^{radius √(−ln(1 − Ψ₂))} − 1)/1000 along 2πΨ₃ when
// radius > 0.01 (core's pickBlurredPixel); `count` points follow the N parameters at P.
vec2 pickBlurredPoint(int P, int N, int count, float radius) {
  vec2 q = tablePoint(P, N, tableIndex(psi(), count));
  if (radius > 0.01) {
    float dr = (exp(radius * sqrt(-log(1.0 - psi()))) - 1.0) * 0.001;
    float da = psi() * kTwoPi;
    q += dr * vec2(cos(da), sin(da));
  }
  return q;
}
// svg_wf and text_wf: a painted pixel (scaled and moved, the weight not applied), or (Ψ₁, Ψ₂) without
// two of them.
vec3 pixelOrDraws(vec3 p, float w, int P, int N, float radius, vec4 scaleOffset, float scale) {
  int count = tableSize(P, N) / 2;
  if (count > 1) {
    vec2 q = pickBlurredPoint(P, N, count, radius);
    return vec3((q * scaleOffset.xy + scaleOffset.zw) * scale, w * p.z);
  }
  float a = psi();
  float b = psi();
  return vec3(a, b, w * p.z);
}
vec3 V_svg_wf(vec3 p, float w, int P, int A) {
  return pixelOrDraws(p, w, P, 8, P_(P, 0), vec4(P_(P, 4), P_(P, 5), P_(P, 6), P_(P, 7)), 1.0);
}
vec3 V_text_wf(vec3 p, float w, int P, int A) {
  return pixelOrDraws(p, w, P, 7, P_(P, 1), vec4(P_(P, 2), P_(P, 3), P_(P, 4), P_(P, 5)), 3.0);
}
// hopalong: w · a point of the orbit's first 2²⁰ (Ψ picks it), z carried.
vec3 V_hopalong(vec3 p, float w, int P, int A) {
  int count = tableSize(P, 6) / 2;
  return vec3(w * tablePoint(P, 6, tableIndex(psi(), count)), w * p.z);
}
// obj_mesh_primitive_wf: w (a P₁ + b P₂ + c P₃) on a face of the mesh (Ψ₁ picks it, by the cumulative
// weights where the table has them), a = 1 − √Ψ₂, b = √Ψ₂ (1 − Ψ₃), c = √Ψ₂ Ψ₃; nothing, and no draw,
// for a mesh without faces. The table: faces, weighted, picks, [cumulative], 9 numbers a face.
vec3 V_obj_mesh_primitive_wf(vec3 p, float w, int P, int A) {
  int at = tableAt(P, 15);
  int faces = int(flameData[at]);
  if (faces == 0) return vec3(0.0);
  bool weighted = flameData[at + 1] != 0.0;
  double picks = double(flameData[at + 2]);
  double pick = min(floor(double(psi()) * picks), picks - 1.0lf);
  int face = int(pick);
  int corners = at + 3;
  if (weighted) {
    // The first face whose cumulative weight exceeds the pick (std::upper_bound).
    int low = 0, high = faces;
    while (low < high) {
      int middle = (low + high) / 2;
      if (double(flameData[at + 3 + middle]) > pick)
        high = middle;
      else
        low = middle + 1;
    }
    face = low;
    corners += faces;
  }
  float r1 = sqrt(psi()), r2 = psi();
  vec3 bary = vec3(1.0 - r1, r1 * (1.0 - r2), r2 * r1);
  int f = corners + 9 * face;
  vec3 sum = vec3(0.0);
  for (int corner = 0; corner < 3; ++corner) {
    int c = f + 3 * corner;
    sum += bary[corner] * vec3(flameData[c], flameData[c + 1], flameData[c + 2]);
  }
  return w * sum;
}
