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
