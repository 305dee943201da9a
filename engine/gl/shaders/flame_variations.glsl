// Flame variations for the GPU backend's chaos game (flame_kernel.h generates the code that calls
// them, per genome). Each is the CPU catalogue's kernel of the same name (core/flame/variations_*.cpp,
// which stays the reference; variations.h has the notation) in float: V_<name>(p, w, P, A) returns
// w · V(p), with the term's parameters at flameData[P...] and its transform's pre-affine (row-major
// 3×4) at flameData[A...]. A 2D variation carries w · z into z, as on the CPU. Ψ draws from the
// orbit's own chaos stream (psi), in the CPU kernel's order.

layout(std430, binding = 8) readonly buffer FlameData { float flameData[]; };
layout(std430, binding = 9) readonly buffer FlamePick { uint flamePick[]; };

uint gChaosRandom;  // the orbit's chaos stream (xorshift32, never 0), as core::laneUniform draws it

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

float P_(int base, int i) { return flameData[base + i]; }
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
