// Flame variations for the GPU backend (flame_variations.glsl has the conventions and the helpers):
// the CPU catalogue's variations_jwildfire*.cpp
// (engine/core/flame/), in float.

// std::round and JWildfire's Tools.FTOI: half away from zero.
// A filled curve's scale: Ψ₂ when Ψ₁ < filled, else 1; both numbers are drawn for every point.
float jwf_filled(float filled) {
  float psi1 = psi(), psi2 = psi();
  return filled > 0.0 && filled > psi1 ? psi2 : 1.0;
}
float jwf_pow10(float v) {
  float v2 = v * v, v4 = v2 * v2;
  return v4 * v4 * v2;
}

// ---- variations_jwildfire_more.cpp ----------------------------------------------------------

vec3 V_rose_wf(vec3 p, float w, int P, int A) {
  float amp = P_(P, 0), waves = roundHalfAway(P_(P, 1)), filled = P_(P, 2);
  float a = atan2c(p.x, p.y);
  float r = amp * cos(waves * a) * jwf_filled(filled);
  return vec3(w * sin(a) * r, w * cos(a) * r, w * p.z);
}
vec3 V_heart_wf(vec3 p, float w, int P, int A) {
  float scaleX = P_(P, 0), shiftT = P_(P, 1), scaleLeft = P_(P, 2), scaleRight = P_(P, 3);
  float a = atan2c(p.x, p.y), r = sqrt(p.x * p.x + p.y * p.y);
  bool left = a < 0.0;
  float t = min((left ? -a : a) / kPi * 60.0 * (left ? scaleLeft : scaleRight) - shiftT, 60.0);
  float side = left ? -1.0 : 1.0;
  float nx = side * 0.001 * (-t * t + 40.0 * t + 1200.0) * sin(kPi * t / 180.0) * r;
  float ny = -0.001 * (-t * t + 40.0 * t + 400.0) * cos(kPi * t / 180.0) * r;
  return vec3(w * nx * scaleX, w * ny, w * p.z);
}
vec3 V_maple_leaf(vec3 p, float w, int P, int A) {
  float t = atan2c(p.x, p.y) - kPi / 2.0;
  float r = w * jwf_filled(P_(P, 0));
  float c6 = cos(6.0 * t), c30 = cos(30.0 * t), ct = cos(t), c3 = cos(3.0 * t);
  float ct2 = ct * ct, ct4 = ct2 * ct2;
  float c30sq = c30 * c30, c30p4 = c30sq * c30sq, c30p12 = c30p4 * c30p4 * c30p4;
  float notch = 1.0 - jwf_pow10(sin(6.0 * t));
  float lobe = 1.0 - jwf_pow10(ct) * c3 * c3;
  float lx = (1.0 + c6 * c6 + 0.2 * jwf_pow10(c6 * cos(24.0 * t)) + (c30p12 / 9.0) * notch) * sin(2.0 * t) *
             (1.0 - ct4) * lobe;
  float ly = 21.0 / 20.0 * cos(2.0 * t) * (1.0 - ct4 + 0.5 * jwf_pow10(ct * c3)) *
             (1.0 + c6 * c6 + 0.2 * jwf_pow10(c6 * cos(18.0 * t)) + (c30p4 / 4.0 + c30p12 / 10.0) * lobe * notch);
  return vec3(r * lx, r * ly, w * p.z);
}
// waves2_wf (power 1) and waves3_wf (power 2): the sine or cosine waves, damped by e^damp.
vec3 jwf_waves(vec3 p, float w, int P, bool squared) {
  float scaleX = P_(P, 0), scaleY = P_(P, 1), freqX = P_(P, 2), freqY = P_(P, 3);
  bool cosX = roundHalfAway(P_(P, 4)) == 1.0, cosY = roundHalfAway(P_(P, 5)) == 1.0;
  float dampX = abs(P_(P, 6)) < 1e-8 ? 1.0 : exp(P_(P, 6));
  float dampY = abs(P_(P, 7)) < 1e-8 ? 1.0 : exp(P_(P, 7));
  float wx = cosX ? cos(p.y * freqX) : sin(p.y * freqX);
  float wy = cosY ? cos(p.x * freqY) : sin(p.x * freqY);
  if (squared) {
    wx *= wx;
    wy *= wy;
  }
  return vec3(w * (p.x + dampX * scaleX * wx) * dampX, w * (p.y + dampY * scaleY * wy) * dampY, w * p.z);
}
vec3 V_waves3_wf(vec3 p, float w, int P, int A) { return jwf_waves(p, w, P, true); }
vec3 V_tangent3D(vec3 p, float w, int P, int A) { return w * vec3(sin(p.x) / cos(p.y), tan(p.y), tan(p.x)); }
// JWildfire's 1/q keeps q where |q|² is 0 (it conjugates it only); the square root's two parts
// are worked out in double, as (radius ± dr) cancel where the other is large.
vec3 V_acosech(vec3 p, float w, int P, int A) {
  float m2 = p.x * p.x + p.y * p.y;
  float inverse = m2 == 0.0 ? 1.0 : 1.0 / m2;
  double re = double(p.x * inverse), im = double(-p.y * inverse);
  double dr = re * re - im * im - 1.0lf, di = 2.0lf * re * im;
  double radius = sqrt(dr * dr + di * di);
  double sr = sqrt(max(0.0lf, 0.5lf * (radius + dr)));
  double si = (di < 0.0lf ? -1.0lf : 1.0lf) * sqrt(max(0.0lf, 0.5lf * (radius - dr)));
  float ar = float(re + sr), ai = float(im + si);
  float lr = 0.5 * log(ar * ar + ai * ai + 1e-20), li = atan2c(ai, ar);
  float s = psi() < 0.5 ? w * 2.0 / kPi : -w * 2.0 / kPi;
  return vec3(s * li, s * lr, w * p.z);
}
vec3 V_cos2_bs(vec3 p, float w, int P, int A) {
  float x1 = P_(P, 0), x2 = P_(P, 1), y1 = P_(P, 2), y2 = P_(P, 3);
  return vec3(w * cos(p.x * x2) * cosh(p.y * y2), -w * sin(p.x * x1) * sinh(p.y * y1), w * p.z);
}
// The denominators below in forms without cancellation (cosh a − cos b = 2 sinh²(a/2) + 2 sin²(b/2),
// ...); where one is 0 nothing is added, z included, as on the CPU.
vec3 V_coth2_bs(vec3 p, float w, int P, int A) {
  float x1 = P_(P, 0), x2 = P_(P, 1), y1 = P_(P, 2), y2 = P_(P, 3);
  float sa = sinh(0.5 * x2 * p.x), sb = sin(0.5 * y2 * p.y);
  float d = 2.0 * (sa * sa + sb * sb);
  if (d == 0.0) return vec3(0.0);
  float f = w / d;
  return vec3(f * sinh(x1 * p.x), f * sin(y1 * p.y), w * p.z);
}
vec3 V_sec2_bs(vec3 p, float w, int P, int A) {
  float x1 = P_(P, 0), x2 = P_(P, 1), y1 = P_(P, 2), y2 = P_(P, 3);
  float cx = cos(p.x), sy = sinh(p.y);
  float d = 2.0 * (cx * cx + sy * sy);  // cos 2x + cosh 2y
  if (d == 0.0) return vec3(0.0);
  float f = w * 2.0 / d;
  return vec3(f * cos(p.x * x2) * cosh(p.y * y2), f * sin(p.x * x1) * sinh(p.y * y1), w * p.z);
}
vec3 V_tan2_bs(vec3 p, float w, int P, int A) {
  float x1 = P_(P, 0), x2 = P_(P, 1), y1 = P_(P, 2), y2 = P_(P, 3);
  float ca = cos(0.5 * x2 * p.x), sb = sinh(0.5 * y2 * p.y);
  float d = 2.0 * (ca * ca + sb * sb);  // cos(x2 x) + cosh(y2 y)
  if (d == 0.0) return vec3(0.0);
  float f = w / d;
  return vec3(f * sin(x1 * p.x), f * sinh(y1 * p.y), w * p.z);
}
vec3 V_chunk(vec3 p, float w, int P, int A) {
  float a = w * P_(P, 0), b = w * P_(P, 1), c = w * P_(P, 2), d = w * P_(P, 3), e = w * P_(P, 4), f = w * P_(P, 5);
  bool outside = clamp(roundHalfAway(P_(P, 6)), 0.0, 1.0) == 1.0;
  float r = a * p.x * p.x + b * p.x * p.y + c * p.y * p.y + d * p.x + e * p.y + f;
  bool keep = outside ? r > 0.0 : r <= 0.0;
  return keep ? vec3(p.x, p.y, w * p.z) : vec3(0.0);
}

// ---- variations_jwildfire_shapes.cpp --------------------------------------------------------

vec3 V_bwraps7(vec3 p, float w, int P, int A) {
  float cellsize = P_(P, 0), space = P_(P, 1), gain = P_(P, 2), innerTwist = P_(P, 3), outerTwist = P_(P, 4);
  float radius = 0.5 * (cellsize / (1.0 + space * space));
  float g2 = gain * gain + 1e-6;
  float maxBubble = g2 * radius;
  maxBubble = maxBubble > 2.0 ? 1.0 : maxBubble / (maxBubble * maxBubble / 4.0 + 1.0);
  float r2 = radius * radius, rFactor = radius / maxBubble;
  vec2 v = p.xy;
  if (cellsize != 0.0) {
    vec2 c = (floor(v / cellsize) + 0.5) * cellsize;
    vec2 l = v - c;
    if (!(dot(l, l) > r2)) {
      l *= g2;
      l *= rFactor / (dot(l, l) / 4.0 + 1.0);
      float t = dot(l, l) / r2;  // 0 at the centre, 1 at the rim
      float theta = innerTwist * (1.0 - t) + outerTwist * t;
      float s = sin(theta), co = cos(theta);
      v = vec2(c.x + co * l.x + s * l.y, c.y - s * l.x + co * l.y);
    }
  }
  return vec3(w * v, w * p.z);
}
vec3 V_yin_yang(vec3 p, float w, int P, int A) {
  float radius = clamp(P_(P, 0), 0.0, 1.0);
  float sinA = sin(kPi * P_(P, 1)), cosA = cos(kPi * P_(P, 1));
  float sinB = sin(kPi * P_(P, 2)), cosB = cos(kPi * P_(P, 2));
  bool dual = clamp(roundHalfAway(P_(P, 3)), 0.0, 1.0) == 1.0;
  bool outside = clamp(roundHalfAway(P_(P, 4)), 0.0, 1.0) == 1.0;
  float u = psi();
  float rx = 0.0, ry = 0.0;
  if (p.x * p.x + p.y * p.y < 1.0) {
    bool yang = dual && u > 0.5;
    float inv = yang ? -1.0 : 1.0, rr = yang ? 1.0 - radius : radius;
    float s = yang ? sinB : sinA, c = yang ? cosB : cosA;
    float xx = p.x * c - p.y * s, yy = p.x * s + p.y * c;
    if (yy > 0.0) {
      float t = sqrt(1.0 - yy * yy);
      float alfa = (1.0 - xx / t) * 0.5;
      float t1 = (t - 0.5) * 2.0;
      float k1 = alfa * rr + (1.0 - alfa);
      rx = (t1 * k1 + alfa * (rr - 1.0)) * inv;
      ry = sqrt(1.0 - t1 * t1) * k1 * inv;
    } else {
      rx = (xx * (1.0 - rr) + rr) * inv;
      ry = yy * (1.0 - rr) * inv;
    }
  } else if (outside) {
    rx = p.x;
    ry = p.y;
  }
  return vec3(w * rx, w * ry, w * p.z);
}
vec3 V_affine3D(vec3 p, float w, int P, int A) {
  vec3 translate = vec3(P_(P, 0), P_(P, 1), P_(P, 2));
  const float degree = kPi / 180.0;
  float sinX = sin(P_(P, 6) * degree), cosX = cos(P_(P, 6) * degree);
  float sinY = sin(P_(P, 7) * degree), cosY = cos(P_(P, 7) * degree);
  float sinZ = sin(P_(P, 8) * degree), cosZ = cos(P_(P, 8) * degree);
  vec3 s = p * vec3(P_(P, 3), P_(P, 4), P_(P, 5));
  float ax = s.x + P_(P, 9) * s.y + P_(P, 10) * s.z;
  float ay = P_(P, 11) * s.x + s.y + P_(P, 12) * s.z;
  float az = P_(P, 13) * s.x + P_(P, 14) * s.y + s.z;
  float u = cosY * ax + sinY * (sinX * ay + cosX * az);
  float v = cosX * ay - sinX * az;
  return w * (vec3(cosZ * u - sinZ * v, sinZ * u + cosZ * v, -sinY * ax + cosY * (sinX * ay + cosX * az)) + translate);
}
vec3 V_cannabiscurve_wf(vec3 p, float w, int P, int A) {
  float a = atan2c(p.x, p.y);
  float r = (1.0 + 0.9 * cos(8.0 * a)) * (1.0 + 0.1 * cos(24.0 * a)) * (0.9 + 0.1 * cos(200.0 * a)) * (1.0 + sin(a));
  r *= jwf_filled(P_(P, 0));
  float turned = a + kPi / 2.0;
  return vec3(w * sin(turned) * r, w * cos(turned) * r, w * p.z);
}
vec3 V_cloverleaf_wf(vec3 p, float w, int P, int A) {
  float a = atan2c(p.x, p.y);
  float r = (sin(2.0 * a) + 0.25 * sin(6.0 * a)) * jwf_filled(P_(P, 0));
  return vec3(w * sin(a) * r, w * cos(a) * r, w * p.z);
}
vec3 V_japanese_maple_leaf(vec3 p, float w, int P, int A) {
  float t = atan2c(p.x, p.y) * 0.5 + kPi / 2.0;
  float r = w * 0.667 * jwf_filled(P_(P, 0));
  float c8 = cos(8.0 * t), c80 = cos(80.0 * t), ct = cos(t), c3 = cos(3.0 * t);
  float st = sin(t), ct2 = ct * ct, ct4 = ct2 * ct2, ct8 = ct4 * ct4;
  float shared8 = c8 * c8 + 0.2 * jwf_pow10(c8 * cos(24.0 * t));
  float fringe = c80 * c80 / 6.0 + jwf_pow10(c80) / 15.0;
  float notch = 1.0 - jwf_pow10(sin(8.0 * t));
  float lobe = 1.0 - jwf_pow10(ct) * c3 * c3;
  float lx = (4.0 / 15.0 + shared8 + fringe) * notch * sin(2.0 * t) * (1.0 + st) *
             (lobe + ct8 * ct * jwf_pow10(cos(5.0 * t)) / 30.0);
  float ly = (8.0 / 30.0 + shared8 + fringe * lobe * notch) * cos(2.0 * t) * (1.0 + st + jwf_pow10(ct * c3));
  return vec3(r * lx, r * ly, w * p.z);
}
vec3 V_spherical3D_wf(vec3 p, float w, int P, int A) {
  float sgn = roundHalfAway(P_(P, 0)) == 0.0 ? 1.0 : -1.0;
  float exponent = P_(P, 1);
  float rr = dot(p, p) + kEpsilon;
  float r = sgn * w / (abs(exponent - 2.0) < 1e-8 ? rr : pow(rr, exponent / 2.0));
  return p * r;
}
vec3 V_waves2_wf(vec3 p, float w, int P, int A) { return jwf_waves(p, w, P, false); }
vec3 V_butterfly3D(vec3 p, float w, int P, int A) {
  float wx = w * 1.3029400317411197908970256609023;  // 4/√(3π)
  float y2 = 2.0 * p.y;
  float r = wx * sqrt(abs(p.x * p.y) / (kEpsilon + p.x * p.x + y2 * y2));
  return vec3(r * p.x, r * y2, r * abs(y2) * sqrt(p.x * p.x + p.y * p.y) / 4.0);
}
vec3 V_cylinder_apo(vec3 p, float w, int P, int A) { return w * vec3(sin(p.x), p.y, cos(p.x)); }

// ---- variations_jwildfire_tail.cpp ----------------------------------------------------------

vec3 V_dustpoint(vec3 p, float w, int P, int A) {
  float sgn = psi() < 0.5 ? 1.0 : -1.0;
  float pick = psi();
  float r = sqrt(p.x * p.x + p.y * p.y) + kEpsilon;
  vec2 q = p.xy / 3.0;
  if (pick < 0.5)
    q = vec2(p.x / r - 1.0, sgn * p.y / r);
  else if (pick >= 0.75)
    q.x += 2.0 / 3.0;
  return vec3(w * q, w * p.z);
}
// prepost_affine's rotation, row-major (yaw, pitch, roll in degrees at P + 3 ...).
mat3 jwf_prepostRotation(int P) {
  const float degree = kPi / 180.0;
  float sy = sin(P_(P, 3) * degree), cy = cos(P_(P, 3) * degree);
  float sp = sin(P_(P, 4) * degree), cp = cos(P_(P, 4) * degree);
  float sr = sin(P_(P, 5) * degree), cr = cos(P_(P, 5) * degree);
  // GLSL's mat3 takes columns: this is the transpose of the CPU's rows.
  return mat3(cy * cr - sy * sp * sr, sy * cp, cy * sr + sy * sp * cr,
              -sy * cr - cy * sp * sr, cy * cp, cy * sp * cr - sy * sr,
              -cp * sr, -sp, cp * cr);
}
vec3 jwf_prepostScale(int P) {
  vec3 s = vec3(P_(P, 0), P_(P, 1), P_(P, 2));
  return vec3(s.x == 0.0 ? 1e-8 : s.x, s.y == 0.0 ? 1e-8 : s.y, s.z == 0.0 ? 1e-8 : s.z);
}
vec3 V_prepost_affine(vec3 p, float w, int P, int A) {
  if (w == 0.0) return p;
  return jwf_prepostRotation(P) * (w * jwf_prepostScale(P) * p) + vec3(P_(P, 6), P_(P, 7), P_(P, 8));
}
vec3 V_pre_prepost_affine(vec3 p, float w, int P, int A) {
  if (w == 0.0) return p;
  // The transpose of the rotation turns it back.
  vec3 q = (p - vec3(P_(P, 6), P_(P, 7), P_(P, 8))) * jwf_prepostRotation(P);
  return q / (w * jwf_prepostScale(P));
}
// The n-gon pushed onto its circumcircle (circlize) or the circle pulled onto it, blended by w.
vec3 jwf_circlize(vec3 p, float w, int P, bool inverse) {
  float sides = clamp(roundHalfAway(P_(P, 0)), 3.0, 50.0), rotation = P_(P, 1) * kPi / 180.0;
  bool reverse = clamp(roundHalfAway(P_(P, 2)), 0.0, 1.0) == 1.0;
  bool circlize = reverse != inverse;
  float angle = atan2c(p.y, p.x);
  float r = sqrt(p.x * p.x + p.y * p.y) + kEpsilon;
  float piN = kPi / sides, a = angle - rotation;
  float factor = cos(piN) / cos(a - piN * (2.0 * floor(sides * a / kTwoPi) + 1.0));
  float target = circlize ? r / factor : r * factor;
  r = r + (target - r) * w;
  return vec3(r * cos(angle), r * sin(angle), w * p.z);
}
vec3 V_prepost_circlize(vec3 p, float w, int P, int A) { return jwf_circlize(p, w, P, false); }
vec3 V_pre_prepost_circlize(vec3 p, float w, int P, int A) { return jwf_circlize(p, w, P, true); }
// Weight 0 or a zero denominator leaves the point.
vec3 V_prepost_mobius(vec3 p, float w, int P, int A) {
  vec2 a = vec2(P_(P, 0), P_(P, 4)), b = vec2(P_(P, 1), P_(P, 5));
  vec2 c = vec2(P_(P, 2), P_(P, 6)), d = vec2(P_(P, 3), P_(P, 7));
  vec2 u = vec2(a.x * p.x - a.y * p.y + b.x, a.x * p.y + a.y * p.x + b.y);
  vec2 v = vec2(c.x * p.x - c.y * p.y + d.x, c.x * p.y + c.y * p.x + d.y);
  float den = dot(v, v);
  if (w == 0.0 || den == 0.0) return vec3(p.xy, w * p.z);
  float k = w / den;
  return vec3(k * (u.x * v.x + u.y * v.y), k * (u.y * v.x - u.x * v.y), w * p.z);
}
vec3 V_pre_prepost_mobius(vec3 p, float w, int P, int A) {
  vec2 a = vec2(P_(P, 0), P_(P, 4)), b = vec2(P_(P, 1), P_(P, 5));
  vec2 c = vec2(P_(P, 2), P_(P, 6)), d = vec2(P_(P, 3), P_(P, 7));
  vec2 u = vec2(d.x * p.x - d.y * p.y - b.x, d.x * p.y + d.y * p.x - b.y);
  vec2 v = vec2(-c.x * p.x + c.y * p.y + a.x, -c.x * p.y - c.y * p.x + a.y);
  float den = dot(v, v);
  if (w == 0.0 || den == 0.0) return vec3(p.xy, w * p.z);
  float k = 1.0 / (w * den);
  return vec3(k * (u.x * v.x + u.y * v.y), k * (u.y * v.x - u.x * v.y), w * p.z);
}

// ---- variations_jwildfire.cpp ---------------------------------------------------------------

// One of vibration2's waves (parameters at P + first, its modulations at P + mod), added to q.
vec2 jwf_vibration(vec2 p, int P, int first, int mod, vec2 q) {
  float dir = P_(P, first), angle = P_(P, first + 1), freq = P_(P, first + 2), amp = P_(P, first + 3);
  float phase = P_(P, first + 4);
  float along = p.x * cos(dir) + p.y * sin(dir);
  float dirL = dir + P_(P, mod) * cos(along * P_(P, mod + 1) * kTwoPi);
  float angleL = angle + P_(P, mod + 2) * cos(along * P_(P, mod + 3) * kTwoPi);
  float phaseL = P_(P, mod + 4) * cos(along * P_(P, mod + 5) * kTwoPi) / freq;
  float ampL = amp + amp * P_(P, mod + 6) * cos(along * P_(P, mod + 7) * kTwoPi);
  float total = angleL + dirL;
  float alongL = p.x * cos(dirL) + p.y * sin(dirL);
  float local = ampL * sin(alongL * freq * kTwoPi + phaseL + kTwoPi * phase / freq);
  return q + local * vec2(cos(total), sin(total));
}
vec3 V_vibration2(vec3 p, float w, int P, int A) {
  vec2 q = jwf_vibration(p.xy, P, 0, 10, p.xy);
  q = jwf_vibration(p.xy, P, 5, 18, q);
  return vec3(w * q, w * p.z);
}

// ---- variations_jwildfire_corpus.cpp --------------------------------------------------------

// The branch k 2π/Re_p (k below 32767) is reduced to one turn in double, where the CPU takes the
// cosine of the whole angle.
vec3 V_juliacomplex(vec3 p, float w, int P, int A) {
  float re = P_(P, 0), im = P_(P, 1), dist = P_(P, 2), logAdd = abs(P_(P, 3));
  float d = re * re + im * im, b = re;
  if (abs(d) < 0.001) {
    d = 1.0;
    b = 1.0;
  } else if (abs(b) < 0.001) {
    b = 1.0;
  }
  float halfInversePower = 0.5 * dist / b;
  float inverseRe = dist * re / d, inverseIm = -dist * im / d;
  bool twists = abs(inverseIm) > 0.001;
  float phi = atan2c(p.y, p.x);
  float r2 = p.x * p.x + p.y * p.y;
  float spiral = twists && abs(r2) > 0.001 ? 0.5 * log(logAdd + r2) * inverseIm : 0.0;
  double turns = double(floor(psi() * 32767.0)) / double(b);
  float branch = float((turns - floor(turns)) * 6.283185307179586lf);
  float angle = phi * inverseRe + spiral + branch;
  float radius = w * pow(r2, halfInversePower) * (twists ? exp(-inverseIm * phi) : 1.0);
  return vec3(radius * cos(angle), radius * sin(angle), w * p.z);
}

// crown_js: a^k t reaches 10¹⁰ and more, so each angle is reduced to one turn in double (a^k by
// repeated products, exact for a whole a as the CPU's pow is).
vec3 V_crown_js(vec3 p, float w, int P, int A) {
  float a = P_(P, 0), b = P_(P, 1);
  double t = -3.141592653589793lf + 6.283185307179586lf * double(psi());
  double speed = 1.0lf;
  vec2 s = vec2(0.0);
  for (int k = 1; k < 15; ++k) {
    speed *= double(a);
    double th = speed * t * (k % 2 == 0 ? -1.0lf : 1.0lf);
    double turns = th * (1.0lf / 6.283185307179586lf);
    float reduced = float((turns - floor(turns)) * 6.283185307179586lf);
    float inverse = 1.0 / pow(a, b * float(k));
    s += vec2(sin(reduced), cos(reduced)) * inverse;
  }
  float mag2 = dot(s, s);
  return vec3(w * s, w * mag2 * mag2);
}

// Minkowski's question-mark function on [0, 1], 20 steps down the Stern–Brocot tree.
float jwf_minkowski(float x) {
  float p = 0.0, q = 1.0, r = 1.0, s = 1.0, y = 0.0, d = 1.0;
  for (int step = 0; step < 20; ++step) {
    d *= 0.5;
    float m = p + r, n = q + s;
    if (x < m / n) {
      r = m;
      s = n;
    } else {
      y += d;
      p = m;
      q = n;
    }
  }
  return y + d;
}
float jwf_minkowskiSine(float x, bool altWave) {
  float lp = fmodc(abs(x), 4.0);
  float p = fmodc(abs(x), 2.0);
  if (p > 1.0) p = 2.0 - p;
  float mink = altWave ? jwf_minkowski(p) - p : jwf_minkowski(p);
  return (lp < 2.0) != (x > 0.0) ? mink : -mink;
}
vec3 V_minkowskope(vec3 p, float w, int P, int A) {
  float separation = P_(P, 0), frequencyX = P_(P, 1), frequencyY = P_(P, 2), amplitude = P_(P, 3);
  float perturbation = P_(P, 4), damping = P_(P, 5);
  bool altWave = frequencyX <= 0.0;
  float pt = perturbation * jwf_minkowskiSine(0.5 * frequencyY * p.y, altWave);
  float wave = jwf_minkowskiSine(0.5 * frequencyX * p.x + pt - 1.0, altWave);
  float t = amplitude * (abs(damping) <= 1e-8 ? 1.0 : exp(-abs(p.x) * damping)) * wave + separation;
  float sgn = abs(p.y) <= t ? -w : w;
  return vec3(sgn * p.xy, w * p.z);
}

// maurer_rose: Ψ₁…Ψ₄ drawn for every point.
vec2 jwf_rose(float theta, float k, float c) { return (cos(k * theta) + c) * vec2(cos(theta), sin(theta)); }
vec3 V_maurer_rose(vec3 p, float w, int P, int A) {
  float k = P_(P, 0) / P_(P, 1), c = P_(P, 2);
  float step = kTwoPi * (P_(P, 3) / 360.0);
  float cycles = P_(P, 4) * step / kTwoPi;
  float showSum = P_(P, 5) + P_(P, 6) + P_(P, 7);
  float lineShare = P_(P, 5) / showSum, pointShare = P_(P, 6) / showSum;
  float pointThreshold = lineShare + pointShare, pointHalfThreshold = lineShare + pointShare / 2.0;
  float lineThickness = P_(P, 8) / 100.0, pointThickness = P_(P, 9) / 100.0, curveThickness = P_(P, 10) / 100.0;
  float psi1 = psi(), psi2 = psi(), psi3 = psi(), psi4 = psi();
  float t = cycles * atan2c(p.y, p.x);
  float theta1 = floor(t / step) * step, theta2 = theta1 + step;
  vec2 a = jwf_rose(theta1, k, c), b = jwf_rose(theta2, k, c);
  vec2 q;
  if (psi1 < lineShare) {
    // Along the chord by its slope, as JWildfire goes.
    float dx = b.x - a.x, dy = b.y - a.y, slope = dy / dx;
    float along = psi2 * sqrt(dx * dx + dy * dy);
    float xOffset = along / sqrt(1.0 + slope * slope);
    if (b.x < a.x) xOffset = -xOffset;
    float yOffset = abs(slope * xOffset);
    if (b.y < a.y) yOffset = -yOffset;
    if (lineThickness != 0.0) {
      xOffset += (psi3 - 0.5) * lineThickness;
      yOffset += (psi4 - 0.5) * lineThickness;
    }
    q = a + vec2(xOffset, yOffset);
  } else if (psi1 <= pointThreshold) {
    vec2 offset = vec2(0.0);
    if (pointThickness != 0.0) {
      float radius = psi2 * pointThickness, angle = psi3 * kTwoPi;
      offset = radius * vec2(cos(angle), sin(angle));
    }
    q = (psi1 <= pointHalfThreshold ? a : b) + offset;
  } else {
    q = jwf_rose(t, k, c);
    if (curveThickness != 0.0) q += (vec2(psi2, psi3) - 0.5) * curveThickness;
  }
  return vec3(w * q, w * p.z);
}

// C's pow, which GLSL leaves undefined for a negative base: odd and even whole powers keep their
// signs, other powers of a negative number are NaN.
float jwf_powc(float x, float y) {
  if (y == 0.0) return 1.0;
  if (x >= 0.0) return x == 0.0 ? (y > 0.0 ? 0.0 : 1.0 / x) : pow(x, y);
  if (y != floor(y)) return intBitsToFloat(0x7fc00000);
  float r = pow(-x, y);
  return mod(y, 2.0) == 1.0 ? -r : r;
}
// JWildfire's square path (hamid_js's preset 9): 400 steps round the unit square.
vec2 jwf_hamidSquarePath(float step) {
  if (step >= 400.0) step -= 400.0 * floor(step / 400.0);
  if (step < 100.0) return vec2(step / 100.0, 0.0);
  if (step < 200.0) return vec2(1.0, (step - 100.0) / 100.0);
  if (step < 300.0) return vec2((300.0 - step) / 100.0, 1.0);
  return vec2(0.0, (400.0 - step) / 100.0);
}
// hamid_js's formulas: jwf_T(k, c) = k c π I / N, JWildfire's parameters a … p at P + 3 ...
#define jwf_T(times, c1) ((times) * (c1) * kPi * I / np)
#define jwf_S(times, c1) sin(jwf_T(times, c1))
#define jwf_C(times, c1) cos(jwf_T(times, c1))
vec4 jwf_hamidLine(int preset, int P, float I, float np) {
  float a = P_(P, 3), b = P_(P, 4), c = P_(P, 5), d = P_(P, 6), e = P_(P, 7), f = P_(P, 8), g = P_(P, 9);
  float h = P_(P, 10), ii = P_(P, 11), j = P_(P, 12), k = P_(P, 13);
  switch (preset) {
    case 0: return vec4(-jwf_S(4.0, a), -jwf_C(2.0, b), -0.5 * e * jwf_S(8.0, c), -0.5 * f * jwf_C(4.0, d));
    case 1: return vec4(-jwf_S(2.0, a), -jwf_C(2.0, b), -0.5 * e * jwf_S(8.0, c), -0.5 * f * jwf_C(12.0, d));
    case 2: return vec4(-jwf_S(8.0, a), -jwf_C(2.0, b), -0.5 * e * jwf_S(6.0, c), -0.5 * f * jwf_C(2.0, d));
    case 3: return vec4(-jwf_S(10.0, a), -jwf_C(2.0, b), -0.5 * e * jwf_S(12.0, c), -0.5 * f * jwf_C(2.0, d));
    case 4: {  // the figure starts 699 steps along
      float s = kPi * (I + 699.0) / np;
      return vec4(sin(10.0 * a * s), cos(8.0 * b * s), sin(12.0 * c * s), cos(10.0 * d * s));
    }
    case 5:  // x1 divides by 1000 where the others divide by N: JWildfire's
      return vec4(-2.0 * a * cos(4.0 * b * kPi * I / 1000.0), 0.5 * c * jwf_powc(jwf_C(6.0, d), 3.0 * ii),
                  -2.0 * e * jwf_S(6.0, f) / 15.0 * j, 4.0 * g * jwf_S(2.0, h) / 15.0 * k);
    case 6:
      return vec4(3.0 * a * jwf_powc(jwf_S(2.0, b), 3.0 * h), -jwf_C(8.0, c),
                  1.5 * d * jwf_powc(jwf_S(2.0, e), 3.0 * ii), -0.5 * f * jwf_C(6.0, g));
    case 7:
      return vec4(jwf_C(6.0, a), -jwf_C(8.0, b), 1.5 * c * jwf_powc(jwf_S(2.0, 1.0), 3.0 * f),
                  -0.5 * d * jwf_C(6.0, e));
    case 8:
      return vec4(jwf_powc(jwf_S(20.0, a), 3.0), jwf_powc(jwf_C(18.0, b), 3.0 * e), jwf_powc(jwf_S(16.0, c), 3.0),
                  jwf_powc(jwf_C(14.0, d), 3.0 * f));
    default: return vec4(jwf_hamidSquarePath(I), jwf_hamidSquarePath(I + 199.0));
  }
}
// A circle's centre and radius.
vec3 jwf_hamidCircle(int preset, int P, float I, float np) {
  float a = P_(P, 3), b = P_(P, 4), c = P_(P, 5), d = P_(P, 6), e = P_(P, 7), f = P_(P, 8), g = P_(P, 9);
  float h = P_(P, 10), ii = P_(P, 11), j = P_(P, 12), k = P_(P, 13), l = P_(P, 14), m = P_(P, 15);
  float nn = P_(P, 16), o = P_(P, 17), p = P_(P, 18);
  const float kDot = 1.0 / 150.0;  // the smallest circle's radius
  switch (preset) {
    case 10:
      return vec3(2.0 * a * jwf_S(2.0, b) / 3.0 + jwf_S(36.0, c) * jwf_C(30.0, d) / 3.0 * k +
                      jwf_powc(jwf_S(14.0, 1.0), 3.0 * l) / 3.0 * m,
                  2.0 * e * jwf_C(2.0, f) / 3.0 * nn + jwf_C(36.0, g) * jwf_C(30.0, h) / 3.0 * o +
                      jwf_powc(jwf_C(14.0, ii), 3.0) / 5.0 * p,
                  kDot + jwf_powc(jwf_S(36.0, j), 4.0) / 9.0);
    case 11: return vec3(jwf_S(14.0, a), jwf_C(32.0, b), jwf_powc(jwf_S(20.0, c), 2.0) / 3.0 * d);
    case 12:
      return vec3(2.0 * a * jwf_S(6.0, b) / 3.0 + jwf_S(36.0, c) * jwf_C(30.0, d) / 4.0 +
                      jwf_powc(jwf_S(14.0, e), 3.0 * k) / 4.0 * l,
                  2.0 * f * jwf_C(6.0, g) / 3.0 + jwf_C(28.0, h) * jwf_C(30.0, ii) / 3.0 +
                      jwf_powc(jwf_C(14.0, 1.0), 3.0 * m) / 5.0 * nn,
                  kDot + jwf_powc(jwf_S(36.0, j), 4.0 * o) / 20.0 * p);
    case 13:
      return vec3(jwf_S(10.0, a), jwf_powc(jwf_C(28.0, b), 3.0 * e), jwf_powc(jwf_S(18.0, c), 2.0) / 3.0 * d);
    case 14:
      return vec3(2.0 * a * jwf_S(18.0, b) / 3.0 + jwf_powc(jwf_S(40.0, c), 3.0) * jwf_C(30.0, d) / 3.0 +
                      jwf_powc(jwf_S(34.0, e), 3.0 * k) / 4.0 * l,
                  2.0 * f * jwf_C(18.0, g) / 3.0 + jwf_powc(jwf_C(28.0, h), 3.0) * jwf_C(40.0, 1.0) / 3.0 +
                      jwf_powc(jwf_C(34.0, ii), 3.0 * m) / 3.0 * nn,
                  kDot + jwf_powc(jwf_S(56.0, j), 4.0 * o) / 8.0 * p);
    case 15:
      return vec3(2.0 * a * jwf_S(14.0, b) / 3.0 + jwf_powc(jwf_S(10.0, c), 3.0) * jwf_C(28.0, d) / 3.0 +
                      jwf_powc(jwf_S(46.0, e), 3.0 * m) / 3.0 * nn,
                  2.0 * jwf_C(14.0, f) / 3.0 + jwf_powc(jwf_C(10.0, g), 3.0) * jwf_C(28.0, h) / 3.0 +
                      jwf_powc(jwf_C(34.0, j), 3.0 * o) / 3.0,
                  kDot + jwf_powc(jwf_S(72.0, k), 6.0) / 9.0 + jwf_powc(jwf_S(12.0, l), 4.0) / 20.0 * p);
    case 16:
      return vec3(jwf_S(38.0, a) * jwf_C(26.0, b) / 2.0 + jwf_powc(jwf_S(18.0, c), 3.0 * l) / 2.0 * m,
                  2.0 * jwf_C(18.0, d) / 3.0 + jwf_C(38.0, e) * jwf_C(36.0, f) / 3.0 +
                      jwf_powc(jwf_C(18.0, g), 3.0 * nn) / 4.0 * o,
                  kDot + jwf_powc(jwf_S(18.0, h), 10.0) * jwf_powc(jwf_S(100.0, ii), 6.0) / 100.0 +
                      jwf_powc(jwf_S(72.0, j), 8.0) * jwf_powc(jwf_C(18.0, k), 6.0) / 20.0 * p);
    case 17:
      return vec3(2.0 * a * jwf_S(10.0, b) + jwf_powc(jwf_S(6.0, c), 3.0) * jwf_C(28.0, d) / 3.0 +
                      jwf_S(126.0, e) / 10.0 * l,
                  2.0 * jwf_C(6.0, f) / 3.0 + jwf_powc(jwf_C(18.0, g), 3.0) * jwf_C(36.0, h) / 3.0 +
                      jwf_C(126.0, ii) / 10.0 * m,
                  kDot + jwf_powc(jwf_S(48.0, j), 4.0) * (1.0 + jwf_powc(jwf_S(12.0, k), 2.0 * nn)) / 18.0 * o);
    case 18:
      return vec3(2.0 * a * jwf_S(18.0, b) / 5.0 + jwf_powc(jwf_S(34.0, c), 3.0 * j) / 3.0 * k +
                      jwf_powc(jwf_S(50.0, d), 3.0 * l) / 3.0 * m,
                  2.0 * jwf_C(18.0, e) / 3.0 + jwf_powc(jwf_C(34.0, f), 3.0) / 3.0 +
                      jwf_powc(jwf_C(50.0, g), 3.0 * nn) / 10.0 * o,
                  kDot + jwf_powc(jwf_S(58.0, ii), 4.0) / 10.0 * p);
    default:
      return vec3(jwf_C(10.0, a) * (c - jwf_powc(jwf_S(16.0, b), 2.0 * h) / 2.0 * ii),
                  jwf_S(10.0, d) * (f - jwf_powc(jwf_C(34.0, e), 2.0 * j) / 2.0 * k),
                  1.0 / 200.0 + jwf_powc(jwf_S(52.0, g), 4.0 * l) / 10.0 * m);
  }
}
#undef jwf_T
#undef jwf_S
#undef jwf_C
vec3 V_hamid_js(vec3 p, float w, int P, int A) {
  float presetValue = clamp(roundHalfAway(P_(P, 0)), 0.0, 19.0);
  int preset = isnan(presetValue) ? 0 : int(presetValue);
  float lines = trunc(clamp(P_(P, 1), -2147483648.0, 2147483647.0));
  float np = lines == 0.0 || isnan(lines) ? 1.0 : lines;
  bool filled = trunc(P_(P, 2)) == 1.0;
  float I = trunc(psi() * np + 1.0);
  vec2 q;
  if (preset < 10) {
    vec4 line = jwf_hamidLine(preset, P, I, np);
    float xdiff = line.z - line.x, ydiff = line.w - line.y;
    float slope = xdiff == 0.0 ? 10000.0 : ydiff / xdiff;
    float along = psi() * sqrt(xdiff * xdiff + ydiff * ydiff);
    float xoffset = along / sqrt(1.0 + slope * slope);
    if (line.z < line.x) xoffset = -xoffset;
    float yoffset = abs(slope * xoffset);
    if (line.w < line.y) yoffset = -yoffset;
    q = line.xy + vec2(xoffset, yoffset);
  } else {
    vec3 circle = jwf_hamidCircle(preset, P, I, np);
    float radius = circle.z;
    if (filled && psi() > 0.05) radius *= psi();
    float angle = psi() * kTwoPi;
    q = circle.xy + radius * vec2(cos(angle), sin(angle));
  }
  return vec3(w * q, w * p.z);
}

// rhodonea's cycles to close the rose (BigInteger.gcd on the whole knumer and kdenom).
float jwf_gcd(float a, float b) {
  uint ua = uint(min(abs(a), 2147483648.0)), ub = uint(min(abs(b), 2147483648.0));
  while (ub != 0u) {
    uint r = ua % ub;
    ua = ub;
    ub = r;
  }
  return float(ua);
}
float jwf_rhodoneaMode(float v) {
  float m = floor(v);
  return m >= 0.0 && m <= 6.0 ? m : 0.0;
}
// Ψ is drawn for every point. Mode 1's clearing of x where y is exactly 0 acts on this term's own
// y here: the CPU tests the running sum, which is the same for a transform's first term.
vec3 V_rhodonea(vec3 p, float w, int P, int A) {
  float kn = P_(P, 0), kd = P_(P, 1), innerSpread = P_(P, 4), outerSpread = P_(P, 5), fill = P_(P, 9);
  float radialOffset = P_(P, 10), cyclesParam = P_(P, 11), metacycles = P_(P, 13);
  float k = kn / kd, cyclesToClose;
  if (fmodc(k, 1.0) == 0.0) {
    if (fmodc(k, 2.0) == 0.0)
      cyclesToClose = 1.0;
    else
      cyclesToClose = radialOffset != 0.0 || innerSpread != 0.0 || outerSpread != 0.0 || fill != 0.0 ? 1.0 : 0.5;
  } else if (fmodc(kn, 1.0) == 0.0 && fmodc(kd, 1.0) == 0.0) {
    float gcd = jwf_gcd(kn, kd);
    if (gcd != 1.0) {
      kn /= gcd;
      kd /= gcd;
    }
    cyclesToClose = fmodc(kn, 2.0) == 0.0 || fmodc(kd, 2.0) == 0.0 ? kd : kd / 2.0;
  } else {
    cyclesToClose = 16.0;
  }
  float cycles = cyclesParam == 0.0 ? cyclesToClose * metacycles : cyclesParam;
  float innerMode = jwf_rhodoneaMode(P_(P, 2)), outerMode = jwf_rhodoneaMode(P_(P, 3));
  float innerRatio = P_(P, 6), outerRatio = P_(P, 7), split = P_(P, 8);
  float cycleOffset = P_(P, 12), expansionStep = P_(P, 14);
  float u = psi();
  float rin = split * sqrt(p.x * p.x + p.y * p.y);
  float tin = atan2c(p.y, p.x);
  float t = cycles * (tin + cycleOffset * kTwoPi);
  float r = cos(k * t) + radialOffset;
  if (fill != 0.0) r += fill * (u - 0.5);
  float cx = r * cos(t), cy = r * sin(t);
  float expansion = floor(cycles * (tin + kPi) / (cyclesToClose * kTwoPi));
  float amount = w + expansion * expansionStep;
  bool outer = abs(rin) > abs(r);
  float mode = outer ? outerMode : innerMode;
  float spread = outer ? outerSpread : innerSpread, ratio = outer ? outerRatio : innerRatio;
  float xin = cx < 0.0 ? -abs(p.x) : abs(p.x), yin = cy < 0.0 ? -abs(p.y) : abs(p.y);
  vec2 q = amount * vec2(cx, cy);
  if (mode == 1.0) {
    q = amount * vec2((rin * spread * ratio - spread * ratio + 1.0) * cx, (rin * spread - spread + 1.0) * cy);
    if (q.y == 0.0) q.x = 0.0;
  } else if (mode == 2.0) {  // towards the point outside, away from it inside
    float sgn = outer ? 1.0 : -1.0;
    q = amount * vec2(cx + sgn * spread * ratio * (outer ? xin - cx : cx - xin),
                      cy + sgn * spread * (outer ? yin - cy : cy - yin));
  } else if (mode == 3.0) {
    float sgn = outer ? 1.0 : -1.0;
    q = amount * vec2(cx + sgn * spread * ratio * xin, cy + sgn * spread * yin);
  } else if (mode == 4.0) {
    q = amount * vec2((0.5 * rin + spread * ratio) * cx, (0.5 * rin + spread) * cy);
  } else if (mode == 5.0 || mode == 6.0) {
    // Mode 5 keeps the point outside and drops it inside; mode 6 the reverse.
    q = outer == (mode == 5.0) ? p.xy : vec2(intBitsToFloat(0x7fc00000));
  }
  return vec3(q, w * p.z);
}

// inversion's shape (0 circle … 6 supershape, in s: shape, scale, rotation; a … f at P + 5 ...):
// its radius at angle tin from the origin.
float jwf_inversionRadius(vec3 s, int P, float tin) {
  float shape = s.x, scale = s.y, t = tin - s.z;
  float a = P_(P, 5), b = P_(P, 6), c = P_(P, 7), d = P_(P, 8), e = P_(P, 9), f = P_(P, 10);
  if (shape == 1.0) return a * b / sqrt(b * cos(t) * b * cos(t) + a * sin(t) * a * sin(t)) * scale;
  if (shape == 2.0) {
    float ct = cos(t), st = sin(t);
    return sqrt(a * a * b * b / (b * b * ct * ct - a * a * st * st)) * scale;
  }
  if (shape == 3.0) {
    float theta = abs(fmodc(t, kTwoPi));
    float sides = floor(a);
    return cos(kPi / sides) / cos(fmodc(theta, kTwoPi / sides) - kPi / sides) * scale;
  }
  if (shape == 4.0) return (cos(a / b * t) + c) * scale;
  if (shape == 5.0) return a * b / pow(pow(abs(a * sin(t)), c) + pow(abs(b * cos(t)), c), 1.0 / c) * scale;
  if (shape == 6.0)
    return pow(pow(abs(cos(c * t / 4.0) / a), e) + pow(abs(sin(c * t / 4.0) / b), f), -1.0 / d) * scale;
  return scale;  // the circle, and any other shape number
}
// The rose's period (JWildfire's Rhodonea.calcPeriod).
float jwf_rosePeriod(float a, float b, float c) {
  float k = a / b;
  if (fmodc(k, 1.0) == 0.0) return fmodc(k, 2.0) == 0.0 || c != 0.0 ? kTwoPi : kPi;
  if (fmodc(a, 1.0) == 0.0 && fmodc(b, 1.0) == 0.0) {
    float kn = a, kd = b;
    float gcd = jwf_gcd(kn, kd);
    if (gcd != 1.0) {
      kn /= gcd;
      kd /= gcd;
    }
    return fmodc(kn, 2.0) == 0.0 || fmodc(kd, 2.0) == 0.0 ? kd * kTwoPi : kd * kPi;
  }
  return kTwoPi;
}
float jwf_pNormSquared(vec2 q, float p, float m) { return pow(pow(abs(q.x), p) + pow(abs(q.y), p), 2.0 / (p * m)); }
// Ψ₁…Ψ₅ drawn for every point; the points passed through or drawn on the outline carry no z.
vec3 V_inversion(vec3 p, float w, int P, int A) {
  float scale = P_(P, 0), shape = trunc(P_(P, 2));
  if (!(shape >= 0.0 && shape <= 6.0)) shape = 0.0;
  vec3 s = vec3(shape, scale, kPi * P_(P, 1));
  float period = shape == 4.0 ? jwf_rosePeriod(P_(P, 5), P_(P, 6), P_(P, 7)) : kTwoPi;
  float imode = trunc(P_(P, 3));
  bool hideUninverted = P_(P, 4) == 1.0;
  float ringMode = trunc(P_(P, 11)), ringScale = P_(P, 12);
  float pnormPoint = P_(P, 13), pnormShape = P_(P, 14), pnormPmod = P_(P, 15), pnormSmod = P_(P, 16);
  float drawShape = P_(P, 17), thickness = P_(P, 18), passthrough = P_(P, 19);
  float ringMin = ringScale <= scale ? ringScale * scale : scale * scale / (ringScale * scale);
  float ringMax = ringScale <= scale ? scale * scale / (ringScale * scale) : ringScale * scale;
  bool ring = ringMode != 0.0 && ringScale != 1.0;
  float psi1 = psi(), psi2 = psi(), psi3 = psi(), psi4 = psi(), psi5 = psi();
  if (drawShape > 0.0 && psi1 < drawShape) {
    // The outline's own point at the angle (not the farthest crossing), as JWildfire draws it.
    float theta = psi2 * period;
    vec2 c = jwf_inversionRadius(s, P, theta) * vec2(cos(theta), sin(theta));
    if (thickness != 0.0) c += 0.01 * (vec2(psi3, psi4) - 0.5) * thickness;
    return vec3(c, 0.0);
  }
  if (passthrough > 0.0 && psi5 < passthrough) return vec3(p.xy, 0.0);
  float rin = sqrt(p.x * p.x + p.y * p.y), tin = atan2c(p.y, p.x);
  float r;
  vec2 c;
  if (shape != 4.0) {
    r = jwf_inversionRadius(s, P, tin);
    c = r * vec2(cos(tin), sin(tin));
  } else {
    // The farthest of the rose's crossings at tin, tin + π, … (at most 1000).
    r = -0.0001;
    c = vec2(0.0);
    float turns = min(trunc(period / kTwoPi), 1000.0);
    for (float i = 0.0; i < turns; i += 1.0) {
      float theta = tin + i * kPi, ri = jwf_inversionRadius(s, P, theta);
      if (abs(ri) > r) {
        c = ri * vec2(cos(theta), sin(theta));
        r = abs(ri);
      }
    }
  }
  bool invert = imode == 1.0 ? rin > r : imode == 2.0 ? rin < r : true;
  if (invert && ring) {
    if (ringMode == 1.0) invert = rin >= ringMin && rin <= ringMax;
    if (ringMode == 2.0) invert = rin <= ringMin || rin >= ringMax;
  }
  if (!invert) return hideUninverted ? vec3(vec2(intBitsToFloat(0x7fc00000)), p.z) : p;
  float num = pnormShape == 2.0 && pnormSmod == 1.0 ? r * r : jwf_pNormSquared(c, pnormShape, pnormSmod);
  float den = pnormPoint == 2.0 && pnormPmod == 1.0 ? p.x * p.x + p.y * p.y
                                                    : jwf_pNormSquared(p.xy, pnormPoint, pnormPmod);
  float factor = w * (num / den);
  return vec3(factor * p.xy, w * p.z);
}

// nBlur (Fractorium's): its precalculated values, worked out per call as on the CPU.
struct jwf_NBlur {
  float numEdges, midAngle, angStart, angStripes, ratioStripes, ratioComplement, ratioHole, tan90m2, arcTan1, arcTan2;
  float speedCalc1, speedCalc2, maxStripes;
  bool hasStripes, negStripes, circumCircle, equalBlur, exactCalc;
};
// Squeezes a stripe's angle towards angTmp (the stripe's edge) when it lies beyond speed.
void jwf_nBlurSqueezeDown(float angTmp, float speed, float angStart, float angMem, inout float angXY,
                          inout vec2 q) {
  if (angTmp - angXY > speed) {
    float shift = (angTmp - speed - angXY) * speed / (angStart - speed);
    float a = angMem - angXY + angTmp - shift;
    q = vec2(sin(a), cos(a));
    angXY = angTmp - shift;
  }
}
// A random point of the polygon (xy), its length (z) and the ring's inner length at its angle (w);
// lenOuter the outer one.
vec4 jwf_nBlurPoint(jwf_NBlur s, out float lenOuter) {
  float angXY;
  if (s.exactCalc) {
    angXY = psi() * kTwoPi;
  } else {
    float t = psi();
    float edge = floor(psi() * s.numEdges);
    angXY = (atan(s.arcTan1 * (t - 0.5)) / s.arcTan2 + 0.5 + edge) * s.midAngle;
  }
  float angMem = angXY;
  vec2 q = vec2(sin(angXY), cos(angXY));
  while (angXY > s.midAngle) angXY -= s.midAngle;
  if (s.hasStripes) {
    int count = 0;
    float angTmp = s.angStart;
    while (angXY > angTmp) {
      angTmp += s.angStripes;
      if (angTmp > s.midAngle) angTmp = s.midAngle;
      ++count;
    }
    if (angTmp != s.midAngle) angTmp -= s.angStart;
    // The negative stripes are the positive ones' complement.
    int drawn = s.negStripes ? 0 : 1;
    float ratio = s.negStripes ? s.ratioComplement : s.ratioStripes;
    float speed = s.negStripes ? s.speedCalc1 : s.speedCalc2;
    if ((count & 1) == drawn) {
      if (angXY > angTmp && (!s.negStripes || float(count) != s.maxStripes)) {
        angXY += s.angStart;
        angMem += s.angStart;
        angTmp += s.angStripes;
        ++count;
      } else {
        angXY -= s.angStart;
        angMem -= s.angStart;
        angTmp -= s.angStripes;
        --count;
      }
      q = vec2(sin(angMem), cos(angMem));
    }
    int kept = 1 - drawn;
    if ((count & 1) == kept && ratio > 1.0) {
      if (angXY > angTmp && float(count) != s.maxStripes) {
        angMem = angMem - angXY + angTmp + (angXY - angTmp) / s.angStart * ratio * s.angStart;
        angXY = angTmp + (angXY - angTmp) / s.angStart * ratio * s.angStart;
      } else {
        angMem = angMem - angXY + angTmp - (angTmp - angXY) / s.angStart * ratio * s.angStart;
        angXY = angTmp + (angXY - angTmp) / s.angStart * ratio * s.angStart;
      }
      q = vec2(sin(angMem), cos(angMem));
    }
    if ((count & 1) == kept && ratio < 1.0) {
      if (abs(angXY - angTmp) > speed && float(count) != s.maxStripes) {
        if (angXY - angTmp > speed) {
          float shift = (angXY - (angTmp + speed)) * speed / (s.angStart - speed);
          float a = angMem - angXY + angTmp + shift;
          q = vec2(sin(a), cos(a));
          angXY = angTmp + shift;
        }
        jwf_nBlurSqueezeDown(angTmp, speed, s.angStart, angMem, angXY, q);
      }
      if (float(count) == s.maxStripes) {
        if (s.negStripes) angTmp = s.midAngle;
        jwf_nBlurSqueezeDown(angTmp, speed, s.angStart, angMem, angXY, q);
      }
    }
  }
  float outerX = s.tan90m2 / (s.tan90m2 - tan(angXY)), outerY = outerX * tan(angXY);
  lenOuter = sqrt(outerX * outerX + outerY * outerY);
  float radius = s.equalBlur ? sqrt(psi()) : psi();
  if (!s.exactCalc && !s.circumCircle) radius *= lenOuter;
  float lenInner = s.ratioHole * lenOuter;
  if (!s.exactCalc && radius < lenInner) {
    float span = s.circumCircle ? 1.0 - lenInner + 2.220446049250313e-16 : lenOuter - lenInner;
    radius = (s.equalBlur ? sqrt(psi()) : psi()) * span + lenInner;
  }
  q *= radius;
  return vec4(q, length(q), lenInner);
}
float jwf_fractoriumInteger(float v, float low, float high) { return clamp(floor(v + 0.5), low, high); }
vec3 V_nBlur(vec3 p, float w, int P, int A) {
  jwf_NBlur s;
  s.numEdges = jwf_fractoriumInteger(P_(P, 0), 3.0, 1000.0);
  float numStripes = jwf_fractoriumInteger(P_(P, 1), -1000.0, 1000.0);
  s.ratioStripes = clamp(P_(P, 2), 0.0, 2.0);
  s.ratioHole = clamp(P_(P, 3), 0.0, 1.0);
  s.circumCircle = jwf_fractoriumInteger(P_(P, 4), 0.0, 1.0) == 1.0;
  bool adjustToLinear = jwf_fractoriumInteger(P_(P, 5), 0.0, 1.0) == 1.0;
  s.equalBlur = jwf_fractoriumInteger(P_(P, 6), 0.0, 1.0) == 1.0;
  s.exactCalc = jwf_fractoriumInteger(P_(P, 7), 0.0, 1.0) == 1.0;
  float highlight = P_(P, 8);
  s.hasStripes = numStripes != 0.0;
  s.negStripes = numStripes < 0.0;
  float absStripes = abs(numStripes);
  s.midAngle = kTwoPi / s.numEdges;
  s.angStripes = 0.0;
  s.angStart = 0.0;
  s.ratioComplement = 0.0;
  if (s.hasStripes) {
    s.angStripes = s.midAngle / (2.0 * absStripes);
    s.angStart = s.angStripes / 2.0;
    s.ratioComplement = 2.0 - s.ratioStripes;
  }
  if (s.ratioHole > 0.95 && s.exactCalc && !s.circumCircle) s.ratioHole = 0.95;
  s.tan90m2 = tan(kPi / 2.0 + s.midAngle / 2.0);
  float sinA = sin(s.midAngle / 2.0), cosA = cos(s.midAngle / 2.0);
  if (!(highlight > 0.1)) highlight = 0.1;
  float adjusted = w;
  if (adjustToLinear) {
    float turns = fmodc(s.numEdges, 4.0) == 0.0 ? s.numEdges / 2.0 - 1.0 : floor(s.numEdges / 2.0);
    adjusted = w / fractoriumZeps(sqrt(2.0 - 2.0 * cos(s.midAngle * turns)) / 2.0);
  }
  if (s.circumCircle) {
    s.exactCalc = false;
    highlight = 0.1;
  }
  s.speedCalc1 = s.ratioComplement * s.angStart;
  s.speedCalc2 = s.ratioStripes * s.angStart;
  s.maxStripes = 2.0 * absStripes;
  s.arcTan1 = (s.negStripes ? 7.5 : 13.0) / pow(s.numEdges, 1.3) * highlight;
  s.arcTan2 = 2.0 * atan(s.arcTan1 / -2.0);
  float lenOuter;
  vec4 point = jwf_nBlurPoint(s, lenOuter);
  for (int tries = 1; s.exactCalc && tries < 100 && (point.z < point.w || point.z > lenOuter); ++tries)
    point = jwf_nBlurPoint(s, lenOuter);
  return vec3(adjusted * (cosA * point.x - sinA * point.y), adjusted * (sinA * point.x + cosA * point.y), w * p.z);
}

// ---- variations_jwildfire.cpp, variations_jwildfire_shapes.cpp, variations_jwildfire_more.cpp (jwa) ----

// Java's (int) of a number as a float: truncated, saturating, NaN as 0.
float jwa_javaInt(float v) { return isnan(v) ? 0.0 : clamp(trunc(v), -2147483648.0, 2147483647.0); }
int jwa_javaIntI(double v) {
  if (isnan(v)) return 0;
  if (v >= 2147483647.0lf) return 2147483647;
  if (v <= -2147483648.0lf) return -2147483647 - 1;
  return int(v);
}
// C's fmod in double (the sign of a), corrected by one step where the quotient rounds (core's laneFmod).
double jwa_dfmod(double a, double m) {
  double am = abs(m);
  double r = a - trunc(a / m) * m;
  r = a >= 0.0lf ? (r < 0.0lf ? r + am : r) : (r > 0.0lf ? r - am : r);
  return a >= 0.0lf ? (r >= am ? r - am : r) : (r <= -am ? r + am : r);
}
// An angle in double brought into [−π, π] for float's sin and cos: t runs to thousands of radians.
float jwa_angle(double v) {
  const double kTwoPiD = 6.283185307179586lf;
  return float(v - kTwoPiD * floor(v / kTwoPiD + 0.5lf));
}
// Bob Jenkins' integer hash as pixel_flow has it, scaled to about [−1, 1] (int arithmetic wraps as Java's).
double jwa_pixelFlowHash(int a) {
  a = (a ^ 61) ^ (a >> 16);
  a = a + a * 8;
  a = a ^ (a >> 4);
  a = a * 0x27d4eb2d;
  a = a ^ (a >> 15);
  return double(a) / 2147483647.0lf;
}
// Java's int / 2: truncated towards 0 (GLSL leaves a negative operand's quotient to the driver).
int jwa_halve(int v) { return (v + (v < 0 ? 1 : 0)) >> 1; }
vec3 V_pixel_flow(vec3 p, float w, int P, int A) {
  float angle = P_(P, 0) * 0.0174532925;  // JWildfire's rounded π/180
  float len = P_(P, 1);
  double width = double(P_(P, 2));
  int seed = jwa_javaIntI(floor(double(clamp(P_(P, 3), -2147483648.0, 2147483647.0)) + 0.5lf));
  float dirX = w * len * cos(angle), dirY = w * len * sin(angle);
  bool direct = roundHalfAway(P_(P, 4)) != 0.0;
  float r01 = psi();
  if (direct) gColour = r01;
  int blockX = jwa_javaIntI(floor(double(p.x) * width));
  blockX = jwa_javaIntI(double(blockX) + (2.0lf - 4.0lf * jwa_pixelFlowHash(blockX * seed + 1)));
  int blockY = jwa_javaIntI(floor(double(p.y) * width));
  blockY = jwa_javaIntI(double(blockY) + (2.0lf - 4.0lf * jwa_pixelFlowHash(blockY * seed + 1)));
  float streak = float((jwa_pixelFlowHash(blockY + blockX * (seed * -1)) +
                        jwa_pixelFlowHash(blockX + jwa_halve(blockY * seed))) * 0.5lf);
  float r2 = r01 * r01;
  float fade = streak * r2 * r2;
  return vec3(dirX * fade, dirY * fade, w * p.z);
}
// The superellipse norm (|a|^e + |b|^e)^(1/e).
float jwa_norm(float a, float b, float e) { return pow(pow(abs(a), e) + pow(abs(b), e), 1.0 / e); }
vec3 V_truchet(vec3 p, float w, int P, int A) {
  bool extended = clamp(floor(P_(P, 0) + 0.5), 0.0, 1.0) == 1.0;
  float exponent = clamp(P_(P, 1), 0.001, 2.0), width = clamp(P_(P, 2), 0.001, 1.0);
  float rotation = P_(P, 3), size = clamp(P_(P, 4), 0.001, 10.0);
  double seed = double(abs(P_(P, 5)));
  bool directColour = clamp(roundHalfAway(P_(P, 6)), 0.0, 1.0) == 1.0;
  float rMax = 0.5 * (pow(2.0, 1.0 / exponent) - 1.0) * width;
  float scale = (cos(-rotation) - sin(-rotation)) / w;
  float tx = p.x * scale, ty = p.y * scale;
  tx -= jwa_javaInt(floor(tx + 0.5));
  ty -= jwa_javaInt(floor(ty + 0.5));
  if (tx < 0.0) tx += 1.0;
  if (ty < 0.0) ty += 1.0;
  // The tile's hash in double: float would round its products of tens of thousands.
  double tile = 0.0lf;
  if (seed == 1.0lf) {
    tile = 1.0lf;
  } else if (seed != 0.0lf) {
    double randint;
    if (!extended) {
      double seed2 = sqrt(seed + seed / 2.0lf) / (seed * 0.5lf) * 0.25lf;
      double xr = floor(double(p.x) + 0.5lf) * seed2, yr = floor(double(p.y) + 0.5lf) * seed2;
      randint = (xr + yr + xr * yr + seed) * seed2 / 2.0lf;
      randint = jwa_dfmod(randint * 32747.0lf + 12345.0lf, 65535.0lf);
    } else {
      int xr = jwa_javaIntI(floor(double(p.x) + 0.5lf)), yr = jwa_javaIntI(floor(double(p.y) + 0.5lf));
      double iterations = min(abs(double(xr + yr + xr * yr)), 1000.0lf);
      randint = floor(seed) + iterations;
      for (double k = 0.0lf; k < iterations; k += 1.0lf)
        randint = jwa_dfmod(randint * 32747.0lf + 12345.0lf, 65535.0lf);
    }
    tile = jwa_dfmod(randint, 2.0lf);
  }
  bool diagonal = extended ? tile == 1.0lf : tile < 1.0lf;
  float r0 = diagonal ? jwa_norm(tx, ty, exponent) : jwa_norm(tx - 1.0, ty, exponent);
  float r1 = diagonal ? jwa_norm(tx - 1.0, ty - 1.0, exponent) : jwa_norm(tx, ty - 1.0, exponent);
  vec2 q = size * vec2(tx + floor(p.x), ty + floor(p.y));
  vec3 o = vec3(0.0);
  if (abs(r0 - 0.5) / rMax < 1.0) {
    if (directColour) gColour = clamp(r0, 0.0, 1.0);
    o.xy += q;
  }
  if (abs(r1 - 0.5) / rMax < 1.0) {
    if (directColour) gColour = clamp(1.0 - r1, 0.0, 1.0);
    o += vec3(q, w * p.z);
  }
  return o;
}
float jwa_shred(float v, float distance, float width) {
  float range = v / distance;
  float whole = jwa_javaInt(range);
  float side = v < 0.0 ? 1.0 : 0.0;
  return distance * ((range - whole) * width + whole + (0.5 - side) * (1.0 - width));
}
vec3 V_shredlin(vec3 p, float w, int P, int A) {
  float xDistance = P_(P, 0), xWidth = clamp(P_(P, 1), -1.0, 1.0);
  float yDistance = P_(P, 2), yWidth = clamp(P_(P, 3), -1.0, 1.0);
  return vec3(w * jwa_shred(p.x, xDistance, xWidth), w * jwa_shred(p.y, yDistance, yWidth), w * p.z);
}
vec3 V_plane_wf(vec3 p, float w, int P, int A) {
  float position = P_(P, 0), size = P_(P, 1);
  float axis = clamp(roundHalfAway(P_(P, 2)), 0.0, 2.0);
  bool direct = clamp(roundHalfAway(P_(P, 3)), 0.0, 1.0) == 1.0;
  float colourMode = clamp(roundHalfAway(P_(P, 4)), 0.0, 3.0);
  float a = 0.5 - psi(), b = 0.5 - psi();
  if (direct) {
    // The square's own (u, v), which on the plane zx are (z, x).
    float cu = (axis == 2.0 ? b : a) + 0.5, cv = (axis == 2.0 ? a : b) + 0.5;
    if (colourMode == 1.0) gColour = cu;
    if (colourMode == 2.0) gColour = cv;
    if (colourMode == 3.0) gColour = cu * cv;
    gColour = clamp(gColour, 0.0, 1.0);
  }
  float u = a * size, v = b * size;
  vec3 q = vec3(u, v, position);
  if (axis == 1.0) q = vec3(position, u, v);
  else if (axis == 2.0) q = vec3(u, position, v);
  return w * q;
}
vec3 V_point_symmetry_wf(vec3 p, float w, int P, int A) {
  float cx = P_(P, 0), cy = P_(P, 1);
  float order = clamp(roundHalfAway(P_(P, 2)), 1.0, 2147483647.0);
  float colourShift = P_(P, 3);
  // ⌊Ψ·order⌋ in double: float's product may round up to the next whole number.
  float k = min(float(floor(double(psi()) * double(order))), order - 1.0);
  if (colourShift != 0.0) gColour = fmodc(gColour + k * colourShift, 1.0);
  float turn = jwa_angle(double(k) * (6.283185307179586lf / double(order)));
  float s = sin(turn), c = cos(turn);
  float dx = (p.x - cx) * w, dy = (p.y - cy) * w;
  return vec3(cx + dx * c + dy * s, cy + dy * c - dx * s, w * p.z);
}
vec3 V_mirror_wf(vec3 p, float w, int P, int A) {
  bool on = abs(w) > 1e-8;  // the weight only switches it off
  bool xAxis = on && roundHalfAway(P_(P, 0)) > 0.0, yAxis = on && roundHalfAway(P_(P, 1)) > 0.0;
  bool zAxis = on && roundHalfAway(P_(P, 2)) > 0.0;
  float xShift = P_(P, 3), yShift = P_(P, 4), zShift = P_(P, 5), xScale = P_(P, 6), yScale = P_(P, 7);
  float psi1 = psi(), psi2 = psi(), psi3 = psi();
  vec3 q = p;
  if (xAxis && psi1 < 0.5) {
    q.x = xScale * (-q.x - xShift);
    q.y = yScale * q.y;
    gColour = fmodc(gColour + P_(P, 8), 1.0);
  }
  if (yAxis && psi2 < 0.5) {
    q.x = xScale * q.x;
    q.y = yScale * (-q.y - yShift);
    gColour = fmodc(gColour + P_(P, 9), 1.0);
  }
  if (zAxis && psi3 < 0.5) {
    q.z = -q.z - zShift;
    gColour = fmodc(gColour + P_(P, 10), 1.0);
  }
  return q;
}
vec3 V_triangle(vec3 p, float w, int P, int A) {
  float root = sqrt(psi()), r2 = psi();
  float a = 1.0 - root, b = root * (1.0 - r2), c = r2 * root;
  vec3 v1 = vec3(P_(P, 0), P_(P, 1), P_(P, 2)), v2 = vec3(P_(P, 3), P_(P, 4), P_(P, 5));
  vec3 v3 = vec3(P_(P, 6), P_(P, 7), P_(P, 8));
  return w * (a * v1 + b * v2 + c * v3);
}
vec3 V_spirograph3D(vec3 p, float w, int P, int A) {
  float a = P_(P, 0), b = P_(P, 1), c = P_(P, 2), width = P_(P, 5);
  double tMin = double(P_(P, 3)), tMax = double(P_(P, 4));
  float mode = clamp(roundHalfAway(P_(P, 6)), 0.0, 4.0);
  float ab = a + b;
  double ratio = (double(a) + double(b)) / double(b);
  bool directColour = clamp(roundHalfAway(P_(P, 7)), 0.0, 1.0) == 1.0;
  // t runs to a thousand radians and more: the angles are reduced in double.
  double t = (tMax - tMin) * double(psi()) + tMin;
  if (directColour) gColour = float(jwa_dfmod(t / 6.283185307179586lf, 1.0lf));  // negative below t = 0
  float w1 = 0.0, w2 = 0.0, w3 = 0.0;
  if (mode == 0.0) {
    w1 = w2 = w3 = width * psi() - width / 2.0;
  } else if (mode == 1.0) {
    float offset = width * psi() - width / 2.0;
    float t36 = jwa_angle(36.0lf * t);
    w1 = offset * sin(t36);
    w2 = offset * sin(t36 + kTwoPi / 3.0);
    w3 = offset * sin(t36 + 2.0 * kTwoPi / 3.0);
  } else if (mode == 2.0) {
    w1 = width * psi() - width / 2.0;
    w2 = width * psi() - width / 2.0;
    w3 = width * psi() - width / 2.0;
  } else if (mode == 3.0) {
    w1 = width * gaussPsi() / 2.0;
    w2 = width * gaussPsi() / 2.0;
    w3 = width * gaussPsi() / 2.0;
  } else {
    w1 = psi() < 0.5 ? width : -width;
  }
  float t1 = jwa_angle(t), tr = jwa_angle(ratio * t);
  float sr = sin(tr);
  return w * vec3(ab * cos(t1) - c * cos(tr) + w1, ab * sin(t1) - c * sr + w2, c * sr + w3);
}
// Inside or outside by the sign of Inigo Quilez' signed distance to the trapezoid, as on the CPU; a dropped
// point is NaN (the chaos game's escape).
vec3 V_crop_trapezoid(vec3 p, float w, int P, int A) {
  float r1 = P_(P, 0), r2 = P_(P, 1), he = P_(P, 2);
  bool invert = clamp(P_(P, 3), 0.0, 1.0) >= 1.0;
  float k2x = r2 - r1, k2y = 2.0 * he, k2k2 = k2x * k2x + k2y * k2y;
  float px = abs(p.x), py = p.y;
  float cax = max(0.0, px - (py < 0.0 ? r1 : r2)), cay = abs(py) - he;
  float along = clamp(((r2 - px) * k2x + (he - py) * k2y) / k2k2, 0.0, 1.0);
  float cbx = px - r2 + k2x * along, cby = py - he + k2y * along;
  float s = cbx < 0.0 && cay < 0.0 ? -1.0 : 1.0;
  float d = s * sqrt(min(cax * cax + cay * cay, cbx * cbx + cby * cby));
  bool drop = invert ? d <= 0.0 : d > 0.0;
  return drop ? vec3(uintBitsToFloat(0x7fc00000u)) : w * p;
}

// ---- Terms that read the sum before them (variations_2d_c.cpp: hexcrop; variations_jwildfire_shapes.cpp:
// flower_db, recurrenceplot; variations_jwildfire_holdout.cpp: dc_gnarly). Each returns the new sum.

// Inside the hexagon (even–odd crossings of a ray to −x) p + centre is added; outside the sum becomes
// (dropoff, dropoff).
vec3 V_hexcrop(vec3 p, float w, int P, int A) {
  float sx = P_(P, 0), sy = P_(P, 1), dropoff = P_(P, 4);
  const float kHx[6] = float[6](-0.5, 0.5, 1.4142135623730950488, 0.5, -0.5, -1.4142135623730950488);
  const float kHy[6] = float[6](1.0606601717798212866, 1.0606601717798212866, 0.0,
                                -1.0606601717798212866, -1.0606601717798212866, 0.0);
  float px = p.x + P_(P, 2), py = p.y + P_(P, 3);
  bool inside = false;
  for (int k = 0, j = 5; k < 6; j = k++) {
    float hxk = kHx[k] * sx, hxj = kHx[j] * sx, hyk = kHy[k] * sy, hyj = kHy[j] * sy;
    if ((hyk <= py && py < hyj) || (hyj <= py && py < hyk))
      if (px < (hxj - hxk) * (py - hyk) / fractoriumZeps(hyj - hyk) + hxk) inside = !inside;
  }
  float z = gSum.z + w * p.z;
  return inside ? vec3(gSum.x + px * w, gSum.y + py * w, z) : vec3(dropoff, dropoff, z);
}

// The rose added to the sum; z is the sum's, moved by the stem and the fold and held at −stem_length.
vec3 V_flower_db(vec3 p, float w, int P, int A) {
  float petals = P_(P, 0), split = P_(P, 1), spread = P_(P, 2), thickness = P_(P, 3), stem = P_(P, 4);
  float foldStrength = P_(P, 5), foldRadius = P_(P, 6);
  float t = atan2c(p.y, p.x);
  float r = w * sqrt(p.x * p.x + p.y * p.y) * abs((spread + sin(petals * t)) * cos(split * petals * t));
  vec2 s = gSum.xy + vec2(sin(t), cos(t)) * r;
  float pz = gSum.z - thickness * (2.0 / r - 1.0);
  float rNew = length(s);
  if (rNew > foldRadius) pz += (rNew - foldRadius) * foldStrength;
  if (stem != 0.0 && pz <= -stem) pz = -stem;
  return vec3(s, pz);
}

// recurrenceplot's signal in double (dsin): whether a pair is near decides how many pairs are drawn,
// which must be the CPU's count; exp, tanh and tan of a·u are float's (the GPU has no double ones).
const double sumj_kPi = 3.141592653589793lf;
double sumj_legendre(int degree, double x) {
  double previous = 1.0lf, current = x;
  if (degree == 0) return 1.0lf;
  for (int d = 1; d < degree; ++d) {
    double next = ((2.0lf * d + 1.0lf) * x * current - d * previous) / (d + 1.0lf);
    previous = current;
    current = next;
  }
  return current;
}
double sumj_chebyshev(int degree, double x) {
  double previous = 1.0lf, current = x;
  if (degree == 0) return 1.0lf;
  for (int d = 1; d < degree; ++d) {
    double next = 2.0lf * x * current - previous;
    previous = current;
    current = next;
  }
  return current;
}
double sumj_recurrenceSignal(int id, double a, double b, double n, int k, double i) {
  double u = i * sumj_kPi / n, h = i * sumj_kPi / (0.5lf * n);
  double sum = 0.0lf;
  switch (id) {
    case 0: return 50.0lf * dsin(4.0lf * u) + 25.0lf * dsin(40.0lf * u);
    case 1: return 10.0lf * dsin(5.0lf * u) * 5.0lf * dsin(15.0lf * u);
    case 2: return 50.0lf * dcos(24.0lf * u + 5.0lf * dsin(6.0lf * u));
    case 3: return 50.0lf * dsin(20.0lf * u) + 50.0lf * dsin(22.0lf * u + sumj_kPi);
    case 4: return 50.0lf * dsin(20.0lf * u) + 10.0lf * dsin(22.0lf * u);
    case 5: return 50.0lf * dsin(a * u + dsin(a * u));
    case 6: return a / (1.0lf + double(exp(float(-b * (i - n / 2.0lf) / n))));
    case 7:
      return (400.0lf / sumj_kPi) *
             (dsin(h) + dsin(3.0lf * h) / 3.0lf + dsin(5.0lf * h) / 5.0lf + dsin(7.0lf * h) / 7.0lf);
    case 8:
      return 400.0lf / sumj_kPi * sumj_kPi *
             (dsin(h) - dsin(3.0lf * h) / 9.0lf + dsin(5.0lf * h) / 25.0lf - dsin(7.0lf * h) / 49.0lf);
    case 9: return double(tanh(clamp(float(a * u), -20.0, 20.0)));  // GLSL's tanh may give NaN far out
    case 10: return dsin(a * u) / dcos(a * u);
    case 11:
      for (int m = 1; m <= 8; ++m) sum += dsin(m * h) / m;
      return (-200.0lf / sumj_kPi) * sum;
    case 12: return 50.0lf * dsin(40.0lf * u) + 50.0lf * dsin(44.0lf * u);
    case 13: return 50.0lf * dsin(40.0lf * u) + 50.0lf * dsin(44.0lf * u + sumj_kPi);
    case 14: return 100.0lf * dsin(16.0lf * u) - 500.0lf + i * 0.25lf;
    case 15: return 100.0lf * dsin(16.0lf * u);
    case 16: return 1.0lf / dcos(a * u);
    case 17: return 50.0lf * dcos(50.0lf * u + 25.0lf * dsin(u));
    case 18: {
      double d = 2.0lf * a * i / n - a;
      return a * double(exp(float(-b * d * d)));
    }
    case 19: return 500.0lf * dsin(10.0lf * u) * double(exp(float(-5.0lf * i / n)));
    case 20: return 500.0lf * dsin(20.0lf * u) * double(exp(float(-3.0lf * i / n)));
    case 21: return 50.0lf * (dsin(2.0lf * u) / dcos(2.0lf * u));
    case 22: {
      int degree = dcol_javaInt(b);
      return degree >= 0 && degree <= 10 ? a * sumj_legendre(degree, 2.0lf * i / n - 1.0lf) : 0.0lf;
    }
    case 23:
      for (int j = 1; j <= k; ++j)
        sum += dsin(i * (2.0lf * j - 1.0lf) * b * (2.0lf * sumj_kPi) / n) / (2.0lf * j - 1.0lf);
      return sum * (4.0lf * a / sumj_kPi);
    case 24:
      for (int j = 1; j <= k; ++j) sum += dsin(i * j * b * (2.0lf * sumj_kPi) / n) / j;
      return sum * (-2.0lf * a / sumj_kPi);
    case 25:
      for (int j = 1; j <= k; ++j)
        sum += dcos(i * (2.0lf * j) * b * (2.0lf * sumj_kPi) / n) / ((2.0lf * j - 1.0lf) * (2.0lf * j + 1.0lf));
      return (4.0lf * a / sumj_kPi) * (0.5lf - sum);
    case 26:
      for (int j = 1; j <= k; ++j)
        sum += (j % 2 == 0 ? 1.0lf : -1.0lf) * dcos(i * (2.0lf * j) * b * sumj_kPi / n) / (j * j);
      return a * sumj_kPi * sumj_kPi / 3.0lf + 4.0lf * a * sum;
    case 27: {
      double v = b * sumj_kPi * (i - 0.5lf * n) / n;
      return a * dsin(v) / v;
    }
    case 28: {
      double v = (i - 0.5lf * n) / n;
      return a * double(exp(float(-b * v * v))) * dcos(2.0lf * k * sumj_kPi * i / n);
    }
    case 29: return k >= 0 && k <= 12 ? a * sumj_chebyshev(k, 2.0lf * i / n - 1.0lf) : 0.0lf;
    default: return 0.0lf;
  }
}
// Pairs drawn until one is near (up to 1000, else NaN); the samples ⌊N Ψ⌋ in double, exactly the CPU's.
vec3 V_recurrenceplot(vec3 p, float w, int P, int A) {
  int id = dcol_javaInt(double(P_(P, 0)));
  double a = double(P_(P, 1)), b = double(P_(P, 2));
  int k = clamp(dcol_javaInt(double(P_(P, 3))), 0, 1000);
  double n = double(dcol_javaInt(double(P_(P, 4))));
  int directColour = dcol_javaInt(double(P_(P, 5)));
  float colourScale = 1.0 / (P_(P, 6) == 0.0 ? 1e-5 : P_(P, 6));
  float angle = P_(P, 7), colourOffset = P_(P, 8);
  double tolerance = double(P_(P, 9));
  float runningSum = gStage == 1 ? 0.0 : 1.0;
  float px = uintBitsToFloat(0x7fc00000u), py = px;
  for (int tries = 0; tries < 1000; ++tries) {
    double si = double(dcol_javaInt(n * double(psi())));
    double sj = double(dcol_javaInt(n * double(psi())));
    double d = abs(sumj_recurrenceSignal(id, a, b, n, k, si) - sumj_recurrenceSignal(id, a, b, n, k, sj));
    if (d < tolerance) {
      px = float(si / n - 0.5lf);
      py = float(sj / n - 0.5lf);
      break;
    }
  }
  vec3 s = gSum + w * vec3(px, py, p.z);
  if (directColour == 0 || isnan(px)) return s;
  float sx = s.x + runningSum * p.x, sy = s.y + runningSum * p.y;
  float index = directColour == 1 ? 0.5 * colourScale * sx * sy + colourOffset
                                  : 0.5 * (colourScale * (cos(angle) * sx + sin(angle) * sy + colourOffset) + 1.0);
  if (directColour == 1 || directColour == 2) gColour = fmodc(abs(index), 1.0);
  return s;
}

// std::clamp: NaN stays NaN (GLSL's clamp may make it a bound).
float sumj_clamp(float v, float lo, float hi) { return v < lo ? lo : (hi < v ? hi : v); }
// The blurred point's gnarly offset by mode, half of both added to the sum; the colour index by dc, and
// z moved (or with reset_z replaced) by colour · scale_z + offset_z.
vec3 V_dc_gnarly(vec3 p, float w, int P, int A) {
  float mode = sumj_clamp(roundHalfAway(P_(P, 0)), 0.0, 8.0);
  float sx = P_(P, 1), sy = P_(P, 2), fx1 = P_(P, 3), fy1 = P_(P, 4), fx2 = P_(P, 5), fy2 = P_(P, 6);
  float fx3 = P_(P, 7), fy3 = P_(P, 8);
  bool dc = sumj_clamp(roundHalfAway(P_(P, 9)), 0.0, 1.0) != 0.0;
  float colour1 = P_(P, 10), colour2 = P_(P, 11);
  float fmag = isnan(P_(P, 12)) ? 1.0 : sumj_clamp(P_(P, 12), 0.05, 1.0);
  float distort = P_(P, 13), blur = P_(P, 14), scaleZ = P_(P, 15), offsetZ = P_(P, 16);
  bool reset = sumj_clamp(roundHalfAway(P_(P, 17)), 0.0, 1.0) > 0.0;
  float x0 = p.x, y0 = p.y;
  if (blur > 0.0) {
    float turn = psi() * kTwoPi;
    float sum = 0.0;
    for (int k = 0; k < 6; ++k) sum += psi();
    float r = blur * (sum - 3.0);
    x0 += r * cos(turn);
    y0 += r * sin(turn);
  } else if (blur < 0.0) {
    x0 += psi() * blur * 2.0 - blur;
    y0 += psi() * blur * 2.0 - blur;
  }
  float x1, y1;
  if (mode == 1.0) {
    x1 = cos(fx1 * y0 + sin(fx2 * (y0 + sin(fx3 * y0))));
    y1 = cos(fy1 * x0 + sin(fy2 * (x0 + sin(fy3 * x0))));
  } else if (mode == 2.0) {
    x1 = sin(fx1 * y0 + sin(fx2 * (y0 + cos(fx3 * y0))));
    y1 = sin(fy1 * x0 + sin(fy2 * (x0 + cos(fy3 * x0))));
  } else if (mode == 3.0) {
    x1 = cos(fx1 * y0 + sin(fx2 * (x0 + sin(fx3 * y0))));
    y1 = cos(fy1 * x0 + sin(fy2 * (y0 + sin(fy3 * x0))));
  } else if (mode == 4.0) {
    x1 = sin(fx1 * y0 + sin(sqrt(abs(fx2 * (y0 + cos(fx3 * y0))))));
    y1 = sin(fy1 * x0 + sin(sqrt(abs(fy2 * (x0 + cos(fy3 * x0))))));
  } else if (mode == 5.0) {
    x1 = cos(fx1 * y0 + asinh(fx2 * (y0 + sin(fx3 * y0))));
    y1 = cos(fy1 * x0 + asinh(fy2 * (x0 + sin(fy3 * x0))));
  } else if (mode == 6.0) {
    x1 = cos(fx1 * y0 + tan(fx2 * (y0 + sin(fx3 * y0))));
    y1 = cos(fy1 * x0 + tan(fy2 * (x0 + sin(fy3 * x0))));
  } else if (mode == 7.0) {
    float vx = fx2 * (y0 + cos(fx3 * y0)), vy = fy2 * (x0 + cos(fy3 * x0));
    x1 = sin(fx1 * y0 + sin(vx * vx));
    y1 = sin(fy1 * x0 + sin(vy * vy));
  } else if (mode == 8.0) {
    float vx = fx2 * (x0 + cos(fx3 * y0)), vy = fy2 * (y0 + cos(fy3 * x0));
    x1 = sin(fx1 * y0 + sin(vx * vx));
    y1 = sin(fy1 * x0 + sin(vy * vy));
  } else {
    x1 = sin(fx1 * y0);
    y1 = sin(fy1 * x0);
  }
  x1 *= sx;
  y1 *= sy;
  vec2 s = gSum.xy + w * vec2(x0 + x1, y0 + y1) / 2.0;
  if (dc) {
    float ds = distort == 0.0 ? 0.0 : log(sqrt(x1 * x1 + y1 * y1)) * distort;
    gColour = fmodc(abs(cos(x0 + x1 * colour1 + ds) + sin(y0 + y1 * colour2 + ds)), fmag);
  }
  float dz = gColour * scaleZ + offsetZ;
  return vec3(s, reset ? dz : gSum.z + w * p.z + dz);
}

// ---- colormap_wf (variations_colormap.cpp): its picture is its table (VariationInfo::table) ----------

// JWildfire's Tools.FTOI: half away from zero, through Java's saturating int; NaN as 0.
int cmap_ftoi(double v) { return v > 0.0lf ? jwa_javaIntI(v + 0.5lf) : (v < 0.0lf ? jwa_javaIntI(-(abs(v) + 0.5lf)) : 0); }
// JWildfire's tiling of a pixel index into [0, side) (core's tiled: −side lands one side too far, as there).
int cmap_tiled(int index, int side) {
  if (index < 0) return index - (index / side - 1) * side;
  return index >= side ? index - (index / side) * side : index;
}
// Pixel (column, row) of the picture at `at` (width, height, then red, green, blue, alpha a pixel).
vec4 cmap_pixel(int at, int width, int column, int row) {
  int k = at + 2 + 4 * (row * width + column);
  return vec4(flameData[k], flameData[k + 1], flameData[k + 2], flameData[k + 3]);
}
// core's nearestPaletteEntry: the first entry of the palette (scaled) nearest to (r, g, b).
int cmap_nearestEntry(int paletteAt, ivec3 c, double scale) {
  int best = 0;
  double bestDistance = 0.0lf;
  for (int k = 0; k < 256; ++k) {
    uint e = variationPalette(paletteAt, k);
    dvec3 d = dvec3(double(e & 255u), double((e >> 8) & 255u), double((e >> 16) & 255u)) * scale - dvec3(c);
    double distance = dot(d, d);
    if (k == 0 || distance < bestDistance) {
      bestDistance = distance;
      best = k;
    }
  }
  return best;
}
// Returns the new sum (it reads it: reset_z replaces its z); x and y only a pre_/post_ term keeps.
vec3 V_colormap_wf(vec3 p, float w, int P, int A) {
  const int N = 15;
  double scaleX = P_(P, 0), scaleY = P_(P, 1), offsetX = P_(P, 3), offsetY = P_(P, 4);
  float scaleZ = P_(P, 2), offsetZ = P_(P, 5);
  bool tileX = cmap_ftoi(P_(P, 6)) == 1, tileY = cmap_ftoi(P_(P, 7)) == 1, resets = cmap_ftoi(P_(P, 8)) != 0;
  int dcColor = cmap_ftoi(P_(P, 9));
  bool blend = cmap_ftoi(P_(P, 10)) > 0, withAlpha = cmap_ftoi(P_(P, 11)) > 0;
  int paletteAt = int(P_(P, N + 1));
  int at = tableAt(P, N + 2);
  int width = int(flameData[at]), height = int(flameData[at + 1]);
  double u = (double(p.x) - (offsetX + 0.5lf) + 1.0lf) / scaleX * double(width - 2);
  double v = (double(p.y) - (offsetY + 0.5lf) + 1.0lf) / scaleY * double(height - 2);
  int column = blend ? jwa_javaIntI(trunc(u)) : cmap_ftoi(u);
  int row = blend ? jwa_javaIntI(trunc(v)) : cmap_ftoi(v);
  if (tileX) column = cmap_tiled(column, width);
  if (tileY) row = cmap_tiled(row, height);
  vec4 c = vec4(0.0);
  if (column >= 0 && column < width && row >= 0 && row < height) {
    c = cmap_pixel(at, width, column, row);
    if (blend) {
      // Bilinear with the right, lower and lower-right pixels (transparent black past the edge) by the
      // fractions, negative for negative u, v (JWildfire extrapolates there).
      float fu = float(u - trunc(u)), fv = float(v - trunc(v));
      bool right = column < width - 1, below = row < height - 1;
      vec4 ru = right ? cmap_pixel(at, width, column + 1, row) : vec4(0.0);
      vec4 lb = below ? cmap_pixel(at, width, column, row + 1) : vec4(0.0);
      vec4 rb = right && below ? cmap_pixel(at, width, column + 1, row + 1) : vec4(0.0);
      vec4 top = c + (ru - c) * fu, bottom = lb + (rb - lb) * fu;
      c = top + (bottom - top) * fv;
    }
  }
  ivec3 rounded = ivec3(cmap_ftoi(c.r), cmap_ftoi(c.g), cmap_ftoi(c.b));
  if (dcColor == 0) {
    uvec3 bytes = uvec3(clamp(rounded, ivec3(0), ivec3(255)));
    gRgb = kRgbPainted | bytes.r | bytes.g << 8 | bytes.b << 16;
  }
  if (dcColor > 0) gColour = float(cmap_nearestEntry(paletteAt, rounded, 200.0lf / 256.0lf)) / 255.0;
  gHidden = withAlpha && c.a <= 0.1;
  float dz = offsetZ;
  if (abs(scaleZ) > 1e-8) dz += scaleZ * (0.299 * c.r + 0.588 * c.g + 0.113 * c.b) / 255.0;
  bool inPlace = gStage != 1;
  vec3 o = gSum + (inPlace ? p : vec3(0.0));
  o.z = resets ? dz : o.z + dz;
  return o;
}

// subflame_wf and glynns3subfl: a point of the embedded flame's attractor. Their table is the CPU's
// cloud of it (x, y, z and colour index per point), built once per embedded flame; Ψ picks a point
// and the shape's parameters at S (scale, angle in degrees, offset_x, offset_y, offset_z,
// colorscale_z, color_mode) move it. False, Ψ drawn all the same, when the cloud is empty.
bool subflamePoint(int P, int S, int N, out vec3 q) {
  int count = tableSize(P, N) / 4;
  float draw = psi();
  q = vec3(0.0);
  if (count == 0) return false;
  int at = tableAt(P, N) + 4 * tableIndex(draw, count);
  float scale = P_(S, 0), angle = P_(S, 1) * kPi / 180.0;
  float cosA = cos(angle), sinA = sin(angle);
  float x = scale * flameData[at], y = scale * flameData[at + 1], c = flameData[at + 3];
  q = vec3(x * cosA - y * sinA + P_(S, 2), x * sinA + y * cosA + P_(S, 3),
           scale * flameData[at + 2] + P_(S, 4) + P_(S, 5) * c);
  float mode = P_(S, 6);  // −1 leaves the colour alone; a NaN is taken as −1
  if (!isnan(mode) && clamp(roundHalfAway(mode), -2.0, 4.0) != -1.0) gColour = c;
  return true;
}
// subflame_wf: the point q added without the weight, as JWildfire adds it.
vec3 V_subflame_wf(vec3 p, float w, int P, int A) {
  vec3 q;
  subflamePoint(P, P, 12, q);
  return q;
}
// glynns3subfl: with chance `probability` Glynn's circle inversion of (x, y) replaces the sum's x and
// y (z carried), else w q is added (the CPU's glynns3subfl says the rule). Draws: the inversion's,
// the branch's, the subflame's.
vec3 V_glynns3subfl(vec3 p, float w, int P, int A) {
  float probability = clamp(P_(P, 0), 0.0, 1.0);
  bool show = trunc(clamp(P_(P, 1), 0.0, 1.0)) == 1.0;
  float radius = P_(P, 2), thickness = clamp(P_(P, 3), 0.0, 1.0), contrast = clamp(P_(P, 4), 0.0, 1.0);
  float absPow = abs(P_(P, 5));
  bool circle2 = trunc(P_(P, 6)) == 0.0 || isnan(P_(P, 6));  // Java's (int) cast: NaN is 0
  float radius1 = radius + thickness, radius2 = radius * radius / radius1;
  float gamma2 = radius1 / (radius1 + radius2);
  float phi10 = kPi * P_(P, 7) / 180.0, delta = kPi * P_(P, 8) / 180.0 - phi10;
  float gamma1 = thickness * (2.0 * radius + thickness) / (radius + thickness);
  float inner = circle2 ? radius1 : radius;
  float r = sqrt(p.x * p.x + p.y * p.y);
  float alpha = radius / r;
  vec2 g = p.xy;
  if (r < inner) {
    if (show) {
      float rr, phi;
      if (circle2) {
        phi = kTwoPi * psi();
        rr = psi() < gamma2 ? radius1 : radius2;
      } else {
        rr = radius + thickness - gamma1 * psi();
        phi = phi10 + delta * psi();
      }
      g = rr * vec2(cos(phi), sin(phi));
    }
  } else if (!(psi() > contrast * pow(alpha, absPow))) {
    g = alpha * alpha * p.xy;
  }
  if (psi() < probability) return vec3(w * g, gSum.z + w * p.z);
  vec3 q;
  if (!subflamePoint(P, P + 9, 21, q)) return gSum;
  return gSum + w * q;
}

// parplot2d_wf's surfaces: the kernel generator defines this from the terms' formulas (surface
// `which`, param_a … param_f at flameData[Q …]; flame_kernel.cpp).
vec3 parplotSurface(int which, float u, float v, int Q);
// The surfaces' third variable, isosfplot3d_wf's z (its formulas' isosf_z), set before the call.
float gParplotThird = 0.0;
// parplot2d_wf: w (X(u, v), Y(u, v), Z(u, v)), (u, v) drawn in [umin, umax] × [vmin, vmax] (or read
// from x and y with solid 0); the colour index from u and v with direct_color (the CPU's
// parplot2dWf says the rule). After the parameters: which surface, −1 where a formula does not
// compile, which adds nothing and draws nothing, as on the CPU.
vec3 V_parplot2d_wf(vec3 p, float w, int P, int A) {
  int which = int(P_(P, 17));
  if (which < 0) return vec3(0.0);
  float uMin = P_(P, 1), uMax = P_(P, 2), vMin = P_(P, 3), vMax = P_(P, 4);
  if (uMin > uMax) {
    float swap = uMin;
    uMin = uMax;
    uMax = swap;
  }
  if (vMin > vMax) {
    float swap = vMin;
    vMin = vMax;
    vMax = swap;
  }
  float du = uMax - uMin, dv = vMax - vMin;
  bool solid = roundHalfAway(P_(P, 10)) != 0.0;
  float mode = roundHalfAway(P_(P, 6));
  bool setsColour = roundHalfAway(P_(P, 5)) > 0.0 && mode != 0.0;
  float s = p.x, t = p.y;
  if (solid) {
    s = psi();
    t = psi();
  }
  float u = uMin + s * du, v = vMin + t * dv;
  vec3 q = parplotSurface(which, u, v, P + 11);
  if (setsColour) {
    float cu = (u - uMin) / du, cv = (v - vMin) / dv;
    float c = mode == 1.0 ? cu : mode == 2.0 ? cv : cv * cu;
    gColour = isnan(c) ? 0.0 : clamp(c, 0.0, 1.0);
  }
  return w * q;
}
