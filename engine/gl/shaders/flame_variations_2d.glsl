// Flame variations for the GPU backend (flame_variations.glsl has the conventions and the helpers):
// the CPU catalogue's variations_2d_a.cpp, variations_2d_b.cpp and variations_2d_c.cpp
// (engine/core/flame/), in float.

// ---- Fractorium's parameter rules and shared helpers (variations_2d_shared.h) -----------------

float v2d_cyclic(float v, float lo, float hi) {  // REAL_CYCLIC
  if (v > hi) return lo + fmodc(v - lo, hi - lo);
  if (v < lo) return hi - fmodc(hi - v, hi - lo);
  return v;
}
float v2d_nonzero(float v) {  // REAL_NONZERO: within 1e-6 of 0 becomes ±ε
  return v > -1e-6 && v < 1e-6 ? (v < 0.0 ? -kFractoriumEps : kFractoriumEps) : v;
}
float v2d_safeSqrt(float v) { return v <= 0.0 ? 0.0 : sqrt(v); }
bool v2d_odd(float whole) { return fmodc(whole, 2.0) != 0.0; }


// Complex numbers as vec2 (principal branches, as std::complex).
vec2 v2d_cmul(vec2 a, vec2 b) { return vec2(a.x * b.x - a.y * b.y, a.x * b.y + a.y * b.x); }
vec2 v2d_cdiv(vec2 a, vec2 b) {
  float s = max(abs(b.x), abs(b.y));  // scaled, so |b|² stays in float's range
  vec2 bs = b / s;
  return vec2(a.x * bs.x + a.y * bs.y, a.y * bs.x - a.x * bs.y) / (s * dot(bs, bs));
}
vec2 v2d_csqrt(vec2 z) {
  if (z.x == 0.0 && z.y == 0.0) return vec2(0.0);
  float r = length(z);
  if (z.x >= 0.0) {
    float t = sqrt(0.5 * (r + z.x));
    return vec2(t, z.y / (2.0 * t));
  }
  float t = sqrt(0.5 * (r - z.x));
  return vec2(abs(z.y) / (2.0 * t), z.y < 0.0 ? -t : t);
}
vec2 v2d_clog(vec2 z) { return vec2(log(length(z)), atan2c(z.y, z.x)); }

// ---- inverse hyperbolic functions (variations_2d_a.cpp) --------------------------------------

vec2 v2d_arcsech(vec2 z) {
  vec2 q = v2d_cdiv(vec2(1.0, 0.0), z);
  return v2d_clog(q + v2d_cmul(v2d_csqrt(q + vec2(1.0, 0.0)), v2d_csqrt(q - vec2(1.0, 0.0))));
}
vec3 V_arcsech(vec3 p, float w, int P, int A) { return vec3(w / kPi * v2d_arcsech(p.xy), w * p.z); }
// The ±1 outside the weight, as on the CPU.
vec3 V_arcsech2(vec3 p, float w, int P, int A) {
  vec2 r = 2.0 * w / kPi * v2d_arcsech(p.xy);
  return r.y < 0.0 ? vec3(r.x, r.y + 1.0, w * p.z) : vec3(-r.x, r.y - 1.0, w * p.z);
}
vec3 V_arcsinh(vec3 p, float w, int P, int A) {
  vec2 q = p.xy;
  vec2 r = v2d_clog(q + v2d_csqrt(v2d_cmul(q, q) + vec2(1.0, 0.0)));
  return vec3(2.0 * w / kPi * r, w * p.z);
}
vec3 V_arctanh(vec3 p, float w, int P, int A) {
  vec2 q = p.xy;
  vec2 r = v2d_clog(v2d_cdiv(q + vec2(1.0, 0.0), vec2(1.0, 0.0) - q));
  return vec3(w / kPi * r, w * p.z);
}

// ---- barycentric and bipolar coordinates -------------------------------------------------------

vec3 V_barycentroid(vec3 p, float w, int P, int A) {
  float a = P_(P, 0), b = P_(P, 1), c = P_(P, 2), d = P_(P, 3);
  float dot00 = a * a + b * b, dot01 = a * c + b * d, dot11 = c * c + d * d;
  float invDenom = 1.0 / fractoriumZeps(dot00 * dot11 - dot01 * dot01);
  float dot02 = a * p.x + b * p.y, dot12 = c * p.x + d * p.y;
  float u = (dot11 * dot02 - dot01 * dot12) * invDenom;
  float v = (dot00 * dot12 - dot01 * dot02) * invDenom;
  return vec3(w * sqrt(u * u + p.x * p.x) * sign(u), w * sqrt(v * v + p.y * p.y) * sign(v), w * p.z);
}
float v2d_bipolarTau(float x, float y) {
  float y2 = y * y;
  return 0.5 * (log((x + 1.0) * (x + 1.0) + y2) - log((x - 1.0) * (x - 1.0) + y2));
}
float v2d_bipolarSigma(float x, float y) { return kPi - atan2c(y, x + 1.0) - atan2c(y, 1.0 - x); }
vec2 v2d_fromBipolar(float tau, float sigma, float w) {
  float t = fractoriumZeps(cosh(tau) - cos(sigma));
  return vec2(w * sinh(tau) / t, w * sin(sigma) / t);
}
vec3 V_bCollide(vec3 p, float w, int P, int A) {
  float a = v2d_cyclic(P_(P, 0), -1.0, 1.0), num = clamp(P_(P, 1), kFractoriumEps, 2147483647.0);
  float cnPi = num / kPi, piCn = kPi / fractoriumZeps(num), caCn = kPi * a / fractoriumZeps(num);
  float tau = v2d_bipolarTau(p.x, p.y), sigma = v2d_bipolarSigma(p.x, p.y);
  float alt = trunc(sigma * cnPi);
  sigma = alt * piCn + fmodc(v2d_odd(alt) ? sigma - caCn : sigma + caCn, piCn);
  return vec3(v2d_fromBipolar(tau, sigma, w), w * p.z);
}
vec3 V_bMod(vec3 p, float w, int P, int A) {
  float radius = max(P_(P, 0), 0.0), dist_ = v2d_cyclic(P_(P, 1), 0.0, 2.0);
  float tau = v2d_bipolarTau(p.x, p.y), sigma = v2d_bipolarSigma(p.x, p.y);
  if (tau < radius && -tau < radius) tau = fmodc(tau + radius + dist_ * radius, 2.0 * radius) - radius;
  return vec3(v2d_fromBipolar(tau, sigma, w), w * p.z);
}
vec3 V_bSwirl(vec3 p, float w, int P, int A) {
  float tau = v2d_bipolarTau(p.x, p.y);
  float sigma = v2d_bipolarSigma(p.x, p.y) + tau * P_(P, 1) + P_(P, 0) / fractoriumZeps(tau);
  return vec3(v2d_fromBipolar(tau, sigma, w), w * p.z);
}
vec3 V_bisplit(vec3 p, float w, int P, int A) {
  float v = 0.1 * w;
  return vec3(v / tan(p.x) * cos(p.y), v / sin(p.x) * -p.y, w * p.z);
}
vec3 V_blob2(vec3 p, float w, int P, int A) {
  float mode = P_(P, 0), waves = P_(P, 1), radius = P_(P, 2), prescale = P_(P, 3), postscale = P_(P, 4);
  float symmetry = clamp(P_(P, 5), -1.0, 1.0), compensation = P_(P, 6);
  float deltaHelp = 1.0 + compensation * symmetry * (symmetry < 0.0 ? -1.0 : 1.0);
  float r = sqrt(p.x * p.x + p.y * p.y);
  if (r < radius) return w * p;
  float delta = (sin(atan2c(p.y, p.x) * waves) + symmetry) / deltaHelp;
  float positive = delta < 0.0 ? -1.0 : 1.0;
  delta = exp(prescale * log(delta * positive)) * postscale * (mode != 0.0 ? mode : positive);
  float rad = radius + (r - radius) * delta, rz = fractoriumZeps(r);
  return vec3(w * rad * p.x / rz, w * rad * p.y / rz, w * p.z);
}

// ---- blocks ------------------------------------------------------------------------------------

float v2d_blockAngle(float v, float r2) {
  float t = r2 + 1.0, v2 = 2.0 * v;
  float vmax = 0.5 * (v2d_safeSqrt(t + v2) + v2d_safeSqrt(t - v2));
  float a = v / fractoriumZeps(vmax);
  return atan2c(a, v2d_safeSqrt((1.0 - a) * (1.0 + a)));
}
vec3 V_block(vec3 p, float w, int P, int A) {
  float r2 = p.x * p.x + p.y * p.y;
  return vec3(w * (2.0 / kPi) * v2d_blockAngle(p.x, r2), w * (2.0 / kPi) * v2d_blockAngle(p.y, r2), w * p.z);
}
// The weight enters twice, as on the CPU.
vec3 V_blocky(vec3 p, float w, int P, int A) {
  float mp = v2d_nonzero(P_(P, 2));
  float vx = w / (kPi / 2.0) * P_(P, 0), vy = w / (kPi / 2.0) * P_(P, 1);
  float r = w / fractoriumZeps((cos(p.x) + cos(p.y)) / mp + 1.0);
  float r2 = p.x * p.x + p.y * p.y;
  return vec3(vx * v2d_blockAngle(p.x, r2) * r, vy * v2d_blockAngle(p.y, r2) * r, w * p.z);
}

// ---- circles -----------------------------------------------------------------------------------

vec3 V_cardioid(vec3 p, float w, int P, int A) {
  float r2 = p.x * p.x + p.y * p.y, rz = fractoriumZeps(sqrt(r2));
  float r = w * sqrt(r2 + sin(atan2c(p.y, p.x) * P_(P, 0)) + 1.0);
  return vec3(r * p.x / rz, r * p.y / rz, w * p.z);
}
vec3 V_circlecrop2(vec3 p, float w, int P, int A) {
  float inner = min(P_(P, 0), P_(P, 1)), outer = max(P_(P, 0), P_(P, 1));
  bool zero = clamp(P_(P, 2), 0.0, 1.0) != 0.0;
  float r = sqrt(p.x * p.x + p.y * p.y);
  vec2 o = vec2(0.0);
  if (r > outer || r < inner) {
    if (!zero) {
      float a = atan2c(p.y, p.x);
      o = vec2(sin(a), cos(a)) * outer * w;
    }
  } else {
    o = p.xy * w;
  }
  return vec3(o, w * p.z);
}
vec3 V_circlesplit(vec3 p, float w, int P, int A) {
  float radius = P_(P, 0), split = P_(P, 1);
  float r = sqrt(p.x * p.x + p.y * p.y);
  vec2 q = p.xy;
  if (!(r < radius - split)) {
    float a = atan2c(p.y, p.x), len = r + split;
    q = vec2(cos(a), sin(a)) * len;
  }
  return vec3(w * q, w * p.z);
}
// The angle along the square of half-side max(|x|, |y|) (returned in side).
float v2d_circlizeAngle(float px, float py, out float side) {
  float ax = abs(px), ay = abs(py), perimeter;
  if (ax >= ay) {
    perimeter = px >= ay ? ax + py : 5.0 * ax - py;
    side = ax;
  } else {
    perimeter = py >= ax ? 3.0 * ay - px : 7.0 * ay + px;
    side = ay;
  }
  return kPi / 4.0 * perimeter / side - kPi / 4.0;
}
vec3 V_circlize(vec3 p, float w, int P, int A) {
  float side;
  float a = v2d_circlizeAngle(p.x, p.y, side);
  float r = w / (kPi / 4.0) * side + P_(P, 0);
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_circlize2(vec3 p, float w, int P, int A) {
  float side;
  float a = v2d_circlizeAngle(p.x, p.y, side);
  float r = w * (side + P_(P, 0));
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_circus(vec3 p, float w, int P, int A) {
  float scale = P_(P, 0), inv = 1.0 / P_(P, 0);
  float r0 = sqrt(p.x * p.x + p.y * p.y), rz = fractoriumZeps(r0);
  float r = r0 <= 1.0 ? r0 * scale : r0 * inv;
  return vec3(w * r * p.x / rz, w * r * p.y / rz, w * p.z);
}
vec3 V_collideoscope(vec3 p, float w, int P, int A) {
  float num = fractoriumZeps(P_(P, 1));
  float knPi = num / kPi, piKn = kPi / num, kaKn = kPi * P_(P, 0) / num;
  float a = atan2c(p.y, p.x);
  float r = w * sqrt(p.x * p.x + p.y * p.y);
  if (a >= 0.0) {
    float alt = trunc(a * knPi);
    a = alt * piKn + fmodc(v2d_odd(alt) ? a - kaKn : a + kaKn, piKn);
  } else {
    float alt = trunc(-a * knPi);
    a = -(alt * piKn + fmodc(v2d_odd(alt) ? -kaKn - a : kaKn - a, piKn));
  }
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
float v2d_coswrap(float v, float phase, float blend, float repeat) {
  float u = 0.5 * v + 0.5;
  float b = fmodc(repeat * u, 1.0);
  float mid = u + (0.5 - cos(u * 4.0 + phase) * 0.5 - u) * blend;
  return mid + (0.5 - cos(b * 4.0 + phase) * 0.5 - mid) * blend;
}
// The −1 outside the weight, as on the CPU.
vec3 V_coswrap(vec3 p, float w, int P, int A) {
  float repeatRaw = fractoriumInteger(P_(P, 0), -2147483647.0, 2147483647.0);
  float repeat = abs(repeatRaw == 0.0 ? (P_(P, 0) < 0.0 ? -1.0 : 1.0) : repeatRaw);
  float px = kPi * v2d_cyclic(P_(P, 3), -1.0, 1.0), py = kPi * v2d_cyclic(P_(P, 4), -1.0, 1.0);
  float blendX = 0.5 - cos(P_(P, 1) + px) * 0.5, blendY = 0.5 - cos(P_(P, 2) + py) * 0.5;
  return vec3(-1.0 + 2.0 * w * v2d_coswrap(p.x, px, blendX, repeat),
              -1.0 + 2.0 * w * v2d_coswrap(p.y, py, blendY, repeat), w * p.z);
}
vec3 V_crescents(vec3 p, float w, int P, int A) {
  float s = sin(p.x), c = cos(p.x), k = w * (cosh(p.y) + 1.0) * s * s;
  return vec3(k * s, k * c, w * p.z);
}
// The weight is left off φ, as on the CPU.
vec3 V_curvature(vec3 p, float w, int P, int A) {
  return vec3(w / fractoriumZeps(sqrt(p.x * p.x + p.y * p.y)), atan2c(p.y, p.x), w * p.z);
}
vec3 V_cylinder2(vec3 p, float w, int P, int A) {
  return vec3(w * (p.x / fractoriumZeps(sqrt(p.x * p.x + 1.0))), w * p.y, w * p.z);
}
vec3 V_deltaa(vec3 p, float w, int P, int A) {
  float y2 = p.y * p.y;
  float r = w * (sqrt(y2 + (p.x + 1.0) * (p.x + 1.0)) / sqrt(y2 + (p.x - 1.0) * (p.x - 1.0)));
  float a = (atan2c(p.y, p.x - 1.0) - atan2c(p.y, p.x + 1.0)) / 2.0;
  return vec3(r * cos(a), r * sin(a), w * p.z);
}

// ---- cells, eclipse (variations_2d_b.cpp) -------------------------------------------------------

// The cells' coordinates and hashes in double, as on the CPU (the hashes need the very arguments).
vec3 V_dust(vec3 p, float w, int P, int A) {
  double density = double(fractoriumZeps(v2d_nonzero(P_(P, 0))));
  float distortion = P_(P, 1), power = P_(P, 2);
  double fx = floor(double(abs(p.x))), fy = floor(double(abs(p.y)));
  double cx = (fx - density * trunc(fx / density)) / density, cy = (fy - density * trunc(fy / density)) / density;
  float a = (float(cx) + hashShadertoy(cx, cy, 1.0lf) * distortion) * kTwoPi;
  float r = exp(log(float(cy) + hashShadertoy(cy, cx, 2.0lf) * distortion) * power);
  return vec3(w * cos(a) * r, w * sin(a) * r, w * p.z);
}
vec3 V_eclipse(vec3 p, float w, int P, int A) {
  float shift = v2d_cyclic(P_(P, 0), -2.0, 2.0);
  float px = w * p.x;
  if (abs(p.y) <= w) {
    float c2 = sqrt(w * w - p.y * p.y);
    if (abs(p.x) <= c2) {
      float moved = p.x + shift * w;
      px = abs(moved) >= c2 ? -(w * p.x) : w * moved;
    }
  }
  return vec3(px, w * p.y, w * p.z);
}

// ---- elliptic coordinates ----------------------------------------------------------------------

// log(1 + u) without losing u's digits next to 1.
float v2d_log1p(float u) {
  float v = 1.0 + u;
  return v == 1.0 ? u : log(v) * u / (v - 1.0);
}
// The elliptic coordinates of p, worked out where float would cancel: X = (d₊ + d₋)/2 (at least 1),
// S = √(X² − 1), μ = acosh X, ν = acos(x/X) ∈ [0, π] (unsigned). X² − 1 and X² − x² are formed
// without the differences of near-equal numbers that the CPU's double absorbs.
struct v2d_Elliptic {
  float xmax, s, mu, nu;
};
v2d_Elliptic v2d_elliptic(float x, float y) {
  float dp = sqrt((x + 1.0) * (x + 1.0) + y * y), dm = sqrt((x - 1.0) * (x - 1.0) + y * y);
  float r2 = x * x + y * y, pm = dp * dm, q = 1.0 - x * x + y * y;
  v2d_Elliptic e;
  e.xmax = 0.5 * (dp + dm);
  float xm1 = r2 >= 1.0 ? 0.5 * (r2 - 1.0 + pm) : 2.0 * y * y / (pm + 1.0 - r2);  // X² − 1
  float xmx = q >= 0.0 ? 0.5 * (q + pm) : 2.0 * x * x * y * y / (pm - q);          // X² − x²
  if (!(e.xmax >= 1.0)) {
    e.xmax = 1.0;
    xm1 = 0.0;
    xmx = 1.0 - x * x;
  }
  e.s = sqrt(max(xm1, 0.0));
  e.mu = v2d_log1p(xm1 / (e.xmax + 1.0) + e.s);
  e.nu = atan2c(sqrt(max(xmx, 0.0)), x);
  return e;
}
vec3 V_eCollide(vec3 p, float w, int P, int A) {
  float a = v2d_cyclic(P_(P, 0), 0.0, 1.0), num = fractoriumInteger(P_(P, 1), 1.0, 2147483647.0);
  float cnPi = num / kPi, piCn = kPi / num, caCn = kPi * a / num;
  v2d_Elliptic e = v2d_elliptic(p.x, p.y);
  float alt = trunc(e.nu * cnPi);
  float nu = alt * piCn + fmodc(v2d_odd(alt) ? e.nu - caCn : e.nu + caCn, piCn);
  if (!(p.y > 0.0)) nu = -nu;
  return vec3(w * e.xmax * cos(nu), w * e.s * sin(nu), w * p.z);
}
vec3 V_eMod(vec3 p, float w, int P, int A) {
  float radius = max(P_(P, 0), 0.0), dist_ = v2d_cyclic(P_(P, 1), 0.0, 2.0);
  v2d_Elliptic e = v2d_elliptic(p.x, p.y);
  float mu = e.mu, nu = p.y < 0.0 ? -e.nu : e.nu;
  if (mu < radius && -mu < radius)
    mu = nu > 0.0 ? fmodc(mu + radius + dist_ * radius, 2.0 * radius) - radius
                  : fmodc(mu - radius - dist_ * radius, 2.0 * radius) + radius;
  return vec3(w * cosh(mu) * cos(nu), w * sinh(mu) * sin(nu), w * p.z);
}
vec3 V_ePush(vec3 p, float w, int P, int A) {
  float push = P_(P, 0), dist = P_(P, 1), rotate = v2d_cyclic(P_(P, 2), -kPi, kPi);
  v2d_Elliptic e = v2d_elliptic(p.x, p.y);
  float mu = e.mu * dist + push, nu = (p.y < 0.0 ? -e.nu : e.nu) + rotate;
  return vec3(w * cosh(mu) * cos(nu), w * sinh(mu) * sin(nu), w * p.z);
}
vec3 V_eRotate(vec3 p, float w, int P, int A) {
  float rotate = v2d_cyclic(P_(P, 0), -kPi, kPi);
  v2d_Elliptic e = v2d_elliptic(p.x, p.y);
  float nu = fmodc((p.y < 0.0 ? -e.nu : e.nu) + rotate + kPi, kTwoPi) - kPi;
  return vec3(w * e.xmax * cos(nu), w * e.s * sin(nu), w * p.z);
}
vec3 V_eScale(vec3 p, float w, int P, int A) {
  float scale = v2d_nonzero(clamp(P_(P, 0), 0.0, 1.0)), angle = v2d_cyclic(P_(P, 1), 0.0, kTwoPi);
  v2d_Elliptic e = v2d_elliptic(p.x, p.y);
  float mu = e.mu * scale, nu = p.y < 0.0 ? -e.nu : e.nu;
  nu = fmodc(fmodc(scale * (nu + kPi + angle), kTwoPi * scale) - angle - scale * kPi, kTwoPi);
  if (nu > kPi) nu -= kTwoPi;
  if (nu < -kPi) nu += kTwoPi;
  return vec3(w * cosh(mu) * cos(nu), w * sinh(mu) * sin(nu), w * p.z);
}
vec3 V_eSwirl(vec3 p, float w, int P, int A) {
  float inner = P_(P, 0), outer = P_(P, 1);
  v2d_Elliptic e = v2d_elliptic(p.x, p.y);
  float mu = e.mu;
  float nu = (p.y < 0.0 ? -e.nu : e.nu) + mu * outer + (inner == 0.0 ? 0.0 : inner / mu);
  return vec3(w * cosh(mu) * cos(nu), w * sinh(mu) * sin(nu), w * p.z);
}

// ---- polynomials, exponentials and functions of r --------------------------------------------

// Only the first two terms weighted, as on the CPU.
vec3 V_ennepers(vec3 p, float w, int P, int A) {
  float x2 = p.x * p.x, y2 = p.y * p.y;
  return vec3(w * (p.x - x2 * p.x / 3.0) + p.x * y2, w * (p.y - y2 * p.y / 3.0) + p.y * x2, w * p.z);
}
// erf by Abramowitz & Stegun 7.1.26 (error below 1.5e-7; GLSL has none).
float v2d_erf(float v) {
  float x = abs(v), t = 1.0 / (1.0 + 0.3275911 * x);
  float poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  float e = 1.0 - poly * exp(-x * x);
  return v < 0.0 ? -e : e;
}
vec3 V_erf(vec3 p, float w, int P, int A) { return w * vec3(v2d_erf(p.x), v2d_erf(p.y), p.z); }
// The weight only inside f, as on the CPU.
vec3 V_excinis(vec3 p, float w, int P, int A) {
  float lengthScalar = P_(P, 0), radiusFunc = clamp(P_(P, 1), 0.0, 5.0), eps = P_(P, 2);
  float rPrior = sqrt(p.x * p.x + p.y * p.y) * lengthScalar;
  float rEps = abs(rPrior) > eps ? 0.0 : (rPrior >= 0.0 ? 1.0 : -1.0) * eps;
  float r = w / fractoriumZeps(rPrior + rEps);
  float f = r;
  if (radiusFunc < 1.0)
    f = r;
  else if (radiusFunc < 2.0)
    f = cos(r);
  else if (radiusFunc < 3.0)
    f = exp(r);
  else if (radiusFunc < 4.0)
    f = log(abs(r) + abs(rEps));
  else
    f = 1.0 / fractoriumZeps(r + rEps);
  return vec3((p.x - p.y) * (p.x + p.y) * f, 2.0 * p.x * p.y * f, w * p.z);
}
vec3 V_exp2(vec3 p, float w, int P, int A) {
  float e = w * exp(p.x * kPi);
  return vec3(e * cos(p.y * kPi), e * sin(p.y * kPi), w * p.z);
}
vec3 V_expo(vec3 p, float w, int P, int A) {
  float re = P_(P, 0), im = P_(P, 1);
  float k = 0.5 * log(fractoriumZeps(re * re + im * im)), t = atan2c(im, re);
  float e = w * exp(p.x * k - p.y * t), a = p.x * t + p.y * k;
  return vec3(e * cos(a), e * sin(a), w * p.z);
}
vec3 V_fdisc(vec3 p, float w, int P, int A) {
  float a = kTwoPi / (sqrt(p.x * p.x + p.y * p.y) + 1.0);
  float r = (atan2c(p.y, p.x) / kPi + 1.0) * 0.5;
  return vec3(w * r * cos(a), w * r * sin(a), w * p.z);
}
vec2 v2d_fibonacci(float x, float y, float w, float sc, float sc2) {
  const float lnPhi = 0.48121182505960344, invRoot5 = 0.4472135954999579;
  float a1 = y * lnPhi, a2 = -(x * kPi + y * lnPhi);
  float e1 = sc * exp(sc2 * (x * lnPhi)), e2 = sc * exp(sc2 * -(x * lnPhi - y * kPi));
  return vec2(w * (e1 * cos(a1) - e2 * cos(a2)) * invRoot5, w * (e1 * sin(a1) - e2 * sin(a2)) * invRoot5);
}
vec3 V_fibonacci(vec3 p, float w, int P, int A) { return vec3(v2d_fibonacci(p.x, p.y, w, 1.0, 1.0), w * p.z); }
vec3 V_fibonacci2(vec3 p, float w, int P, int A) {
  return vec3(v2d_fibonacci(p.x, p.y, w, P_(P, 0), P_(P, 1)), w * p.z);
}

// ---- flips and flowers ---------------------------------------------------------------------------

vec3 V_flipcircle(vec3 p, float w, int P, int A) {
  return vec3(w * p.x, p.x * p.x + p.y * p.y > w * w ? w * p.y : -(w * p.y), w * p.z);
}
vec3 V_flipx(vec3 p, float w, int P, int A) { return vec3(p.y > 0.0 ? -(w * p.x) : w * p.x, w * p.y, w * p.z); }
vec3 V_flipy(vec3 p, float w, int P, int A) { return vec3(w * p.x, p.x > 0.0 ? -(w * p.y) : w * p.y, w * p.z); }
vec3 V_flowerdb(vec3 p, float w, int P, int A) {
  float petals = P_(P, 0), split = petals * P_(P, 1), spread = P_(P, 2);
  float r = w * sqrt(p.x * p.x + p.y * p.y), t = atan2c(p.y, p.x);
  float r2 = r * abs((spread + sin(petals * t)) * cos(split * t));
  return vec3(r2 * cos(t), r2 * sin(t), w * p.z);
}
vec3 V_foci_p(vec3 p, float w, int P, int A) {
  float ex = fractoriumZeps(exp(p.x));
  float e1 = ex * P_(P, 0), e2 = P_(P, 1) / ex;
  float r = w / fractoriumZeps(e1 + e2 - cos(p.y));
  return vec3((e1 - e2) * r, sin(p.y) * r, w * p.z);
}
vec3 V_funnel(vec3 p, float w, int P, int A) {
  float effect = fractoriumInteger(P_(P, 0), -2147483647.0, 2147483647.0) * kPi;
  float t = 1.0 / fractoriumZeps(cos(p.y)) + effect;
  return vec3(w * (tanh(p.x) * t), w * (tanh(p.y) * t), w * p.z);
}
// ln Γ(v) for v ≥ 0 (GLSL has none): moved up to 7 or more, then Stirling's series.
float v2d_lgamma(float v) {
  float prod = 1.0;
  for (int k = 0; k < 8 && v < 7.0; ++k) {
    prod *= v;
    v += 1.0;
  }
  float zi = 1.0 / v, zi2 = zi * zi;
  float s = (v - 0.5) * log(v) - v + 0.91893853320467274 + zi * (1.0 / 12.0 - zi2 * (1.0 / 360.0 - zi2 / 1260.0));
  return s - log(abs(prod));
}
vec3 V_gamma(vec3 p, float w, int P, int A) {
  return vec3(w * v2d_lgamma(sqrt(p.x * p.x + p.y * p.y)), w * atan2c(p.y, p.x), w * p.z);
}
vec3 V_henon(vec3 p, float w, int P, int A) {
  return vec3((1.0 - P_(P, 0) * p.x * p.x + p.y) * w, P_(P, 1) * p.x * w, w * p.z);
}
// δ outside the weight in the second form, as on the CPU.
vec3 V_hole(vec3 p, float w, int P, int A) {
  float a = P_(P, 0);
  bool inside = fractoriumInteger(P_(P, 1), 0.0, 1.0) != 0.0;
  float r0 = sqrt(p.x * p.x + p.y * p.y), rz = fractoriumZeps(r0);
  float delta = pow(atan2c(p.y, p.x) / kPi + 1.0, a);
  float r = inside ? w * delta / (r0 + delta) : w * r0 + delta;
  return vec3(r * p.x / rz, r * p.y / rz, w * p.z);
}
vec3 V_idisc(vec3 p, float w, int P, int A) {
  float a = kPi / (sqrt(p.x * p.x + p.y * p.y) + 1.0);
  float r = atan2c(p.y, p.x) * w / kPi;
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_inkdrop(vec3 p, float w, int P, int A) {
  float r = max(P_(P, 0), 0.0), cx = P_(P, 1), cy = P_(P, 2);
  float dx = p.x - cx, dy = p.y - cy, d2 = dx * dx + dy * dy;
  float adjust = sqrt(d2 + r * r) - sqrt(d2), bearing = atan2c(dy, dx);
  return vec3(w * (p.x + cos(bearing) * adjust), w * (p.y + sin(bearing) * adjust), w * p.z);
}

// ---- Jacobi's elliptic functions -------------------------------------------------------------------

// which = 0 sn, 1 cn, 2 dn of x + iy by the addition theorems.
vec2 v2d_jacobi(int which, float x, float y, float k, float w) {
  vec3 fx = jacobiSnCnDn(x, k), fy = jacobiSnCnDn(y, 1.0 - k);
  vec2 num;
  if (which == 0)
    num = vec2(fx.x * fy.z, fx.y * fx.z * fy.y * fy.x);
  else if (which == 1)
    num = vec2(fx.y * fy.y, -fx.z * fx.x * fy.z * fy.x);
  else
    num = vec2(fx.z * fy.y * fy.z, -fx.y * fx.x * fy.x * k);
  float denom = w / fractoriumZeps(fx.x * fx.x * fy.x * fy.x * k + fy.y * fy.y);
  return denom * num;
}
vec3 V_jac_sn(vec3 p, float w, int P, int A) {
  return vec3(v2d_jacobi(0, p.x, p.y, clamp(P_(P, 0), -1.0, 1.0), w), w * p.z);
}
vec3 V_jac_cn(vec3 p, float w, int P, int A) {
  return vec3(v2d_jacobi(1, p.x, p.y, clamp(P_(P, 0), -1.0, 1.0), w), w * p.z);
}
vec3 V_jac_dn(vec3 p, float w, int P, int A) {
  return vec3(v2d_jacobi(2, p.x, p.y, clamp(P_(P, 0), -1.0, 1.0), w), w * p.z);
}
// No weight on x and y, as on the CPU.
vec3 V_Kaleidoscope(vec3 p, float w, int P, int A) {
  float pull = P_(P, 0), rotate = P_(P, 1), lineUp = P_(P, 2), shiftX = P_(P, 3), shiftY = P_(P, 4);
  const float s = 0.70710678118654752, c = 0.70710678118654752;
  float ox = rotate * p.x * c - p.y * s + lineUp + shiftX;
  float oy = p.y > 0.0 ? rotate * p.y * c + p.x * s + pull + lineUp + shiftY
                       : rotate * p.y * c + p.x * s - pull - lineUp;
  return vec3(ox, oy, w * p.z);
}

// ---- random ones -------------------------------------------------------------------------------------

vec3 V_tanh_spiral(vec3 p, float w, int P, int A) {
  float a = P_(P, 0);
  float t = (psi() - 0.5) * kTwoPi;
  float aux = fractoriumZeps(cos(a * t) + cosh(t));
  return vec3(w * (sinh(t) / aux), w * (sin(a * t) / aux), w * p.z);
}
vec3 V_tile_hlp(vec3 p, float w, int P, int A) {
  float width = v2d_nonzero(P_(P, 0)), shift = width * w;
  float u = psi();
  float v = p.x / width;
  bool positive = v > 0.0;
  float f = positive ? v - trunc(v) : v + trunc(v);
  float move = cos(f * kPi) < 2.0 * u - 1.0 ? (positive ? -shift : shift) : 0.0;
  return vec3(w * p.x + move, w * p.y, w * p.z);
}
vec3 V_tile_log(vec3 p, float w, int P, int A) {
  float spread = P_(P, 0);
  float logU = log(1.0 - psi());
  float s = psi() < 0.5 ? spread : -spread;
  return vec3(w * (p.x + roundHalfAway(logU * s)), w * p.y, w * p.z);
}

// ---- cells and grids (variations_2d_c.cpp) ----------------------------------------------------------

// The cell's centre and its hash in double, as on the CPU.
vec3 V_bwraps_rand(vec3 p, float w, int P, int A) {
  float cell = P_(P, 0), space = P_(P, 1), gain = P_(P, 2), innerTwist = P_(P, 3), outerTwist = P_(P, 4);
  float symm = P_(P, 5);
  double seed = double(P_(P, 6));
  float g2 = gain * gain;
  float halfCell = 0.5 * (cell / (1.0 + space * space));
  vec2 q = p.xy;
  if (cell != 0.0) {
    double dcell = double(cell), invCell = 1.0lf / dcell;
    double cx = (floor(double(p.x) * invCell) + 0.5lf) * dcell, cy = (floor(double(p.y) * invCell) + 0.5lf) * dcell;
    float lx = float(double(p.x) - cx), ly = float(double(p.y) - cy);
    float radius = halfCell * (symm == 0.0 ? hashShadertoy(cx, cy, seed) : hashShadertoy(cx * cx, cy * cy, seed));
    float mb = g2 * radius;
    float maxBubble = mb > 2.0 ? 1.0 : mb / (mb * mb * 0.25 + 1.0);
    float r2 = radius * radius;
    if (!(lx * lx + ly * ly > r2)) {
      float rFactor = radius / fractoriumZeps(maxBubble);
      float lx2 = lx * g2, ly2 = ly * g2;
      float r = rFactor / ((lx2 * lx2 + ly2 * ly2) * 0.25 + 1.0);
      float lx3 = lx2 * r, ly3 = ly2 * r;
      float t = (lx3 * lx3 + ly3 * ly3) / fractoriumZeps(r2);
      float theta = innerTwist * (1.0 - t) + outerTwist * t;
      float c = cos(theta), s = sin(theta);
      q = vec2(float(cx) + c * lx3 + s * ly3, float(cy) - s * lx3 + c * ly3);
    }
  }
  return vec3(q * w, w * p.z);
}
// Java's (int) of a number: truncated, saturating, NaN as 0.
int v2d_javaInt(float v) {
  if (isnan(v)) return 0;
  if (v >= 2147483647.0) return 2147483647;
  if (v <= -2147483648.0) return -2147483647 - 1;
  return int(v);
}
// Hugo Elias' integer noise in [0, 1], the int arithmetic wrapping as on the CPU.
float v2d_noise2(int x, int y) {
  uint k = uint(x + y * 57);
  k = (k << 13) ^ k;
  uint v = k * (k * k * 15731u + 789221u) + 1376312589u;
  return float(v & 0x7fffffffu) * (1.0 / 2147483647.0);
}
// X and Y read but not used, as on the CPU.
vec3 V_CircleLinear(vec3 p, float w, int P, int A) {
  float sc = v2d_nonzero(P_(P, 0)), k = P_(P, 1), dens1 = P_(P, 2), dens2 = P_(P, 3), reverse = P_(P, 4);
  float seed = fractoriumInteger(P_(P, 7), -2147483647.0, 2147483647.0);
  int m = v2d_javaInt(floor(0.5 * p.x / sc)), n = v2d_javaInt(floor(0.5 * p.y / sc));
  float m21 = 2.0 * float(m) + 1.0, n21 = 2.0 * float(n) + 1.0;
  vec2 q = vec2(p.x - m21 * sc, p.y - n21 * sc);
  float u = fractoriumZeps(length(q));
  float v = (0.3 + 0.7 * v2d_noise2(m + 10, n + 3)) * sc;
  float z1 = v2d_noise2(v2d_javaInt(float(m) + seed), n);
  if (z1 < dens1 && u < v) {
    bool plain = reverse > 0.0 ? z1 < dens1 * dens2 : z1 > dens1 * dens2;
    q *= plain ? k : v / u * (1.0 - k) + k;
  }
  return vec3(w * (q.x + m21 * sc), w * (q.y + n21 * sc), w * p.z);
}
// foci_p's map with the result fuzzed by fuzzyMode and blended in by fuzzyInterpolationMode.
vec3 V_dragonfire(vec3 p, float w, int P, int A) {
  float c1 = P_(P, 0), c2 = P_(P, 1), mode = clamp(P_(P, 2), 0.0, 7.0), radius = P_(P, 3);
  float blendMode = clamp(P_(P, 4), 0.0, 6.0), position = P_(P, 5), logScalar = P_(P, 6), scalar = P_(P, 7);
  float val = position;
  if (!(blendMode < 2.0)) {
    float a = position * kPi;
    float trig = blendMode < 3.0 ? cos(a) : blendMode < 4.0 ? tan(a) : blendMode < 5.0 ? sinh(a) : asinh(a);
    val = (1.0 - trig) * scalar;
  }
  float ex = exp(p.x) * c1, enx = c2 / fractoriumZeps(ex);
  float r = w / fractoriumZeps(ex + enx - cos(p.y));
  vec2 f = vec2((ex - enx) * r, sin(p.y) * r), q = f;
  if (!(mode < 1.0)) {
    vec2 fuzz = vec2(cos(logScalar / fractoriumZeps(log(abs(f.x)))), cos(logScalar / fractoriumZeps(log(abs(f.y)))));
    vec2 dir = vec2(fuzz.x < 0.0 ? -radius : radius, fuzz.y < 0.0 ? -radius : radius);
    vec2 nf;
    if (mode < 2.0)
      nf = f + fuzz;
    else if (mode < 3.0)
      nf = f * sin(fuzz);
    else if (mode < 4.0)
      nf = f * exp(sin(fuzz));
    else if (mode < 5.0)
      nf = f + dir;
    else if (mode < 6.0)
      nf = f + exp(dir);
    else
      nf = f + vec2(exp(sin(dir.x)), exp(cos(dir.y)));
    q = blendMode < 1.0 ? nf : f * (1.0 - val) + nf * val;
  }
  return vec3(q, w * p.z);
}
vec3 V_fourth(vec3 p, float w, int P, int A) {
  float spin = v2d_cyclic(P_(P, 0), 0.0, kTwoPi), space = P_(P, 1), twist = P_(P, 2), cx = P_(P, 3), cy = P_(P, 4);
  float w2 = w * w, r2 = p.x * p.x + p.y * p.y;
  vec2 q = w * p.xy;
  if (p.x > 0.0 && p.y > 0.0) {
    float r = sqrt(r2), k = w / r / fractoriumZeps(r);
    q = k * p.xy;
  } else if (p.x > 0.0 && p.y < 0.0) {
    if (r2 < w2) q = w * sqrt(w2 / r2 - 1.0) * p.xy;
  } else if (p.x < 0.0 && p.y > 0.0) {
    float sx = p.x - cx, sy = p.y + cy;
    float r = sqrt(sx * sx + sy * sy);
    if (r < w) {
      float a = atan2c(sy, sx) + spin + twist * (w - r);
      r *= w;
      q = vec2(r * cos(a) + cx, r * sin(a) - cy);
    } else {
      r = w * (1.0 + space / fractoriumZeps(r));
      q = vec2(r * sx + cx, r * sy - cy);
    }
  }
  return vec3(q, w * p.z);
}
float v2d_gdoffsClip(float a) { return a < 0.0 ? -fmodc(abs(a), 1.0) : fmodc(abs(a), 1.0); }
float v2d_gdoffsOsc(float p, float a) { return v2d_gdoffsClip((-cos(p * a * kTwoPi) + 1.0) / 2.0); }
float v2d_gdoffsFlip(float a, float b, float c) { return c * (b - a) + a; }
float v2d_gdoffs(float v, float b, float osc) {
  float mid = v2d_gdoffsFlip(v, v2d_gdoffsOsc(v, 4.0), osc);
  return v2d_gdoffsFlip(mid, v2d_gdoffsOsc(v2d_gdoffsClip(b * v), 4.0), osc);
}
vec3 V_gdoffs(vec3 p, float w, int P, int A) {
  float dx = clamp(P_(P, 0), 0.0, 16.0) * 0.1, dy = clamp(P_(P, 1), 0.0, 16.0) * 0.1;
  float ax = (abs(P_(P, 2)) < 0.1 ? 0.1 : abs(P_(P, 2))) * 2.0;
  float ay = (abs(P_(P, 3)) < 0.1 ? 0.1 : abs(P_(P, 3))) * 2.0;
  float cx = P_(P, 4), cy = P_(P, 5), gamma = fractoriumInteger(P_(P, 6), 1.0, 6.0);
  bool square = fractoriumInteger(P_(P, 7), 0.0, 1.0) != 0.0;
  float b = gamma * 2.0 / max(ax, ay);
  float oscX = v2d_gdoffsOsc(dx, 1.0), oscY = square ? oscX : v2d_gdoffsOsc(dy, 1.0);
  return vec3(w * v2d_gdoffs(p.x + cx, b, oscX), w * v2d_gdoffs(p.y + cy, b, oscY), w * p.z);
}
vec3 V_gnarly(vec3 p, float w, int P, int A) {
  float cell = P_(P, 0), twist = P_(P, 1);
  float r2 = fractoriumZeps(0.25 * cell * cell);
  vec2 q = p.xy;
  if (cell != 0.0) {
    vec2 c = (floor(q / cell) + 0.5) * cell;
    vec2 l = q - c;
    float d2 = dot(l, l);
    if (d2 <= r2) {
      float theta = twist * log(d2 / r2);
      float s = sin(theta), co = cos(theta);
      q = vec2(c.x + co * l.x + s * l.y, c.y - s * l.x + co * l.y);
    }
  }
  return vec3(w * q, w * p.z);
}
vec3 V_gridout(vec3 p, float w, int P, int A) {
  float rx = trunc(p.x >= 0.0 ? p.x + 0.5 : p.x - 0.5), ry = trunc(p.y >= 0.0 ? p.y + 0.5 : p.y - 0.5);
  vec2 q = p.xy;
  if (ry <= 0.0) {
    if (rx > 0.0) {
      if (-ry >= rx)
        q.x += 1.0;
      else
        q.y += 1.0;
    } else {
      if (ry <= rx)
        q.x += 1.0;
      else
        q.y -= 1.0;
    }
  } else {
    if (rx > 0.0) {
      if (ry >= rx)
        q.x -= 1.0;
      else
        q.y += 1.0;
    } else {
      if (ry > -rx)
        q.x -= 1.0;
      else
        q.y -= 1.0;
    }
  }
  return vec3(w * q, w * p.z);
}
vec3 V_hex_modulus(vec3 p, float w, int P, int A) {
  const float root3 = 1.7320508075688772, halfRoot3 = 0.8660254037844386;
  float hsize = halfRoot3 / fractoriumZeps(P_(P, 0)), scale = w / halfRoot3;
  float px = p.x * hsize, py = p.y * hsize, third = py / 3.0;
  float cx = root3 / 3.0 * px - third, cz = 2.0 * third, cy = -cx - cz;
  float rx = roundHalfAway(cx), ry = roundHalfAway(cy), rz = roundHalfAway(cz);
  float dx = abs(rx - cx), dy = abs(ry - cy), dz = abs(rz - cz);
  if (dx > dy && dx > dz)
    rx = -ry - rz;
  else if (dy > dz)
    ry = -rx - rz;
  else
    rz = -rx - ry;
  return vec3((px - (root3 * rx + halfRoot3 * rz)) * scale, (py - 1.5 * rz) * scale, w * p.z);
}
float v2d_interferenceWave(float type, float a, float b, float c, float p, float v) {
  if (type == 1.0) return a * 2.0 * pow(abs(asin(cos(b * v + c - kPi / 2.0))) / kPi, p);
  if (type == 2.0) return a * pow(sin(b * v + c) < 0.0 ? kFractoriumEps : 1.0, p);
  return a * pow(abs(sin(b * v + c)), p);
}
vec3 V_interference2(vec3 p, float w, int P, int A) {
  float a1 = P_(P, 0), b1 = P_(P, 1), c1 = P_(P, 2), p1 = P_(P, 3), t1 = fractoriumInteger(P_(P, 4), 0.0, 2.0);
  float a2 = P_(P, 5), b2 = P_(P, 6), c2 = P_(P, 7), p2 = P_(P, 8), t2 = fractoriumInteger(P_(P, 9), 0.0, 2.0);
  return vec3(w * (v2d_interferenceWave(t1, a1, b1, c1, p1, p.x) + v2d_interferenceWave(t2, a2, b2, c2, p2, p.x)),
              w * (v2d_interferenceWave(t1, a1, b1, c1, p1, p.y) + v2d_interferenceWave(t2, a2, b2, c2, p2, p.y)),
              w * p.z);
}

// ---- random ones ---------------------------------------------------------------------------------

// Fractorium's Rand(n): ⌊Ψ·n⌋, or ⌊Ψ·2³²⌋ for n = 0; the product in double, so that no rounding
// reaches the next whole number.
float v2d_whole(float upper) { return float(floor(double(psi()) * double(upper == 0.0 ? 4294967296.0 : upper))); }
// All three numbers drawn at every point, as on the CPU.
vec3 V_vignette(vec3 p, float w, int P, int A) {
  float posX = P_(P, 0), posY = P_(P, 1), innerRadius = P_(P, 2), fadeRadius = v2d_nonzero(P_(P, 3));
  float power = v2d_nonzero(P_(P, 4)), blur = P_(P, 5);
  float inner = abs(innerRadius), fade = abs(fadeRadius), powerHelper = 1.0 / abs(power);
  float u1 = psi(), u2 = psi(), u3 = psi();
  vec2 q = p.xy;
  float dist = length(q - vec2(posX, posY));
  if (dist < inner) {
    if (innerRadius < 0.0) q = vec2(0.0);
  } else {
    dist = (dist - inner) / fade;
    float kept = 1.0 - pow(u1, powerHelper);
    float du = dist * u2;
    float blurR = blur * du * du, blurA = u3 * kTwoPi;
    bool dropped = fadeRadius > 0.0 ? kept < dist : 1.0 - kept > dist;
    q = dropped ? vec2(0.0) : q + blurR * vec2(cos(blurA), sin(blurA));
  }
  return vec3(q * w, w * p.z);
}
// The draws left to right, as on the CPU.
vec3 V_waffle(vec3 p, float w, int P, int A) {
  float slices = v2d_nonzero(P_(P, 0)), xt = P_(P, 1), yt = P_(P, 2);
  float whole = trunc(min(abs(slices), 4294967296.0));
  float sinR = w * sin(P_(P, 3)), cosR = w * cos(P_(P, 3));
  float pick = v2d_whole(5.0);
  float a, r;
  if (pick == 0.0) {
    float a0 = v2d_whole(whole), a1 = psi();
    float r0 = v2d_whole(whole), r1 = psi();
    a = (a0 + a1 * xt) / slices;
    r = (r0 + r1 * yt) / slices;
  } else if (pick == 1.0) {
    float a0 = v2d_whole(whole), a1 = psi();
    float r0 = v2d_whole(whole);
    a = (a0 + a1) / slices;
    r = (r0 + yt) / slices;
  } else if (pick == 2.0) {
    float a0 = v2d_whole(whole);
    float r0 = v2d_whole(whole), r1 = psi();
    a = (a0 + xt) / slices;
    r = (r0 + r1) / slices;
  } else if (pick == 3.0) {
    a = psi();
    float r0 = v2d_whole(whole), r1 = psi();
    r = (r0 + yt + r1 * (1.0 - yt)) / slices;
  } else {
    float a0 = v2d_whole(whole), a1 = psi();
    a = (a0 + xt + a1 * (1.0 - xt)) / slices;
    r = psi();
  }
  return vec3(cosR * a + sinR * r, -sinR * a + cosR * r, w * p.z);
}
// The weight enters twice, as on the CPU; power 0 is taken as 2.
vec3 V_wavesn(vec3 p, float w, int P, int A) {
  float freqX = P_(P, 0), freqY = P_(P, 1), scaleX = P_(P, 2), scaleY = P_(P, 3), incX = P_(P, 4), incY = P_(P, 5);
  float power = P_(P, 6) == 0.0 ? 2.0 : P_(P, 6);
  float absN = trunc(min(abs(power), 4294967296.0)), cn = 1.0 / power / 2.0;
  float angle = (atan2c(p.y, p.x) + kTwoPi * v2d_whole(absN)) / power;
  float r = w * pow(p.x * p.x + p.y * p.y, cn);
  float xn = r * cos(angle), yn = r * sin(angle);
  float sinY = sin(freqX * yn), sinX = sin(freqY * xn);
  return vec3(w * (xn + 0.5 * (scaleX * sinY + abs(xn) * incX * sinY)),
              w * (yn + 0.5 * (scaleY * sinX + abs(yn) * incY * sinX)), w * p.z);
}

// ---- variations_jwildfire_corpus.cpp (dc_booleans), variations_jwildfire_holdout.cpp (dc_quadtree, dc_ducks,
// dc_inversion), variations_jwildfire_glsl.cpp (glsl_apollonian): JWildfire's true-colour painters. Their
// patterns iterate folds, logarithms or inversions many times, so they run in double, with trig and
// logarithms of their own (GLSL has none in double) and `precise` against fused multiply-adds.

double rgb_nan() { return packDouble2x32(uvec2(0u, 0x7ff80000u)); }
// The natural logarithm in double: v = 2^e m, m in [√½, √2), ln m = 2 atanh((m − 1)/(m + 1)) by its series.
double rgb_dlog(double v) {
  if (isnan(v) || v < 0.0lf) return rgb_nan();
  if (v == 0.0lf) return -packDouble2x32(uvec2(0u, 0x7ff00000u));
  if (isinf(v)) return v;
  int e;
  double m = frexp(v, e);
  if (m < 0.70710678118654752lf) {
    m *= 2.0lf;
    e -= 1;
  }
  precise double s = (m - 1.0lf) / (m + 1.0lf);
  precise double s2 = s * s;
  precise double series = 1.0lf / 21.0lf;
  for (int k = 9; k >= 0; --k) series = series * s2 + 1.0lf / double(2 * k + 1);
  precise double r = double(e) * 0.69314718055994531lf + 2.0lf * s * series;
  return r;
}
// atan in double: float's atan refined by two Newton steps on sin y − v cos y.
double rgb_datan(double v) {
  double y = double(atan(float(v)));
  for (int k = 0; k < 2; ++k) {
    double s = dsin(y), c = dcos(y);
    y -= (s - v * c) / (c + v * s);
  }
  return y;
}
// Java's (int) of a double: truncated, saturated, NaN 0 (core's javaInt).
int rgb_javaInt(double v) {
  if (isnan(v)) return 0;
  if (v >= 2147483647.0lf) return 2147483647;
  if (v <= -2147483648.0lf) return -2147483647 - 1;
  return int(v);
}
// The colour channel's byte: ⌊256 c⌋ clamped into 0–255 (core's rgbByte).
double rgb_byte(double c) { return clamp(double(rgb_javaInt(floor(c * 256.0lf))), 0.0lf, 255.0lf); }
// The palette's entry nearest to (r, g, b), the first of equals (core's nearestPaletteEntry).
int rgb_nearest(int at, int r, int g, int b) {
  int best = 0, bestDistance = 0;
  for (int k = 0; k < 256; ++k) {
    uint e = variationPalette(at, k);
    int dr = int(e & 255u) - r, dg = int(e >> 8 & 255u) - g, db = int(e >> 16 & 255u) - b;
    int d = dr * dr + dg * dg + db * db;
    if (k == 0 || d < bestDistance) {
      bestDistance = d;
      best = k;
    }
  }
  return best;
}
// Paints the bytes (Gradient 0) or the palette's entry nearest to them (Gradient 1).
void rgb_paint(int at, bool matched, dvec3 bytes) {
  uint r = uint(bytes.x), g = uint(bytes.y), b = uint(bytes.z);
  gRgb = matched ? kRgbPainted | variationPalette(at, rgb_nearest(at, int(r), int(g), int(b)))
                 : kRgbPainted | r | g << 8 | b << 16;
}

// java.util.Random's 48-bit state as three 16-bit limbs held in doubles, whose products stay exact.
dvec3 rgb_javaStep(dvec3 s) {
  const double kLimb = 65536.0lf;
  double r0 = s.x * 58989.0lf + 11.0lf;  // multiplier 0x5DEECE66D: limbs 0xE66D, 0xDEEC, 0x5; increment 0xB
  double c0 = floor(r0 / kLimb);
  double r1 = s.x * 57068.0lf + s.y * 58989.0lf + c0;
  double c1 = floor(r1 / kLimb);
  double r2 = s.x * 5.0lf + s.y * 57068.0lf + s.z * 58989.0lf + c1;
  return dvec3(r0 - c0 * kLimb, r1 - c1 * kLimb, r2 - floor(r2 / kLimb) * kLimb);
}
double rgb_javaNextDouble(inout dvec3 s) {
  s = rgb_javaStep(s);
  double high = floor((s.z * 4294967296.0lf + s.y * 65536.0lf + s.x) / 4194304.0lf);  // 26 bits
  s = rgb_javaStep(s);
  double low = floor((s.z * 4294967296.0lf + s.y * 65536.0lf + s.x) / 2097152.0lf);  // 27 bits
  return (high * 134217728.0lf + low) * (1.0lf / 9007199254740992.0lf);
}
// dc_booleans' integer parameters: NaN taken as 0, clamped and truncated.
float rgb_booleansInt(float v, float lo, float hi) { return trunc(clamp(isnan(v) ? 0.0 : v, lo, hi)); }
vec3 V_dc_booleans(vec3 p, float w, int P, int A) {
  int seed = rgb_javaInt(double(P_(P, 0)));
  uint bits = uint(seed);
  dvec3 s = dvec3(double((bits & 0xffffu) ^ 0xe66du), double((bits >> 16) ^ 0xdeecu),
                  double((seed < 0 ? 0xffffu : 0u) ^ 5u));
  double offsetX = double(seed) * rgb_javaNextDouble(s);
  double offsetY = double(seed) * rgb_javaNextDouble(s);
  int type = int(rgb_booleansInt(P_(P, 1), 0.0, 2.0));
  double zoom = double(P_(P, 2));
  bool colourOnly = rgb_booleansInt(P_(P, 3), 0.0, 1.0) == 1.0;
  int gradient = int(rgb_booleansInt(P_(P, 4), 0.0, 2.0));
  bool resets = rgb_booleansInt(P_(P, 7), 0.0, 1.0) == 1.0 && gStage == 1;
  vec2 u = p.xy;
  if (!colourOnly) {
    u.x = psi() - 0.5;
    u.y = psi() - 0.5;
  }
  // t = ⌊u⌋ op ⌊v⌋, the colour hsv(sin t, 1, cos t) in bytes, its luminance by JWildfire's truncated shares.
  int a = rgb_javaInt(double(u.x) * zoom + offsetX), b = rgb_javaInt(double(u.y) * zoom + offsetY);
  double t = double(type == 0 ? (a ^ b) : type == 1 ? (a & b) : (a | b));
  double hue = dsin(t), value = dcos(t);
  const double kOffsets[3] = double[3](1.0lf, 2.0lf / 3.0lf, 1.0lf / 3.0lf);
  const double kShares[3] = double[3](0.299lf, 0.587lf, 0.114lf);
  double bytes[3];
  int luminance = 0;
  for (int c = 0; c < 3; ++c) {
    double channel = value * clamp(abs(fract(hue + kOffsets[c]) * 6.0lf - 3.0lf) - 1.0lf, 0.0lf, 1.0lf);
    bytes[c] = clamp(floor(channel * 256.0lf), 0.0lf, 255.0lf);
    luminance += int(bytes[c] * kShares[c]);
  }
  double level = double(luminance) / 255.0lf;
  if (gradient == 2) gColour = float(level);
  else rgb_paint(int(P_(P, 9)), gradient == 1, dvec3(bytes[0], bytes[1], bytes[2]));
  float dz = float(level * double(P_(P, 5)) + double(P_(P, 6)));
  return vec3(gSum.x + w * u.x, gSum.y + w * u.y, (resets ? 0.0 : gSum.z) + dz);
}

// JWildfire's DC_BaseFunc (dc_quadtree, dc_ducks, dc_inversion): integer parameters NaN taken as lo.
float rgb_limitedInt(float v, float lo, float hi) { return isnan(v) ? lo : trunc(clamp(v, lo, hi)); }
// The point the pattern is read at: uniform in the square of half-width `halfWidth`, or with ColorOnly
// (parameter k) the point itself.
dvec2 rgb_dcPoint(vec3 p, int P, int k, double halfWidth) {
  if (rgb_limitedInt(P_(P, k), 0.0, 1.0) == 1.0) return dvec2(p.xy);
  double u = halfWidth * (2.0lf * double(psi()) - 1.0lf);
  double v = halfWidth * (2.0lf * double(psi()) - 1.0lf);
  return dvec2(u, v);
}
// The common tail: the colour (grey level as the index with Gradient 2, else painted), the point and z.
// P[k …]: ColorOnly, Gradient, scale_z, offset_z, reset_z; N the parameter count.
vec3 rgb_dcFinish(vec3 p, float w, int P, int k, int N, dvec2 q, dvec3 colour) {
  dvec3 bytes = dvec3(rgb_byte(colour.x), rgb_byte(colour.y), rgb_byte(colour.z));
  double level = (trunc(bytes.x * 0.299lf) + trunc(bytes.y * 0.587lf) + trunc(bytes.z * 0.114lf)) / 255.0lf;
  float gradient = rgb_limitedInt(P_(P, k + 1), 0.0, 2.0);
  if (gradient == 2.0) gColour = float(level);
  else rgb_paint(int(P_(P, N + 1)), gradient == 1.0, bytes);
  bool reset = rgb_limitedInt(P_(P, k + 4), 0.0, 1.0) == 1.0;
  float dz = float(level * double(P_(P, k + 2)) + double(P_(P, k + 3)));
  return vec3(gSum.x + w * float(q.x), gSum.y + w * float(q.y), reset ? dz : gSum.z + w * p.z + dz);
}

// dc_quadtree: its cells' hashes take the sine of ids up to 4^levels, which needs double.
vec3 V_dc_quadtree(vec3 p, float w, int P, int A) {
  double zoom = isnan(P_(P, 0)) ? 0.1lf : clamp(double(P_(P, 0)), 0.1lf, 50.0lf), time = double(P_(P, 2));
  double width = isnan(P_(P, 3)) ? 100.0lf : clamp(double(P_(P, 3)), 100.0lf, 1000.0lf);
  double levels = double(rgb_limitedInt(P_(P, 4), 1.0, 50.0));
  dvec2 q = rgb_dcPoint(p, P, 5, 0.5lf);
  precise double ux = q.x / zoom + 0.5lf, uy = q.y / zoom + 0.5lf, r = 1.0lf, id = 1.0lf;
  precise dvec3 o = dvec3(0.0lf, 0.0lf, 1.0lf);
  for (double level = 0.0lf; level < levels; level += 1.0lf) {
    if (min(min(ux, 1.0lf - ux), min(uy, 1.0lf - uy)) < 0.3lf * r / width) {
      o -= 1.0lf;
      break;
    }
    precise double hash =
        0.5lf + 0.5lf * dsin(id + time) * dsin(id * 2.17lf - time) * dsin(id * 5.7lf + time);
    if (hash > 0.7lf) break;
    double fx = ux < 0.5lf ? 0.0lf : 1.0lf, fy = uy < 0.5lf ? 0.0lf : 1.0lf;
    id = 4.0lf * id + 2.0lf * fy + fx;
    ux = ux * 2.0lf - fx;
    uy = uy * 2.0lf - fy;
    r *= 2.0lf;
    if (r > width) break;
    o += 0.13lf;
  }
  return rgb_dcFinish(p, w, P, 5, 10, q, o);
}

// JWildfire's G.atan2, the first-order approximation dc_ducks is drawn with.
double rgb_glslAtan2(double y, double x) {
  const double kQuarter = 0.78539816339744831lf, kThreeQuarters = 3.0lf * 0.78539816339744831lf;
  double ay = abs(y);
  precise double angle =
      x >= 0.0lf ? kQuarter - kQuarter * ((x - ay) / (x + ay)) : kThreeQuarters - kQuarter * ((x + ay) / (ay - x));
  return y < 0.0lf ? -angle : angle;
}
double rgb_band(double f) { return floor(0.5lf + f * 1.1lf) / 1.1lf; }
vec3 V_dc_ducks(vec3 p, float w, int P, int A) {
  double t = double(P_(P, 1)) / 65.0lf * 30.0lf, zoom = double(P_(P, 2));
  precise double stepX = 0.1lf * dsin(t / 3.0lf) - 0.1lf, stepY = 5.0lf + 0.1lf * dcos(t / 5.0lf);
  dvec2 q = rgb_dcPoint(p, P, 3, 1.0lf);
  precise double ex = q.x * zoom, ey = q.y * zoom, c = 0.0lf;
  for (int k = 0; k < 50; ++k) {
    double ay = abs(ey);
    precise double nx = rgb_dlog(sqrt(ex * ex + ay * ay)), ny = rgb_glslAtan2(ay, ex) - 6.2lf;
    ex = nx + stepX;
    ey = ny + stepY;
    c += sqrt(ex * ex + ey * ey);
  }
  const double kLn2 = 0.69314718055994531lf;
  precise double d = rgb_dlog(rgb_dlog(c * 0.05lf) / kLn2) / kLn2 * 6.0lf;
  double fr = rgb_band(0.1lf + 0.7lf * dsin(d)), fg = rgb_band(0.1lf + 0.5lf * dsin(d - 0.7lf)),
         fb = rgb_band(0.7lf + 0.7lf * dcos(d - 0.7lf));
  return rgb_dcFinish(p, w, P, 3, 8, q, dvec3(fb, fr, fg));
}

vec3 V_dc_inversion(vec3 p, float w, int P, int A) {
  // Time and the scales in double (after its 10 parameters, the memory slot and the palette's place):
  // the iterated inversions part from the CPU's at a float's rounding of them.
  const int D = P + 12;
  double time = paramDouble(D, 1);
  double iterations = double(rgb_limitedInt(P_(P, 2), 0.0, 100.0));
  // setParameter clamps the scales into [1.1, 3] (a NaN passes).
  double scaleX = isnan(paramDouble(D, 3)) ? paramDouble(D, 3) : clamp(paramDouble(D, 3), 1.1lf, 3.0lf);
  double scaleY = isnan(paramDouble(D, 4)) ? paramDouble(D, 4) : clamp(paramDouble(D, 4), 1.1lf, 3.0lf);
  double offsetX = dsin(time * 0.123lf), offsetY = rgb_datan(time * 0.0567lf);
  double s = 2.1lf + time * 0.025lf;
  precise dvec3 b = dvec3(dsin(s * 1.790lf), dsin(s * 1.345lf), dsin(s * 1.123lf)) * 0.5lf + 0.5lf;
  precise double length = sqrt(b.x * b.x + b.y * b.y + b.z * b.z);
  b /= length;
  dvec2 q = rgb_dcPoint(p, P, 5, 1.0lf);
  precise double vx = q.x, vy = q.y, l = 0.0lf, least = 10000.0lf;
  for (double k = 0.0lf; k < iterations; k += 1.0lf) {
    vx = abs(vx) * scaleX + offsetX;
    vy = vy * scaleY + offsetY;
    precise double dx = vx - 0.5lf, dy = vy - 0.5lf;
    precise double f = 0.9lf * (0.9lf / (dx * dx + dy * dy));
    vx = 0.5lf - dx * f;
    vy = 0.5lf - dy * f;
    vx += dsin(vx * 0.001lf) / dcos(vy * 0.001lf);
    vy += dsin(vx * 0.001lf) * dcos(vy * 0.001lf);
    l = sqrt(vx * vx * vx * vx + vy * vy * vy * vy);
    least = isnan(l) || isnan(least) ? l + least : min(l, least);  // Java's Math.min
  }
  precise double m = 3.0lf * least * (1.0lf - least);
  precise double brightness = l * l * 11.0lf * (m * m * m * m * m + 0.14lf);
  dvec3 colour = dvec3(1.0 - exp(-float(b.x * brightness)), 1.0 - exp(-float(b.y * brightness)),
                       1.0 - exp(-float(b.z * brightness)));
  return rgb_dcFinish(p, w, P, 5, 10, q, colour);
}

// glsl_apollonian's matrices (js.glsl.mat3 by columns) and the matrix times a vector, summed as Java does.
dvec3 rgb_times(dmat3 m, dvec3 v) {
  precise dvec3 r = m[0] * v.x + m[1] * v.y;
  r += m[2] * v.z;
  return r;
}
vec3 V_glsl_apollonian(vec3 p, float w, int P, int A) {
  const double kHeight = 1000000.0lf;
  double width = isnan(P_(P, 0)) ? 100.0lf : trunc(clamp(double(P_(P, 0)), 100.0lf, 10000000.0lf));
  float g = P_(P, 3);
  bool index = !isnan(g) && clamp(roundHalfAway(g), 0.0, 1.0) == 1.0;
  double pi = trunc(double(psi()) * width), pj = trunc(double(psi()) * kHeight);
  vec3 o = vec3(w * float(pi / width - 0.5lf), w * float(pj / kHeight - 0.5lf), w * p.z);
  // The pattern at the pixel's centre: v = f m (2 uv, 0) folded 50 times, then 0.6 sin v + ½.
  double time = isnan(P_(P, 2)) || isinf(P_(P, 2)) ? 0.0lf : double(P_(P, 2));
  double t = 0.05lf * time;
  double sa = dsin(t + 1.0lf), ca = dcos(t + 1.0lf), sb = dsin(t + 2.0lf), cb = dcos(t + 2.0lf);
  double sc = dsin(t + 3.0lf), cc = dcos(t + 3.0lf);
  precise dmat3 m = dmat3(dvec3(cb * cc, -cb * sc, sb),
                          dvec3(sa * sb * cc + ca * sc, -sa * sb * sc + ca * cc, -sa * cb),
                          dvec3(-ca * sb * cc + sa * sc, ca * sb * sc + sa * cc, ca * cb));
  precise dmat3 folded = m * (1.2lf + 0.1lf * dsin(0.1lf * time));
  precise dmat3 zoomed = m * (2.0lf + 0.25lf * dsin(0.3lf * time));
  precise double u = 2.0lf * (pi + 0.5lf) / width - 1.0lf, v = 2.0lf * (pj + 0.5lf) / kHeight - 1.0lf;
  precise dvec3 q = rgb_times(zoomed, dvec3(2.0lf * u, 2.0lf * v, 0.0lf));
  for (int k = 0; k < 50; ++k) {
    precise double d = q.x * q.x + q.y * q.y + q.z * q.z;
    precise dvec3 f = rgb_times(folded, q);
    q = abs(f / d * 0.5lf - 0.5lf) * 2.0lf - 1.0lf;
  }
  vec3 c = sin(vec3(q)) * 0.6 + 0.5;
  if (index) {
    float grey = c.x * c.y;
    if (!isnan(grey)) gColour = grey;
  } else {
    gRgb = kRgbPainted | uint(rgb_byte(double(c.x))) | uint(rgb_byte(double(c.y))) << 8
           | uint(rgb_byte(double(c.z))) << 16;
  }
  return o;
}
