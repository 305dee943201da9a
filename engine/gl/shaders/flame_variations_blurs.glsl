// Flame variations for the GPU backend (flame_variations.glsl has the conventions and the helpers):
// the CPU catalogue's variations_blurs.cpp, variations_blurs_more.cpp, variations_blur_b2.cpp and variations_truchet.cpp
// (engine/core/flame/), in float.

// ---- helpers (blurs_ prefix: the family files share one shader) ---------------------------------

// pow that C's pow matches at a zero base (GLSL leaves pow(0, y) undefined).
float blurs_pow(float x, float y) {
  if (x == 0.0) return y > 0.0 ? 0.0 : (y == 0.0 ? 1.0 : uintBitsToFloat(0x7f800000u));  // +∞
  return pow(x, y);
}
// std::round: half away from zero.
// Whether a whole number is odd, as fmod(v, 2) != 0 (NaN and ±∞ count as odd, as there).
bool blurs_isOdd(float v) { return !(mod(v, 2.0) == 0.0); }
// 2π · frac(k/n): the angle 2πk/n of a random branch k reduced in double, where k (up to 32767 or
// 2²⁴) times 2π/n is too large for float's cos and sin.
float blurs_turns(float k, float n) {
  double t = double(k) / double(n);
  return float(t - floor(t)) * kTwoPi;
}
// Fractorium's REAL_CYCLIC, fmod from the end the value left.
float blurs_cyclic(float v, float lo, float hi) {
  if (v > hi) return lo + fmodc(v - lo, hi - lo);
  if (v < lo) return hi - fmodc(hi - v, hi - lo);
  return v;
}
// Fractorium's integer parameter: ⌊v + ½⌋ clamped.
// REAL_NONZERO: within 10⁻⁶ of 0 becomes ±ε.
float blurs_nonzero(float v) { return v > -1e-6 && v < 1e-6 ? (v < 0.0 ? -kFractoriumEps : kFractoriumEps) : v; }

// ---- variations_blurs.cpp ----------------------------------------------------------------------

vec3 V_gaussian(vec3 p, float w, int P, int A) {
  float angle = psi() * kTwoPi;
  float r = w * gaussPsi();
  return vec3(r * cos(angle) + p.x, r * sin(angle) + p.y, w * p.z);
}
vec3 V_blur_square(vec3 p, float w, int P, int A) {
  float a = psi(), b = psi();
  return vec3(2.0 * w * (a - 0.5), 2.0 * w * (b - 0.5), w * p.z);
}
vec3 V_circleblur(vec3 p, float w, int P, int A) {
  float rad = sqrt(psi());
  float angle = psi() * kTwoPi;
  return vec3(w * cos(angle) * rad, w * sin(angle) * rad, w * p.z);
}
vec3 V_blur_pixelize(vec3 p, float w, int P, int A) {
  float size = max(P_(P, 0), kFractoriumEps), inverse = 1.0 / size, v = w * size, scale = P_(P, 1);
  float cx = floor(p.x * inverse), cy = floor(p.y * inverse);
  float a = psi(), b = psi();
  return vec3(v * (cx + scale * (a - 0.5) + 0.5), v * (cy + scale * (b - 0.5) + 0.5), w * p.z);
}
vec3 V_blur_heart(vec3 p, float w, int P, int A) {
  float pw = P_(P, 0), a = P_(P, 1), b = P_(P, 2), scale = fractoriumZeps(abs(a) + abs(b));
  float u = (psi() - 0.5) * 2.0;
  float v = (psi() - 0.5) * 2.0;
  float k = v < 0.0 ? -1.0 : 1.0;
  float limit = (a * blurs_pow(abs(u), pw) + k * b * sqrt(abs(1.0 - u * u)) - a) / scale;
  v = k > 0.0 ? min(v, limit) : max(v, limit);
  return w * vec3(u, v, p.z);
}
vec3 V_d_spherical(vec3 p, float w, int P, int A) {
  float r2 = p.x * p.x + p.y * p.y;
  float f = psi() < P_(P, 0) ? w / fractoriumZeps(r2) : w;
  return vec3(f * p.x, f * p.y, w * p.z);
}
vec3 V_juliaq(vec3 p, float w, int P, int A) {
  float power = fractoriumZeps(P_(P, 0)), inverse = P_(P, 1) / power;
  float k = floor(psi() * 32767.0);
  float a = atan2c(p.y, p.x) * inverse + blurs_turns(k, power);
  float r = w * blurs_pow(p.x * p.x + p.y * p.y, 0.5 * inverse);
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_Juliac(vec3 p, float w, int P, int A) {
  float reInverse = 1.0 / fractoriumZeps(P_(P, 0));
  double re = 1.0lf / double(reInverse);
  float im = 0.01 * P_(P, 1), halfDist = 0.5 * P_(P, 2);
  double k = double(floor(psi() * 16777216.0));
  float branch = float(k - re * trunc(k / re));  // C's fmod(k, re), k ≥ 0
  float arg = atan2c(p.y, p.x) + branch * kTwoPi;
  float lnmod = halfDist * log(p.x * p.x + p.y * p.y);
  float angle = arg * reInverse + lnmod * im;
  float m = w * exp(lnmod * reInverse - arg * im);
  return vec3(m * cos(angle), m * sin(angle), w * p.z);
}
// cos(a t) − cosh t as −2 (sin²(a t/2) + sinh²(t/2)): float's difference of the two near t = 0 loses
// what the pole's huge values need.
vec3 V_coth_spiral(vec3 p, float w, int P, int A) {
  float a = P_(P, 0);
  float t = (psi() - 0.5) * kTwoPi;
  float sa = sin(0.5 * a * t), sh = sinh(0.5 * t);
  float aux = fractoriumZeps(-2.0 * (sa * sa + sh * sh));
  return vec3(w * (-sinh(t) / aux), w * (sin(a * t) / aux), w * p.z);
}
vec3 V_depth_gaussian(vec3 p, float w, int P, int A) {
  float blur = P_(P, 0) / 10.0, radius = P_(P, 1);
  float r = sqrt(-2.0 * log(1.0 - psi()));
  float angle = psi() * kTwoPi;
  float rad = sqrt(p.x * p.x + p.y * p.y);
  float aux = rad > radius ? r * blur * (rad - radius) : 0.0;
  return w * vec3(p.x + aux * cos(angle), p.y + aux * sin(angle), p.z);
}
vec3 V_depth_ngon(vec3 p, float w, int P, int A) {
  float side = kTwoPi / fractoriumZeps(P_(P, 0)), halfSide = side / 2.0, blur = P_(P, 1) / 10.0, radius = P_(P, 2);
  float angle = psi() * kTwoPi;
  float phi = angle - side * floor(angle / fractoriumZeps(side));
  phi = phi > halfSide ? phi - side : phi;
  float rad = sqrt(p.x * p.x + p.y * p.y);
  float stretch = 1.0 / fractoriumZeps(cos(phi));
  float aux = rad > radius ? stretch * blur * (rad - radius) : 0.0;
  return w * vec3(p.x + aux * cos(angle), p.y + aux * sin(angle), p.z);
}
// Fractorium's flam3-compatible depth_ngon2 is depth_ngon (its other parameters act in the other form).
vec3 V_depth_ngon2(vec3 p, float w, int P, int A) { return V_depth_ngon(p, w, P, A); }
vec3 V_depth_sine(vec3 p, float w, int P, int A) {
  float power = max(P_(P, 0), 0.0), blur = P_(P, 1) / 10.0, radius = P_(P, 2);
  float angle = psi() * kTwoPi;
  float u = psi();
  float r = power == 1.0 ? acos(u * 2.0 - 1.0) / kPi : acos(exp(log(1.0 - u) * power) * 2.0 - 1.0) / kPi;
  float rad = sqrt(p.x * p.x + p.y * p.y);
  float aux = rad > radius ? r * blur * (rad - radius) : 0.0;
  return w * vec3(p.x + aux * cos(angle), p.y + aux * sin(angle), p.z);
}
// cosh τ − cos σ as 2 (sinh²(τ/2) + sin²(σ/2)), free of float's cancellation where both are near 1.
vec3 V_bTransform(vec3 p, float w, int P, int A) {
  float rotate = P_(P, 0), power = clamp(P_(P, 1), 1.0, 2147483647.0), move = P_(P, 2), split = P_(P, 3);
  float xp1 = p.x + 1.0, y2 = p.y * p.y;
  float tau = 0.5 * (log(xp1 * xp1 + y2) - log((p.x - 1.0) * (p.x - 1.0) + y2)) / power + move;
  float sigma = kPi - atan2c(p.y, xp1) - atan2c(p.y, 1.0 - p.x) + rotate;
  sigma = sigma / power + kTwoPi / power * floor(psi() * power);
  tau += p.x >= 0.0 ? split : -split;
  float sh = sinh(0.5 * tau), ss = sin(0.5 * sigma);
  float d = fractoriumZeps(2.0 * (sh * sh + ss * ss));
  return vec3(w * sinh(tau) / d, w * sin(sigma) / d, w * p.z);
}
vec3 V_boarders2(vec3 p, float w, int P, int A) {
  float c = fractoriumZeps(abs(P_(P, 0))), cl = c * fractoriumZeps(abs(P_(P, 1)));
  float cr = c + c * fractoriumZeps(abs(P_(P, 2)));
  float rx = roundHalfAway(p.x), ry = roundHalfAway(p.y);
  float dx = p.x - rx, dy = p.y - ry;
  float px = dx * c + rx, py = dy * c + ry;
  if (psi() < cr) {
    if (abs(dx) >= abs(dy)) {
      float side = dx >= 0.0 ? cl : -cl;
      px += side;
      py += side * dy / fractoriumZeps(dx);
    } else {
      float side = dy >= 0.0 ? cl : -cl;
      py += side;
      px += dx / dy * side;
    }
  }
  return vec3(w * px, w * py, w * p.z);
}
vec3 V_GlynnSim5(vec3 p, float w, int P, int A) {
  float radius = P_(P, 0), inner = P_(P, 0) + P_(P, 1), contrast = clamp(P_(P, 2), 0.0, 1.0), power = P_(P, 3);
  float u = psi();
  float r = sqrt(p.x * p.x + p.y * p.y);
  float alpha = abs(radius / fractoriumZeps(r));
  vec2 q = vec2(0.0);
  if (!(r < inner)) q = u > contrast * blurs_pow(alpha, power) ? w * p.xy : vec2(w * alpha * alpha);
  return vec3(q, w * p.z);
}
vec3 V_GlynnSim4(vec3 p, float w, int P, int A) {
  float radius = P_(P, 0), contrast = clamp(P_(P, 1), 0.0, 1.0), power = P_(P, 2);
  float u = psi();
  float r = sqrt(p.x * p.x + p.y * p.y);
  float alpha = abs(radius / fractoriumZeps(r));
  float f = u > contrast * blurs_pow(alpha, power) ? w : w * (alpha * alpha);
  return vec3(r < radius ? w * vec2(P_(P, 3), P_(P, 4)) : f * p.xy, w * p.z);
}
vec3 V_checks(vec3 p, float w, int P, int A) {
  float cx = P_(P, 0), cy = P_(P, 1), cells = 1.0 / fractoriumZeps(P_(P, 2)), spread = P_(P, 3);
  float rx = spread * psi();
  float ry = spread * psi();
  float sum = roundHalfAway(p.x * cells) + roundHalfAway(p.y * cells);
  bool odd = abs(fmodc(sum, 2.0)) == 1.0;
  return w * vec3(p.x + (odd ? rx - cx : cx), p.y + (odd ? -cy : cy + ry), p.z);
}
// r + x as y²/(r − x) for x < 0, where float's sum cancels.
vec3 V_glynnia2(vec3 p, float w, int P, int A) {
  float v2 = w * sqrt(2.0) / 2.0;
  bool root = psi() > 0.5;
  float r = sqrt(p.x * p.x + p.y * p.y);
  bool upper = r > 0.0 && p.y > 0.0;
  float sgn = upper ? 1.0 : -1.0;
  float rx = p.x < 0.0 ? p.y * p.y / (r - p.x) : r + p.x;
  if (root) {
    float d = sqrt(rx);
    d = upper ? d : fractoriumZeps(d);
    return vec3(sgn * v2 * d, -(v2 / d * p.y), w * p.z);
  }
  float g = sqrt(r * (p.y * p.y + rx * rx));
  float f = w / (upper ? g : fractoriumZeps(g));
  return vec3(sgn * f * rx, f * p.y, w * p.z);
}
vec3 V_hex_rand(vec3 p, float w, int P, int A) {
  const float kSqrt3Half = 0.86602540378443865, kTwoOverSqrt3 = 1.1547005383792515, kThirdTurn = 2.0943951023931955;
  float cellsX = P_(P, 0), cellsY = P_(P, 1), halfSize = P_(P, 2) * 0.5, power = P_(P, 3);
  float density = clamp(P_(P, 4), 0.0, 1.0);
  double seed = double(P_(P, 5));
  // The angle within the hexagon's six triangles, and the distance to its edge in that direction.
  float k = psi() * 6.0;
  float sector = floor(k), t = k - sector;
  float edge = sqrt(1.0 + t * t - t);
  float sgn = sector - floor(k / 2.0) * 2.0 == 1.0 ? 1.0 : -1.0;
  float angle = kThirdTurn * floor(sector / 2.0) + sgn * asin(kSqrt3Half * t / edge) - kPi / 2.0;
  float cx = floor(psi() * cellsX * 2.0) - cellsX;
  float cy = floor(psi() * cellsY * 2.0) - cellsY;
  // The hashes take the centre as the CPU computes it, in double.
  double hx = double(cx) + 0.5lf * double(cy), hy = double(cy) * 0.86602540378443864676lf;
  float spread = sqrt(psi());
  vec2 q = vec2(0.0);
  if (hashShadertoy(hy, hx, seed) < density) {
    float r = halfSize * edge * spread * kTwoOverSqrt3 * blurs_pow(hashShadertoy(hx, hy, seed), power);
    q = vec2((cos(angle) * r + float(hx)) * w, (sin(angle) * r + float(hy)) * w);
  }
  return vec3(q, w * p.z);
}
// crackle2's jittered point of the unit cell c.
vec2 blurs_cracklePoint(float cx, float cy, float jitter) {
  return vec2(cx + jitter * hashShadertoy(double(cx), double(cy), 34554.0lf),
              cy + jitter * hashShadertoy(double(cy), double(cx) * 3.0lf, 34561.0lf));
}
vec3 V_crackle2(vec3 p, float w, int P, int A) {
  float cellsize = max(P_(P, 0), 0.0001), jitter = 1.0 / fractoriumZeps(cellsize);
  float cx = floor(p.x), cy = floor(p.y);
  vec2 q0 = blurs_cracklePoint(cx, cy, jitter);
  bool vertical = psi() < 0.5;
  float step_ = psi() < 0.5 ? 1.0 : -1.0;
  float nx = vertical ? cx : cx + step_, ny = vertical ? cy + step_ : cy;
  vec2 q1 = blurs_cracklePoint(nx, ny, jitter);
  float t = psi();
  return vec3((q0 + (q1 - q0) * t) * cellsize, w * p.z);
}
vec3 V_cpow3(vec3 p, float w, int P, int A) {
  float r = P_(P, 0), d = fractoriumZeps(P_(P, 1)), divisor = fractoriumZeps(P_(P, 2)), spread = P_(P, 3);
  float a0 = atan2c((d < 0.0 ? -log(-d) : log(d)) * r, kTwoPi);
  float c = cos(a0) * r * cos(a0) / divisor, e = cos(a0) * r * sin(a0) / divisor;
  float coeff = e == 0.0 ? 0.0 : -0.095 * spread / e;
  float a = atan2c(p.y, p.x);
  a = a < 0.0 ? a + kTwoPi : a;
  a = cos(a / 2.0) < 2.0 * psi() - 1.0 ? a - kTwoPi : a;
  float sgn = psi() < 0.5 ? kTwoPi : -kTwoPi;
  a += sgn * roundHalfAway(log(1.0 - psi()) * coeff);
  float k = floor(psi() * 32767.0);
  float lnr2 = log(p.x * p.x + p.y * p.y);
  float m = w * exp(c / 2.0 * lnr2 - e * a);
  float angle = c * a + e / 2.0 * lnr2 + blurs_turns(k, divisor);
  return vec3(m * cos(angle), m * sin(angle), w * p.z);
}

// ---- variations_blurs_more.cpp -----------------------------------------------------------------

// Hugo Elias' integer noise of a cell in [0, 1] (Fractorium's DiscreteNoise2), int arithmetic
// wrapping as Java's does.
float blurs_cellNoise(int x, int y) {
  uint k = uint(x) + uint(y) * 57u;
  k = (k << 13) ^ k;
  uint v = k * (k * k * 15731u + 789221u) + 1376312589u;
  return float(double(v & 0x7fffffffu) * (1.0lf / 2147483647.0lf));
}
// Java's (int) of a whole float: saturating, NaN as 0.
int blurs_javaInt(float v) {
  if (isnan(v)) return 0;
  if (v >= 2147483647.0) return 2147483647;
  if (v <= -2147483648.0) return -2147483647 - 1;
  return int(v);
}
vec3 V_asteria(vec3 p, float w, int P, int A) {
  float alpha = blurs_cyclic(P_(P, 0), 0.0, 1.0);
  float s = sin(kPi * alpha), c = cos(kPi * alpha);
  float u = psi();
  float x0 = w * p.x, y0 = w * p.y;
  float r = x0 * x0 + y0 * y0;
  float ax = abs(x0) - 1.0, ay = abs(y0) - 1.0;
  bool inside = r < 1.0, nearCorner = sqrt(ax * ax + ay * ay) < 1.0;
  bool keep = inside && nearCorner ? u > 0.35 : !inside;
  if (keep) return vec3(x0, y0, w * p.z);
  float xx = x0 * c - y0 * s, yy = x0 * s + y0 * c;
  float t = 1.0 - abs(yy);
  float nx = xx / sqrt(max(1.0 - yy * yy, kEpsilon)) * (1.0 - sqrt(max(1.0 - t * t, 0.0)));
  return vec3(nx * c + yy * s, -nx * s + yy * c, w * p.z);
}
vec3 V_Circle_Rand(vec3 p, float w, int P, int A) {
  float sideX = P_(P, 0) * 0.5, sideY = P_(P, 1) * 0.5, size = max(P_(P, 2), 0.0), power = P_(P, 3);
  float density = clamp(P_(P, 4), 0.0, 1.0);
  double seed = double(P_(P, 5));
  float a = psi() * kTwoPi;
  float r = sqrt(psi());
  float cx = 2.0 * (floor(psi() * sideX * 2.0 + 0.5) - sideX);
  float cy = 2.0 * (floor(psi() * sideY * 2.0 + 0.5) - sideY);
  float ret = hashShadertoy(double(cy), double(cx), seed) < density
                  ? size * r * exp(log(hashShadertoy(double(cx), double(cy), seed)) * power)
                  : 0.0;
  vec2 q = ret > 0.0 ? w * vec2(cos(a) * ret + cx, sin(a) * ret + cy) : vec2(0.0);
  return vec3(q, w * p.z);
}
// The point is the last drawn one: the CPU moves it into its cell and back, which float need not copy.
// The loop runs to its end without `break`: llvmpipe handed a draw of the try after the last to q.x
// when the loop broke off.
vec3 V_CircleRand(vec3 p, float w, int P, int A) {
  float sc = blurs_nonzero(P_(P, 0)), dens = P_(P, 1), spanX = P_(P, 2), spanY = P_(P, 3);
  float seed = fractoriumInteger(P_(P, 4), -2147483647.0, 2147483647.0);
  vec2 q = vec2(0.0);
  bool done = false;
  for (int tries = 1; tries <= 11; ++tries) {
    if (done) continue;
    float u1 = psi();
    float u2 = psi();
    q = vec2(spanX * (1.0 - 2.0 * u1), spanY * (1.0 - 2.0 * u2));
    float m = floor(0.5 * q.x / sc), k = floor(0.5 * q.y / sc);
    float dx = q.x - (m * 2.0 + 1.0) * sc, dy = q.y - (k * 2.0 + 1.0) * sc;
    bool outside = blurs_cellNoise(blurs_javaInt(m + seed), blurs_javaInt(k)) > dens ||
                   sqrt(dx * dx + dy * dy) >
                       (0.3 + 0.7 * blurs_cellNoise(blurs_javaInt(m + 10.0), blurs_javaInt(k + 3.0))) * sc;
    done = tries > 10 || !outside;
  }
  return w * vec3(q, p.z);
}
vec3 V_CircleTrans1(vec3 p, float w, int P, int A) {
  float sc = fractoriumZeps(blurs_nonzero(P_(P, 0))), dens = P_(P, 1), cx = P_(P, 2), cy = P_(P, 3);
  float seed = fractoriumInteger(P_(P, 4), -2147483647.0, 2147483647.0);
  float spanX = abs(cx), spanY = abs(cy);
  float ux = (p.x - cx) * 0.5 + cx, uy = (p.y - cy) * 0.5 + cy;
  float m = floor(0.5 * ux / sc), k = floor(0.5 * uy / sc);
  float dx = ux - (m * 2.0 + 1.0) * sc, dy = uy - (k * 2.0 + 1.0) * sc;
  bool keep = blurs_cellNoise(blurs_javaInt(m + seed), blurs_javaInt(k)) > dens ||
              sqrt(dx * dx + dy * dy) >
                  (0.3 + 0.7 * blurs_cellNoise(blurs_javaInt(m + 10.0), blurs_javaInt(k + 3.0))) * sc;
  // The random circle point (Fractorium's CircleR), drawn by every point; no `break`, as in CircleRand.
  float rx = 0.0, ry = 0.0, rm = 0.0, rk = 0.0;
  bool done = false;
  for (int tries = 1; tries <= 11; ++tries) {
    if (done) continue;
    float qx = spanX * (1.0 - 2.0 * psi());
    float qy = spanY * (1.0 - 2.0 * psi());
    rm = floor(0.5 * qx / sc);
    rk = floor(0.5 * qy / sc);
    float angle = kTwoPi * psi();
    float u = 0.3 + 0.7 * blurs_cellNoise(blurs_javaInt(rm + 10.0), blurs_javaInt(rk + 3.0));
    rx = u * cos(angle);
    ry = u * sin(angle);
    done = tries > 10 || !(blurs_cellNoise(blurs_javaInt(rm + seed), blurs_javaInt(rk)) > dens);
  }
  ux = keep ? ux : rx + (rm * 2.0 + 1.0) * sc;
  uy = keep ? uy : ry + (rk * 2.0 + 1.0) * sc;
  return w * vec3(ux, uy, p.z);
}
// Below a spread of 1 Fractorium's branch is any 32-bit integer: the angle is then as good as random
// and float cannot follow the CPU's (nor need to).
vec3 V_cpow2(vec3 p, float w, int P, int A) {
  float divisor = P_(P, 2), spread = fractoriumZeps(P_(P, 3));
  float c = P_(P, 0) * cos(kPi / 2.0 * P_(P, 1)) / divisor, d = P_(P, 0) * sin(kPi / 2.0 * P_(P, 1)) / divisor;
  float branches = spread >= 1.0 ? min(floor(spread), 4294967295.0) : 0.0;
  float u = psi();
  float a = atan2c(p.y, p.x);
  float k = branches >= 1.0 ? floor(u * branches) : floor(u * 4294967296.0) - 2147483648.0;
  k += a < 0.0 ? 1.0 : 0.0;
  a += kTwoPi * k;
  if (cos(a * (0.5 / spread)) < psi() * 2.0 - 1.0) a -= kTwoPi * spread;
  float lnr2 = log(p.x * p.x + p.y * p.y);
  float r = w * exp(c / 2.0 * lnr2 - d * a);
  float t = c * a + d / 2.0 * lnr2 + blurs_turns(floor(psi() * 32767.0), divisor);
  return vec3(r * cos(t), r * sin(t), w * p.z);
}
// depth_blur's star (starShape and starPoint in the CPU file): the offset's length factor, and its
// angle in `angle`. s = (length, sin α, cos α, 2 power), step = 2π/power.
vec4 blurs_starShape(float power, float range) {
  float alpha0 = kPi / fractoriumZeps(power);
  float length_ = sqrt(1.0 + range * range - 2.0 * range * cos(alpha0));
  float alpha = asin(sin(alpha0) * range / fractoriumZeps(length_));
  return vec4(length_, sin(alpha), cos(alpha), power * 2.0);
}
float blurs_starPoint(vec4 s, float step_, float oddSign, float u1, float u2, out float angle) {
  float f = u1 * s.w;
  float whole = trunc(f);
  f -= whole;
  float t = f * s.x;
  float zz = sqrt(1.0 + t * t - 2.0 * t * s.z);
  float turn = asin(s.y * t / fractoriumZeps(zz));
  angle = step_ * trunc(whole / 2.0) + (blurs_isOdd(whole) ? oddSign : -oddSign) * turn - kPi / 2.0;
  return zz * sqrt(u2);
}
vec3 V_depth_blur(vec3 p, float w, int P, int A) {
  vec4 star = blurs_starShape(P_(P, 0), P_(P, 1));
  float blur = P_(P, 2) / 10.0, radius = P_(P, 3);
  float u1 = psi(), u2 = psi();
  float angle;
  float len = blurs_starPoint(star, kTwoPi / fractoriumZeps(P_(P, 0)), -1.0, u1, u2, angle);
  float rad = sqrt(p.x * p.x + p.y * p.y);
  float aux = rad > radius ? len * blur * (rad - radius) : 0.0;
  return w * vec3(p.x + aux * cos(angle), p.y + aux * sin(angle), p.z);
}
vec3 V_depth_blur2(vec3 p, float w, int P, int A) {
  vec4 star = blurs_starShape(P_(P, 0), P_(P, 1));
  float blur = P_(P, 2) / 10.0, radius = P_(P, 3), x0 = P_(P, 4), y0 = P_(P, 5);
  float invMulX = 1.0 / fractoriumZeps(P_(P, 6)), invMulY = 1.0 / fractoriumZeps(P_(P, 7)), power = P_(P, 8);
  float u1 = psi(), u2 = psi();
  float angle;
  float len = blurs_starPoint(star, kTwoPi / fractoriumZeps(P_(P, 0)), 1.0, u1, u2, angle);
  float dx = (p.x - x0) * invMulX, dy = (p.y - y0) * invMulY;
  float rad = sqrt(dx * dx + dy * dy);
  float aux = rad > radius ? len * blur * exp(log(rad - radius) * power) : 0.0;
  return w * vec3(p.x + aux * cos(angle), p.y + aux * sin(angle), p.z);
}
vec3 V_depth_gaussian2(vec3 p, float w, int P, int A) {
  float blur = P_(P, 0) / 10.0, radius = P_(P, 1), x0 = P_(P, 2), y0 = P_(P, 3);
  float invMulX2 = 1.0 / fractoriumZeps(P_(P, 4) * P_(P, 4)), invMulY2 = 1.0 / fractoriumZeps(P_(P, 5) * P_(P, 5));
  float power = P_(P, 6);
  float r = sqrt(-2.0 * log(1.0 - psi()));
  float angle = psi() * kTwoPi;
  float dx = (p.x - x0) / invMulX2, dy = (p.y - y0) / invMulY2;
  float rad = sqrt(dx * dx + dy * dy);
  float aux = rad > radius ? r * blur * exp(log(rad - radius) * power) : 0.0;
  return w * vec3(p.x + aux * cos(angle), p.y + aux * sin(angle), p.z);
}
vec3 V_depth_sine2(vec3 p, float w, int P, int A) {
  float power = max(P_(P, 0), 0.0), blur = P_(P, 1) / 10.0, radius = P_(P, 2), x0 = P_(P, 3), y0 = P_(P, 4);
  float mulX = fractoriumZeps(P_(P, 5)), mulY = fractoriumZeps(P_(P, 6)), grow = P_(P, 7);
  float angle = psi() * kTwoPi;
  float u = psi();
  float r = power == 1.0 ? acos(u * 2.0 - 1.0) / kPi : acos(exp(log(1.0 - u) * power) * 2.0 - 1.0) / kPi;
  float dx = (p.x - x0) / mulX, dy = (p.y - y0) / mulY;
  float rad = sqrt(dx * dx + dy * dy);
  float aux = rad > radius ? r * blur * exp(log(rad - radius) * grow) : 0.0;
  return w * vec3(p.x + aux * cos(angle), p.y + aux * sin(angle), p.z);
}
vec3 V_GlynnSim2(vec3 p, float w, int P, int A) {
  float radius = max(P_(P, 0), 0.0), thickness = clamp(P_(P, 1), 0.0, 1.0);
  float contrast = clamp(P_(P, 2), 0.0, 1.0), power = abs(P_(P, 3));
  float phi1 = kPi * P_(P, 4) / 180.0, delta = kPi * P_(P, 5) / 180.0 - phi1;
  float gamma = thickness * (2.0 * radius + thickness) / fractoriumZeps(radius + thickness);
  float u1 = psi(), u2 = psi();
  float r = sqrt(p.x * p.x + p.y * p.y);
  float ring = radius + thickness - gamma * u1, phi = phi1 + delta * u2;
  float alpha = abs(radius / fractoriumZeps(r));
  float f = u1 > contrast * blurs_pow(alpha, power) ? w : w * (alpha * alpha);
  return vec3(r < radius ? w * ring * vec2(cos(phi), sin(phi)) : f * p.xy, w * p.z);
}
vec3 V_GlynnSim3(vec3 p, float w, int P, int A) {
  float radius = P_(P, 0), radius1 = P_(P, 0) + P_(P, 1), contrast = clamp(P_(P, 3), 0.0, 1.0), power = P_(P, 4);
  float radius2 = radius * radius / fractoriumZeps(radius1);
  float gamma = radius1 / fractoriumZeps(radius1 + radius2);
  float u1 = psi(), u2 = psi(), u3 = psi();
  float r = sqrt(p.x * p.x + p.y * p.y);
  float phi = kTwoPi * u2, ring = u3 < gamma ? radius1 : radius2;
  float alpha = abs(radius / fractoriumZeps(r));
  float f = u1 > contrast * blurs_pow(alpha, power) ? w : w * (alpha * alpha);
  return vec3(r < radius1 ? w * ring * vec2(cos(phi), sin(phi)) : f * p.xy, w * p.z);
}
vec3 V_hex_truchet(vec3 p, float w, int P, int A) {
  float size = clamp(P_(P, 0), -1.0, 1.0), side = P_(P, 1);
  double seed = double(P_(P, 2));
  float oneMinusSize = (1.0 - size) * 0.85;
  float low = (0.15 + oneMinusSize * 0.5) * (0.15 + oneMinusSize * 0.5);
  float span = (1.0 - oneMinusSize * 0.5) * (1.0 - oneMinusSize * 0.5) - low, cells = side * 2.0 + 1.0;
  float angle = psi() * kTwoPi;
  float r = sqrt(psi() * span + low);
  float cornerX = angle < 2.0943 ? 1.0 : (angle < 4.1887 ? -1.0 : 0.0);
  float cornerY = angle < 4.1887 ? 0.5773 : -1.1547;
  float cx = 2.0 * (floor(psi() * cells) - side);
  float cy = 2.0 * (floor(psi() * cells) - side);
  float turn = hashShadertoy(double(cx), double(cy), seed) < 0.5 ? 0.0 : 1.0471;
  float c = cos(turn), s = sin(turn), a = angle + 2.6179 - turn;
  return vec3((cos(a) * r + cornerX * c + cornerY * s + cx + 0.5 * cy) * w,
              (sin(a) * r - cornerX * s + cornerY * c + 0.866 * cy) * w, w * p.z);
}

// ---- variations_blur_b2.cpp --------------------------------------------------------------------

vec3 V_Lissajous(vec3 p, float w, int P, int A) {
  float t = (P_(P, 1) - P_(P, 0)) * psi() + P_(P, 0);
  float spread = psi() - 0.5;
  float shift = P_(P, 4) * t + P_(P, 6) * spread;
  return w * vec3(sin(P_(P, 2) * t + P_(P, 5)) + shift, sin(P_(P, 3) * t) + shift, p.z);
}
vec3 V_Spirograph(vec3 p, float w, int P, int A) {
  float a = P_(P, 0), b = P_(P, 1), d = P_(P, 2), tMin = P_(P, 3), yMin = P_(P, 4), tMax = P_(P, 5), yMax = P_(P, 6);
  float t = (tMax - tMin) * psi() + tMin;
  float shift = (yMax - yMin) * psi() + yMin;
  float ab = a + b, inner = ab / b * t;
  return w * vec3(ab * cos(t) - P_(P, 7) * cos(inner) + d * cos(t) + shift,
                  ab * sin(t) - P_(P, 8) * sin(inner) + d * sin(t) + shift, p.z);
}
vec3 V_point_symmetry(vec3 p, float w, int P, int A) {
  float cx = P_(P, 0), cy = P_(P, 1), order = P_(P, 2), step_ = kTwoPi / fractoriumZeps(P_(P, 2));
  float angle = floor(psi() * order) * step_;
  float dx = (p.x - cx) * w, dy = (p.y - cy) * w;
  float c = cos(angle), s = sin(angle);
  return vec3(cx + dx * c + dy * s, cy + dy * c - dx * s, w * p.z);
}
vec3 V_spher(vec3 p, float w, int P, int A) {
  float u = psi();
  float r2 = fractoriumZeps(p.x * p.x + p.y * p.y);
  float k = r2 > 1.0 ? (u < 0.5 ? w / r2 : w) : 0.0;
  return vec3(k * p.x, k * p.y, w * p.z);
}
vec3 V_squish(vec3 p, float w, int P, int A) {
  float power = max(P_(P, 0), 2.0), invPower = 1.0 / power;
  float ax = abs(p.x), ay = abs(p.y);
  float s, q;
  if (ax > ay) {
    s = ax;
    q = p.x > 0.0 ? p.y : 4.0 * s - p.y;
  } else {
    s = ay;
    q = p.y > 0.0 ? 2.0 * s - p.x : 6.0 * s + p.x;
  }
  q = invPower * (q + 8.0 * s * floor(power * psi()));
  vec2 o;
  if (q <= s) {
    o = vec2(s, q);
  } else if (q <= 3.0 * s) {
    o = vec2(2.0 * s - q, s);
  } else if (q <= 5.0 * s) {
    o = vec2(-s, 4.0 * s - q);
  } else if (q <= 7.0 * s) {
    o = vec2(-(6.0 * s - q), -s);
  } else {
    o = vec2(s, 8.0 * s - q);
  }
  return w * vec3(o, p.z);
}
vec3 V_sschecks(vec3 p, float w, int P, int A) {
  float cx = P_(P, 0), cy = P_(P, 1), invSize = 1.0 / fractoriumZeps(P_(P, 2)), jitter = P_(P, 3);
  float u = psi();
  float r = w / fractoriumZeps(p.x * p.x + p.y * p.y);
  float cell = roundHalfAway(p.x * invSize) + roundHalfAway(p.y * invSize);
  bool odd = fmodc(cell, 2.0) != 0.0;
  float dx = odd ? -cx + jitter * u : cx;
  float dy = odd ? -cy : cy + jitter * u;
  return w * vec3(sin(p.x) * r + dx, sin(p.y) * r + dy, p.z);
}
vec3 V_starblur(vec3 p, float w, int P, int A) {
  float power = P_(P, 0), range = P_(P, 1);
  float halfAngle = kPi / power;
  float length_ = sqrt(1.0 + range * range - 2.0 * range * cos(halfAngle));
  float alpha = asin(sin(halfAngle) * range / length_);
  float sinAlpha = sin(alpha), cosAlpha = cos(alpha), sector = kTwoPi / power;
  float f = psi() * power * 2.0;
  float edge = trunc(f);
  f -= edge;
  float px = f * length_;
  float d = sqrt(1.0 + px * px - 2.0 * px * cosAlpha);
  float turn = asin(sinAlpha * px / d);
  float angle = sector * trunc(edge / 2.0) + (blurs_isOdd(edge) ? turn : -turn) - kPi / 2.0;
  d *= sqrt(psi());
  return vec3(w * d * cos(angle), w * d * sin(angle), w * p.z);
}
vec3 V_log_db(vec3 p, float w, int P, int A) {
  float base = P_(P, 0), fixPeriod = P_(P, 1);
  float denominator = w * (base > kFractoriumEps ? 0.5 / log(2.718281828459045 * base) : 0.5);
  float period = fixPeriod > kFractoriumEps ? kPi * fixPeriod : kPi;
  float turns = 0.0;
  for (int k = 0; k < 7; ++k) {
    float adp = floor(psi() * 10.0) - 5.0;
    turns += abs(adp) >= 3.0 ? 0.0 : adp;
  }
  return vec3(denominator * log(p.x * p.x + p.y * p.y), w * (atan2c(p.y, p.x) + turns * period), w * p.z);
}
vec3 V_starblur2(vec3 p, float w, int P, int A) {
  float power = P_(P, 0), range = P_(P, 1), width = P_(P, 4);
  float pz = fractoriumZeps(power), halfAngle = kPi / pz;
  float length_ = sqrt(1.0 + range * range - 2.0 * range * cos(halfAngle));
  float alpha = asin(sin(halfAngle) * range / fractoriumZeps(length_));
  float hole = min(abs(P_(P, 2)), 1.0), holeSq = hole * hole;
  float stripes = fractoriumZeps(abs(P_(P, 3)));
  float sinAlpha = sin(alpha), cosAlpha2 = cos(alpha) * 2.0;
  float k = psi() * power * 2.0;
  float edge = floor(k);
  float f = k - edge;
  float fs = trunc(f * stripes);
  bool even = !blurs_isOdd(edge);
  float dif = even ? width * (f * stripes - fs) : 1.0 - width * (f * stripes - fs);
  float ff = (dif + fs) / stripes;
  float px = ff * length_;
  float d = fractoriumZeps(sqrt(1.0 + px * px - px * cosAlpha2));
  float sgn = edge - floor(k / 2.0) * 2.0 == 1.0 ? 1.0 : -1.0;
  float angle = kTwoPi / pz * trunc(edge / 2.0) + sgn * asin(sinAlpha * px / d) - kPi / 2.0;
  float scaled = w * d * sqrt(psi() * (1.0 - holeSq) + holeSq);
  return vec3(cos(angle) * scaled, sin(angle) * scaled, w * p.z);
}
vec3 V_SphericalN(vec3 p, float w, int P, int A) {
  float power = P_(P, 0), dist = P_(P, 1);
  float r = fractoriumZeps(blurs_pow(sqrt(p.x * p.x + p.y * p.y), dist));
  float k = floor(power * psi());
  float alpha = atan2c(p.y, p.x) + k * (kTwoPi / fractoriumZeps(floor(power)));
  return vec3(w * cos(alpha) / r, w * sin(alpha) / r, w * p.z);
}
vec3 V_SplitBrdr(vec3 p, float w, int P, int A) {
  float sx = P_(P, 0), sy = P_(P, 1), px = P_(P, 2), py = P_(P, 3);
  float b = w / ((p.x * p.x + p.y * p.y) * 0.25 + 1.0);
  float roundX = roundEven(p.x), roundY = roundEven(p.y);
  float offX = p.x - roundX, offY = p.y - roundY;
  float ax = offX * 0.5 + roundX, ay = offY * 0.5 + roundY;
  if (psi() < 0.75) {
    if (abs(offX) >= abs(offY)) {
      if (offX >= 0.0) {
        ax += sx;
        ay += sy * offY / fractoriumZeps(offX);
      } else {
        ax -= sy;
        ay -= sy * offY / fractoriumZeps(offX);
      }
    } else {
      if (offY >= 0.0) {
        ay += sy;
        ax += offX / fractoriumZeps(offY) * sy;
      } else {
        ay -= sy;
        ax -= offX / fractoriumZeps(offY) * sx;
      }
    }
  }
  return vec3(p.x * b + w * ax + p.x * px, p.y * b + w * ay + p.y * py, w * p.z);
}
vec3 V_npolar(vec3 p, float w, int P, int A) {
  float parity = P_(P, 0), nnz = P_(P, 1) == 0.0 ? 1.0 : P_(P, 1);
  float vvar = w / kPi, vvar2 = vvar * 0.5, absN = abs(nnz), cn = 1.0 / nnz / 2.0;
  bool odd = fmodc(abs(parity), 2.0) != 0.0;
  float turn = kTwoPi * floor(psi() * absN);
  float r2 = p.x * p.x + p.y * p.y;
  if (odd) {
    float angle = (atan2c(p.y, p.x) + turn) / nnz;
    float r = w * blurs_pow(r2, cn) * parity;
    return vec3(cos(angle) * r, sin(angle) * r, w * p.z);
  }
  float lx = vvar * atan2c(p.x, p.y), ly = vvar2 * log(r2);
  float angle = (atan2c(ly, lx) + turn) / nnz;
  float r = w * blurs_pow(lx * lx + ly * ly, cn);
  float s = sin(angle) * r, c = cos(angle) * r;
  return vec3(vvar2 * log(c * c + s * s), vvar * atan2c(c, s), w * p.z);
}
vec3 V_phoenix_julia(vec3 p, float w, int P, int A) {
  float power = fractoriumZeps(P_(P, 0)), invN = P_(P, 1) / power;
  float dx = P_(P, 2) + 1.0, dy = P_(P, 3) + 1.0;
  float k = floor(psi() * 32767.0);
  float t = atan2c(p.y * dy, p.x * dx) * invN + blurs_turns(k, power);
  float r = w * blurs_pow(p.x * p.x + p.y * p.y, invN / 2.0);
  return vec3(r * cos(t), r * sin(t), w * p.z);
}
vec3 V_MobiusN(vec3 p, float w, int P, int A) {
  float reA = P_(P, 0), imA = P_(P, 1), reB = P_(P, 2), imB = P_(P, 3);
  float reC = P_(P, 4), imC = P_(P, 5), reD = P_(P, 6), imD = P_(P, 7);
  float power = abs(P_(P, 8)) < 1.0 ? 1.0 : P_(P, 8);
  float exponent = 4.0 * P_(P, 9) / power, root = 1.0 / exponent, whole = floor(power);
  float r = blurs_pow(sqrt(p.x * p.x + p.y * p.y), exponent);
  float alpha = atan2c(p.y, p.x) * power;
  float ux = r * cos(alpha), uy = r * sin(alpha);
  float reU = reA * ux - imA * uy + reB, imU = reA * uy + imA * ux + imB;
  float reV = reC * ux - imC * uy + reD, imV = reC * uy + imC * ux + imD;
  float radV = reV * reV + imV * imV;
  float vx = (reU * reV + imU * imV) / radV, vy = (imU * reV - reU * imV) / radV;
  float rr = blurs_pow(sqrt(vx * vx + vy * vy), root);
  float k = floor(power * psi());
  float angle = (atan2c(vy, vx) + k * kTwoPi) / whole;
  return vec3(w * rr * cos(angle), w * rr * sin(angle), w * p.z);
}

// ---- variations_truchet.cpp --------------------------------------------------------------------

// C's fmod in double (exact for the LCG's whole-number-sized values below).
double blurs_dfmod(double a, double m) { return a - m * trunc(a / m); }
// Whether the square Truchet tile of an LCG or hash value v is of type 1: fmod(fmod(32747 v + 12345,
// 65535), 2) ≥ 1, in double as on the CPU.
bool blurs_tileType(double v) {
  precise double a = v * 32747.0lf + 12345.0lf;
  return !(blurs_dfmod(blurs_dfmod(a, 65535.0lf), 2.0lf) < 1.0lf);
}
// The square Truchet tile the point falls in (truchetTile on the CPU): the position in its tile and
// the distances from the two arcs' centre lines relative to their half-width.
vec4 blurs_truchetTile(vec2 q, float scale, bool type1, float exponent, float oneOverExponent, float rmax,
                       bool roundAway) {
  vec2 s = q * scale;
  vec2 rr = s - (roundAway ? vec2(roundHalfAway(s.x), roundHalfAway(s.y)) : floor(s + 0.5));
  float x = rr.x < 0.0 ? 1.0 + rr.x : rr.x, y = rr.y < 0.0 ? 1.0 + rr.y : rr.y;
  float xval1 = type1 ? x - 1.0 : x, xval2 = type1 ? x : x - 1.0;
  float r0 = blurs_pow(blurs_pow(abs(xval1), exponent) + blurs_pow(abs(y), exponent), oneOverExponent);
  float r1 = blurs_pow(blurs_pow(abs(xval2), exponent) + blurs_pow(abs(y - 1.0), exponent), oneOverExponent);
  return vec4(x, y, abs(r0 - 0.5) / rmax, abs(r1 - 0.5) / rmax);
}
vec3 V_Truchet_fill(vec3 p, float w, int P, int A) {
  float exponent = clamp(blurs_cyclic(P_(P, 0), 0.001, 2.0), 0.001, 2.0);
  float width = clamp(blurs_cyclic(P_(P, 1), 0.001, 1.0), 0.001, 1.0);
  float seed = P_(P, 2);
  float oneOverEx = 1.0 / exponent;
  float rmax = fractoriumZeps(0.5 * (pow(2.0, oneOverEx) - 1.0) * width);
  bool type1 = seed == 1.0;
  if (seed != 0.0 && seed != 1.0) {
    double ds = double(seed);
    double seed2 = sqrt(ds * 1.5lf) / (ds * 0.5lf) * 0.25lf;
    double xr = double(roundHalfAway(abs(p.x))) * seed2, yr = double(roundHalfAway(abs(p.y))) * seed2;
    precise double randint = (ds + xr + yr + xr * yr) * seed2 * 0.5lf;
    type1 = blurs_tileType(randint);
  }
  vec4 t = blurs_truchetTile(p.xy, 1.0 / w, type1, exponent, oneOverEx, rmax, true);
  vec2 c = 2.0 * (t.xy + floor(p.xy));
  return vec3((t.z < 1.0 ? c : vec2(0.0)) + (t.w < 1.0 ? c : vec2(0.0)) - p.xy, w * p.z);
}
vec3 V_Truchet_glyph(vec3 p, float w, int P, int A) {
  float exponent = clamp(P_(P, 0), 0.001, 2.0), width = clamp(P_(P, 1), 0.001, 1.0);
  float clampedAmp = max(P_(P, 2), kFractoriumEps), maxSize = max(P_(P, 3), 0.0);
  float rads = P_(P, 4) * kPi / 180.0, seed = P_(P, 5);
  float oneN = 1.0 / fractoriumZeps(exponent);
  float rmax = fractoriumZeps(0.5 * (pow(2.0, oneN) - 1.0) * width);
  float halfAmpMax = clampedAmp * 0.5 * maxSize, amp = fractoriumZeps(clampedAmp);
  float c = cos(rads), s = sin(rads);
  bool type1 = seed == 1.0;
  if (seed != 0.0 && seed != 1.0)
    type1 = blurs_tileType(hashShadertoyD(double(floor(abs(p.x) + 0.5)), double(floor(abs(p.y) + 0.5)), double(seed)));
  vec2 v = p.xy - (floor(p.xy / amp) + 0.5) * amp;
  float u = c * v.x + s * v.y, vv = -s * v.x + c * v.y;
  if (!(abs(u) + abs(vv) < halfAmpMax)) return vec3(p.xy, w * p.z);
  vec4 t = blurs_truchetTile(p.xy, 1.0 / w, type1, exponent, oneN, rmax, false);
  vec2 cc = 2.0 * (t.xy + floor(p.xy));
  return vec3((t.z < 1.0 ? cc : vec2(0.0)) + (t.w < 1.0 ? cc : vec2(0.0)) - p.xy, w * p.z);
}
vec3 V_Truchet_inv(vec3 p, float w, int P, int A) {
  float exponent = clamp(P_(P, 0), 0.001, 2.0), width = clamp(P_(P, 1), 0.001, 1.0);
  float rotation = P_(P, 2), size = max(P_(P, 3), 0.0), seed = P_(P, 4);
  float oneN = 1.0 / fractoriumZeps(exponent);
  float rmax = fractoriumZeps(0.5 * (pow(2.0, oneN) - 1.0) * width);
  bool type1 = seed == 1.0;
  if (seed != 0.0 && seed != 1.0) {
    double ds = double(seed);
    double seed2 = sqrt(ds * 1.5lf) / (ds * 0.5lf) * 0.25lf;
    double xr = double(floor(p.x + 0.5)) * seed2, yr = double(floor(p.y + 0.5)) * seed2;
    precise double randint = (xr + yr + xr * yr + ds) * (seed2 * 0.5lf);
    type1 = blurs_tileType(randint);
  }
  vec4 t = blurs_truchetTile(p.xy, (cos(rotation) + sin(rotation)) / w, type1, exponent, oneN, rmax, false);
  bool off = t.z > 1.0 && t.w > 1.0;
  return vec3(off ? (t.xy + floor(p.xy)) * size : vec2(0.0), w * p.z);
}
vec3 V_Truchet_hex_fill(vec3 p, float w, int P, int A) {
  const double kSqrt3 = 1.7320508075688772lf;
  float sides = floor(P_(P, 0) + 0.5);
  bool flipX = fractoriumInteger(P_(P, 1), 0.0, 1.0) != 0.0, flipY = fractoriumInteger(P_(P, 2), 0.0, 1.0) != 0.0;
  float spreadX = P_(P, 3), spreadY = P_(P, 4), seed = floor(P_(P, 5) + 0.5);
  float sectors = 3.0 * sides, oneOverSectors = 1.0 / fractoriumZeps(sectors);
  float l1 = log(psi());
  float rx = floor(l1 * (psi() < 0.5 ? spreadX : -spreadX));
  float l2 = log(psi());
  float rz = floor(l2 * (psi() < 0.5 ? spreadY : -spreadY));
  // The hexagon's centre as the CPU computes it, in double, for the hash.
  double hx = kSqrt3 * double(rx) + kSqrt3 / 2.0lf * double(psi() < 0.5 ? rz : -rz), hy = 1.5lf * double(rz);
  bool keep = true;
  if (seed == 1.0) {
    keep = blurs_isOdd(rx) || blurs_isOdd(rz);
  } else if (seed >= 2.0) {
    keep = !(hashShadertoy(hx, hy, double(seed)) < 0.5);
  }
  float rangle = floor(psi() * sectors) * kTwoPi * oneOverSectors;
  float yAux = flipY && !keep ? -p.y : p.y, xAux = flipX && !keep ? -p.x : p.x;
  float ang = yAux * oneOverSectors * kPi + rangle, a = 1.0 + xAux * oneOverSectors * kPi;
  float fx = a * cos(ang), fy = a * sin(ang);
  float split = atan2c(fy, fx);
  if (split < 0.0) split += kTwoPi;
  float centre = (kPi + floor(1.5 * split / kPi) * kTwoPi) / 3.0;
  float nx = fx - cos(centre) * 2.0, ny = fy - sin(centre) * 2.0;
  float turn = keep ? 0.5 : -0.5;
  float h = 0.86602540378443865;
  float tx = h * nx - turn * ny, ty = turn * nx + h * ny;
  return vec3(w * (tx * 0.5 + float(hx)), w * (ty * 0.5 + float(hy)), w * p.z);
}
vec3 V_Truchet_hex_crop(vec3 p, float w, int P, int A) {
  const double kSqrt3 = 1.7320508075688772lf;
  float wd = clamp(P_(P, 0), 0.0, 5.0), mode = fractoriumInteger(P_(P, 1), 0.0, 2.0);
  bool inv = fractoriumInteger(P_(P, 2), 0.0, 1.0) != 0.0;
  float seed = floor(P_(P, 3) + 0.5);
  float d1 = 0.5 + wd, d2 = 0.5 - wd;
  const float kCoef = 1.5 / kPi;
  float u = psi();
  // Cube coordinates of the hexagon, rounded, the coordinate with the largest rounding error recomputed.
  float yOver3 = p.y / 3.0;
  float cx = 0.57735026918962576 * p.x - yOver3, cz = 2.0 * yOver3, cy = -cx - cz;
  float rx = roundHalfAway(cx), ry = roundHalfAway(cy), rz = roundHalfAway(cz);
  float dx = abs(rx - cx), dy = abs(ry - cy), dz = abs(rz - cz);
  if (dx > dy && dx > dz) {
    rx = -ry - rz;
  } else if (dy > dz) {
    ry = -rx - rz;
  } else {
    rz = -rx - ry;
  }
  double hxd = kSqrt3 * double(rx) + kSqrt3 / 2.0lf * double(rz), hyd = 1.5lf * double(rz);
  float hx = float(hxd), hy = float(hyd);
  float fx = p.x - hx, fy = p.y - hy;
  float add = 0.0;
  if (seed == 1.0) {
    if (!blurs_isOdd(rx) && !blurs_isOdd(rz)) add = kPi / 3.0;
  } else if (seed >= 2.0) {
    if (hashShadertoy(hxd, hyd, double(seed)) < 0.5) add = kPi / 3.0;
  }
  float angle = atan2c(fy, fx) + kPi / 6.0 - add;
  float angle2 = floor(angle * kCoef) / kCoef + kPi / 6.0 + add;
  float x0 = cos(angle2), y0 = sin(angle2);
  float dist = sqrt((fx - x0) * (fx - x0) + (fy - y0) * (fy - y0));
  bool crop = inv ? (dist > d1 || dist < d2) : (dist < d1 && dist > d2);
  if (crop) {
    if (mode < 0.5) {
      fx = 0.0;
      fy = 0.0;
    } else if (mode < 1.5) {
      fx = x0;
      fy = y0;
    } else {
      float rangle = atan2c(fy - y0, fx - x0), d = u < 0.5 ? d1 : d2;
      fx = x0 + cos(rangle) * d;
      fy = y0 + sin(rangle) * d;
    }
  }
  return vec3((fx + hx) * w, (fy + hy) * w, w * p.z);
}
vec3 V_squares(vec3 p, float w, int P, int A) {
  float cell = P_(P, 0), minRing = max(P_(P, 1), 0.0), maxRing = max(P_(P, 2), 0.0), rings = P_(P, 3);
  double seed = double(P_(P, 4)), zeroSeed = double(P_(P, 6));
  float zero = P_(P, 5);
  vec2 q = p.xy;
  if (cell != 0.0) {
    // The cell's centre in double, as the CPU hashes it.
    double dcell = double(cell);
    double dcx = (floor(double(p.x) / dcell) + 0.5lf) * dcell, dcy = (floor(double(p.y) / dcell) + 0.5lf) * dcell;
    float cx = float(dcx), cy = float(dcy);
    float lx = p.x - cx, ly = p.y - cy;
    float ax = abs(floor(lx * rings * 2.0 / cell + 0.5));
    float ay = abs(floor(ly * rings * 2.0 / cell + 0.5));
    float m = max(ax, ay);
    float top = maxRing + floor(hashShadertoy(dcx * dcx, dcy * dcy, seed) * (rings - maxRing));
    float level = m > top || m < minRing ? 0.0 : m - minRing;
    float angle = hashShadertoy(dcx * dcx, dcy * dcy, zeroSeed) < zero ? 0.0 : level * kPi / 2.0;
    float c = cos(angle), s = sin(angle);
    q = vec2(cx + lx * c - ly * s, cy + lx * s + ly * c);
  }
  return w * vec3(q, p.z);
}

// ---- variations_jwildfire_tail.cpp, variations_jwildfire_holdout.cpp (szubieta, dc_triTile) --------------
// and juliaNab of variations_blurs_more.cpp (helpers prefixed jwb_: the _jwildfire file's come after this one).

float jwb_nan() { return uintBitsToFloat(0x7fc00000u); }
// JWildfire's (int) Tools.limitValue of a cut_ shape's count (a NaN stays NaN, so no mode matches).
float jwb_intParam(float v, float lo, float hi) { return isnan(v) ? v : trunc(clamp(v, lo, hi)); }
// The same for the holdout file's counts, where a NaN is taken as the low end.
float jwb_limitedInt(float v, float lo, float hi) { return isnan(v) ? lo : trunc(clamp(v, lo, hi)); }
// GLSL's clamp and smoothstep as JWildfire's G writes them: a NaN passes, and edge0 > edge1 is fine.
float jwb_clamp(float v, float lo, float hi) { return isnan(v) ? v : min(max(v, lo), hi); }
float jwb_smoothstep(float e0, float e1, float v) {
  float t = jwb_clamp((v - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
// JWildfire's G.atan2, a cheap approximation (within about 0.07 rad) the cut_ shapes use.
float jwb_fastAtan2(float y, float x) {
  const float kQuarter = kPi / 4.0;
  float ay = abs(y);
  float angle =
      x >= 0.0 ? kQuarter - kQuarter * ((x - ay) / (x + ay)) : 3.0 * kQuarter - kQuarter * ((x + ay) / (ay - x));
  return y < 0.0 ? -angle : angle;
}
// std::max(a, b) as C++ has it: a unless a < b (so a NaN b leaves a).
float jwb_max(float a, float b) { return a < b ? b : a; }

vec3 V_juliaNab(vec3 p, float w, int P, int A) {
  float branches = abs(P_(P, 0)), root = fractoriumZeps(branches);
  float exponent = 1.0 / root / 2.0 * P_(P, 1), b = P_(P, 2), separ = P_(P, 3);
  // The branch in double: Ψ |n| has more bits than float holds.
  float k = float(floor(double(psi()) * double(branches)));
  float a = (atan2c(p.y, blurs_pow(abs(p.x), separ)) + kTwoPi * k) / root;
  float r = w * blurs_pow(dot(p.xy, p.xy), exponent);
  return vec3(r * cos(a) + b, r * sin(a) + b, p.z);
}

// java.util.Random's 48-bit state as (low 32 bits, high 16 bits): GLSL has no 64-bit integers.
uvec2 jwb_mul48(uvec2 a, uvec2 b) {
  uint hi, lo;
  umulExtended(a.x, b.x, hi, lo);
  return uvec2(lo, (hi + a.y * b.x + a.x * b.y) & 0xffffu);
}
uvec2 jwb_add48(uvec2 a, uvec2 b) {
  uint carry;
  uint lo = uaddCarry(a.x, b.x, carry);
  return uvec2(lo, (a.y + b.y + carry) & 0xffffu);
}
const uvec2 jwb_kJavaMultiplier = uvec2(0xdeece66du, 0x5u), jwb_kJavaIncrement = uvec2(0xbu, 0u);
uvec2 jwb_javaStep(uvec2 s) { return jwb_add48(jwb_mul48(s, jwb_kJavaMultiplier), jwb_kJavaIncrement); }
// The state 4k steps on, in O(log k): the step s → m s + a composed with itself by squaring.
uvec2 jwb_javaSkip4(uvec2 s, uint k) {
  uvec2 mul = jwb_kJavaMultiplier, add = jwb_kJavaIncrement;
  for (int i = 0; i < 2; ++i) {  // four steps as one
    add = jwb_mul48(jwb_add48(mul, uvec2(1u, 0u)), add);
    mul = jwb_mul48(mul, mul);
  }
  uvec2 accMul = uvec2(1u, 0u), accAdd = uvec2(0u);
  for (; k > 0u; k >>= 1) {
    if ((k & 1u) != 0u) {
      accMul = jwb_mul48(accMul, mul);
      accAdd = jwb_add48(jwb_mul48(accAdd, mul), add);
    }
    add = jwb_mul48(jwb_add48(mul, uvec2(1u, 0u)), add);
    mul = jwb_mul48(mul, mul);
  }
  return jwb_add48(jwb_mul48(accMul, s), accAdd);
}
// nextDouble() from the state, which it advances by two steps (26 and 27 bits).
double jwb_javaNextDouble(inout uvec2 s) {
  s = jwb_javaStep(s);
  uint high = (s.y << 10) | (s.x >> 22);
  s = jwb_javaStep(s);
  uint low = (s.y << 11) | (s.x >> 21);
  return (double(high) * 134217728.0lf + double(low)) * (1.0lf / 9007199254740992.0lf);
}
vec3 V_stabilize(vec3 p, float w, int P, int A) {
  // In double: Ψ n and the chance p/1000 need more bits than float holds.
  double count = max(1.0lf, min(double(roundHalfAway(P_(P, 0))), 2147483647.0lf));
  double chance = double(P_(P, 2)) / 1000.0lf;
  bool dc = clamp(roundHalfAway(P_(P, 3)), 0.0, 1.0) != 0.0;
  int seed = blurs_javaInt(roundHalfAway(P_(P, 1)));
  uvec2 seeded = uvec2(uint(seed) ^ jwb_kJavaMultiplier.x, (seed < 0 ? 0xffffu : 0u) ^ jwb_kJavaMultiplier.y);
  if (!(double(psi()) < chance)) return p;  // the weight is not applied
  uint k = uint(min(floor(double(psi()) * count), count - 1.0lf));
  uvec2 s = jwb_javaSkip4(seeded, k);
  double px = jwb_javaNextDouble(s) * 2.0lf - 1.0lf;
  double py = jwb_javaNextDouble(s) * 2.0lf - 1.0lf;
  if (dc) {  // ½, ¼, ¾, ⅛, …: (2(k + 1 − 2^L) + 1) / 2^(L+1), L = ⌊log₂(k + 1)⌋
    int level = findMSB(k + 1u);
    gColour = float(2u * (k + 1u - (1u << level)) + 1u) / exp2(float(level + 1));
  }
  return vec3(float(px), float(py), 0.0);
}

// The cut_ shapes' point: the transform's (mode 0) or a uniform one in [lo, lo + span)².
vec2 jwb_cutPoint(bool random, vec2 p, float lo, float span) {
  if (!random) return p;
  float x = span * psi() + lo;
  float y = span * psi() + lo;
  return vec2(x, y);
}
vec3 jwb_cutResult(bool drop, vec2 q, float z, float w) { return drop ? vec3(jwb_nan()) : w * vec3(q, z); }
vec3 V_cut_fractal(vec3 p, float w, int P, int A) {
  bool random = jwb_intParam(P_(P, 1), 0.0, 1.0) == 1.0;
  double time = double(P_(P, 2)), zoom = double(P_(P, 4));
  float iters = jwb_intParam(P_(P, 3), 1.0, 100.0);
  bool invert = jwb_intParam(P_(P, 5), 0.0, 1.0) == 1.0;
  // In double: the fractal's steps magnify float's rounding far beyond the pattern's scale.
  double cx = dcos(time + 1.5lf) * 0.15lf - 0.25lf, cy = dsin(time + 1.8lf) * 0.15lf - 0.25lf;
  vec2 q = jwb_cutPoint(random, p.xy, -0.5, 1.0);
  precise double ux = double(q.y) * zoom, uy = double(q.x) * zoom;
  for (float k = 0.0; k < iters; ++k) {
    precise double s = 0.5lf / (ux * ux + uy * uy);
    ux = abs(ux) * s + cx;
    uy = abs(uy) * s + cy;
  }
  precise double pattern = abs(ux * ux + uy * uy - 0.01lf) * 2.0lf;
  return jwb_cutResult(invert ? pattern <= 0.5lf : pattern > 0.5lf, q, p.z, w);
}
vec3 V_cut_glypho(vec3 p, float w, int P, int A) {
  bool random = jwb_intParam(P_(P, 0), 0.0, 1.0) == 1.0;
  float zoom = clamp(P_(P, 1), 0.1, 50.0);
  bool invert = jwb_intParam(P_(P, 2), 0.0, 1.0) == 1.0;
  float f1 = P_(P, 3), f2 = P_(P, 4), f3 = P_(P, 5);
  vec2 q = jwb_cutPoint(random, p.xy, -0.5, 1.0);
  vec2 u = q * zoom;
  // 30 discs: scales 1, 1.5, 2, each at ten angles 10⁻⁴ + jπ/5 (JWildfire's stepped angle).
  const float kStep = kPi / 5.0;
  float m = 0.0;
  for (int i = 0; i < 30; ++i) {
    float s = 1.0 + 0.5 * float(i / 10), a = 0.0001 + float(i % 10) * kStep + s * kStep * 0.5;
    vec2 v = u * s + 0.4 * vec2(cos(a), sin(a));
    m += jwb_smoothstep(f1 * s, 0.0, length(v)) * f3;
  }
  bool on = !(fract(m * f3) < f2);
  return jwb_cutResult(invert ? on : !on, q, p.z, w);
}
vec3 V_cut_triskel(vec3 p, float w, int P, int A) {
  bool random = jwb_intParam(P_(P, 0), 0.0, 1.0) == 1.0;
  float zoom = P_(P, 1);
  bool invert = jwb_intParam(P_(P, 2), 0.0, 1.0) == 1.0;
  vec2 q = jwb_cutPoint(random, p.xy, -1.0, 2.0);
  vec2 u = vec2(q.x * zoom, q.y * zoom + 0.1);
  float shade = 0.0;
  for (int arm = 0; arm < 3; ++arm) {
    u = vec2(-0.5 * u.x - 0.866 * u.y, 0.866 * u.x - 0.5 * u.y);
    float ax = u.x + 0.03, ay = u.y - 0.577;
    float l = 3.0 * sqrt(ax * ax + ay * ay), b = jwb_fastAtan2(ay, ax);
    shade = jwb_max(shade, l + fract(b / 7.0 + 0.3) < 2.0 ? 0.5 + 0.5 * sin(b + 6.24 * l) : 0.0);
  }
  float pattern = jwb_smoothstep(0.0, 0.1, abs(shade - 0.5)) - jwb_smoothstep(0.8, 0.9, shade);
  return jwb_cutResult(invert ? pattern <= 0.5 : pattern > 0.5, q, p.z, w);
}
// One family of cut_web's threads: |mod(v 10/2π + time, 2) − 1| − thick, smoothed over ±d/2.
float jwb_webThread(float v, float d, float time, float thick) {
  float m = v * (10.0 / kTwoPi) + time;
  return jwb_smoothstep(-0.5 * d, 0.5 * d, abs(m - 2.0 * floor(m / 2.0) - 1.0) - thick);
}
vec3 V_cut_web(vec3 p, float w, int P, int A) {
  float time = P_(P, 1);
  bool random = jwb_intParam(P_(P, 2), 0.0, 1.0) == 1.0;
  float thick = clamp(P_(P, 3), 0.0, 0.9);
  bool invert = jwb_intParam(P_(P, 4), 0.0, 1.0) == 1.0;
  vec2 q = jwb_cutPoint(random, p.xy, -1.0, 2.0);
  vec2 u = q * 0.5;
  float l = log(length(u)), b = jwb_fastAtan2(u.y, u.x);
  float d = l * 0.05 * (10.0 / kTwoPi);
  float pattern = jwb_webThread(l - 4.0 * b, d, time, thick) + jwb_webThread(b + 4.0 * l, d, time, thick);
  return jwb_cutResult(invert ? pattern <= 0.0 : pattern > 0.0, q, p.z, w);
}

// szubieta: a disc (JWildfire's 20-sided nBlur polygon) of radius scale at a random cell of the width ×
// height grid, the colour index Paul Bourke's pattern at the cell.
vec3 V_szubieta(vec3 p, float w, int P, int A) {
  float width = jwb_limitedInt(P_(P, 0), 32.0, 256.0), height = jwb_limitedInt(P_(P, 1), 32.0, 256.0);
  bool squareTile = jwb_limitedInt(P_(P, 2), 0.0, 1.0) == 1.0;
  float scale = isnan(P_(P, 3)) ? 0.0 : clamp(P_(P, 3), 0.0, 1.0);
  // nBlur's constants for 20 sides: the sector, tan(π/2 + sector/2), the spread 13/20^1.3 and its norm.
  const float kSector = kTwoPi / 20.0, kEdgeTan = -6.31375151, kSpread = 0.264608845, kSpreadNorm = -0.263080916;
  const float kTurnSin = 0.156434465, kTurnCos = 0.987688341;
  // The cell and the sector in double: Ψ · cells and Ψ · 32767 have more bits than float holds.
  double cells = double(width * height);
  uint cell = uint(min(floor(double(psi()) * cells), cells - 1.0lf)), rows = uint(height);
  float ci = float(cell / rows), cj = float(cell % rows);
  float u = psi();
  float edge = float(uint(floor(double(psi()) * 32767.0lf)) % 20u);
  float angle = (atan(kSpread * (u - 0.5)) / kSpreadNorm + 0.5 + edge) * kSector;
  vec2 q = vec2(sin(angle), cos(angle));
  for (int k = 0; k < 20 && angle > kSector; ++k) angle -= kSector;
  float t = tan(angle);
  float ex = kEdgeTan / (kEdgeTan - t), ey = ex * t;
  q *= sqrt(psi()) * sqrt(ex * ex + ey * ey);
  q = vec2(kTurnCos * q.x - kTurnSin * q.y, kTurnSin * q.x + kTurnCos * q.y);
  float w10 = 0.1 * w;
  int gi = int(ci), gj = int(cj);
  // Java's int % keeps the dividend's sign; |a % m| = |a| % m.
  int value = squareTile ? (gi & (gj - 2 * (gi ^ gj) + gj) & gi) % 256 : abs(gi * gi - 2 * (gi | gj) + gj * gj) % 255;
  gColour = float(abs(value)) / 255.0;
  return vec3(w10 * (q.x * scale + (ci - width / 2.0)), w10 * (q.y * scale + (cj - height / 2.0)), w * p.z);
}

// dc_triTile: a random tile of a substitution tiling, reached by random subdivisions of a prototile, and
// a uniform point of it. In double: the tiles' corners meet exactly (the point-in-tile test compares
// them), as on the CPU.
struct jwb_Tile {
  int type;  // which prototile (1 or 2)
  double col;
  dvec2 a, b, c;
};
struct jwb_Tiling {
  int tiling;
  double alfa, col1, col2;
};
jwb_Tile jwb_tile(jwb_Tiling s, int type, dvec2 a, dvec2 b, dvec2 c) {
  return jwb_Tile(type, type == 1 ? s.col1 : s.col2, a, b, c);
}
dvec2 jwb_lerp(dvec2 p, dvec2 q, double t) {
  precise dvec2 r = p + t * (q - p);
  return r;
}
dvec2 jwb_mid(dvec2 p, dvec2 q) { return (p + q) / 2.0lf; }
// The prototile t of each tiling (the CPU's cos and sin of its angles, to the last bit).
jwb_Tile jwb_prototile(jwb_Tiling s, int t) {
  const dvec2 o = dvec2(0.0lf);
  const double c72 = 0.30901699437494745lf, s72 = 0.95105651629515353lf, c36 = 0.80901699437494745lf;
  const double s36 = 0.58778525229247314lf, inv = 0.61803398874989479lf, sqrtInv = 0.78615137775742328lf;
  const double c60 = 0.50000000000000011lf, s60 = 0.8660254037844386lf, c30 = 0.86602540378443871lf;
  const double s30 = 0.49999999999999994lf;
  if (s.tiling == 1)
    return t == 1 ? jwb_tile(s, 1, o, dvec2(c72, s72), dvec2(0.6180339887498949lf, 0.0lf))
                  : jwb_tile(s, 2, o, dvec2(c36, s36), dvec2(1.6180339887498949lf, 0.0lf));
  if (s.tiling == 2) return jwb_tile(s, t, o, dvec2(c60, 0.0lf), dvec2(0.0lf, s60));
  if (s.tiling == 3)
    return t == 1 ? jwb_tile(s, 1, o, dvec2(c60, s60), dvec2(1.0000000000000002lf, 0.0lf))
                  : jwb_tile(s, 2, o, dvec2(c30, s30), dvec2(1.7320508075688774lf, 0.0lf));
  if (s.tiling == 4) return jwb_tile(s, t, o, dvec2(c72, s72), dvec2(0.6180339887498949lf, 0.0lf));
  if (s.tiling == 5)
    return t == 1 ? jwb_tile(s, 1, o, dvec2(0.0lf, 1.0lf), dvec2(2.0lf, 0.0lf))
                  : jwb_tile(s, 2, o, dvec2(0.0lf, 2.0lf), dvec2(1.0lf, 0.0lf));
  return t == 1 ? jwb_tile(s, 1, o, dvec2(inv, sqrtInv), dvec2(inv, 0.0lf))
                : jwb_tile(s, 2, o, dvec2(0.0lf, sqrtInv), dvec2(1.0lf, 0.0lf));
}
// One child of the tile, picked by u (JWildfire's devis for each tiling).
jwb_Tile jwb_subdivide(jwb_Tiling s, jwb_Tile tile, double u) {
  double al = s.alfa;
  dvec2 a = tile.a, b = tile.b, c = tile.c;
  bool one = tile.type == 1;
  if (s.tiling == 1) {  // FiveFold: Penrose triangles without rotations
    if (one) {
      dvec2 p4 = jwb_lerp(b, c, al);
      return u < al * al ? jwb_tile(s, 1, c, a, p4) : jwb_tile(s, 2, b, p4, a);
    }
    dvec2 p4 = jwb_lerp(c, a, al), p5 = jwb_lerp(c, b, al);
    return u < al * al          ? jwb_tile(s, 2, b, p4, a)
           : u < 2.0lf * al * al ? jwb_tile(s, 2, c, p5, p4)
                                 : jwb_tile(s, 1, b, p4, p5);
  }
  if (s.tiling == 2) {  // trihex: two kinds swap places in half the children
    dvec2 p4 = jwb_mid(a, c), p5 = jwb_mid(b, c), p6 = jwb_mid(a, p5);
    int other = 3 - tile.type;
    return u < 0.25lf  ? jwb_tile(s, tile.type, p4, p5, c)
           : u < 0.5lf ? jwb_tile(s, other, p4, p5, a)
           : u < 0.75lf ? jwb_tile(s, other, p6, p5, b)
                        : jwb_tile(s, tile.type, p6, a, b);
  }
  if (s.tiling == 3) {  // equithirds
    if (one) {
      dvec2 p4 = jwb_lerp(a, c, 0.5lf), p5 = jwb_lerp(p4, b, al);
      return u < al ? jwb_tile(s, 2, b, p5, a) : u < 2.0lf * al ? jwb_tile(s, 2, c, p5, b) : jwb_tile(s, 2, a, p5, c);
    }
    dvec2 p4 = jwb_lerp(a, c, al), p5 = jwb_lerp(c, a, al);
    return u < al ? jwb_tile(s, 2, b, p4, a) : u < 2.0lf * al ? jwb_tile(s, 2, c, p5, b) : jwb_tile(s, 1, p4, b, p5);
  }
  if (s.tiling == 4) {  // overlapping Robinson triangles
    dvec2 p4 = jwb_lerp(b, a, al), p5 = jwb_lerp(a, b, al), p6 = jwb_lerp(b, c, al);
    return u < 0.3lf    ? jwb_tile(s, 2, p4, b, p6)
           : u < 0.63lf ? jwb_tile(s, 3 - tile.type, p6, a, p5)
                        : jwb_tile(s, 1, c, a, p6);
  }
  if (s.tiling == 5) {  // pinwheel: five children, ⌊5u⌋
    int k = clamp(int(u * 5.0lf), 0, 4);
    if (one) {
      dvec2 p4 = jwb_lerp(b, c, 0.2lf), p5 = jwb_lerp(b, c, 0.6lf), p6 = jwb_lerp(a, c, 0.5lf);
      dvec2 p7 = jwb_lerp(a, p4, 0.5lf);
      return k == 0   ? jwb_tile(s, 2, p4, a, b)
             : k == 1 ? jwb_tile(s, 2, p7, p6, a)
             : k == 2 ? jwb_tile(s, 1, p7, p4, p6)
             : k == 3 ? jwb_tile(s, 1, p5, p6, p4)
                      : jwb_tile(s, 2, p5, c, p6);
    }
    dvec2 p4 = jwb_lerp(c, b, 0.2lf), p5 = jwb_lerp(c, b, 0.6lf), p6 = jwb_lerp(a, b, 0.5lf);
    dvec2 p7 = jwb_lerp(a, p4, 0.5lf);
    return k == 0   ? jwb_tile(s, 1, p4, c, a)
           : k == 1 ? jwb_tile(s, 1, p7, a, p6)
           : k == 2 ? jwb_tile(s, 2, p7, p6, p4)
           : k == 3 ? jwb_tile(s, 2, p5, p4, p6)
                    : jwb_tile(s, 1, p5, p6, b);
  }
  // golden pinwheel
  if (one) {
    dvec2 p4 = jwb_lerp(a, b, al), p5 = jwb_lerp(b, a, al), p6 = jwb_lerp(c, b, al), p7 = jwb_lerp(a, c, al);
    return u < 0.146lf   ? jwb_tile(s, 1, a, p4, p7)
           : u < 0.382lf ? jwb_tile(s, 2, p4, p7, p6)
           : u < 0.618lf ? jwb_tile(s, 2, c, p6, p7)
           : u < 0.764lf ? jwb_tile(s, 1, p4, p6, p5)
                         : jwb_tile(s, 2, p5, p6, b);
  }
  dvec2 p4 = jwb_lerp(b, a, al), p5 = jwb_lerp(b, c, al), p6 = jwb_lerp(c, b, al), p7 = jwb_lerp(a, c, al);
  dvec2 p8 = jwb_lerp(c, a, al), p9 = jwb_lerp(p4, p7, al), p10 = jwb_lerp(p7, p4, al);
  return u < 0.146lf   ? jwb_tile(s, 2, p4, b, p5)
         : u < 0.236lf ? jwb_tile(s, 1, p4, p5, p9)
         : u < 0.382lf ? jwb_tile(s, 2, p10, a, p4)
         : u < 0.472lf ? jwb_tile(s, 1, p7, a, p10)
         : u < 0.618lf ? jwb_tile(s, 2, p9, p5, p7)
         : u < 0.764lf ? jwb_tile(s, 2, p6, p5, p7)
         : u < 0.854lf ? jwb_tile(s, 1, p7, p6, p8)
                       : jwb_tile(s, 2, p8, p6, c);
}
// A walk of subdivisions (steps, on, eq, depth), at most 64 as on the CPU; each child's kind enters
// path as a binary digit when record is set (Java's int, wrapping).
jwb_Tile jwb_walkTiles(jwb_Tiling s, jwb_Tile tile, vec4 walk, bool record, inout uint path) {
  float left = walk.x, k = 1.0, taken = 0.0;
  while (left > 0.0 && taken < 64.0) {
    tile = jwb_subdivide(s, tile, double(psi()));
    taken += 1.0;
    if (record) path = 2u * path + uint(tile.type - 1);
    bool other = float(tile.type) != walk.z;
    if (walk.y == 0.0) {
      if (k == walk.x && other) left += walk.w;
    } else if (k >= walk.x && k < walk.x + walk.w && other) {
      left += 1.0;
    }
    left -= 1.0;
    k += 1.0;
  }
  return tile;
}
// JWildfire's discretNoise: Hugo Elias' integer hash over [0, 1].
double jwb_discreteNoise(uint n) {
  uint h = (n << 13) ^ n;
  uint r = h * (h * h * 15731u + 789221u) + 1376312589u;
  return double(r & 0x7fffffffu) / 2147483647.0lf;
}
// A uniform point of the triangle as JWildfire's tile blur finds it: the corners sorted by x, two
// draws pick a point of a parallelogram over half the triangle, folded back in.
dvec2 jwb_pointInTile(jwb_Tile tile) {
  dvec2 p1, p2, p3;
  dvec2 a = tile.a, b = tile.b, c = tile.c;
  if (a.x <= b.x && a.x <= c.x) {
    p1 = a;
    p2 = b.x <= c.x ? b : c;
    p3 = b.x <= c.x ? c : b;
  } else if (b.x <= a.x && b.x <= c.x) {
    p1 = b;
    p2 = a.x <= c.x ? a : c;
    p3 = a.x <= c.x ? c : a;
  } else {
    p1 = c;
    p2 = a.x <= b.x ? a : b;
    p3 = a.x <= b.x ? b : a;
  }
  double r1 = double(psi());
  double r2 = double(psi());
  dvec2 q;
  if (p1.x == p2.x && p2.x == p3.x) {
    double v1, v2;
    if (p1.y <= p2.y && p1.y <= p3.y) {
      v1 = p1.y;
      v2 = p3.y > p2.y ? p2.y : p3.y;
    } else if (p2.y <= p1.y && p2.y <= p3.y) {
      v1 = p2.y;
      v2 = p3.y > p1.y ? p1.y : p3.y;
    } else {
      v1 = p3.y;
      v2 = p2.y > p1.y ? p1.y : p2.y;
    }
    precise double y = v1 + r1 * (v2 - v1);
    q = dvec2(p1.x, y);
  } else if (p1.x == p2.x) {
    dvec2 p4 = jwb_mid(p1, p3);
    precise dvec2 p5 = p3 + p2 - p4, p6 = p1 + p2 - p4;
    q = jwb_lerp(jwb_lerp(p3, p4, r1), jwb_lerp(p5, p2, r1), r2);
    precise double edge = p3.y + (p2.y - p3.y) / (p2.x - p3.x) * (q.x - p3.x);
    precise double line = p3.y + (p3.y - p1.y) / (p3.x - p1.x) * (p2.x - p3.x);
    bool above = p2.y > line;
    if (above ? q.y > edge : q.y < edge) q = jwb_lerp(jwb_lerp(p2, p6, r1), jwb_lerp(p4, p1, r1), r2);
  } else {
    dvec2 p4 = jwb_mid(p1, p3);
    precise dvec2 p5 = p1 + p2 - p4, p6 = p3 + p2 - p4;
    q = jwb_lerp(jwb_lerp(p1, p4, r1), jwb_lerp(p5, p2, r1), r2);
    precise double edge = p1.y + (p2.y - p1.y) / (p2.x - p1.x) * (q.x - p1.x);
    precise double line = p1.y + (p3.y - p1.y) / (p3.x - p1.x) * (p2.x - p1.x);
    bool above = p2.y > line;
    if (above ? q.y > edge : q.y < edge) q = jwb_lerp(jwb_lerp(p2, p6, r1), jwb_lerp(p4, p3, r1), r2);
  }
  // Degenerate tiles: a point of the segment.
  if (p1 == p2) q = jwb_lerp(p1, p3, r1);
  if (p1 == p3) q = jwb_lerp(p1, p2, r1);
  if (p2 == p3) q = jwb_lerp(p1, p2, r1);
  return q;
}
vec3 V_dc_triTile(vec3 p, float w, int P, int A) {
  int tiling = int(jwb_limitedInt(P_(P, 0), 1.0, 6.0));
  int t = roundHalfAway(P_(P, 1)) <= 1.0 ? 1 : 2;
  double alfa = tiling == 1 || tiling == 4 ? 0.6180339887498949lf
                : tiling == 3              ? 1.0lf / 3.0lf
                : tiling == 6              ? 0.3819660112501051lf
                                           : 0.0lf;
  jwb_Tiling s = jwb_Tiling(tiling, alfa, double(P_(P, 2)), double(P_(P, 3)));
  vec4 first = vec4(roundHalfAway(P_(P, 5)), jwb_limitedInt(P_(P, 4), 0.0, 1.0), jwb_limitedInt(P_(P, 6), 0.0, 2.0),
                    roundHalfAway(P_(P, 7)));
  jwb_Tile tile = jwb_prototile(s, t);
  tile.col = 0.0lf;  // JWildfire's t2 starts with colour 0, which stays where no step is taken
  uint path = 0u;
  tile = jwb_walkTiles(s, tile, first, false, path);
  int kind = tile.type;
  int Q = kind == 1 ? 8 : 12;  // the second walk's parameters: itt1, … or itt2, …
  vec4 second = vec4(roundHalfAway(P_(P, Q + 1)), jwb_limitedInt(P_(P, Q), 0.0, 1.0),
                     jwb_limitedInt(P_(P, Q + 2), 0.0, 2.0), roundHalfAway(P_(P, Q + 3)));
  tile = jwb_walkTiles(s, tile, second, true, path);
  double base = jwb_discreteNoise(path + (kind == 1 ? 43u : 31u));
  dvec2 q = jwb_pointInTile(tile);
  double sum = base + tile.col;
  gColour = float(sum - trunc(sum));  // C's fmod(·, 1)
  return vec3(w * float(q.x), w * float(q.y), w * p.z);
}

// dc_crackle_wf: crackle's map of a random point of the blurred disc (the point itself with weight 0),
// its Voronoi distance L giving the colour index. After its parameters (flame_kernel.cpp puts them
// there, as for crackle): its slice z as a double's two halves, then the noise tables' place.
vec3 V_dc_crackle_wf(vec3 p, float w, int P, int A) {
  float cellsize = P_(P, 0), power = P_(P, 1), distort = P_(P, 2), scale = P_(P, 3);
  float colourScale = P_(P, 5), colourOffset = P_(P, 6);
  vec3 o = vec3(0.0, 0.0, w * p.z);
  if (cellsize == 0.0) return o;  // crackle's guard: no cells, nothing drawn or coloured
  // The slice and the tables only move the cells with distort (crackleCentre reads them only then).
  double slice =
      distort == 0.0 ? 0.0lf : packDouble2x32(uvec2(floatBitsToUint(P_(P, 7)), floatBitsToUint(P_(P, 8))));
  int N = distort == 0.0 ? 0 : int(P_(P, 9));
  float halfSize = cellsize / 2.0;
  vec2 u = p.xy;
  if (w != 0.0) {
    float a = psi(), b = psi(), c = psi();
    float blurred = (a + b) / 2.0 + (c - 0.5) / 4.0;
    float theta = kTwoPi * psi();
    u = blurred * vec2(sin(theta), cos(theta));
  }
  vec3 cell = crackleCell(u, halfSize, distort, slice, N);
  vec2 centre = cell.xy;
  float distance = cell.z;
  float pull = pow(distance + 1e-30, power) * scale / (distance + 1e-30);
  float c = distance * colourScale + colourOffset;
  gColour = c > 1.0 ? 1.0 : (c >= 0.0 ? c : 0.0);  // a NaN as 0
  o.xy = w * ((u - centre) * pull + centre);
  return o;
}

// ---- per-orbit memory, a moved transform point and octaves of noise (variations_plugins.cpp:
// smartcrop; variations_jwildfire_glsl.cpp: fract_mandelbrot_wf; variations_blurs_more.cpp: crob;
// variations_direct_colour.cpp: dc_perlin) -------------------------------------------------------

const float lane_kFractoriumEps = 2.220446049250313e-16;  // Fractorium's Zeps: the double's epsilon
float lane_zeps(float v) { return v == 0.0 ? lane_kFractoriumEps : v; }
float lane_nan() { return uintBitsToFloat(0x7fc00000u); }

// Zy0rg's smartcrop as Fractorium has it. Its memory (4 doubles after its first slot in gLane): the
// last point let through, times w, and its colour index. The transform's point it crops for static
// ≤ 1 is the point itself in a pre_ or ordinary term, gVariationT in a post_ one.
vec3 V_smartcrop(vec3 p, float w, int P, int A) {
  float power = P_(P, 0), radius = P_(P, 1), roundstr = P_(P, 2), roundwidth = P_(P, 3);
  float distortion = P_(P, 4), edge = P_(P, 5), scatter = P_(P, 6), offset = P_(P, 7), rotation = P_(P, 8);
  float cropmode = P_(P, 9), staticMode = P_(P, 10);
  int M = int(P_(P, 11));
  bool keepInside = (power > 0.0) == (radius > 0.0);
  float workRadius = abs(radius);
  float workPower = power == 0.0 ? lane_kFractoriumEps : abs(power);
  bool radial = workPower < 2.0;
  if (radial) workPower *= kPi;
  float alpha = kTwoPi / workPower;
  float halfSin = sin(alpha / 2.0);
  float roundCoeff = roundstr / lane_zeps(halfSin) / workPower * 2.0;
  float turn = rotation * alpha;
  bool readsPoint = staticMode > 1.0;
  bool cropReplaces = staticMode > 1.0 || staticMode == -1.0;
  bool keepReplaces = staticMode > 0.0;
  bool keepsTransformPoint = staticMode == 3.0;
  vec3 t = gStage == 2 ? gVariationT : p;
  vec3 q = readsPoint ? p : t;
  float angle = atan2c(q.y, q.x);
  float rad = sqrt(q.x * q.x + q.y * q.y);
  // All three drawn, in the plugin's order, as the CPU does.
  float a = psi(), b = psi(), c = psi();
  bool cropped = false, toMemory = false, toOrigin = false;
  vec2 moved = vec2(0.0);
  if (radial) {
    float jitter = edge * (a - 0.5);
    float sector = angle / kTwoPi + 1.0 + jitter;
    sector = (sector - trunc(sector)) * kTwoPi;
    if ((sector > workPower) == keepInside) {
      cropped = true;
      if (cropmode == 2.0) {
        toMemory = true;
      } else {
        float spread = (c * scatter + offset + jitter) * kPi;
        float turned = trunc(b * 2.0) > 0.0 ? workPower + spread : -spread;
        moved = w * rad * vec2(cos(turned), sin(turned));
      }
    }
  } else {
    float coeff = 1.0;
    if (distortion != 0.0) {
      float side = (angle + kPi) / alpha;
      side -= trunc(side);
      side = side < 0.5 ? side : 1.0 - side;
      coeff = 1.0 / cos(side * alpha);
      if (roundstr != 0.0) {
        float width = (roundwidth != 1.0 ? exp(log(side * 2.0) * roundwidth) : side * 2.0) * roundCoeff;
        coeff = abs((1.0 - width) * coeff + width);
      }
      if (distortion != 1.0) coeff = exp(log(coeff) * distortion);
    }
    float reach = coeff * (edge != 0.0 ? workRadius + edge * (a - 0.5) : workRadius);
    if ((rad > reach) == keepInside) {
      cropped = true;
      if (cropmode == 2.0) {
        toMemory = true;
      } else if (cropmode == 0.0) {
        toOrigin = true;
      } else {
        float r = cropmode == -1.0 ? rad : reach + coeff * ((edge != 0.0 ? b : a) * scatter + offset);
        moved = w * r * vec2(cos(angle + turn), sin(angle + turn));
      }
    }
  }
  vec3 result;
  if (!cropped) {
    vec3 kept = w * (keepsTransformPoint ? t : q);
    gLane[M] = double(kept.x);
    gLane[M + 1] = double(kept.y);
    gLane[M + 2] = double(kept.z);
    if (cropmode == 2.0) gLane[M + 3] = double(gColour);
    result = keepReplaces ? kept : kept + p;
  } else if (toMemory) {
    result = vec3(gLane[M], gLane[M + 1], gLane[M + 2]);
    gColour = float(gLane[M + 3]);
    if (!cropReplaces) result += p;
  } else if (toOrigin) {
    result = cropReplaces ? vec3(0.0) : p;
  } else {
    result = vec3(moved, w * q.z);
    if (!cropReplaces) result += p;
  }
  return result;
}

// JWildfire's fract_mandelbrot_wf. The orbits run in double with the CPU's operations (precise:
// no fused multiply-adds), since where a start escapes, and the buddhabrot's orbit, hang on every bit.
// JWildfire's count parameter: rounded half away from 0, clamped, NaN as `nanValue`.
int lane_jwfCount(float v, float lo, float hi, float nanValue) {
  return int(isnan(v) ? nanValue : clamp(roundHalfAway(v), lo, hi));
}
// One step of z → z^power + c as the CPU expands it; sq: the squares of the point before the step.
void lane_mandelbrotStep(int power, dvec2 c, inout dvec2 z, inout dvec2 sq, inout double count) {
  precise double x = z.x, y = z.y;
  precise double xs = x * x, ys = y * y;
  precise double nx, ny;
  if (power == 2) {
    ny = 2.0lf * x * y + c.y;
    nx = (xs - ys) + c.x;
  } else if (power == 3) {
    nx = xs * x - 3.0lf * x * ys + c.x;
    ny = 3.0lf * xs * y - ys * y + c.y;
  } else if (power == 4) {
    nx = xs * xs + ys * ys - 6.0lf * xs * ys + c.x;
    ny = 4.0lf * x * y * (xs - ys) + c.y;
  } else {
    precise double px = x * (xs * xs - 10.0lf * xs * ys + 5.0lf * ys * ys);
    precise double py = y * (ys * ys - 10.0lf * xs * ys + 5.0lf * xs * xs);
    for (int k = 5; k < power; ++k) {
      precise double ax = x * px - y * py, ay = x * py + px * y;
      px = ax;
      py = ay;
    }
    nx = px + c.x;
    ny = py + c.y;
  }
  z = dvec2(nx, ny);
  sq = dvec2(xs, ys);
  count += 1.0lf;
}
// JWildfire's iterate from c: steps while the point has not escaped, at most maxIter tests; the tests.
int lane_mandelbrotIterate(int power, dvec2 c, int maxIter, out dvec2 z, out dvec2 sq, out double count) {
  z = c;
  sq = dvec2(0.0lf);
  count = 0.0lf;
  int tests = 0;
  while (tests++ < maxIter && !(sq.x + sq.y >= 4.0lf)) lane_mandelbrotStep(power, c, z, sq, count);
  return tests;
}
float lane_fractHeight(float count, float maxIter, float scalez, float offsetz, bool logZ) {
  float t = count / maxIter;
  return scalez / 10.0 * (logZ ? log(1.0 + t) * 0.43429448190325176 : t) + offsetz;
}
vec3 V_fract_mandelbrot_wf(vec3 p, float w, int P, int A) {
  int maxIter = lane_jwfCount(P_(P, 0), 1.0, 10000.0, 1.0);
  int power = lane_jwfCount(P_(P, 6), 2.0, 64.0, 2.0);
  int clipIterMin = lane_jwfCount(P_(P, 9), -1e9, 1e9, 0.0);
  int clipIterMax = lane_jwfCount(P_(P, 10), -1e9, 1e9, 0.0);
  int maxClipIter = lane_jwfCount(P_(P, 11), -1.0, 100.0, 0.0);
  int minIter = lane_jwfCount(P_(P, 12), -1.0, 1e9, 0.0);
  // The bounds in double (after its 20 parameters and the memory slot): where the starts fall hangs
  // on them, and a float's −2.35 moves a start by 1e-7, which tips its escape count now and then.
  double xmin = paramDouble(P + 21, 1), xmax = paramDouble(P + 21, 2);
  double ymin = paramDouble(P + 21, 3), ymax = paramDouble(P + 21, 4);
  float scalez = P_(P, 8), scale = P_(P, 13), offsetx = P_(P, 14), offsety = P_(P, 15), offsetz = P_(P, 16);
  float zFill = clamp(P_(P, 17), 0.0, 1.0);
  bool buddhabrot = lane_jwfCount(P_(P, 5), -1.0, 1.0, 0.0) > 0;
  bool directColour = lane_jwfCount(P_(P, 7), -1.0, 1.0, 0.0) != 0;
  bool logZ = lane_jwfCount(P_(P, 18), 0.0, 1.0, 0.0) == 1;
  bool colourOnly = lane_jwfCount(P_(P, 19), 0.0, 1.0, 0.0) == 1;
  int M = int(P_(P, 20));
  dvec2 z, sq;
  double count;
  if (buddhabrot) {
    // The lane's memory: drawing or not, the start, the point, its squares, the steps, the length.
    dvec2 c;
    double len = gLane[M + 8];
    if (gLane[M] == 0.0lf) {
      for (int k = 0;; ++k) {
        c.x = (xmax - xmin) * double(psi()) + xmin;
        c.y = (ymax - ymin) * double(psi()) + ymin;
        int tests = lane_mandelbrotIterate(power, c, maxIter, z, sq, count);
        if (sq.x + sq.y >= 4.0lf && tests > minIter) {
          len = double(tests);
          break;
        }
        if (k == 249) return vec3(lane_nan());
      }
      z = c;
      sq = dvec2(0.0lf);
      count = 0.0lf;
      for (int skip = 0; skip < minIter; ++skip) lane_mandelbrotStep(power, c, z, sq, count);
    } else {
      c = dvec2(gLane[M + 1], gLane[M + 2]);
      z = dvec2(gLane[M + 3], gLane[M + 4]);
      sq = dvec2(gLane[M + 5], gLane[M + 6]);
      count = gLane[M + 7];
    }
    lane_mandelbrotStep(power, c, z, sq, count);
    gLane[M] = count >= len ? 0.0lf : 1.0lf;
    gLane[M + 1] = c.x;
    gLane[M + 2] = c.y;
    gLane[M + 3] = z.x;
    gLane[M + 4] = z.y;
    gLane[M + 5] = sq.x;
    gLane[M + 6] = sq.y;
    gLane[M + 7] = count;
    gLane[M + 8] = len;
    gColour = clamp(float(double(gColour) + count / len), 0.0, 1.0);
    return vec3(scale * w * (vec2(z) + vec2(offsetx, offsety)), 0.0);
  }
  // Up to max_clip_iter starts; the first neither deep inside nor far outside is kept.
  dvec2 c0 = dvec2(0.0lf);
  int tests = 0;
  for (int k = 0; k < maxClipIter; ++k) {
    if (colourOnly) {
      c0 = dvec2(p.xy);
    } else {
      c0.x = (xmax - xmin) * double(psi()) + xmin;
      c0.y = (ymax - ymin) * double(psi()) + ymin;
    }
    tests = lane_mandelbrotIterate(power, c0, maxIter, z, sq, count);
    bool clipped = (clipIterMax < 0 && tests >= maxIter + clipIterMax) || (clipIterMin > 0 && tests <= clipIterMin);
    if (!clipped) break;
    if (k == maxClipIter - 1) return vec3(lane_nan());
  }
  vec3 o = vec3(0.0);
  if (!colourOnly) o.xy = scale * w * (vec2(c0) + vec2(offsetx, offsety));
  float height = scale * w * lane_fractHeight(float(tests), float(maxIter), scalez, offsetz, logZ);
  if (zFill > 1e-8 && psi() < zFill) {
    float below = scale * w * lane_fractHeight(float(tests - 1), float(maxIter), scalez, offsetz, logZ);
    height = (below - height) * psi() + height;
  }
  o.z = height;
  if (directColour) {
    float c = gColour + float(tests) / float(maxIter);
    if (c > 1.0) c -= 1.0;
    gColour = c < 0.0 ? 0.0 : (c > 1.0 ? 1.0 : c);
  }
  return o;
}

// Fractorium's crob: a crop to the frame [left, right] × [top, bottom], the outside sent to a random
// point of the band inside the frame (blur) or to the origin, unweighted; as an ordinary term it moves
// the transform's point (gVariationT) there too. The rejection loops stop at 64 tries, as the CPU's.
// Ψ^e as std::pow has it for Ψ in [0, 1) and e ≥ 0 (GLSL's pow leaves 0^e undefined).
float lane_powUnit(float u, float e) { return e == 0.0 ? 1.0 : (u == 0.0 ? 0.0 : pow(u, e)); }
vec3 V_crob(vec3 p, float w, int P, int A) {
  float top = min(P_(P, 0), P_(P, 1)), bottom = max(P_(P, 0), P_(P, 1));
  if (top == bottom) {
    top = -1.0;
    bottom = 1.0;
  }
  float left = min(P_(P, 2), P_(P, 3)), right = max(P_(P, 2), P_(P, 3));
  if (left == right) {
    left = -1.0;
    right = 1.0;
  }
  bool blur = fractoriumInteger(P_(P, 4), -2147483647.0, 2147483647.0) != 0.0;
  float ratio = max(min(P_(P, 5), 1.0), 0.0), power = max(P_(P, 6), 0.0);
  float intervalX = abs(right) - left, intervalY = abs(bottom) - top;
  float halfX = intervalX / 2.0, halfY = intervalY / 2.0;
  float minHalf = halfX > halfY ? halfY : halfX;
  float x0c = halfX > halfY ? right - minHalf : right - halfX;
  float y0c = halfX < halfY ? top + minHalf : top + halfY;
  float setProb = intervalY / (intervalX + intervalY);
  float inset = blur ? minHalf * ratio : 0.0;
  float quarter = 0.25 * setProb, halfProb = 0.5 * setProb, threeQuarters = 0.75 * setProb;
  float section = psi();
  vec2 c = vec2(0.0);
  if (blur) {
    if (section < setProb) {
      for (int tries = 0; tries < 64; ++tries) {
        c.y = top + psi() * halfY;
        c.x = right - lane_powUnit(psi(), power) * ratio * minHalf;
        if (!((c.y - y0c) / lane_zeps(c.x - x0c) < -1.0)) break;
      }
      c.x = section < halfProb ? left + right - c.x : c.x;
      c.y = section > quarter && section < threeQuarters ? bottom + top - c.y : c.y;
    } else {
      for (int tries = 0; tries < 64; ++tries) {
        c.x = right - psi() * halfX;
        c.y = top + lane_powUnit(psi(), power) * ratio * minHalf;
        float gradient = (c.y - y0c) / lane_zeps(c.x - x0c);
        if (!(gradient <= 0.0 && gradient > -1.0)) break;
      }
      c.y = section > halfProb ? bottom + top - c.y : c.y;
      c.x = section > quarter && section < threeQuarters ? left + right - c.x : c.x;
    }
  }
  bool outside = p.x < left + inset || p.x > right - inset || p.y < top + inset || p.y > bottom - inset;
  if (!outside) c = vec2(0.0);
  if (outside && gStage == 1) gVariationT.xy = c;
  return vec3(c, w * p.z);
}

// Fractorium's dc_perlin with voxflame's simplex noise (simplexNoise3D, the tables' place after its
// parameters and crackle's two slice words). Its octaves scale x twice and z never, as the CPU's.
float lane_perlinNoise(int N, dvec3 v, float amps, float freqs, int octaves) {
  float total = 0.0, a = 1.0;
  for (int k = 0; k < octaves; ++k) {
    total += simplexNoise3D(N, v) / lane_zeps(a);
    a *= amps;
    v.x *= double(freqs);
    v.y *= double(freqs);
    v.x *= double(freqs);
  }
  return total;
}
vec3 V_dc_perlin(vec3 p, float w, int P, int A) {
  float shape = fractoriumInteger(P_(P, 0), 0.0, 2.0), map = fractoriumInteger(P_(P, 1), 0.0, 5.0);
  float selectCentre = clamp(P_(P, 2), -1.0, 1.0), selectRange = clamp(P_(P, 3), 0.1, 2.0);
  float centre = P_(P, 4), range = P_(P, 5), edge = P_(P, 6), scale = P_(P, 7);
  int octaves = int(fractoriumInteger(P_(P, 8), 1.0, 5.0));
  float amps = P_(P, 9), freqs = P_(P, 10), z0 = P_(P, 11);
  int bailout = int(fractoriumInteger(P_(P, 12), 2.0, 1000.0));
  float seed = isinf(P_(P, 13)) || isnan(P_(P, 13)) ? 0.0 : P_(P, 13);
  int N = int(P_(P, 16));
  float bottom = selectCentre - selectRange, top = selectCentre + selectRange;
  bottom = bottom > 0.75 ? 0.75 : (bottom < -2.0 ? -3.0 : bottom);
  top = top < -0.75 ? -0.75 : (top > 3.0 ? 3.0 : top);
  // The point in double: the noise's simplex choice hangs on its last bits.
  double vx = 0.0lf, vy = 0.0lf;
  float n = 0.0, e = 0.0;
  int tries = 0;
  do {
    e = 0.0;
    float r;
    if (shape == 0.0) {
      vx = double(1.0 + edge) * (double(psi()) - 0.5lf);
      vy = double(1.0 + edge) * (double(psi()) - 0.5lf);
      r = float(max(abs(vx), abs(vy)));
      if (r > 1.0 - edge) e = 0.5 * (r - 1.0 + edge) / edge;
    } else {
      if (shape == 1.0) {
        r = psi() + psi();
        r = (r > 1.0 ? 2.0 - r : r) * (1.0 + edge);
      } else {
        r = (1.0 + edge) * psi();
      }
      if (r > 1.0 - edge) e = 0.5 * (r - 1.0 + edge) / edge;
      float theta = psi() * kTwoPi;
      vx = double(0.5 * r * sin(theta));
      vy = double(0.5 * r * cos(theta));
    }
    precise double r2 = vx * vx + vy * vy;
    precise dvec3 v = double(scale) * dvec3(vx, vy, double(z0));
    if (map == 1.0 || map == 2.0 || map == 3.0) {
      double f = map == 1.0 ? (r2 == 0.0lf ? 1.0lf / double(lane_kFractoriumEps) : 1.0lf / r2)
                            : 1.0lf / (r2 + (map == 2.0 ? 0.5lf : 0.25lf));
      v.xy *= f;
    } else if (map == 4.0 || map == 5.0) {
      double lift = sqrt(abs(0.25lf - r2));
      v.z = double(scale) * ((map == 4.0 ? 1.0lf : 2.0lf) * lift + double(z0));
    }
    n = lane_perlinNoise(N, v, amps, freqs, octaves);
    e = n > 0.0 ? n * (1.0 + e * e * 20.0) + 2.0 * e : n * (1.0 + e * e * 20.0) - 2.0 * e;
  } while ((e < bottom || e > top) && tries++ < bailout);
  float c = centre + range * n + seed;
  gColour = c - floor(c);
  return vec3(w * vec2(vx, vy), w * p.z);
}
