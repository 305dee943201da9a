// Flame variations for the GPU backend (flame_variations.glsl has the conventions and the helpers):
// the CPU catalogue's variations_2d_d.cpp, variations_2d_m.cpp and variations_2d_s.cpp
// (engine/core/flame/), in float.


// ---- shared helpers (this file's, prefixed v2dm_) --------------------------------------------

float v2dm_signNz(float v) { return v < 0.0 ? -1.0 : 1.0; }
// Fractorium's INTEGER parameter: ⌊v + ½⌋ clamped.
// GLSL's tanh may overflow to NaN for large arguments; it is ±1 in float well before 20.
float v2dm_tanh(float v) { return tanh(clamp(v, -20.0, 20.0)); }
// Fractorium's wrap of a cyclic parameter into [lo, hi] (fmod from the end it left).
float v2dm_wrapCyclic(float v, float lo, float hi) {
  if (v > hi) return lo + fmodc(v - lo, hi - lo);
  if (v < lo) return hi - fmodc(hi - v, hi - lo);
  return v;
}
// std::pow with a whole exponent: defined for a negative base, as GLSL's pow is not.
float v2dm_powWhole(float b, float e) {
  if (e == 0.0) return 1.0;
  float m = pow(abs(b), e);
  return (b < 0.0 && fmodc(e, 2.0) != 0.0) ? -m : m;
}
// std::pow for any exponent: NaN for a negative base and a fractional exponent.
float v2dm_powC(float b, float e) {
  if (e == 0.0) return 1.0;
  if (b == 0.0) return e > 0.0 ? 0.0 : uintBitsToFloat(0x7f800000u);
  if (b > 0.0) return pow(b, e);
  return e == trunc(e) ? v2dm_powWhole(b, e) : uintBitsToFloat(0x7fc00000u);
}

// ---- polynomial maps (variations_2d_m.cpp) ----------------------------------------------------

vec3 V_lens(vec3 p, float w, int P, int A) {
  return w * vec3(0.5 * (p.x * p.x - p.y * p.y), p.x * p.y, p.z);
}
vec3 V_linearT(vec3 p, float w, int P, int A) {
  return w * vec3(v2dm_signNz(p.x) * pow(abs(p.x), P_(P, 0)), v2dm_signNz(p.y) * pow(abs(p.y), P_(P, 1)), p.z);
}
vec3 V_lozi(vec3 p, float w, int P, int A) {
  return w * vec3(1.0 - P_(P, 0) * abs(p.x) + p.y, P_(P, 1) * p.x, p.z);
}
// The weight inside the powers; the linear and constant terms without it.
vec3 V_polynomial(vec3 p, float w, int P, int A) {
  float aw = abs(w);
  return vec3(pow(aw * abs(p.x), P_(P, 0)) * sign(p.x) + P_(P, 2) * p.x + P_(P, 4),
              pow(aw * abs(p.y), P_(P, 1)) * sign(p.y) + P_(P, 3) * p.y + P_(P, 5), w * p.z);
}
vec3 V_projective(vec3 p, float w, int P, int A) {
  float s = w / fractoriumZeps(P_(P, 0) * p.x + P_(P, 1) * p.y + P_(P, 2));
  return vec3((P_(P, 3) * p.x + P_(P, 4) * p.y + P_(P, 5)) * s, (P_(P, 6) * p.x + P_(P, 7) * p.y + P_(P, 8)) * s,
              w * p.z);
}
vec3 V_rational3(vec3 p, float w, int P, int A) {
  float x = p.x, y = p.y, x2 = x * x, y2 = y * y;
  float cubeRe = x2 * x - 3.0 * x * y2, cubeIm = 3.0 * x2 * y - y2 * y;
  float sqRe = x2 - y2, sqIm = 2.0 * x * y;
  float tr = P_(P, 0) * cubeRe + P_(P, 1) * sqRe + P_(P, 2) * x + P_(P, 3);
  float ti = P_(P, 0) * cubeIm + P_(P, 1) * sqIm + P_(P, 2) * y;
  float br = P_(P, 4) * cubeRe + P_(P, 5) * sqRe + P_(P, 6) * x + P_(P, 7);
  float bi = P_(P, 4) * cubeIm + P_(P, 5) * sqIm + P_(P, 6) * y;
  float den = 1.0 / fractoriumZeps(br * br + bi * bi);
  return vec3(w * (tr * br + ti * bi) * den, w * (ti * br - tr * bi) * den, w * p.z);
}
// The weight on q02 and q11 only, as Fractorium has it.
vec3 V_q_ode(vec3 p, float w, int P, int A) {
  float x = p.x, y = p.y, x2 = x * x, y2 = y * y, xy = x * y;
  return vec3((P_(P, 0) + w * P_(P, 1) * x + P_(P, 2) * x2) + (P_(P, 3) * xy + P_(P, 4) * y + P_(P, 5) * y2),
              (P_(P, 6) + P_(P, 7) * x + P_(P, 8) * x2) + (P_(P, 9) * xy + w * P_(P, 10) * y + P_(P, 11) * y2),
              w * p.z);
}

// ---- shapes (variations_2d_m.cpp) -------------------------------------------------------------

// The n-gon's radius at angle a (lazyjess).
float v2dm_lazyjessEdge(float a, float w, float sinVertex, float vertex, float slice) {
  return w * 1.41421356237310 * sinVertex / fractoriumZeps(sin(kPi - fmodc(a + 0.5 * slice, slice) - vertex));
}
vec3 V_lazyjess(vec3 p, float w, int P, int A) {
  float sides = max(P_(P, 0), 2.0), spin = P_(P, 1), space = P_(P, 2), corner = P_(P, 3);
  float vertex = kPi * (sides - 2.0) / fractoriumZeps(2.0 * sides), sinVertex = sin(vertex);
  float slice = kTwoPi / fractoriumZeps(sides);
  bool strip = sides == 2.0;
  float modulus = sqrt(p.x * p.x + p.y * p.y), phi = atan2c(p.y, p.x);
  bool inside = strip ? abs(p.x) < w : modulus < v2dm_lazyjessEdge(phi + kTwoPi, w, sinVertex, vertex, slice);
  vec2 q;
  if (inside) {
    float a = phi + spin + (strip ? 0.0 : kTwoPi);
    float sx = w * modulus * cos(a), sy = w * modulus * sin(a);
    float spun = strip ? modulus : length(vec2(sx, sy));
    bool stays = strip ? abs(sx) < w : spun < v2dm_lazyjessEdge(a, w, sinVertex, vertex, slice);
    if (stays) {
      q = vec2(sx, sy);
    } else {
      float back = atan2c(sy, sx) - spin + (corner - 1.0) * slice + (strip ? 0.0 : kTwoPi);
      q = vec2(w * spun * cos(back), -(w * spun * sin(back)));
    }
  } else {
    q = w * (1.0 + space / fractoriumZeps(modulus)) * p.xy;
  }
  return vec3(q, w * p.z);
}
vec3 V_loonie2(vec3 p, float w, int P, int A) {
  float sides = fractoriumInteger(P_(P, 0), 1.0, 50.0);
  float a = kTwoPi / sides, st = -kPi / 2.0 * clamp(P_(P, 1), -1.0, 1.0);
  float c = kPi / 2.0 * clamp(P_(P, 2), -1.0, 1.0);
  float sina = sin(a), cosa = cos(a), sins = sin(st), coss = cos(st), sinc = sin(c), cosc = cos(c);
  float w2 = w * w;
  int turns = sides >= 2.0 ? int(sides) - 1 : 0;
  float xr = p.x, yr = p.y;
  float r2 = xr * coss + abs(yr) * sins;
  for (int k = 0; k < turns; ++k) {
    float swap = xr * cosa - yr * sina;
    yr = xr * sina + yr * cosa;
    xr = swap;
    r2 = max(r2, xr * coss + abs(yr) * sins);
  }
  r2 = r2 * cosc + sqrt(p.x * p.x + p.y * p.y) * sinc;
  r2 = turns > 1 ? r2 * r2 : abs(r2) * r2;
  float scale = w;
  if (r2 > 0.0 && r2 < w2) {
    scale = w * sqrt(abs(w2 / r2 - 1.0));
  } else if (r2 < 0.0) {
    scale = w / sqrt(abs(w2 / r2) - 1.0);
  }
  return vec3(scale * p.xy, w * p.z);
}
vec3 V_loonie3(vec3 p, float w, int P, int A) {
  float w2 = w * w;
  float q = (p.x * p.x + p.y * p.y) / p.x;
  float r2 = p.x > kFractoriumEps ? q * q : 2.0 * w2;
  float scale = r2 < w2 ? w * sqrt(w2 / r2 - 1.0) : w;
  return vec3(scale * p.xy, w * p.z);
}
vec3 V_mask(vec3 p, float w, int P, int A) {
  float d = w / fractoriumZeps(p.x * p.x + p.y * p.y);
  float u = P_(P, 3) * p.x + P_(P, 0), v = P_(P, 4) * p.y + P_(P, 1);
  float s = sin(u), c = cos(u), k = cosh(v) + P_(P, 2);
  return vec3(d * s * k * s * s, d * c * k * s * s, w * p.z);
}
vec3 V_mcarpet(vec3 p, float w, int P, int A) {
  float r = w / ((p.x * p.x + p.y * p.y) * 0.25 + 1.0);
  return vec3(p.x * r * P_(P, 0) + w * (1.0 - P_(P, 2) * p.x * p.x + p.y), p.y * r * P_(P, 1) + w * P_(P, 3) * p.x,
              w * p.z);
}
vec3 V_oscilloscope2(vec3 p, float w, int P, int A) {
  float separation = max(P_(P, 0), 0.0), tpf = kTwoPi * P_(P, 1), tpf2 = kTwoPi * P_(P, 2);
  float amplitude = P_(P, 3), perturbation = P_(P, 4), damping = P_(P, 5);
  float pt = perturbation * sin(tpf2 * p.y);
  float damp = damping == 0.0 ? 1.0 : exp(-abs(p.x) * damping);
  float t = amplitude * damp * cos(tpf * p.x + pt) + separation;
  float s = abs(p.y) <= t ? -1.0 : 1.0;
  return vec3(s * w * p.xy, w * p.z);
}
vec3 V_ovoid(vec3 p, float w, int P, int A) {
  float r = w / fractoriumZeps(p.x * p.x + p.y * p.y);
  return vec3(p.x * r * P_(P, 0), p.y * r * P_(P, 1), w * p.z);
}
vec3 V_panorama1(vec3 p, float w, int P, int A) {
  vec2 q = p.xy / sqrt(p.x * p.x + p.y * p.y + 1.0);
  return w * vec3(atan2c(q.x, q.y) / kPi, length(q) - 0.5, p.z);
}
vec3 V_panorama2(vec3 p, float w, int P, int A) {
  vec2 q = p.xy / (sqrt(p.x * p.x + p.y * p.y) + 1.0);
  return w * vec3(atan2c(q.x, q.y) / kPi, length(q) - 0.5, p.z);
}
vec3 V_petal(vec3 p, float w, int P, int A) {
  float s = sin(p.x), c = cos(p.x), cy = cos(p.y);
  float bx = c * cy, by = s * cy;
  return w * vec3(c * bx * bx * bx, c * by * by * by, p.z);
}

// ---- Möbius-like maps (variations_2d_m.cpp) ---------------------------------------------------

vec3 V_murl(vec3 p, float w, int P, int A) {
  float power = max(P_(P, 1), 2.0);
  float cp = P_(P, 0) / (power - 1.0), vp = w * (cp + 1.0);
  float angle = atan2c(p.y, p.x) * power;
  float r = cp * pow(p.x * p.x + p.y * p.y, power / 2.0);
  float re = r * cos(angle) + 1.0, im = r * sin(angle);
  float r1 = vp / (re * re + im * im);
  return vec3(r1 * (p.x * re + p.y * im), r1 * (p.y * re - p.x * im), w * p.z);
}
vec3 V_murl2(vec3 p, float w, int P, int A) {
  float c = clamp(P_(P, 0), -1.0, 1.0), power = P_(P, 1);
  float vp = c == -1.0 ? 0.0 : w * pow(c + 1.0, 2.0 / power);
  float angle = atan2c(p.y, p.x) * power;
  float r = c * pow(p.x * p.x + p.y * p.y, power / 2.0);
  float re = r * cos(angle) + 1.0, im = r * sin(angle);
  r = pow(re * re + im * im, 1.0 / power);
  angle = atan2c(im, re) * (2.0 / power);
  re = r * cos(angle);
  im = r * sin(angle);
  float r1 = vp / (r * r);
  return vec3(r1 * (p.x * re + p.y * im), r1 * (p.y * re - p.x * im), w * p.z);
}
// Fractorium's wrap of a cyclic parameter into [−π, π].
float v2dm_wrapToPi(float v) {
  if (v > kPi) return -kPi + fmodc(v + kPi, kTwoPi);
  if (v < -kPi) return kPi - fmodc(kPi - v, kTwoPi);
  return v;
}
// Fractorium applies no weight here.
vec3 V_poincare(vec3 p, float w, int P, int A) {
  float c1r = P_(P, 0), c2r = P_(P, 2);
  float a1 = fmodc(v2dm_wrapToPi(P_(P, 1)), kPi), a2 = fmodc(v2dm_wrapToPi(P_(P, 3)), kPi);
  vec2 c1 = sqrt(1.0 + c1r * c1r) * vec2(cos(a1), sin(a1)), c2 = sqrt(1.0 + c2r * c2r) * vec2(cos(a2), sin(a2));
  vec2 d1 = p.xy - c1;
  vec2 d2 = c1 + c1r * c1r * d1 / fractoriumZeps(dot(d1, d1)) - c2;
  return vec3(c2 + c2r * c2r * d2 / fractoriumZeps(dot(d2, d2)), w * p.z);
}
vec3 V_poincare2(vec3 p, float w, int P, int A) {
  float pp = P_(P, 0), q = P_(P, 1);
  float a0 = kTwoPi / pp;
  float dist2 = 1.0 - (cos(a0) - 1.0) / (cos(a0) + cos(kTwoPi / q));
  float dist = dist2 > 0.0 ? 1.0 / sqrt(dist2) : 1.0;
  bool hyperbolic = 1.0 / pp + 1.0 / q < 0.5;
  float cx = hyperbolic ? cos(a0) * dist : 0.0, cy = hyperbolic ? sin(a0) * dist : 0.0;
  float a = p.x - cx, b = p.y - cy;
  float c = 1.0 - cx * p.x - cy * p.y, d = cy * p.x - cx * p.y;
  float num = w / fractoriumZeps(c * c + d * d);
  return vec3((a * c + b * d) * num, (b * c - a * d) * num, w * p.z);
}
// Fractorium drops the strip's own z, and so does this 2D variation.
vec3 V_mobius_strip(vec3 p, float w, int P, int A) {
  float radius = P_(P, 0), width = P_(P, 1), rectX = P_(P, 2), rectY = P_(P, 3);
  float sinX = sin(P_(P, 4) * kTwoPi), cosX = cos(P_(P, 4) * kTwoPi);
  float sinY = sin(P_(P, 5) * kTwoPi), cosY = cos(P_(P, 5) * kTwoPi);
  float t = 0.0, s = 0.0;
  if (rectX != 0.0) {
    float d = (p.x + rectX) / (2.0 * rectX);
    t = kTwoPi * (d - floor(d));
  }
  if (rectY != 0.0) {
    float d = (p.y + rectY) / (2.0 * rectY);
    s = 2.0 * width * (d - floor(d)) - width;
  }
  float band = radius + s * cos(t / 2.0);
  float mx = band * cos(t), my = band * sin(t), mz = s * sin(t / 2.0);
  float ry = my * cosY + mz * sinY, rz = mz * cosY - my * sinY;
  return vec3(w * (mx * cosX - rz * sinX), w * ry, w * p.z);
}
// One half of ortho: q (mirrored to x ≥ 0) moved along its circle orthogonal to the unit circle.
vec2 v2dm_orthoArc(float qx, float qy, float r2, float turn) {
  float side = qx >= 0.0 ? 1.0 : -1.0;
  float ax = side * qx;
  float xo = (r2 + 1.0) / (side > 0.0 ? fractoriumZeps(2.0 * ax) : 2.0 * ax);  // Zeps on the x ≥ 0 side only
  float ro = sqrt((ax - xo) * (ax - xo) + qy * qy);
  float theta = atan(1.0, ro);
  float a = fmodc(turn * theta + atan2c(qy, xo - ax) + theta, 2.0 * theta) - theta;
  return vec2(side * (xo - cos(a) * ro), sin(a) * ro);
}
vec3 V_ortho(vec3 p, float w, int P, int A) {
  float turnIn = v2dm_wrapToPi(P_(P, 0)), turnOut = v2dm_wrapToPi(P_(P, 1));
  float r2 = p.x * p.x + p.y * p.y;
  vec2 q;
  if (r2 < 1.0) {
    q = v2dm_orthoArc(p.x, p.y, r2, turnIn);
  } else {
    float r = sqrt(r2), inv = 1.0 / r;
    float ix = inv * (p.x / fractoriumZeps(r)), iy = inv * (p.y / fractoriumZeps(r));
    vec2 o = v2dm_orthoArc(ix, iy, ix * ix + iy * iy, turnOut);
    float angle = atan2c(o.y, ix >= 0.0 ? o.x : -o.x);
    float back = 1.0 / sqrt(o.x * o.x + o.y * o.y);
    q = vec2((ix >= 0.0 ? 1.0 : -1.0) * back * cos(angle), back * sin(angle));
  }
  return w * vec3(q, p.z);
}

// ---- waves and moduli (variations_2d_m.cpp) ---------------------------------------------------

float v2dm_modulus(float v, float size, float shift) {
  float f = fmodc(v + size + shift, 2.0 * size);
  return f >= 0.0 ? f - size : f + size;
}
vec3 V_modulusx(vec3 p, float w, int P, int A) {
  return w * vec3(v2dm_modulus(p.x, P_(P, 0), P_(P, 1)), p.y, p.z);
}
vec3 V_modulusy(vec3 p, float w, int P, int A) {
  return w * vec3(p.x, v2dm_modulus(p.y, P_(P, 0), P_(P, 1)), p.z);
}
vec3 V_pressure_wave(vec3 p, float w, int P, int A) {
  float fx = P_(P, 0) * kTwoPi, fy = P_(P, 1) * kTwoPi;
  return w * vec3(p.x + sin(fx * p.x) / fractoriumZeps(fx), p.y + sin(fy * p.y) / fractoriumZeps(fy), p.z);
}
vec3 V_pulse(vec3 p, float w, int P, int A) {
  return w * vec3(p.x + P_(P, 2) * sin(p.x * P_(P, 0)), p.y + P_(P, 3) * sin(p.y * P_(P, 1)), p.z);
}
// The distance is Fractorium's √(x² y²) (a product, not a sum), at least ε.
vec3 V_ripple(vec3 p, float w, int P, int A) {
  float f = P_(P, 0) * 5.0, a = P_(P, 2) * 0.01, cx = P_(P, 3), cy = P_(P, 4), ph = P_(P, 5) * kTwoPi - kPi;
  float s = fractoriumZeps(P_(P, 6)), is = 1.0 / s;
  float vxp = P_(P, 1) * ph, pxa = ph * a, pixa = (kPi - ph) * a;
  float px = p.x * s - cx, py = p.y * s + cy;
  float d = max(kFractoriumEps, abs(px * py));
  float nx = px / d, ny = py / d;
  float wave = cos(f * d - vxp);
  float d1 = wave * pxa + d, d2 = wave * pixa + d;
  float u1 = cx + nx * d1, v1 = -cy + ny * d1, u2 = cx + nx * d2, v2 = -cy + ny * d2;
  return vec3(w * (u1 + (u2 - u1) * ph) * is, w * (v1 + (v2 - v1) * ph) * is, w * p.z);
}
vec3 V_rippled(vec3 p, float w, int P, int A) {
  float d = fractoriumZeps(p.x * p.x + p.y * p.y);
  return vec3(w / 2.0 * (v2dm_tanh(d) * 2.0 * p.x), w / 2.0 * (cos(d) * 2.0 * p.y), w * p.z);
}

// ---- rotation and inversions (variations_2d_m.cpp) --------------------------------------------

vec3 V_rotate(vec3 p, float w, int P, int A) {
  float rad = P_(P, 0) / 180.0 * kPi, s = sin(rad), c = cos(rad);
  return w * vec3(p.x * c - p.y * s, p.x * s + p.y * c, p.z);
}
// The weight applied twice, as Fractorium does.
vec3 V_roundspher(vec3 p, float w, int P, int A) {
  float r2 = fractoriumZeps(p.x * p.x + p.y * p.y);
  float e = 1.0 / r2 + 4.0 / (kPi * kPi), t = w / r2;
  return vec3(w * (t * p.x / e), w * (t * p.y / e), w * p.z);
}

// ---- swirls and polygons (variations_2d_s.cpp) ------------------------------------------------

vec3 V_scry2(vec3 p, float w, int P, int A) {
  float sector = kTwoPi / fractoriumZeps(P_(P, 0));
  float tanHalf2 = 2.0 * tan(sector * 0.5);
  float r2 = p.x * p.x + p.y * p.y;
  float s = 1.0 / fractoriumZeps(sqrt(r2) * (r2 + 1.0));
  float nx = p.x * s, ny = p.y * s;
  float dang = (atan2c(ny, nx) + kPi) / sector;
  float rad = sqrt(nx * nx + ny * ny);
  float whole = floor(dang), frac = dang - whole;
  bool upper = frac > 0.5;
  float xang = atan((upper ? 1.0 - frac : frac) * tanHalf2) / sector;
  float coeff = 1.0 / cos(xang * sector);
  float ang = ((upper ? whole + 1.0 : whole) + (upper ? -xang : xang)) * sector - kPi;
  return vec3(w * coeff * rad * cos(ang), w * coeff * rad * sin(ang), w * p.z);
}
// The sector index truncated towards 0, as Fractorium's int() does.
vec3 V_shredrad(vec3 p, float w, int P, int A) {
  float sides = P_(P, 0) == 0.0 ? kFractoriumEps : P_(P, 0);
  float width = clamp(P_(P, 1), -1.0, 1.0);
  float alpha = kTwoPi / sides;
  float r = sqrt(p.x * p.x + p.y * p.y);
  float xang = (atan2c(p.y, p.x) + 3.0 * kPi + alpha / 2.0) / alpha;
  float k = trunc(xang);
  float zang = ((xang - k) * width + k) * alpha - kPi - alpha / 2.0 * width;
  return vec3(w * r * cos(zang), w * r * sin(zang), w * p.z);
}
vec3 V_squarize(vec3 p, float w, int P, int A) {
  float r = sqrt(p.x * p.x + p.y * p.y);
  float a = atan2c(p.y, p.x);
  if (a < 0.0) a += kTwoPi;
  float s = 4.0 * r * a / kPi;
  vec2 q = vec2(r, -(8.0 * r - s));
  if (s <= r) {
    q = vec2(r, s);
  } else if (s <= 3.0 * r) {
    q = vec2(2.0 * r - s, r);
  } else if (s <= 5.0 * r) {
    q = vec2(-r, 4.0 * r - s);
  } else if (s <= 7.0 * r) {
    q = vec2(-(6.0 * r - s), -r);
  }
  return w * vec3(q, p.z);
}
// At the origin the result is its limit, the origin.
vec3 V_swirl3(vec3 p, float w, int P, int A) {
  float r = sqrt(p.x * p.x + p.y * p.y);
  float a = atan2c(p.y, p.x) + log(r) * P_(P, 0);
  return vec3(r == 0.0 ? vec2(0.0) : w * r * vec2(cos(a), sin(a)), w * p.z);
}
vec3 V_swirl3r(vec3 p, float w, int P, int A) {
  float shift = P_(P, 0), lo = max(P_(P, 1), 0.0), hi = max(P_(P, 2), 0.0);
  float minR = min(lo, hi), maxR = max(lo, hi);
  float minA = minR > 0.0 ? log(minR) * shift : 0.0, maxA = maxR > 0.0 ? log(maxR) * shift : 0.0;
  float r = sqrt(p.x * p.x + p.y * p.y);
  float turn = r < minR ? minA : (r > maxR ? maxA : log(r) * shift);
  float a = atan2c(p.y, p.x) + turn;
  return vec3(r == 0.0 ? vec2(0.0) : w * r * vec2(cos(a), sin(a)), w * p.z);
}
// target, target0, target2: the point turned by even or odd by the ring (or spiral band) it lies in.
vec3 v2dm_targetRings(vec3 p, float w, int P, bool weighted, bool spiral, float minSize) {
  float even = P_(P, 0), odd = P_(P, 1), size = max(P_(P, 2), minSize);
  float half_ = size * 0.5;
  float r = sqrt(p.x * p.x + p.y * p.y), phi = atan2c(p.y, p.x);
  float t = spiral ? P_(P, 3) * log(r) + (phi + kPi) / kPi : log(r);
  if (t < 0.0) t -= half_;
  // fmod by a zero size is NaN on the CPU, which takes odd.
  bool isEven = size != 0.0 && fmodc(abs(t), size) < half_;
  float a = phi + (isEven ? even : odd);
  float factor = weighted ? w : 1.0;
  return vec3(factor * r * cos(a), factor * r * sin(a), w * p.z);
}
// Fractorium's target applies no weight; target0 and target2 do.
vec3 V_target(vec3 p, float w, int P, int A) { return v2dm_targetRings(p, w, P, false, false, kFractoriumEps); }
vec3 V_target0(vec3 p, float w, int P, int A) { return v2dm_targetRings(p, w, P, true, false, 0.0); }
vec3 V_target2(vec3 p, float w, int P, int A) { return v2dm_targetRings(p, w, P, true, true, kFractoriumEps); }
vec3 V_xheart(vec3 p, float w, int P, int A) {
  float ang = kPi / 4.0 + 0.5 * (kPi / 4.0) * P_(P, 0);
  float sa = sin(ang), ca = cos(ang);
  float rat = 6.0 + 2.0 * P_(P, 1);
  float r24 = p.x * p.x + p.y * p.y + 4.0;
  if (r24 == 0.0) r24 = 1.0;
  float bx = 4.0 / r24, by = rat / r24;
  float px = ca * (bx * p.x) - sa * (by * p.y), py = sa * (bx * p.x) + ca * (by * p.y);
  return vec3(w * px, px > 0.0 ? w * py : -w * py, w * p.z);
}

// ---- sine grids and shifts (variations_2d_s.cpp) ----------------------------------------------

vec3 V_shift(vec3 p, float w, int P, int A) {
  float sx = P_(P, 0), sy = P_(P, 1), rad = P_(P, 2) / 180.0 * kPi;
  float s = sin(rad), c = cos(rad);
  return w * vec3(p.x + (c * sx - s * sy), p.y + (-(c * sy) - s * sx), p.z);
}
// sigmoid's slope −5 shift, or −5/shift with amplitude sgn shift where |shift| < 1 (ε at 0).
vec2 v2dm_sigmoidSlope(float shift) {
  if (shift < 1.0 && shift > -1.0) {
    if (shift == 0.0) return vec2(-5.0 * kFractoriumEps, 1.0);
    return vec2(-5.0 / shift, shift < 0.0 ? -1.0 : 1.0);
  }
  return vec2(-5.0 * shift, 1.0);
}
vec3 V_sigmoid(vec3 p, float w, int P, int A) {
  vec2 sx = v2dm_sigmoidSlope(P_(P, 0)), sy = v2dm_sigmoidSlope(P_(P, 1));
  float c0 = sx.y / fractoriumZeps(1.0 + exp(sx.x * p.x));
  float c1 = sy.y / fractoriumZeps(1.0 + exp(sy.x * p.y));
  float vv = abs(w);
  return vec3(vv * 2.0 * (c0 - 0.5), vv * 2.0 * (c1 - 0.5), w * p.z);
}
vec3 V_sintrange(vec3 p, float w, int P, int A) {
  float k = P_(P, 0), x2 = p.x * p.x, y2 = p.y * p.y;
  float v = (x2 + y2) * k;
  return w * vec3(sin(p.x) * (x2 + k - v), sin(p.y) * (y2 + k - v), p.z);
}
vec3 V_sinusgrid(vec3 p, float w, int P, int A) {
  float ax = P_(P, 0), ay = P_(P, 1);
  float fx = fractoriumZeps(P_(P, 2) * kTwoPi), fy = fractoriumZeps(P_(P, 3) * kTwoPi);
  float sx = -cos(p.x * fx), sy = -cos(p.y * fy);
  return w * vec3(p.x + (sx - p.x) * ax, p.y + (sy - p.y) * ay, p.z);
}
vec3 V_spiralwing(vec3 p, float w, int P, int A) {
  float d = fractoriumZeps(p.x * p.x + p.y * p.y);
  float c1 = fractoriumZeps(p.x * p.x), c2 = fractoriumZeps(p.y * p.y);
  return vec3(w * (1.0 / d) * cos(c1) * sin(c2), w * (1.0 / d) * sin(c1) * sin(c2), w * p.z);
}
vec3 V_squirrel(vec3 p, float w, int P, int A) {
  float a = fractoriumZeps(P_(P, 0)), b = fractoriumZeps(P_(P, 1));
  float u = sqrt(max(a * p.x * p.x + b * p.y * p.y, 0.0));
  return w * vec3(cos(u) * tan(p.x), sin(u) * tan(p.y), p.z);
}
// w p plus a term added to both coordinates outside the weight.
vec3 V_stwin(vec3 p, float w, int P, int A) {
  float sx = p.x * w * 0.05, sy = p.y * w * 0.05;
  float x2 = sx * sx, y2 = sy * sy, sum = x2 + y2;
  float result = (x2 - y2) * sin(kTwoPi * P_(P, 0) * (sx + sy)) / (sum != 0.0 ? sum : 1.0);
  return vec3(w * p.x + result, w * p.y + result, w * p.z);
}
vec3 V_tancos(vec3 p, float w, int P, int A) {
  float d = fractoriumZeps(p.x * p.x + p.y * p.y);
  return vec3(w / d * (v2dm_tanh(d) * 2.0 * p.x), w / d * (cos(d) * 2.0 * p.y), w * p.z);
}
vec3 V_trade(vec3 p, float w, int P, int A) {
  float r1 = max(P_(P, 0), kFractoriumEps), r2 = max(P_(P, 2), kFractoriumEps);
  float c1 = r1 + max(P_(P, 1), 0.0), c2 = r2 + max(P_(P, 3), 0.0);
  bool right = p.x > 0.0;
  float dx = right ? c1 - p.x : -c2 - p.x;
  float r = sqrt(dx * dx + p.y * p.y);
  if (r > (right ? r1 : r2)) return w * p;
  float scaled = r * (right ? r2 / r1 : r1 / r2), a = atan2c(p.y, dx);
  return vec3(w * (scaled * cos(a) + (right ? -c2 : c1)), w * scaled * sin(a), w * p.z);
}
vec3 V_unicorngaloshen(vec3 p, float w, int P, int A) {
  float multX = P_(P, 0), multY = P_(P, 1), sine = P_(P, 2), ampX = P_(P, 3), ampY = P_(P, 5);
  float freqX = kPi * P_(P, 4), freqY = kPi * P_(P, 6), mode = clamp(P_(P, 7), 0.0, 4.0);
  float x = p.x, y = p.y;
  float r = w / fractoriumZeps(sqrt(y * y * multY + multX * x * x));
  float fx = ampX, fy = ampY;
  if (sine > 0.0) {
    vec2 s;
    if (mode <= 0.0) {
      s = vec2(x, y);
    } else if (mode <= 1.0) {
      s = vec2(exp(-x), exp(-y));
    } else if (mode <= 2.0) {
      s = vec2(1.0 / fractoriumZeps(x), 1.0 / fractoriumZeps(y));
    } else if (mode <= 3.0) {
      s = vec2(log(abs(x)), ampY * log(abs(y)));
    } else {
      s = vec2(atan2c(x, y), atan2c(y, x));
    }
    fx = 1.0 + ampX * sin(s.x * freqX);
    fy = 2.0 + ampY * sin(s.y * freqY);
  }
  return vec3(fx * (x - y) * (x + multY * y) * r, fy * x * y * r, w * p.z);
}
// Two plane waves; the phases wrapped into [0, 1] as Fractorium does.
vec3 V_vibration(vec3 p, float w, int P, int A) {
  float dir = P_(P, 0), tot = P_(P, 1) + P_(P, 0), dir2 = P_(P, 5), tot2 = P_(P, 6) + P_(P, 5);
  float freq = P_(P, 2) * kTwoPi, shift = kTwoPi * v2dm_wrapCyclic(P_(P, 4), 0.0, 1.0) / fractoriumZeps(P_(P, 2));
  float freq2 = P_(P, 7) * kTwoPi, shift2 = kTwoPi * v2dm_wrapCyclic(P_(P, 9), 0.0, 1.0) / fractoriumZeps(P_(P, 7));
  float a1 = P_(P, 3) * sin((p.x * cos(dir) + p.y * sin(dir)) * freq + shift);
  float a2 = P_(P, 8) * sin((p.x * cos(dir2) + p.y * sin(dir2)) * freq2 + shift2);
  return w * vec3(p.x + a1 * cos(tot) + a2 * cos(tot2), p.y + a1 * sin(tot) + a2 * sin(tot2), p.z);
}

// ---- Truchet tiles (variations_2d_s.cpp) ------------------------------------------------------

vec3 V_truchet_knot(vec3 p, float w, int P, int A) {
  float cellX = floor(p.x), cellY = floor(p.y);
  float along = (psi() - 0.5) * 0.5;
  float across = (psi() * 2.0 - 1.0) * (1.0 - 0.1 - 0.25);
  float dir0 = abs(cellX + cellY);
  bool turned = dir0 - 2.0 * floor(dir0 * 0.5) >= 0.5;
  return w * vec3(cellX + (turned ? -across : along), cellY + (turned ? along : across), p.z);
}

// ---- waves (variations_2d_s.cpp) --------------------------------------------------------------

// Each sine (or with mode 1 its lift ½(1 + sin)) to a power truncated towards 0.
vec3 V_waves22(vec3 p, float w, int P, int A) {
  bool liftX = fractoriumInteger(P_(P, 4), 0.0, 1.0) >= 0.5, liftY = fractoriumInteger(P_(P, 5), 0.0, 1.0) >= 0.5;
  float sx = sin(p.y * P_(P, 2)), sy = sin(p.x * P_(P, 3));
  float bx = liftX ? 0.5 * (1.0 + sx) : sx, by = liftY ? 0.5 * (1.0 + sy) : sy;
  return w * vec3(p.x + v2dm_powWhole(bx, trunc(P_(P, 6))) * P_(P, 0),
                  p.y + v2dm_powWhole(by, trunc(P_(P, 7))) * P_(P, 1), p.z);
}
vec3 V_waves2_radial(vec3 p, float w, int P, int A) {
  float nul = P_(P, 4), distance = P_(P, 5);
  float span = fractoriumZeps(distance - nul);
  float d = sqrt(p.x * p.x + p.y * p.y);
  float factor = d < nul ? 0.0 : (d < distance ? (d - nul) / span : 1.0);
  return w * vec3(p.x + factor * sin(p.y * P_(P, 0)) * P_(P, 1), p.y + factor * sin(p.x * P_(P, 2)) * P_(P, 3), p.z);
}
vec3 V_waves3(vec3 p, float w, int P, int A) {
  float sx = P_(P, 0) * 0.5 * (1.0 + sin(p.y * P_(P, 4))), sy = P_(P, 1) * 0.5 * (1.0 + sin(p.x * P_(P, 5)));
  return w * vec3(p.x + sin(p.y * P_(P, 2)) * sx, p.y + sin(p.x * P_(P, 3)) * sy, p.z);
}
// waves4 and waves42: waves2 whose x amplitude is a hash of the band of y the point is in, squared
// (the hash in double, as the CPU has it).
vec3 v2dm_wavesHashed(vec3 p, float w, int P, double band) {
  bool cont = fractoriumInteger(P_(P, 4), 0.0, 1.0) == 1.0;
  precise double yd = double(p.y);
  precise double k = floor(yd * band);
  precise double h = dsin(k * 12.9898lf + k * 78.233lf + 1.0lf + yd * (double(P_(P, 5)) * 0.001lf)) * 43758.5453lf;
  h -= trunc(h);
  float hf = cont ? (h > 0.5lf ? 1.0 : 0.0) : float(h);
  return w * vec3(p.x + sin(p.y * P_(P, 2)) * hf * hf * P_(P, 0), p.y + sin(p.x * P_(P, 3)) * P_(P, 1), p.z);
}
vec3 V_waves4(vec3 p, float w, int P, int A) {
  return v2dm_wavesHashed(p, w, P, double(P_(P, 2)) / 6.283185307179586lf);
}
vec3 V_waves42(vec3 p, float w, int P, int A) { return v2dm_wavesHashed(p, w, P, double(P_(P, 6))); }

// ---- w, x, z: Fractorium's shape family (variations_2d_s.cpp) ---------------------------------

// The radius T(a) of the sum of four shapes (hypergon, star, lituus, superformula), each scaled by
// its parameter and left out at 0; the 13 shape parameters from flameData[S] on.
float v2dm_shapeSum(int S, float a) {
  float total = 0.0;
  float hypergon = P_(S, 0), star = P_(S, 3), lituus = P_(S, 6), super_ = P_(S, 8);
  if (hypergon != 0.0) {
    float nn = max(floor(P_(S, 1) + 0.5), 3.0), d = sqrt(1.0 + P_(S, 2) * P_(S, 2));
    float t1 = fmodc(abs(a), kTwoPi / nn) - kPi / nn;
    float t2 = tan(t1) * tan(t1) + 1.0, d2 = d * d;
    total += t2 >= d2 ? hypergon : hypergon * (d - sqrt(d2 - t2)) / sqrt(t2);
  }
  if (star != 0.0) {
    float nn = max(floor(P_(S, 4) + 0.5), 3.0);
    float slope = clamp(P_(S, 5), kFractoriumEps, kPi / 2.0);
    // Fractorium steps back from tan(π/2), which is undefined.
    float k = abs(slope - kPi / 2.0) < 1e-6 ? tan(slope - 0.05) : tan(slope);
    float t1 = tan(abs(fmodc(abs(a), kTwoPi / nn) - kPi / nn));
    total += star * sqrt(k * k * (1.0 + t1 * t1) / ((t1 + k) * (t1 + k)));
  }
  if (lituus != 0.0) total += lituus * pow(abs(a / kPi + 1.0), -P_(S, 7));
  if (super_ != 0.0) {
    float t4 = a * (P_(S, 9) / 4.0);
    total += super_ * pow(pow(abs(cos(t4)), P_(S, 11)) + pow(abs(sin(t4)), P_(S, 12)),
                          -1.0 / fractoriumZeps(P_(S, 10)));
  }
  return total;
}
// Inside the shape the point turned by angle, its radius scaled by T(φ + angle)/T(φ); outside it stays.
vec3 V_w(vec3 p, float w, int P, int A) {
  float turn = v2dm_wrapCyclic(P_(P, 0), -kPi, kPi);
  float a = atan2c(p.y, p.x), r = sqrt(p.x * p.x + p.y * p.y);
  float a2 = a + turn;
  if (a2 < -kPi) a2 += kTwoPi;
  if (a2 > kPi) a2 -= kTwoPi;
  float total = v2dm_shapeSum(P + 1, a);
  if (r > total) return w * p;
  float scaled = w * v2dm_shapeSum(P + 1, a2) * r / total;
  return vec3(scaled * cos(a2), scaled * sin(a2), w * p.z);
}
vec3 V_x(vec3 p, float w, int P, int A) {
  float a = atan2c(p.y, p.x), total = v2dm_shapeSum(P, a);
  float r = w * sqrt(p.x * p.x + p.y * p.y + total * total);
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_z(vec3 p, float w, int P, int A) {
  float a = atan2c(p.y, p.x);
  float r = w * (sqrt(p.x * p.x + p.y * p.y) + v2dm_shapeSum(P, a));
  return vec3(r * cos(a), r * sin(a), w * p.z);
}

// ---- xtrb (variations_2d_d.cpp) ---------------------------------------------------------------

// The triangle of xtrb's tiling and the hexagon's width (Fractorium's precalc).
struct v2dm_Xtrb {
  float width, ha, hb, hc, ab, ac, ba, bc, ca, cb, s2a, s2b, s2c, s2ab, s2ac, s2bc, width1, width2, width3;
};
// The trilinear point (al, be, ga) moved into the hexagon round its nearest corner, or kept scaled by
// width (u ≥ width3).
vec2 v2dm_xtrbHex(v2dm_Xtrb t, float al, float be, float ga, float u) {
  float al1, be1, ga1, de1;
  bool keep = u >= t.width3;
  if (be < al) {
    if (ga < be) {
      if (keep) {
        de1 = t.width * be;
        ga1 = t.width * ga;
      } else {
        ga1 = t.width1 * ga + t.width2 * t.hc * ga / be;
        de1 = t.width1 * be + t.width2 * t.s2ab * (3.0 - ga / be);
      }
      al1 = t.s2a - t.ba * de1 - t.ca * ga1;
      be1 = de1;
    } else if (ga < al) {
      if (keep) {
        ga1 = t.width * ga;
        de1 = t.width * be;
      } else {
        de1 = t.width1 * be + t.width2 * t.hb * be / ga;
        ga1 = t.width1 * ga + t.width2 * t.s2ac * (3.0 - be / ga);
      }
      al1 = t.s2a - t.ba * de1 - t.ca * ga1;
      be1 = de1;
    } else if (keep) {
      al1 = t.width * al;
      be1 = t.width * be;
    } else {
      be1 = t.width1 * be + t.width2 * t.hb * be / al;
      al1 = t.width1 * al + t.width2 * t.s2ac * (3.0 - be / al);
    }
  } else {
    if (ga < al) {
      if (keep) {
        de1 = t.width * al;
        ga1 = t.width * ga;
      } else {
        ga1 = t.width1 * ga + t.width2 * t.hc * ga / al;
        de1 = t.width1 * al + t.width2 * t.s2ab * (3.0 - ga / al);
      }
      be1 = t.s2b - t.ab * de1 - t.cb * ga1;
      al1 = de1;
    } else if (ga < be) {
      if (keep) {
        ga1 = t.width * ga;
        de1 = t.width * al;
      } else {
        de1 = t.width1 * al + t.width2 * t.ha * al / ga;
        ga1 = t.width1 * ga + t.width2 * t.s2bc * (3.0 - al / ga);
      }
      be1 = t.s2b - t.ab * de1 - t.cb * ga1;
      al1 = de1;
    } else if (keep) {
      be1 = t.width * be;
      al1 = t.width * al;
    } else {
      al1 = t.width1 * al + t.width2 * t.ha * al / be;
      be1 = t.width1 * be + t.width2 * t.s2bc * (3.0 - al / be);
    }
  }
  return vec2(al1, be1);
}
// The weight enters twice, as in Fractorium.
vec3 V_xtrb(vec3 p, float w, int P, int A) {
  float power = fractoriumInteger(P_(P, 0), -2147483647.0, 2147483647.0);
  if (power == 0.0) power = v2dm_signNz(P_(P, 0));
  float radius = P_(P, 1), dist = P_(P, 3);
  float br = 0.047 + P_(P, 4), cr = 0.047 + P_(P, 5), ar = kPi - br - cr;
  float tanA2 = sin(ar / 2.0) / cos(ar / 2.0), tanB2 = sin(br / 2.0) / cos(br / 2.0);
  float tanC2 = sin(cr / 2.0) / cos(cr / 2.0);
  float sinC = sin(cr), cosC = cos(cr);
  float a = radius * (tanC2 + tanB2), b = radius * (tanC2 + tanA2), c = radius * (tanB2 + tanA2);
  v2dm_Xtrb t;
  t.width = P_(P, 2);
  t.width1 = 1.0 - t.width;
  t.width2 = 2.0 * t.width;
  t.width3 = 1.0 - t.width * t.width;
  float s2 = radius * (a + b + c);
  t.ha = s2 / a / 6.0;
  t.hb = s2 / b / 6.0;
  t.hc = s2 / c / 6.0;
  t.ab = a / b;
  t.ac = a / c;
  t.ba = b / a;
  t.bc = b / c;
  t.ca = c / a;
  t.cb = c / b;
  t.s2a = 6.0 * t.ha;
  t.s2b = 6.0 * t.hb;
  t.s2c = 6.0 * t.hc;
  t.s2bc = s2 / (b + c) / 6.0;
  t.s2ab = s2 / (a + b) / 6.0;
  t.s2ac = s2 / (a + c) / 6.0;
  float absN = trunc(min(abs(power), 4294967296.0)), cn = dist / power / 2.0;

  float u1 = psi(), u2 = psi();
  float alpha = p.y + radius, beta = p.x * sinC - p.y * cosC + radius;
  float m = floor(alpha / t.s2a), k = floor(beta / t.s2b);
  float offAl = alpha - m * t.s2a, offBe = beta - k * t.s2b;
  float offGa = t.s2c - t.ac * offAl - t.bc * offBe;
  vec2 ab;
  if (offGa > 0.0) {
    ab = v2dm_xtrbHex(t, offAl, offBe, offGa, u1);
  } else {
    ab = vec2(t.s2a, t.s2b) - v2dm_xtrbHex(t, t.s2a - offAl, t.s2b - offBe, -offGa, u1);
  }
  alpha = ab.x + m * t.s2a;
  beta = ab.y + k * t.s2b;
  float px = (beta - radius + (alpha - radius) * cosC) / sinC, py = alpha - radius;
  float angle = (atan2c(py, px) + kTwoPi * floor(u2 * absN)) / power;
  float r = w * pow(px * px + py * py, cn);
  return vec3(w * r * cos(angle), w * r * sin(angle), w * p.z);
}

// ---- synth (variations_2d_d.cpp) --------------------------------------------------------------

// The wave at flameData[Q...] (amplitude, type, skew, frequency, phase, layer) at t, layered onto factor.
float v2dm_synthLayer(int Q, float a, float t, float factor) {
  float amplitude = P_(Q, 0), skew = P_(Q, 2), frequency = P_(Q, 3);
  if (amplitude == 0.0) return factor;
  float v = P_(Q, 4) + t * frequency;
  float y = v / kTwoPi;
  y -= floor(y);
  if (skew != 0.0) {
    v = 0.5 + 0.5 * skew;
    y = y > v ? 0.5 + 0.5 * (y - v) / fractoriumZeps(1.0 - v) : 0.5 - 0.5 * (v - y) / fractoriumZeps(v);
  }
  float x;
  int type = int(fractoriumInteger(P_(Q, 1), 0.0, 8.0));
  if (type == 0) {  // sine
    x = sin(y * kTwoPi);
  } else if (type == 1) {  // cosine
    x = cos(y * kTwoPi);
  } else if (type == 2) {  // square
    x = y > 0.5 ? 1.0 : -1.0;
  } else if (type == 3) {  // saw
    x = 1.0 - 2.0 * y;
  } else if (type == 4) {  // triangle
    x = y > 0.5 ? 3.0 - 4.0 * y : 2.0 * y - 1.0;
  } else if (type == 5) {  // concave
    x = 8.0 * (y - 0.5) * (y - 0.5) - 1.0;
  } else if (type == 6) {  // convex
    x = 2.0 * sqrt(y) - 1.0;
  } else if (type == 7) {  // n-gon
    x = 1.0 / fractoriumZeps(cos((y - 0.5) * (kTwoPi / frequency))) - 1.0;
  } else {  // inverted n-gon
    float c = cos((y - 0.5) * (kTwoPi / frequency));
    x = c / fractoriumZeps(1.0 - c);
  }
  int layer = int(fractoriumInteger(P_(Q, 5), 0.0, 3.0));
  if (layer == 0) return factor + amplitude * x;
  if (layer == 1) return factor * (1.0 + amplitude * x);
  float v2 = a + amplitude * x;
  return layer == 2 ? (factor > v2 ? factor : v2) : (factor < v2 ? factor : v2);
}
// The modulation at t: a plus the five layered waves, mixed with 1 by mix.
float v2dm_synthValue(int P, float t) {
  float a = P_(P, 0), mixv = P_(P, 3);
  float factor = a;
  for (int k = 0; k < 5; ++k) factor = v2dm_synthLayer(P + 5 + 6 * k, a, t, factor);
  return factor * mixv + (1.0 - mixv);
}
// A quadratic Bézier map of x whose slope at 0 is m, joining the identity further out.
float v2dm_bezierQuadMap(float x, float m) {
  float sgn = 1.0, t = 0.0;
  if (m < 0.0) {
    m = -m;
    sgn = -1.0;
  }
  if (x < 0.0) {
    x = -x;
    sgn = -sgn;
  }
  float iM = m > 1.0e-10 ? 1.0 / m : 1e10;
  float limit = iM < m * 2.0 ? m * 2.0 : iM;
  if (x > limit || m == 1.0) return sgn * x;
  if (m < 1.0 && x <= 1.0) {
    t = x;
    if (abs(m - 0.5) > 1e-10) t = (-m + sqrt(m * m + (1.0 - 2.0 * m) * x)) / (1.0 - 2.0 * m);
    return sgn * (x + (m - 1.0) * t * t);
  }
  if (1.0 < m && x <= 1.0) {
    t = x;
    if (abs(m - 2.0) > 1e-10) t = (-iM + sqrt(iM * iM + (1.0 - 2.0 * iM) * x)) / (1.0 - 2.0 * iM);
    return sgn * (x + (m - 1.0) * t * t);
  }
  if (m < 1.0) {
    t = sqrt((x - 1.0) / (limit - 1.0));
    return sgn * (x + (m - 1.0) * t * t + 2.0 * (1.0 - m) * t + (m - 1.0));
  }
  t = (1.0 - m) + sqrt((m - 1.0) * (m - 1.0) + (x - 1.0));
  return sgn * (x + (m - 1.0) * t * t - 2.0 * (m - 1.0) * t + (m - 1.0));
}
float v2dm_synthInterpolate(float x, float m, bool bezier) { return bezier ? v2dm_bezierQuadMap(x, m) : x * m; }
// (sin t, cos t) modulated: multiplied by the modulation at t and t + π/2, or mixed with it.
vec2 v2dm_synthSinCos(int P, float t, bool mixIn) {
  float sn = sin(t), cs = cos(t);
  if (!mixIn) return vec2(sn * v2dm_synthValue(P, t), cs * v2dm_synthValue(P, t + kPi / 2.0));
  float mixv = P_(P, 3);
  return vec2((1.0 - mixv) * sn + (v2dm_synthValue(P, t) - 1.0),
              (1.0 - mixv) * cs + (v2dm_synthValue(P, t + kPi / 2.0) - 1.0));
}
vec3 V_synth(vec3 p, float w, int P, int A) {
  int mode = int(fractoriumInteger(P_(P, 1), 0.0, 26.0));
  float power = P_(P, 2), mixv = P_(P, 3);
  bool smooth_ = fractoriumInteger(P_(P, 4), 0.0, 1.0) != 0.0;
  float vx = p.x, vy = p.y, r2 = vx * vx + vy * vy;
  float theta0 = atan2c(vx, vy);  // flam3's θ
  float px = 0.0, py = 0.0;
  float u1 = 0.0, u2 = 0.0, u3 = 0.0;
  // The blurs and julia draw; the other modes leave the stream alone.
  if (mode == 2 || mode == 3 || mode == 4 || mode == 15 || mode == 19 || mode == 20) {
    u1 = psi();
    if (mode != 15) u2 = psi();
    if (mode == 2 || mode == 3 || mode == 4 || mode == 19) u3 = psi();
  }
  if (mode == 0) {  // spherical
    float r = v2dm_synthInterpolate(pow(fractoriumZeps(r2), (power + 1.0) / 2.0), v2dm_synthValue(P, theta0), smooth_);
    px = r * sin(theta0);
    py = r * cos(theta0);
  } else if (mode == 1) {  // bubble
    float r = v2dm_synthInterpolate(sqrt(r2) / (r2 / 4.0 + 1.0), v2dm_synthValue(P, theta0), smooth_);
    px = r * sin(theta0);
    py = r * cos(theta0);
  } else if (mode == 2) {  // the legacy blur
    float r0 = (u1 + u2 + 0.002 * u3) / 2.002;
    float t = kTwoPi * psi() - kPi;
    float r = v2dm_synthInterpolate(pow(fractoriumZeps(r0 * r0), power / 2.0), v2dm_synthValue(P, t), smooth_);
    px = r0 * sin(t) * r;
    py = r0 * cos(t) * r;
  } else if (mode == 3) {  // blur
    float r0 = 0.5 * (u1 + u2), t = kTwoPi * u3 - kPi;
    float r = v2dm_synthInterpolate(pow(fractoriumZeps(r0 * r0), -power / 2.0), v2dm_synthValue(P, t), smooth_);
    px = r * sin(t);
    py = r * cos(t);
  } else if (mode == 4) {  // zigzag blur
    float v = 1.0 + 0.1 * (u1 + u2 - 1.0) * power;
    float t = 2.0 * asin((u3 - 0.5) * 2.0);
    px = t / kPi;
    py = v2dm_synthInterpolate(v, v2dm_synthValue(P, t), smooth_) - 1.0;
  } else if (mode == 5) {  // raw circle
    float r = v2dm_synthInterpolate(sqrt(r2), v2dm_synthValue(P, theta0), smooth_);
    px = r * sin(theta0);
    py = r * cos(theta0);
  } else if (mode == 6) {  // raw x
    px = v2dm_synthInterpolate(vx, v2dm_synthValue(P, vy), smooth_);
    py = vy;
  } else if (mode == 7) {  // raw y
    px = vx;
    py = v2dm_synthInterpolate(vy, v2dm_synthValue(P, vx), smooth_);
  } else if (mode == 8) {  // raw xy
    px = v2dm_synthInterpolate(vx, v2dm_synthValue(P, vy), smooth_);
    py = v2dm_synthInterpolate(vy, v2dm_synthValue(P, vx), smooth_);
  } else if (mode == 9) {  // shift x
    px = vx + v2dm_synthValue(P, vy) - 1.0;
    py = vy;
  } else if (mode == 10) {  // shift y
    px = vx;
    py = vy + v2dm_synthValue(P, vx) - 1.0;
  } else if (mode == 11) {  // shift xy
    px = vx + v2dm_synthValue(P, vy) - 1.0;
    py = vy + v2dm_synthValue(P, vx) - 1.0;
  } else if (mode == 12) {  // sinusoidal
    px = v2dm_synthValue(P, vx) - 1.0 + (1.0 - mixv) * sin(vx);
    py = v2dm_synthValue(P, vy) - 1.0 + (1.0 - mixv) * sin(vy);
  } else if (mode == 13) {  // swirl
    vec2 sc = v2dm_synthSinCos(P, pow(fractoriumZeps(r2), power / 2.0), smooth_);
    px = sc.x * vx - sc.y * vy;
    py = sc.y * vx + sc.x * vy;
  } else if (mode == 14) {  // hyperbolic
    float r = pow(fractoriumZeps(r2), power / 2.0);
    vec2 sc = v2dm_synthSinCos(P, theta0, smooth_);
    px = sc.x / r;
    py = sc.y * r;
  } else if (mode == 15) {  // julia
    float r = pow(fractoriumZeps(r2), power / 4.0);
    vec2 sc = v2dm_synthSinCos(P, theta0 / 2.0 + (u1 < 0.5 ? kPi : 0.0), smooth_);
    px = r * sc.y;
    py = r * sc.x;
  } else if (mode == 16) {  // disc
    float t = theta0 / kPi, r = kPi * pow(fractoriumZeps(r2), power / 2.0);
    vec2 sc = v2dm_synthSinCos(P, r, smooth_);
    px = sc.x * t;
    py = sc.y * t;
  } else if (mode == 17) {  // rings
    float r = sqrt(r2);
    float mu = fractoriumZeps(power * power);
    r += -2.0 * mu * trunc((r + mu) / (2.0 * mu)) + r * (1.0 - mu);
    vec2 sc = v2dm_synthSinCos(P, r, smooth_);
    px = sc.x * theta0;
    py = sc.y * theta0;
  } else if (mode == 18) {  // cylinder
    float r = pow(fractoriumZeps(r2), power / 2.0);
    vec2 sc = v2dm_synthSinCos(P, vx, smooth_);
    px = r * sc.x;
    py = r * vy;
  } else if (mode == 19) {  // ring blur
    float r0 = 1.0 + 0.1 * (u1 + u2 - 1.0) * power, t = kTwoPi * u3 - kPi;
    float r = v2dm_synthInterpolate(r0, v2dm_synthValue(P, t), smooth_);
    px = r * sin(t);
    py = r * cos(t);
  } else if (mode == 20) {  // ring blur 2: the angle drawn first, then the radius
    float t = kTwoPi * u1 - kPi;
    float r = v2dm_synthValue(P, t) + 0.1 * pow(fractoriumZeps(u2), power);
    px = r * sin(t);
    py = r * cos(t);
  } else if (mode == 21 || mode == 22) {  // shift θ; shift and stretch (the same in Fractorium)
    float r = pow(fractoriumZeps(r2), power / 2.0);
    float t = theta0 - 1.0 + v2dm_synthValue(P, r);
    px = r * sin(t);
    py = r * cos(t);
  } else if (mode == 23) {  // shift along the tangent
    float r = pow(fractoriumZeps(r2), power / 2.0);
    float mu = v2dm_synthValue(P, r) - 1.0;
    px = vx + mu * cos(theta0);
    py = vy - mu * sin(theta0);
  } else if (mode == 24) {  // mirror in the curve y = synth(x) − 1
    px = vx;
    py = 2.0 * (v2dm_synthValue(P, vx) - 1.0) - vy;
  } else if (mode == 25) {  // mirror in both
    px = 2.0 * (v2dm_synthValue(P, vy) - 1.0) - vx;
    py = 2.0 * (v2dm_synthValue(P, vx) - 1.0) - vy;
  } else {  // spherical 2
    float r = v2dm_synthInterpolate(sqrt(r2), v2dm_synthValue(P, theta0), smooth_);
    r = v2dm_powC(r, power);
    px = r * sin(theta0);
    py = r * cos(theta0);
  }
  return vec3(w * px, w * py, w * p.z);
}
// The Bessel function J₁(x) = (1/π) ∫₀^π cos(τ − x sin τ) dτ by the trapezoid rule, which for this
// periodic integrand is exact but for terms of order J_{2N}(x): N a little above |x| is plenty.
float v2dm_besselJ1(float x) {
  int n = int(min(abs(x), 8192.0)) + 24;
  float sum = 0.0;
  for (int j = 1; j < n; ++j) {
    float tau = kPi * float(j) / float(n);
    sum += cos(tau - x * sin(tau));
  }
  return sum / float(n);  // the ends, cos 0 and cos π, cancel
}
// sin(f sgn(v) |v|^pw), or sn(f v | 1 − jacok) for pw in [0, 10⁻⁴), J₁(f v) for pw in (−10⁻⁴, 0).
float v2dm_waves2bWave(float v, float freq, float pw, float jacok) {
  if (pw >= 0.0 && pw < 1e-4) return jacobiSnCnDn(v * freq, jacok).x;
  if (pw < 0.0 && pw > -1e-4) return v2dm_besselJ1(v * freq);
  return sin((v < 0.0 ? -1.0 : 1.0) * pow(fractoriumZeps(abs(v)), pw) * freq);
}
// Fractorium's SafeDivInv(q, r): 1/r where r < ε, else q/r.
float v2dm_safeDivInv(float q, float r) { return r < kFractoriumEps ? 1.0 / r : q / r; }
vec3 V_waves2b(vec3 p, float w, int P, int A) {
  float pwX = clamp(P_(P, 2), -10.0, 10.0), pwY = clamp(P_(P, 3), -10.0, 10.0);
  float scaleInfX = P_(P, 5), scaleInfY = P_(P, 7), unity = P_(P, 8), jacok = clamp(P_(P, 9), -1.0, 1.0);
  float csX = v2dm_safeDivInv(unity, unity + p.x * p.x) * (P_(P, 4) - scaleInfX) + scaleInfX;
  float csY = v2dm_safeDivInv(unity, unity + p.y * p.y) * (P_(P, 6) - scaleInfY) + scaleInfY;
  return w * vec3(p.x + csX * v2dm_waves2bWave(p.y, P_(P, 0), pwX, jacok),
                  p.y + csY * v2dm_waves2bWave(p.x, P_(P, 1), pwY, jacok), p.z);
}
// ---- variations_fractorium.cpp (mirrors and symmetries), variations_2d_m.cpp (rays), variations_2d_c.cpp ----
// Fractorium's mirrors: one coordinate's magnitude, negated when Ψ < ½; the weight is not applied.
vec3 V_mirror_x(vec3 p, float w, int P, int A) { return vec3(psi() < 0.5 ? -abs(p.x) : abs(p.x), p.y, p.z); }
vec3 V_mirror_y(vec3 p, float w, int P, int A) { return vec3(p.x, psi() < 0.5 ? -abs(p.y) : abs(p.y), p.z); }
vec3 V_mirror_z(vec3 p, float w, int P, int A) { return vec3(p.x, p.y, psi() < 0.5 ? -abs(p.z) : abs(p.z)); }
// JWildfire's post_axis_symmetry_wf: the weight is the distance moved, not a factor. Its axis-z turn
// ends at centre_y, as JWildfire's does (and the CPU's).
vec3 V_axis_symmetry_wf(vec3 p, float w, int P, int A) {
  int axis = int(clamp(roundHalfAway(P_(P, 0)), 0.0, 2.0));
  vec3 centre = vec3(P_(P, 1), P_(P, 2), P_(P, 3));
  float halfTurn = P_(P, 4) * kTwoPi / 180.0 / 2.0;
  float s = sin(halfTurn), c = cos(halfTurn), shift = w / 2.0;
  bool near = psi() < 0.5;
  if (abs(w) <= 1e-8) return p;
  gColour = fmodc(gColour + (near ? P_(P, 5 + axis) : P_(P, 8 + axis)), 1.0);
  float sgn = near ? 1.0 : -1.0;  // the two sides turn opposite ways
  bool rotate = abs(halfTurn) > 1e-8;
  if (axis == 2) {
    float d = p.z - centre.z;
    p.z = near ? centre.z + d + shift : centre.z - d - shift;
    if (rotate) {
      float dx = p.x - centre.x, dz = p.z - centre.z;
      p.x = centre.x + dx * c + sgn * dz * s;
      p.z = centre.y + dz * c - sgn * dx * s;
    }
    return p;
  }
  if (axis == 0) {
    float d = p.x - centre.x;
    p.x = near ? centre.x + d + shift : centre.x - d - shift;
  } else {
    float d = p.y - centre.y;
    p.y = near ? centre.y + d + shift : centre.y - d - shift;
  }
  if (rotate) {
    float dx = p.x - centre.x, dy = p.y - centre.y;
    p.xy = vec2(centre.x + dx * c + sgn * dy * s, centre.y + dy * c - sgn * dx * s);
  }
  return p;
}
vec3 V_rays1(vec3 p, float w, int P, int A) {
  float r2 = p.x * p.x + p.y * p.y;
  float u = 1.0 / fractoriumZeps(tan(sqrt(r2))) + w * (4.0 / (kPi * kPi));
  return vec3(w * u * r2 / fractoriumZeps(p.x), w * u * r2 / fractoriumZeps(p.y), w * p.z);
}
vec3 V_rays2(vec3 p, float w, int P, int A) {
  float r2 = p.x * p.x + p.y * p.y;
  float u = 1.0 / cos(r2 * tan(1.0 / fractoriumZeps(r2)));
  return vec3(w / 10.0 * u * r2 / fractoriumZeps(p.x), w / 10.0 * u * r2 / fractoriumZeps(p.y), w * p.z);
}
vec3 V_rays3(vec3 p, float w, int P, int A) {
  float r2 = p.x * p.x + p.y * p.y, r4 = r2 * r2;
  float u = 1.0 / sqrt(cos(sin(r4) * sin(1.0 / fractoriumZeps(r4))));
  return vec3(w / 10.0 * u * cos(r2) * r2 / fractoriumZeps(p.x), w / 10.0 * u * tan(r2) * r2 / fractoriumZeps(p.y),
              w * p.z);
}
// A hyperbolic translation of the unit disc: 1/p shifted along x, inverted again, shifted back.
vec3 V_hypershift(vec3 p, float w, int P, int A) {
  float shift = P_(P, 0);
  float inv = 1.0 / fractoriumZeps(p.x * p.x + p.y * p.y);
  vec2 q = vec2(inv * p.x + shift, inv * p.y);
  float r = w * (1.0 - shift * shift) / fractoriumZeps(dot(q, q));
  return vec3(r * q.x + shift, r * q.y, w * p.z);
}
