// Flame variations for the GPU backend (flame_variations.glsl has the conventions and the helpers):
// the CPU catalogue's variations_3d_more.cpp, variations_3d_quaternion.cpp, variations_3d_shapes.cpp,
// variations_3d_sum.cpp, variations_apophysis.cpp, variations_fractorium.cpp and the rest of
// variations_flam3.cpp and variations_plugins.cpp (engine/core/flame/), in float. Those that read the
// sum of the terms before them, replace it, or move the colour index stay on the CPU.

// Fractorium's integer parameter (⌊v + ½⌋, clamped) and std::round (half away from zero).

// ---- quaternions (variations_3d_quaternion.cpp) --------------------------------------------------

// q = x + v, v = (y, z): each result is (X, K y, K z); a = |v|, 1/a guarded as Fractorium's Zeps.
float v3d_inverseA(vec3 p) { return 1.0 / fractoriumZeps(sqrt(p.y * p.y + p.z * p.z)); }
vec3 v3d_quat(vec3 p, float X, float K) { return vec3(X, K * p.y, K * p.z); }
vec3 V_sinq(vec3 p, float w, int P, int A) {
  float a = length(p.yz);
  return v3d_quat(p, w * sin(p.x) * cosh(a), w * cos(p.x) * sinh(a) * v3d_inverseA(p));
}
vec3 V_cosq(vec3 p, float w, int P, int A) {
  float a = length(p.yz);
  return v3d_quat(p, w * cos(p.x) * cosh(a), -w * sin(p.x) * sinh(a) * v3d_inverseA(p));
}
vec3 V_sinhq(vec3 p, float w, int P, int A) {
  float a = length(p.yz);
  return v3d_quat(p, w * sinh(p.x) * cos(a), w * cosh(p.x) * sin(a) * v3d_inverseA(p));
}
vec3 V_coshq(vec3 p, float w, int P, int A) {
  float a = length(p.yz);
  return v3d_quat(p, w * cosh(p.x) * cos(a), w * sinh(p.x) * sin(a) * v3d_inverseA(p));
}
// The reciprocals divide by |q|², as Fractorium does.
float v3d_quatNi(vec3 p, float w) { return w / fractoriumZeps(dot(p, p)); }
vec3 V_secq(vec3 p, float w, int P, int A) {
  float a = length(p.yz), ni = v3d_quatNi(p, w);
  return v3d_quat(p, ni * cos(p.x) * cosh(a), ni * sin(p.x) * sinh(a) * v3d_inverseA(p));
}
vec3 V_sechq(vec3 p, float w, int P, int A) {
  float a = length(p.yz), ni = v3d_quatNi(p, w);
  return v3d_quat(p, ni * cosh(p.x) * cos(a), -ni * sinh(p.x) * sin(a) * v3d_inverseA(p));
}
vec3 V_cscq(vec3 p, float w, int P, int A) {
  float a = length(p.yz), ni = v3d_quatNi(p, w);
  return v3d_quat(p, ni * sin(p.x) * cosh(a), -ni * cos(p.x) * sinh(a) * v3d_inverseA(p));
}
vec3 V_cschq(vec3 p, float w, int P, int A) {
  float a = length(p.yz), ni = v3d_quatNi(p, w);
  return v3d_quat(p, ni * sinh(p.x) * cos(a), -ni * cosh(p.x) * sin(a) * v3d_inverseA(p));
}
// tan, cot and their hyperbolic forms: (S C + D B a², ±(D C − S B)) scaled by ni.
vec2 v3d_tanLike(float S, float C, float D, float B, float a2, float ni) {
  return vec2((S * C + D * B * a2) * ni, (D * C - S * B) * ni);
}
vec3 V_tanq(vec3 p, float w, int P, int A) {
  float a2 = dot(p.yz, p.yz), a = sqrt(a2), inv = v3d_inverseA(p);
  float s = sin(p.x), c = cos(p.x), sh = sinh(a), ch = cosh(a);
  vec2 t = v3d_tanLike(s * ch, c * ch, c * sh * inv, -s * sh * inv, a2, v3d_quatNi(p, w));
  return v3d_quat(p, t.x, t.y);
}
vec3 V_cotq(vec3 p, float w, int P, int A) {
  float a2 = dot(p.yz, p.yz), a = sqrt(a2), inv = v3d_inverseA(p);
  float s = sin(p.x), c = cos(p.x), sh = sinh(a), ch = cosh(a);
  vec2 t = v3d_tanLike(s * ch, c * ch, c * sh * inv, -s * sh * inv, a2, v3d_quatNi(p, w));
  return v3d_quat(p, t.x, -t.y);
}
vec3 V_tanhq(vec3 p, float w, int P, int A) {
  float a2 = dot(p.yz, p.yz), a = sqrt(a2), inv = v3d_inverseA(p);
  float s = sin(a), c = cos(a), sh = sinh(p.x), ch = cosh(p.x);
  vec2 t = v3d_tanLike(sh * c, ch * c, ch * s * inv, sh * s * inv, a2, v3d_quatNi(p, w));
  return v3d_quat(p, t.x, t.y);
}
vec3 V_cothq(vec3 p, float w, int P, int A) {
  float a2 = dot(p.yz, p.yz), a = sqrt(a2), inv = v3d_inverseA(p), q2 = dot(p, p);
  float s = sin(a), c = cos(a), sh = sinh(p.x), ch = cosh(p.x);
  vec2 t = v3d_tanLike(sh * c, ch * c, ch * s * inv, sh * s * inv, a2, w / fractoriumZeps(q2 * q2));
  return v3d_quat(p, t.x, t.y);
}
vec3 V_estiq(vec3 p, float w, int P, int A) {
  float a = length(p.yz), e = exp(p.x);
  return v3d_quat(p, w * e * cos(a), w * e * sin(a) * v3d_inverseA(p));
}
vec3 V_loq(vec3 p, float w, int P, int A) {
  float denominator = 0.5 * w / log(P_(P, 0));
  float a2 = dot(p.yz, p.yz), a = sqrt(a2);
  return v3d_quat(p, log(p.x * p.x + a2) * denominator, w * atan2c(a, p.x) / fractoriumZeps(a));
}

// ---- shapes (variations_3d_shapes.cpp) -----------------------------------------------------------

vec3 V_blade3D(vec3 p, float w, int P, int A) {
  float t = psi() * w * sqrt(p.x * p.x + p.y * p.y);
  float s = sin(t), c = cos(t);
  return w * vec3(p.x * (c + s), p.x * (c - s), p.z * (s - c));
}
vec3 V_blob3D(vec3 p, float w, int P, int A) {
  float low = P_(P, 0), diff = P_(P, 1) - P_(P, 0), waves = P_(P, 2);
  float rho = sqrt(p.x * p.x + p.y * p.y);
  float wave = sin(waves * atan2c(p.x, p.y));
  float r = rho * (low + diff * (0.5 + 0.5 * wave));
  float invRho = 1.0 / fractoriumZeps(rho);
  return w * vec3(p.x * invRho * r, p.y * invRho * r, wave * r);
}
vec3 V_bubble2(vec3 p, float w, int P, int A) {
  float sx = P_(P, 0), sy = P_(P, 1), sz = P_(P, 2);
  float r = w / fractoriumZeps(0.25 * dot(p, p) + 1.0);
  return vec3(p.x * r * sx, p.y * r * sy, w * (p.z >= 0.0 ? p.z + sz : p.z - sz) + p.z * r * sz);
}
vec3 V_disc3d(vec3 p, float w, int P, int A) {
  float pi = P_(P, 0), scale = w / fractoriumZeps(pi);
  float r = sqrt(p.x * p.x + p.y * p.y);
  float v = scale * atan2c(p.x, p.y);
  return v * vec3(sin(r * pi), cos(r * pi), r * cos(p.z));
}
vec3 V_ovoid3d(vec3 p, float w, int P, int A) {
  float r = w / fractoriumZeps(dot(p, p));
  return p * r * vec3(P_(P, 0), P_(P, 1), P_(P, 2));
}
vec3 V_sphyp3D(vec3 p, float w, int P, int A) {
  bool zOn = roundHalfAway(P_(P, 3)) == 1.0;
  float t = fractoriumZeps(dot(p, p));
  return vec3(p.x * w / pow(t, P_(P, 0)), p.y * w / pow(t, P_(P, 1)), zOn ? p.z * w / pow(t, P_(P, 2)) : w * p.z);
}
vec3 V_spherivoid(vec3 p, float w, int P, int A) {
  float radius = P_(P, 0);
  float rho = sqrt(p.x * p.x + p.y * p.y);
  float zr = sqrt(p.z * p.z + rho * rho);
  float polar = acos(clamp(p.z / zr, -1.0, 1.0));
  float invRho = 1.0 / fractoriumZeps(rho);
  float s = w * sin(polar) * (zr + radius);
  return vec3(p.x * invRho * s, p.y * invRho * s, w * cos(polar) * (zr + radius));
}
// The weight scales the angles, not the result (Fractorium's).
vec3 V_psphere(vec3 p, float w, int P, int A) {
  float vpi = w * kPi, c0 = p.x * vpi, c1 = p.y * vpi, cos1 = cos(c1);
  return vec3(-cos(c0) * sin(c1), sin(c0) * cos1, cos1 * P_(P, 0));
}
vec3 V_svf(vec3 p, float w, int P, int A) {
  float cn = cos(P_(P, 0) * p.y), cy = cos(p.y);
  return w * vec3(cy * cn * cos(p.x), cy * cn * sin(p.x), sin(p.y) * cn);
}
// The (1 − sor) y part of z is outside the weight, as in Fractorium.
vec3 V_taurus(vec3 p, float w, int P, int A) {
  float r = P_(P, 0), freq = P_(P, 1), inv = P_(P, 2), sor = P_(P, 3);
  float sy = sin(p.y);
  float ir = inv * r + (1.0 - inv) * r * cos(freq * p.x);
  return vec3(w * cos(p.x) * (ir + sy), w * sin(p.x) * (ir + sy), w * sor * cos(p.y) + (1.0 - sor) * p.y);
}
vec3 V_helix(vec3 p, float w, int P, int A) {
  float t = p.z * (P_(P, 0) * kTwoPi), width = P_(P, 1);
  return w * vec3(p.x + cos(t) * width, p.y + sin(t) * width, p.z);
}
vec3 V_helicoid(vec3 p, float w, int P, int A) {
  float t = p.z * (P_(P, 0) * kTwoPi) + atan2c(p.y, p.x);
  float wr = w * sqrt(p.x * p.x + p.y * p.y);
  return vec3(wr * cos(t), wr * sin(t), w * p.z);
}
vec3 V_linearT3D(vec3 p, float w, int P, int A) {
  vec3 e = vec3(P_(P, 0), P_(P, 1), P_(P, 2));
  vec3 s = vec3(p.x < 0.0 ? -w : w, p.y < 0.0 ? -w : w, p.z < 0.0 ? -w : w);
  return s * pow(abs(p), e);
}
vec3 V_ho(vec3 p, float w, int P, int A) {
  float px = P_(P, 0), py = P_(P, 1), pz = P_(P, 2);
  float uu = p.x * p.x, vv = p.y * p.y, ww = p.z * p.z;
  float cv = cos(p.y), sv = sin(p.y);
  float cucv = cos(p.x) * cv, sucv = sin(p.x) * cv;
  return w * vec3(pow(abs(cucv), px) + cucv * px + 0.25 * atan2c(vv, ww),
                  pow(abs(sucv), py) + sucv * py + 0.25 * atan2c(uu, ww), pow(abs(sv), pz) + sv * pz);
}
vec3 V_splits3D(vec3 p, float w, int P, int A) {
  float sx = P_(P, 0), sy = P_(P, 1), sz = P_(P, 2);
  return w * vec3(p.x >= 0.0 ? p.x + sx : p.x - sx, p.y >= 0.0 ? p.y + sy : p.y - sy, p.z >= 0.0 ? p.z + sz : p.z - sz);
}
vec3 V_waves2_3D(vec3 p, float w, int P, int A) {
  float freq = P_(P, 0), scale = P_(P, 1);
  float mean = (p.x + p.y) * 0.5;
  return w * vec3(p.x + scale * sin(p.y * freq), p.y + scale * sin(p.x * freq), p.z + scale * sin(mean * freq));
}
// erf by Abramowitz & Stegun 7.1.26 (within 1.5e-7).
float v3d_erf(float x) {
  float t = 1.0 / (1.0 + 0.3275911 * abs(x));
  float poly = t * (0.254829592 + t * (-0.284496736 + t * (1.421413741 + t * (-1.453152027 + t * 1.061405429))));
  return sign(x) * (1.0 - poly * exp(-x * x));
}
vec3 V_xerf(vec3 p, float w, int P, int A) {
  float r2 = dot(p, p);
  return w * vec3(abs(p.x) >= 2.0 ? p.x / r2 : v3d_erf(p.x), abs(p.y) >= 2.0 ? p.y / r2 : v3d_erf(p.y),
                  abs(p.z) >= 2.0 ? p.z / r2 : v3d_erf(p.z));
}
vec3 V_bubbleT3D(vec3 p, float w, int P, int A) {
  float stripes = floor(P_(P, 0) + 0.5), absStripes = abs(stripes);
  bool invStripes = stripes < 0.0;
  float ratio = clamp(clamp(P_(P, 1), 0.0, 2.0), 0.01, 1.99);
  float hole = clamp(P_(P, 2), -360.0, 360.0), exponentZ = P_(P, 3);
  bool symmetryZ = fractoriumInteger(P_(P, 4), 0.0, 1.0) == 1.0, blur = fractoriumInteger(P_(P, 5), 0.0, 1.0) == 1.0;
  float angStrip = absStripes != 0.0 ? kPi / absStripes : 0.0, strip2 = 2.0 * angStrip;
  float sn = sin(angStrip), cs = cos(angStrip), strip1 = fractoriumZeps(ratio * angStrip);
  float holeAngle = symmetryZ ? (hole < 0.0 ? abs(hole) : min(hole, 179.9)) : hole;
  bool invHole = holeAngle < 0.0;
  holeAngle = invHole ? abs(hole) / 360.0 * kTwoPi / 2.0 : kPi - holeAngle / 360.0 * kTwoPi / 2.0;
  float holeComp = kPi - holeAngle;
  bool pushesHole = blur && exponentZ == 1.0;
  float px = p.x, py = p.y, pz = p.z;
  float rad = fractoriumZeps((px * px + py * py) / 4.0 + 1.0);
  if (absStripes != 0.0) {
    float a = atan2c(px, py);
    if (a < 0.0) a += kTwoPi;
    if (a > strip2) {  // the remainder in (0, strip2], as Fractorium's subtraction leaves it
      a = fmodc(a, strip2);
      if (a == 0.0) a = strip2;
    }
    bool cut = invStripes ? a < strip1 : a > strip1;
    if (cut && !blur) {
      px = 0.0;
      py = 0.0;
    } else if (cut) {
      float c = cs, s = sn;
      bool single = invStripes ? absStripes == 1.0 : ratio == 1.0;
      if (!single) {
        float turn = invStripes ? a - (a - strip1) / strip1 * (strip2 - strip1)
                                : a - (a - strip1) / fractoriumZeps(strip2 - strip1) * strip1;
        c = cos(turn);
        s = sin(turn);
      }
      float tx = c * px - s * py, ty = s * px + c * py;
      px = tx;
      py = ty;
    }
  }
  px /= rad;
  py /= rad;
  float angZ = 0.0;
  if (px != 0.0 || py != 0.0) {
    pz = 2.0 / pow(rad, exponentZ) - 1.0;
    float q = px * px + py * py;
    angZ = exponentZ <= 2.0 ? kPi - acos(pz / (q + pz * pz)) : kPi - atan2c(q * q, pz);
  } else {
    pz = 0.0;
  }
  bool cut = false;
  float angTmp = 0.0;
  if (!symmetryZ) {
    cut = invHole ? angZ < holeAngle : angZ > holeAngle;
    angTmp = invHole ? kPi - angZ / fractoriumZeps(holeComp * holeAngle - kPi / 2.0)
                     : (kPi - angZ) / fractoriumZeps(holeComp * holeAngle - kPi / 2.0);
  } else {
    cut = angZ > holeAngle || angZ < kPi - holeAngle;
    angTmp = angZ > holeAngle ? (kPi - angZ) / holeComp * (kPi - 2.0 * holeComp) + holeComp - kPi / 2.0
                              : kPi / 2.0 - (angZ / holeComp * (kPi - 2.0 * holeComp) + holeComp);
  }
  if (cut && !pushesHole) {
    px = 0.0;
    py = 0.0;
    pz = 0.0;
  } else if (cut) {
    float from = angZ - kPi / 2.0;
    float fac = cos(angTmp) / cos(from);
    px *= fac;
    py *= fac;
    pz *= sin(angTmp) / sin(from);
  }
  return w * vec3(px, py, pz);
}

// ---- 3D blurs (variations_3d_shapes.cpp) ---------------------------------------------------------

vec3 V_square3D(vec3 p, float w, int P, int A) {
  float a = psi(), b = psi(), c = psi();
  return w * (vec3(a, b, c) - 0.5);
}
vec3 V_farblur(vec3 p, float w, int P, int A) {
  vec3 d = p - vec3(P_(P, 3), P_(P, 4), P_(P, 5));
  float r = w * dot(d, d) * gaussPsi();
  float u = psi() * kTwoPi;
  float v = psi() * kTwoPi;
  float sv = sin(v);
  return vec3(P_(P, 0) * r * sv * cos(u), P_(P, 1) * r * sv * sin(u), P_(P, 2) * r * cos(v));
}
// A power below 0 counts as 0 (Fractorium's); pow(Ψ, 0) is 1, Ψ = 0 included, as in C.
vec3 V_sphereblur(vec3 p, float w, int P, int A) {
  float power = max(P_(P, 0), 0.0);
  float angle = psi() * kTwoPi;
  float polar = acos(psi() * 2.0 - 1.0);
  float u = psi();
  float up = power == 0.0 ? 1.0 : (u == 0.0 ? 0.0 : (power == 1.0 ? u : pow(u, power)));
  float q = acos(up * 2.0 - 1.0) / kPi;
  float r = q == 0.0 ? 0.0 : w * pow(q, 2.0 / 3.0);  // ∛(q²)
  float sz = sin(polar);
  return vec3(r * cos(angle) * sz, r * sin(angle) * sz, r * cos(polar));
}

// ---- more of Fractorium's 3D ones (variations_3d_more.cpp) ---------------------------------------

// (A q + B)/(C q + D) of q = x + y i + z j; the quotient's k part is dropped.
vec3 V_mobiq(vec3 p, float w, int P, int A) {
  vec4 a = vec4(P_(P, 0), P_(P, 1), P_(P, 2), P_(P, 3)), b = vec4(P_(P, 4), P_(P, 5), P_(P, 6), P_(P, 7));
  vec4 c = vec4(P_(P, 8), P_(P, 9), P_(P, 10), P_(P, 11)), d = vec4(P_(P, 12), P_(P, 13), P_(P, 14), P_(P, 15));
  float qt = p.x, qx = p.y, qy = p.z;
  vec4 nn = vec4(a.x * qt - a.y * qx - a.z * qy, a.x * qx + a.y * qt - a.w * qy, a.x * qy + a.z * qt + a.w * qx,
                 a.w * qt + a.y * qy - a.z * qx) + b;
  vec4 e = vec4(c.x * qt - c.y * qx - c.z * qy, c.x * qx + c.y * qt - c.w * qy, c.x * qy + c.z * qt + c.w * qx,
                c.w * qt + c.y * qy - c.z * qx) + d;
  float ni = w / dot(e, e);
  return ni * vec3(dot(nn, e), nn.y * e.x - nn.x * e.y - nn.z * e.w + nn.w * e.z,
                   nn.z * e.x - nn.x * e.z - nn.w * e.y + nn.y * e.w);
}
vec3 V_julia3Dq(vec3 p, float w, int P, int A) {
  float power = countParam(P_(P, 0)), divisor = countParam(P_(P, 1));
  float invPower = divisor / power, absInvPower = abs(invPower);
  float halfInvPower = 0.5 * invPower - 0.5, branch = kTwoPi / power, branches = abs(power);
  float k = floor(psi() * branches);
  float t = atan2c(p.y, p.x) * invPower + k * branch;
  float pz = p.z * absInvPower;
  float r2 = p.x * p.x + p.y * p.y;
  float r = w * pow(r2 + pz * pz, halfInvPower);
  float rs = r * sqrt(r2);
  return vec3(rs * cos(t), rs * sin(t), r * pz);
}
// A period of 0 stops its wave; ρ = √|x² + y² + z| (z, not z²), as in Fractorium.
float v3d_inversePeriod(float period) { return period == 0.0 ? 0.0 : 1.0 / period; }
vec3 V_heat(vec3 p, float w, int P, int A) {
  float tx = v3d_inversePeriod(P_(P, 0)), px = v3d_inversePeriod(P_(P, 3)), rx = v3d_inversePeriod(P_(P, 6));
  float at = w * P_(P, 2), bt = kTwoPi * tx, ct = P_(P, 1) * tx;
  float ap = w * P_(P, 5), bp = kTwoPi * px, cp = P_(P, 4) * px;
  float ar = w * P_(P, 8), br = kTwoPi * rx, cr = P_(P, 7) * rx;
  float r = sqrt(abs(p.x * p.x + p.y * p.y + p.z));
  r += ar * sin(br * r + cr);
  if (r == 0.0) r = kFractoriumEps;
  float azimuth = at * sin(bt * r + ct) + atan2c(p.y, p.x);
  float polar = ap * sin(bp * r + cp) + acos(clamp(p.z / r, -1.0, 1.0));
  float sp = sin(polar);
  return r * vec3(cos(azimuth) * sp, sin(azimuth) * sp, cos(polar));
}
// |p|² taken as x² + y² + z (z, not z²), as in Fractorium.
vec3 V_hypertile3D(vec3 p, float w, int P, int A) {
  float pp = fractoriumInteger(P_(P, 0), 3.0, 2147483647.0), q = fractoriumInteger(P_(P, 1), 3.0, 2147483647.0);
  float tile = floor(P_(P, 2) + 0.5);
  float pa = kTwoPi / pp, qa = kTwoPi / q;
  float r = -(cos(pa) - 1.0) / fractoriumZeps(cos(pa) + cos(qa));
  r = r > 0.0 ? 1.0 / fractoriumZeps(sqrt(1.0 + r)) : 1.0;
  float cx = r * cos(tile * pa), cy = r * sin(tile * pa);
  float c2 = cx * cx + cy * cy, c2x = 2.0 * cx, c2y = 2.0 * cy;
  float s2x = 1.0 + cx * cx - cy * cy, s2y = 1.0 + cy * cy - cx * cx, s2z = 1.0 - cy * cy - cx * cx;
  float r2 = p.x * p.x + p.y * p.y + p.z;
  float x2cx = c2x * p.x, y2cy = c2y * p.y;
  float d = w / fractoriumZeps(c2 * r2 + x2cx - y2cy + 1.0);
  return d * vec3(p.x * s2x - cx * (y2cy - r2 - 1.0), p.y * s2y + cy * (-x2cx - r2 - 1.0), p.z * s2z);
}
vec3 V_loonie_3D(vec3 p, float w, int P, int A) {
  float vv = w * w;
  float pz = p.z == 0.0 ? atan2c(p.y, p.x) : p.z;
  float r2 = p.x * p.x + p.y * p.y + pz * pz;
  float r = r2 < vv ? w * sqrt(vv / r2 - 1.0) : w;
  return r * vec3(p.x, p.y, pz * 0.5);
}
vec3 V_scry_3D(vec3 p, float w, int P, int A) {
  float invWeight = 1.0 / fractoriumZeps(w);
  float t = dot(p, p);
  float r = 1.0 / fractoriumZeps(sqrt(t) * (t + invWeight));
  float pz = p.z == 0.0 ? atan2c(p.y, p.x) : p.z;
  return r * vec3(p.x, p.y, pz);
}
vec3 V_line(vec3 p, float w, int P, int A) {
  float delta = P_(P, 0) * kPi, phi = P_(P, 1) * kPi;
  vec3 u = vec3(cos(delta) * cos(phi), sin(delta) * cos(phi), sin(phi));
  u /= length(u);
  return u * (psi() * w);
}
vec3 V_hypercrop(vec3 p, float w, int P, int A) {
  float sides = fractoriumZeps(P_(P, 0)), zero = P_(P, 2);
  float coeff = fractoriumZeps(sides * 0.5 / kPi), a0 = kPi / sides;
  float len = 1.0 / fractoriumZeps(cos(a0)), d = P_(P, 1) * sin(a0) * len;
  float angle = floor(atan2c(p.y, p.x) * coeff) / coeff + a0;
  float x0 = cos(angle) * len, y0 = sin(angle) * len;
  float dx = p.x - x0, dy = p.y - y0;
  vec3 f = p;
  if (sqrt(dx * dx + dy * dy) < d) {
    if (zero > 1.5) {
      f.xy = vec2(x0, y0);
    } else if (zero > 0.5) {
      f.xy = vec2(0.0);
    } else {
      float edge = atan2c(dy, dx);
      f.xy = vec2(x0 + cos(edge) * d, y0 + sin(edge) * d);
    }
    f.z = 0.0;
  }
  return f * w;
}
// The random sign bit is Ψ < ½; Fractorium's exponents as it has them.
vec3 V_SuperShape3D(vec3 p, float w, int P, int A) {
  float rho2pi = P_(P, 0) * (2.0 / kPi), phi2pi = P_(P, 1) * (2.0 / kPi), m41 = P_(P, 2) / 4.0, m42 = P_(P, 3) / 4.0;
  float n11 = P_(P, 8), n12 = P_(P, 9), n21 = P_(P, 10), n22 = P_(P, 11), n31 = P_(P, 12), n32 = P_(P, 13);
  float an21 = pow(abs(1.0 / P_(P, 4)), n21), an22 = pow(abs(1.0 / P_(P, 5)), n22);
  float bn31 = pow(abs(1.0 / P_(P, 6)), n31), bn32 = pow(abs(1.0 / P_(P, 7)), n32);
  float spiral = P_(P, 14);
  bool toroid = floor(P_(P, 15) + 0.5) == 1.0;
  float rho = psi() * rho2pi;
  float phi = psi() * phi2pi;
  if (psi() < 0.5) phi = -phi;
  float sr = sin(rho), cr = cos(rho), sp = sin(phi), cp = cos(phi);
  float pr1 = an21 * pow(abs(cos(m41 * rho)), n21) + bn31 * pow(abs(sin(m41 * rho)), n31);
  float pr2 = an22 * pow(abs(cos(m42 * phi)), n22) + bn32 * pow(abs(sin(m42 * phi)), n32);
  float r1 = pow(abs(pr1), n11) + spiral * rho;
  float r2 = pow(abs(pr2), n12);
  float ring = toroid ? r1 + r2 * cp : r1 * r2 * cp;
  return w * vec3(cr * ring, sr * ring, r2 * sp);
}
vec3 V_pRose3D(vec3 p, float w, int P, int A) {
  float l = P_(P, 0), k = P_(P, 1), c = P_(P, 2), z1 = P_(P, 3), z2 = P_(P, 4), refSc = P_(P, 5);
  float opt = P_(P, 6), optSc = P_(P, 7), opt3 = P_(P, 8), transp = P_(P, 9), dist = P_(P, 10);
  float wagsc = P_(P, 11), crvsc = P_(P, 12), f = P_(P, 13), wigsc = P_(P, 14), offset = P_(P, 15);
  float cycle = kTwoPi / fractoriumZeps(k);
  float petals = abs(k) < 0.0001 ? (k < 0.0 ? -0.0001 : 0.0001) : k;
  float freq = f * kTwoPi, wigScale = wigsc * 0.5;
  float smooth12 = min(abs(opt), 2.0), smooth3 = min(abs(opt3), 1.0);
  float absOptSc = abs(optSc), antiOpt1 = 2.0 - smooth12;
  float optDir = opt3 < 0.0 ? -1.0 : (opt < 0.0 ? -1.0 : 1.0);
  float ghost = optDir > 0.0 ? 0.0 : transp * transp;
  bool negative = psi() < 0.5;
  bool ghostly = psi() < ghost;
  float rad = sqrt(p.x * p.x + p.y * p.y);
  float curve1 = rad / l, curve2 = curve1 * curve1, curve3 = (rad - l * 0.5) / l, curve4 = curve2 * curve2;
  float th = atan2c(p.y, p.x);
  float wig = th / fractoriumZeps(cycle) * freq * 0.5 + offset * cycle;
  float sin2 = sin(curve2 * kPi), cos3 = cos(curve3 * kPi);
  float wag = sin(curve1 * kPi * absOptSc) + wagsc * 0.4 * rad + crvsc * 0.5 * (optDir < 0.0 ? sin2 : cos3);
  float wag3 = sin(curve4 * kPi * absOptSc) + wagsc * rad * rad * 0.4 + crvsc * 0.5 * (optDir < 0.0 ? cos3 : sin2);
  float wag2 = sin(curve2 * kPi * absOptSc) + wagsc * 0.4 * rad + crvsc * 0.5 * cos3;
  float wag12 = 0.0;
  if (smooth12 <= 1.0)
    wag12 = wag;
  else if (smooth12 <= 2.0)
    wag12 = wag2 * (1.0 - antiOpt1) + wag * antiOpt1;
  float waggle = 0.0;
  if (smooth3 == 0.0)
    waggle = wag12;
  else if (smooth3 > 0.0)
    waggle = wag12 * (1.0 - smooth3) + wag3 * smooth3;
  bool mirrored = ghostly && negative;
  float petal = w * 0.5 * (mirrored ? refSc : 1.0) * l * cos(petals * th + c);
  float lift = (mirrored ? z2 : z1) * waggle + rad * 0.5 * rad * 0.5 * sin(wig) * wigScale + dist;
  return vec3(petal * cos(th), petal * sin(th), w * (mirrored ? -0.5 : 0.5) * lift);
}

// ---- Fractorium's own (variations_fractorium.cpp) ------------------------------------------------

vec3 V_pow_block(vec3 p, float w, int P, int A) {
  float numerator = P_(P, 0), denominator = P_(P, 1), root = P_(P, 2), correctN = P_(P, 3), correctD = P_(P, 4);
  float power = numerator / fractoriumZeps(denominator * correctN * (1.0 / correctD));
  float divisor = fractoriumZeps(denominator);
  float k = floor(psi() * denominator);
  float r = pow(p.x * p.x + p.y * p.y, power * 0.5) * w;
  float a = (atan2c(p.y, p.x) / divisor + root * kTwoPi * k / divisor) * numerator;
  return vec3(r * cos(a), r * sin(a), w * p.z);
}
vec3 V_poincare3D(vec3 p, float w, int P, int A) {
  float radius = P_(P, 0), a = P_(P, 1) * kPi / 2.0, b = P_(P, 2) * kPi / 2.0;
  vec3 c = vec3(-radius * cos(a) * cos(b), radius * sin(a) * cos(b), -radius * sin(b));
  float c2 = dot(c, c);
  vec3 s = vec3(c.x * c.x - c.y * c.y - c.z * c.z, c.y * c.y - c.x * c.x - c.z * c.z,
                c.z * c.z - c.y * c.y - c.x * c.x) + 1.0;
  float r2 = dot(p, p);
  vec3 k = 2.0 * c * p;
  float d = w / (c2 * r2 - k.x - k.y - k.z + 1.0);
  return d * (p * s + c * (vec3(k.y + k.z, k.x + k.z, k.y + k.x) - r2 - 1.0));
}
// a^n for a whole n, a of either sign (GLSL's pow wants a ≥ 0).
float v3d_wholePow(float a, float n) {
  float m = pow(abs(a), n);
  return a < 0.0 && mod(n, 2.0) == 1.0 ? -m : m;
}
// Its box blur adds mul · a^boxpow · D / scale outside the weight, as Fractorium does.
vec3 V_falloff(vec3 p, float w, int P, int A) {
  float scatter = 0.04 * max(P_(P, 0), kFractoriumEps);
  float minDist = max(P_(P, 1), 0.0);
  vec3 mul = clamp(vec3(P_(P, 2), P_(P, 3), P_(P, 4)), 0.0, 1.0);
  vec3 centre = vec3(P_(P, 5), P_(P, 6), P_(P, 7));
  bool invert = fractoriumInteger(P_(P, 8), 0.0, 1.0) != 0.0;
  float type = fractoriumInteger(P_(P, 9), 0.0, 2.0);
  float boxPow = fractoriumInteger(P_(P, 10), 2.0, 32.0);
  float ax = psi() - 0.5;
  float ay = psi() - 0.5;
  float az = psi() - 0.5;
  vec3 a = vec3(ax, ay, az);
  vec3 d = p - centre;
  float r = sqrt(dot(d, d));
  float rs = max(((invert ? max(1.0 - r, 0.0) : max(r, 0.0)) - minDist) * scatter, 0.0);
  if (type == 0.0) return w * (p + mul * a * rs);
  if (type == 1.0) {
    float radius = r + mul.x * ax * rs;
    float phi = atan2c(p.y, p.x) + mul.y * ay * rs;
    float sigma = asin(r == 0.0 ? 0.0 : p.z / r) + mul.z * az * rs;
    return radius * w * vec3(cos(sigma) * cos(phi), cos(sigma) * sin(phi), sin(sigma));
  }
  float scale = clamp(rs, 0.0, 0.9) + 0.1, denom = 1.0 / scale;
  vec3 target = floor(p * denom) + scale * a;
  vec3 powA = vec3(v3d_wholePow(ax, boxPow), v3d_wholePow(ay, boxPow), v3d_wholePow(az, boxPow));
  return w * (p + (target - p) * mul * rs) + mul * powA * rs * denom;
}
// Hugo Elias' integer noise with 32-bit wrap-around, in [0, 1] (double: the seed counts floor it).
double v3d_voronNoise(int value) {
  uint v = uint(value);
  v = (v << 13) ^ v;
  uint mixed = v * (v * v * 15731u + 789221u) + 1376312589u;
  return double(mixed & 0x7fffffffu) * (1.0lf / 2147483647.0lf);
}
int v3d_seed(float v) {  // clamped into int's range, as Fractorium's int holds it
  float s = floor(v + 0.5);
  return s >= 2147483648.0 ? 2147483647 : (s <= -2147483648.0 ? -2147483647 - 1 : int(s));
}
vec3 V_Voron(vec3 p, float w, int P, int A) {
  float k = P_(P, 0), side = P_(P, 1);
  if (abs(side) < 1e-6) side = side < 0.0 ? -kFractoriumEps : kFractoriumEps;
  double count = double(fractoriumInteger(P_(P, 2), 1.0, 25.0));
  int seedX = v3d_seed(P_(P, 3)), seedY = v3d_seed(P_(P, 4));
  float cellX = floor(p.x / side), cellY = floor(p.y / side);
  // A point beyond ±2²⁰ cells (far outside any flame) escapes, as on the CPU.
  if (!(abs(cellX) < 1048576.0 && abs(cellY) < 1048576.0)) {
    float nan = uintBitsToFloat(0x7fc00000u);
    return vec3(nan, nan, w * p.z);
  }
  int m = int(cellX), nn = int(cellY);
  float best = 20.0, bestX = 0.0, bestY = 0.0;
  for (int di = -1; di < 2; ++di) {
    for (int dj = -1; dj < 2; ++dj) {
      int m1 = m + di, n1 = nn + dj;
      int seeds = int(1.0lf + floor(count * v3d_voronNoise(19 * m1 + 257 * n1 + seedX)));
      for (int l = 0; l < seeds; ++l) {
        float sx = (float(v3d_voronNoise(l + 64 * m1 + 15 * n1 + seedX)) + float(m1)) * side;
        float sy = (float(v3d_voronNoise(l + 21 * m1 + 33 * n1 + seedY)) + float(n1)) * side;
        float ddx = p.x - sx, ddy = p.y - sy;
        float r = sqrt(ddx * ddx + ddy * ddy);
        if (r < best) {
          best = r;
          bestX = sx;
          bestY = sy;
        }
      }
    }
  }
  return w * vec3(k * (p.x - bestX) + bestX, k * (p.y - bestY) + bestY, p.z);
}
vec3 V_smartshape(vec3 p, float w, int P, int A) {
  float power = max(P_(P, 0), 2.0), roundStr = P_(P, 1), roundWidth = P_(P, 2), distortion = P_(P, 3);
  bool compensate = clamp(P_(P, 4), 0.0, 1.0) > 0.0;
  float alpha = kTwoPi / power;
  float alphaCoeff = tan(alpha * 0.5) * 2.0;
  float roundCoeff = roundStr / sin(alpha * 0.5) / power * 2.0;
  float dang = (atan2c(p.y, p.x) + kPi) / alpha;
  float rad = sqrt(p.x * p.x + p.y * p.y);
  float zang1 = floor(dang), xang1 = dang - zang1;
  float xang2 = xang1 > 0.5 ? 1.0 - xang1 : xang1;
  float zang = xang1 > 0.5 ? zang1 + 1.0 : zang1;
  float sgn = xang1 > 0.5 ? -1.0 : 1.0;
  float xang = compensate && distortion >= 1.0 ? atan(xang2 * alphaCoeff) / alpha : xang2;
  float coeff1 = 1.0;
  if (distortion != 0.0) {
    float coeff0 = 1.0 / cos(xang * alpha);
    if (roundStr != 0.0) {
      float width = roundWidth != 1.0 ? exp(log(xang * 2.0) * roundWidth) * roundCoeff : xang * 2.0 * roundCoeff;
      coeff1 = abs((1.0 - width) * coeff0 + width);
    } else {
      coeff1 = coeff0;
    }
  }
  float coeff = distortion != 1.0 ? exp(log(coeff1) * distortion) : coeff1;
  float ang = (zang + sgn * xang) * alpha - kPi;
  float t = w * coeff * rad;
  return vec3(cos(ang) * t, sin(ang) * t, w * p.z);
}
// The point's direction kept, its distance r replaced by w·T²/r, T the sum of four shapes' radii.
vec3 V_y(vec3 p, float w, int P, int A) {
  float hypergon = P_(P, 0), hypergonN = max(floor(P_(P, 1) + 0.5), 3.0), hypergonR = P_(P, 2);
  float star = P_(P, 3), starN = max(floor(P_(P, 4) + 0.5), 3.0);
  float starSlope = clamp(P_(P, 5), kFractoriumEps, kPi / 2.0);
  float lituus = P_(P, 6), lituusA = P_(P, 7);
  float super_ = P_(P, 8), superM = P_(P, 9), superN1 = P_(P, 10), superN2 = P_(P, 11), superN3 = P_(P, 12);
  float hypergonD = sqrt(1.0 + hypergonR * hypergonR), hd2 = hypergonD * hypergonD;
  float tanStarSlope = abs(starSlope - kPi / 2.0) < 1e-6 ? tan(starSlope - 0.05) : tan(starSlope);
  float oneOverN1 = -1.0 / fractoriumZeps(superN1);
  float a = atan2c(p.y, p.x);
  float total = 0.0;
  if (hypergon != 0.0) {
    float t1 = fmodc(abs(a), kTwoPi / hypergonN) - kPi / hypergonN;
    float t2 = tan(t1) * tan(t1) + 1.0;
    total += t2 >= hd2 ? hypergon : hypergon * (hypergonD - sqrt(hd2 - t2)) / sqrt(t2);
  }
  if (star != 0.0) {
    float t1 = tan(abs(fmodc(abs(a), kTwoPi / starN) - kPi / starN));
    total += star * sqrt(tanStarSlope * tanStarSlope * (1.0 + t1 * t1) / ((t1 + tanStarSlope) * (t1 + tanStarSlope)));
  }
  if (lituus != 0.0) total += lituus * pow(abs(a / kPi + 1.0), -lituusA);
  if (super_ != 0.0) {
    float t4 = a * superM / 4.0;
    total += super_ * pow(pow(abs(cos(t4)), superN2) + pow(abs(sin(t4)), superN3), oneOverN1);
  }
  float r = w * total * total / (sqrt(p.x * p.x + p.y * p.y) + kEpsilon);
  return vec3(r * cos(a), r * sin(a), w * p.z);
}

// ---- the rest of flam3's (variations_flam3.cpp) --------------------------------------------------

vec3 V_flux(vec3 p, float w, int P, int A) {
  float xpw = p.x + w, xmw = p.x - w;
  float r = w * (2.0 + P_(P, 0)) * sqrt(sqrt(p.y * p.y + xpw * xpw) / (sqrt(p.y * p.y + xmw * xmw) + kEpsilon));
  float a = (atan2c(p.y, xmw) - atan2c(p.y, xpw)) * 0.5;
  return vec3(r * cos(a), r * sin(a), w * p.z);
}

// ---- direct colour: the colour index in gColour (variations_apophysis.cpp, variations_fractorium.cpp) ----

float v3d_logMap(float v) { return v == 0.0 ? 0.0 : (2.718281828 + log(v * 2.718281828)) * 0.25 * (v < 0.0 ? -1.0 : 1.0); }
float v3d_logScale(float v) {
  return v == 0.0 ? 0.0 : log((abs(v) + 1.0) * 2.718281828) * (v < 0.0 ? -1.0 : 1.0) / 2.718281828;
}

vec3 V_falloff2(vec3 p, float w, int P, int A) {
  float scale = 0.04 * max(P_(P, 0), 1e-6), mindist = max(P_(P, 1), 0.0);
  vec3 mul = clamp(vec3(P_(P, 2), P_(P, 3), P_(P, 4)), 0.0, 1.0);
  float mulC = clamp(P_(P, 5), 0.0, 1.0);
  vec3 centre = vec3(P_(P, 6), P_(P, 7), P_(P, 8));
  bool invert = roundHalfAway(P_(P, 9)) >= 1.0;
  float type = roundHalfAway(P_(P, 10));
  float d = length(p - centre);
  if (invert) d = 1.0 - d;
  d = max(0.0, (max(d, 0.0) - mindist) * scale);
  float a = psi(), b = psi(), c = psi();
  vec3 q;
  if (type == 1.0) {
    float rIn = length(p) + 1e-6;
    float sigma = asin(clamp(p.z / rIn, -1.0, 1.0)) + mul.z * a * d;
    float phi = atan2c(p.y, p.x) + mul.y * b * d;
    float r = rIn + mul.x * c * d;
    q = vec3(r * cos(sigma) * cos(phi), r * cos(sigma) * sin(phi), sin(sigma));
  } else if (type >= 2.0) {
    float sigma = d * a * kTwoPi, phi = d * b * kPi, r = d * c;
    q = p + mul * vec3(r * cos(sigma) * cos(phi), r * cos(sigma) * sin(phi), r * sin(sigma));
  } else {
    q = p + mul * vec3(a, b, c) * d;
  }
  if (mulC != 0.0) gColour = abs(fmodc(gColour + mulC * (psi() - 0.5) * d, 1.0));
  return w * q;
}

vec3 V_falloff3(vec3 p, float w, int P, int A) {
  float type = fractoriumInteger(P_(P, 0), 0.0, 3.0);
  bool square = fractoriumInteger(P_(P, 1), 0.0, 1.0) != 0.0;
  float rMax = 0.04 * max(P_(P, 2), 2.220446e-16);
  float minDist = max(P_(P, 3), 0.0);
  bool invert = fractoriumInteger(P_(P, 4), 0.0, 1.0) != 0.0;
  vec3 mul = clamp(vec3(P_(P, 5), P_(P, 6), P_(P, 7)), 0.0, 1.0);
  float mulC = clamp(P_(P, 8), 0.0, 1.0);
  vec3 centre = vec3(P_(P, 9), P_(P, 10), P_(P, 11));
  float alpha = P_(P, 12);
  float rx = psi() - 0.5, ry = psi() - 0.5, rz = psi() - 0.5, rc = psi() - 0.5;
  vec3 dp = p - centre;
  float radius = square ? max(abs(dp.x), max(abs(dp.y), abs(dp.z))) : length(dp);
  float dist = max(((invert ? max(1.0 - radius, 0.0) : max(radius, 0.0)) - minDist) * rMax, 0.0);
  if (type == 0.0) {
    float sigma = dist * ry * kTwoPi, phi = dist * rz * kPi, rad = dist * rx;
    gColour = abs(fmodc(gColour + mulC * rc * dist, 1.0));
    return w * (p + mul * vec3(rad * cos(sigma) * cos(phi), rad * cos(sigma) * sin(phi), rad * sin(sigma)));
  }
  if (type == 1.0) {
    if (p == vec3(0.0)) return vec3(0.0);  // adds w·0, and leaves the colour
    float rIn = length(p);
    float r = rIn + mul.x * rx * dist;
    float phi = atan2c(p.y, p.x) + mul.y * ry * dist;
    float sigma = asin(p.z / rIn) + mul.z * rz * dist;
    gColour = abs(fmodc(gColour + mulC * rc * dist, 1.0));
    return w * vec3(r * cos(sigma) * cos(phi), r * cos(sigma) * sin(phi), r * sin(sigma));
  }
  float coeff = rMax <= 2.220446e-16 ? dist : dist + alpha * (v3d_logMap(dist) - dist);
  gColour = abs(fmodc(gColour + v3d_logMap(mulC) * v3d_logScale(rc) * coeff, 1.0));
  return w * (p + vec3(v3d_logMap(mul.x) * v3d_logScale(rx), v3d_logMap(mul.y) * v3d_logScale(ry),
                       v3d_logMap(mul.z) * v3d_logScale(rz)) * coeff);
}

// ---- Fractorium's direct-colour family and three that discard the sum (variations_direct_colour.cpp,
// variations_3d_more.cpp, variations_3d_sum.cpp) ----------------------------------------------------

// p + (±1, ±1) through the transform's own 2D affine map, read in Apophysis' order as dc_carpet does.
vec3 V_dc_carpet(vec3 p, float w, int P, int A) {
  float ca = flameData[A], cb = flameData[A + 1], cc = flameData[A + 3], cd = flameData[A + 4];
  float ce = flameData[A + 5], cf = flameData[A + 7];
  float h0 = 0.1 * P_(P, 0);
  float x0 = psi() < 0.5 ? 1.0 : -1.0;
  float y0 = psi() < 0.5 ? 1.0 : -1.0;
  float px = p.x + x0, py = p.y + y0;
  float xr = x0 == y0 ? 0.0 : -2.0;  // Fractorium's integer xor of the two signs
  float h = -h0 + (1.0 - xr) * h0;
  gColour = fmodc(abs(gColour * 0.5 * (1.0 + h) + xr * (1.0 - h) * 0.5), 1.0);
  return vec3(w * (ca * px + cb * py + ce), w * (cc * px + cd * py + cf), w * p.z);
}
vec3 V_dc_cube(vec3 p, float w, int P, int A) {
  float u = 2.0 * psi() - 1.0;
  float v = 2.0 * psi() - 1.0;
  float axis = floor(3.0 * psi());
  bool negative = psi() < 0.5;
  float side = negative ? -1.0 : 1.0;
  vec3 q;
  int face;
  if (axis == 0.0) {
    q = vec3(side, u, v);
    face = negative ? 0 : 1;
  } else if (axis == 1.0) {
    q = vec3(u, side, v);
    face = negative ? 2 : 3;
  } else {
    q = vec3(u, v, side);
    face = negative ? 4 : 5;
  }
  gColour = clamp(P_(P, face), 0.0, 1.0);
  return w * q * vec3(P_(P, 6), P_(P, 7), P_(P, 8));
}
// Apophysis' Round: halves away from zero. The fraction is taken exactly, where float's v ± ½ could
// round up across the next whole number; large values, whole in float, are kept as the CPU keeps them.
float dcol_apophysisRound(float v) {
  float t = trunc(v);
  return abs(v - t) >= 0.5 ? t + sign(v) : t;
}
vec3 V_dc_gridout(vec3 p, float w, int P, int A) {
  float rx = dcol_apophysisRound(p.x), ry = dcol_apophysisRound(p.y);
  bool alongX;
  float step;
  if (ry <= 0.0) {
    if (rx > 0.0) {
      alongX = -ry >= rx;
      step = 1.0;
    } else {
      alongX = ry <= rx;
      step = alongX ? 1.0 : -1.0;
    }
  } else if (rx > 0.0) {
    alongX = ry >= rx;
    step = alongX ? -1.0 : 1.0;
  } else {
    alongX = ry > -rx;
    step = -1.0;
  }
  gColour = fmodc(gColour + (alongX ? 0.25 : 0.75), 1.0);
  return w * vec3(p.x + (alongX ? step : 0.0), p.y + (alongX ? 0.0 : step), p.z);
}
// Onto dc_triangle's edge u + v = 1 from beyond it.
vec2 dcol_ontoEdge(vec2 uv) {
  if (uv.x > uv.y) {
    float u = min(uv.x, 1.0);
    return vec2(u, 1.0 - u);
  }
  float v = min(uv.y, 1.0);
  return vec2(1.0 - v, v);
}
// Both numbers are drawn for every point, as the CPU draws them (Fractorium only for points outside).
vec3 V_dc_triangle(vec3 p, float w, int P, int A) {
  float xx = flameData[A], xy = flameData[A + 1], yx = -flameData[A + 3], yy = -flameData[A + 4];
  float cx = flameData[A + 5], cy = flameData[A + 7];
  float spread = clamp(P_(P, 0), -1.0, 1.0);
  bool zeroEdges = fractoriumInteger(P_(P, 1), 0.0, 1.0) != 0.0;
  float dot00 = xx * xx + xy * xy, dot01 = xx * yx + xy * yy, dot11 = yx * yx + yy * yy;
  float denom = fractoriumZeps(dot00 * dot11 - dot01 * dot01);
  float ru = psi(), rv = psi();
  float px = p.x - cx, py = p.y - cy;
  float dot02 = xx * px + xy * py, dot12 = yx * px + yy * py;
  vec2 uv = vec2((dot11 * dot02 - dot01 * dot12) / denom, (dot00 * dot12 - dot01 * dot02) / denom);
  bool inside = false;
  float f = 1.0;
  if (uv.x + uv.y > 1.0) {
    f = -1.0;
    uv = dcol_ontoEdge(uv);
  } else if (uv.x < 0.0 || uv.y < 0.0) {
    uv = clamp(uv, 0.0, 1.0);
  } else {
    inside = true;
  }
  if (!inside) {
    if (zeroEdges) {
      uv = vec2(0.0);
    } else {
      uv = clamp(uv + vec2(ru, rv) * spread * f, -1.0, 1.0);
      if (uv.x + uv.y > 1.0 && spread > 0.0) uv = dcol_ontoEdge(uv);
    }
  }
  gColour = fmodc(abs(uv.x + uv.y), 1.0);
  return vec3(w * (cx + uv.x * xx + uv.y * yx), w * (cy + uv.x * xy + uv.y * yy), w * p.z);
}
vec3 V_dc_ztransl(vec3 p, float w, int P, int A) {
  float a = clamp(P_(P, 0), 0.0, 1.0), b = clamp(P_(P, 1), 0.0, 1.0);
  float low = min(a, b), span = fractoriumZeps(max(a, b) - low);
  float factor = P_(P, 2);
  bool overwrite = fractoriumInteger(P_(P, 3), 0.0, 1.0) != 0.0;
  bool clampIt = fractoriumInteger(P_(P, 4), 0.0, 1.0) != 0.0;
  float zf = factor * (gColour - low) / span;
  if (clampIt) zf = clamp(zf, 0.0, 1.0);
  return vec3(w * p.x, w * p.y, overwrite ? w * zf : w * p.z * zf);
}
// Java's (int) of a double: truncated, saturating, NaN as 0.
int dcol_javaInt(double v) {
  if (isnan(v)) return 0;
  if (v >= 2147483647.0lf) return 2147483647;
  if (v <= -2147483648.0lf) return -2147483647 - 1;
  return int(v);
}
// Bob Jenkins' 32-bit integer hash as Fractorium has it, over INT_MAX (the int arithmetic wrapping,
// its right shifts keeping the sign).
float dcol_jenkinsHash(int a) {
  a = (a ^ 61) ^ (a >> 16);
  a = int(uint(a) + uint(a) * 8u);
  a = a ^ (a >> 4);
  a = int(uint(a) * 0x27d4eb2du);
  a = a ^ (a >> 15);
  return float(a) / 2147483647.0;
}
// No weight, as Fractorium has it. The block numbers are whole; their products with the seed go
// through double, where they are exact, before Java's int.
vec3 V_randCubes(vec3 p, float w, int P, int A) {
  float size = P_(P, 0), height = P_(P, 1), spread = P_(P, 2), density = P_(P, 4);
  double seed = double(fractoriumInteger(P_(P, 3), -1e6, 1e6));
  float lx = log(1.0 - psi());  // 1 − Ψ is in (0, 1]
  float bx = floor(lx * (psi() < 0.5 ? spread : -spread));
  float ly = log(1.0 - psi());
  float by = floor(ly * (psi() < 0.5 ? spread : -spread));
  float h = dcol_jenkinsHash(dcol_javaInt(double(bx) * seed))
            + dcol_jenkinsHash(dcol_javaInt(double(bx) + double(by) * seed));
  float ux = psi(), uy = psi(), uz = psi();
  gColour = h / 2.0;
  return vec3((bx * density + ux) * size, (by * density + uy) * size, height * h * pow(uz, 0.125));
}
// Fractorium's Powq4c: |v|^e with v's sign (0 counts as +), v itself for e = 1.
float dcol_powq4c(float v, float e) { return e == 1.0 ? v : pow(abs(v), e) * (v < 0.0 ? -1.0 : 1.0); }
// Fractorium's Spread: |(a, b)| with a's sign (+ only for a > 0).
float dcol_spread(float a, float b) { return sqrt(a * a + b * b) * (a > 0.0 ? 1.0 : -1.0); }
vec3 V_curl_sp(vec3 p, float w, int P, int A) {
  float e = fractoriumZeps(P_(P, 0)), inverseE = 1.0 / e;
  float c1 = P_(P, 1), c2 = P_(P, 2), sx = P_(P, 3), sy = P_(P, 4), dcAdjust = 0.1 * P_(P, 5);
  float px = dcol_powq4c(p.x, e), py = dcol_powq4c(p.y, e), pz = dcol_powq4c(p.z, e);
  float d = px * px - py * py;
  float re = dcol_spread(c1 * px + c2 * d, sx) + 1.0;
  float im = dcol_spread(c1 * py + 2.0 * c2 * px * py, sy);
  float c = fractoriumZeps(dcol_powq4c(re * re + im * im, inverseE));
  float r = w / c;
  gColour = clamp(gColour + dcAdjust * c, 0.0, 1.0);
  return vec3((px * re + py * im) * r, (py * re - px * im) * r, pz * w / c);
}
// The chaos step discards the terms summed before it (VariationInfo::replaces), as for hypershift2.
vec3 V_concentric(vec3 p, float w, int P, int A) {
  float radius = P_(P, 0), density = P_(P, 1), rBlur = P_(P, 2), zBlur = P_(P, 3);
  float level = floor(psi() * density) * (1.0 / fractoriumZeps(density));
  float angle = psi() * kTwoPi;
  float ring = level * radius;
  if (rBlur != 0.0) ring += (sqrt(psi()) * 2.0 - 1.0) * rBlur;
  float zb = zBlur != 0.0 ? (psi() * 2.0 - 1.0) * zBlur : 0.0;
  return vec3(ring * cos(angle) * w, ring * sin(angle) * w, (zb - level) * w);
}
vec3 V_hypershift2(vec3 p, float w, int P, int A) {
  float pp_ = max(P_(P, 0), 2.0), qq = max(P_(P, 1), 2.0);
  float pq = kPi / qq, pp = kPi / pp_, spq = sin(pq), spp = sin(pp);
  float shift = sin(kPi * 0.5 - pq - pp) / sqrt(1.0 - spq * spq - spp * spp);
  float lifted = sin(kPi / 2.0 + pp);
  float scale2 = 1.0 / sqrt(lifted * lifted / (spq * spq) - 1.0) * (lifted / spq - 1.0);
  float scale = 1.0 - shift * shift;
  vec2 f = p.xy * scale2;
  float rad = 1.0 / fractoriumZeps(dot(f, f));
  vec2 s = vec2(rad * f.x + shift, rad * f.y);
  rad = w * scale / fractoriumZeps(dot(s, s));
  float angle = (floor(psi() * pp_) * 2.0 + 1.0) * kPi / pp_;
  float X = rad * s.x + shift, Y = rad * s.y;
  float c = cos(angle), sn = sin(angle);
  return vec3(c * X - sn * Y, sn * X + c * Y, p.z * rad);
}
// An ordinary term's: nothing added to x and y, z (which replaces the sum's) max(w, 0) with the chance
// root_face, else w Ψ. (The CPU's pre_/post_ form keeps x and y instead.)
vec3 V_extrude(vec3 p, float w, int P, int A) {
  float u1 = psi(), u2 = psi();
  float keep = gStage == 1 ? 0.0 : 1.0;  // a pre_ or post_ term keeps x and y
  return vec3(keep * p.xy, u1 < P_(P, 0) ? max(w, 0.0) : w * u2);
}
// ---- those that read the sum before them (variations_3d_sum.cpp, variations_direct_colour.cpp) -------
// Each returns the new sum: gSum plus what its kernel adds, or with what it rewrites rewritten. A pre_
// or post_ term (gStage ≠ 1) reads its own point where an ordinary one reads the sum.
// cubic3D's and cubicLattice_3D's spread: xpand/2, or √xpand/2 beyond ±1.
float sum3_latticeFill(float xpand) { return abs(xpand) <= 1.0 ? xpand * 0.5 : sqrt(xpand) * 0.5; }
// One of the cube's eight corners picked by ⌊8Ψ⌋ in Fractorium's order (the CPU's cubeCorner).
vec3 sum3_cubeCorner(float u) {
  float node = floor(u * 8.0);
  float half_ = node - 4.0 * floor(node / 4.0);
  return vec3(node < 4.0 ? 1.0 : -1.0, half_ == 1.0 || half_ == 3.0 ? -1.0 : 1.0, half_ >= 2.0 ? -1.0 : 1.0);
}
vec3 V_cubic3D(vec3 p, float w, int P, int A) {
  float fill = sum3_latticeFill(P_(P, 0)), style = P_(P, 1);
  float smooth_ = abs(w) <= 0.5 ? w * 2.0 : 1.0;
  float smoothStyle =
      abs(style) <= 1.0 ? style : (style > 1.0 ? 1.0 + (style - 1.0) * 0.25 : (style + 1.0) * 0.25 - 1.0);
  float smoothFill = smooth_ * fill, smoothRest = smooth_ * (1.0 - fill), half_ = w * 0.5;
  vec3 k = sum3_cubeCorner(psi());
  float ex = 1.0 - smoothStyle * (1.0 - cos(atan2c(p.x, p.z)));
  float ey = 1.0 - smoothStyle * (1.0 - sin(atan2c(p.y, p.z)));
  float mean = smoothStyle > 1.0 ? (ex + ey) / 2.0 * smoothStyle : (ex + ey) * 0.5;
  vec3 e = vec3(ex, ey, 1.0 - smoothStyle * (1.0 - mean));
  vec3 s = gStage == 1 ? gSum : p;
  return gSum + s - smoothRest * s * e + p * smoothFill * e + k * half_;
}
vec3 V_cubicLattice_3D(vec3 p, float w, int P, int A) {
  float fill = sum3_latticeFill(P_(P, 0));
  bool shaped = fractoriumInteger(P_(P, 1), 1.0, 2.0) == 2.0;
  vec3 k = sum3_cubeCorner(psi());
  vec3 e = vec3(1.0);
  if (shaped) {
    e.x = cos(atan2c(p.x, p.z));
    e.y = sin(atan2c(p.y, p.z));
    e.z = (e.x + e.y) * 0.5;
  }
  vec3 s = gStage == 1 ? gSum : p;
  return gSum + (s + p) * fill * e + k * w;
}
// sin(tan v) in double: tan(c y) is huge near its poles, where float's tan and sin lose every digit.
double sum3_sinTan(double v) {
  double t = dsin(v) / dsin(v + 1.5707963267948966lf);
  return dsin(t);
}
vec3 V_popcorn2_3D(vec3 p, float w, int P, int A) {
  float px = P_(P, 0), py = P_(P, 1), pz = P_(P, 2);
  double c = double(P_(P, 3));
  float sinTanC = float(sum3_sinTan(c)), half_ = w * 0.5, v = abs(w) <= 1.0 ? abs(w) * w : w;
  float lift = v * sinTanC * atan2c(p.y, p.x);
  float t = p.z == 0.0 ? lift : p.z;
  float other = gStage == 1 ? gSum.z : p.z;
  return gSum + vec3(half_ * (p.x + px * float(sum3_sinTan(c * double(p.y)))),
                     half_ * (p.y + py * float(sum3_sinTan(c * double(p.x)))),
                     (other == 0.0 ? lift : 0.0) + v * (pz * sinTanC * t));
}
vec3 V_roundspher3D(vec3 p, float w, int P, int A) {
  const float kTwoOverPi = 2.0 / kPi;
  float r2 = p.x * p.x + p.y * p.y, cosR = cos(sqrt(r2));
  float t = p.z == 0.0 ? cosR : p.z;
  float other = gStage == 1 ? gSum.z : p.z;
  float keep = other == 0.0 ? cosR : other;
  float d = r2 + t * t, e = 1.0 / d + kTwoOverPi * kTwoOverPi;
  // An ordinary term replaces the sum's z (by keep, which is that z where it is not 0).
  return vec3(gSum.xy + w * (w / d * p.xy / e), (gStage == 1 ? 0.0 : gSum.z) + keep + w * (w / d * t / e));
}
// Fractorium's HitsRect(top-left, bottom-right, q), and whether q lies strictly inside the triangle
// (a, b, c) by its barycentric coordinates, as octapol's CPU kernel has them.
bool sum3_inRect(vec2 tl, vec2 br, vec2 q) { return q.x >= tl.x && q.y >= tl.y && q.x <= br.x && q.y <= br.y; }
bool sum3_inTriangle(vec2 a, vec2 b, vec2 c, vec2 q) {
  vec2 v0 = c - a, v1 = b - a, v2 = q - a;
  float d00 = dot(v0, v0), d01 = dot(v0, v1), d02 = dot(v0, v2), d11 = dot(v1, v1), d12 = dot(v1, v2);
  float denom = d00 * d11 - d01 * d01;
  if (denom == 0.0) return false;
  float u = (d11 * d02 - d01 * d12) / denom, v = (d00 * d12 - d01 * d02) / denom;
  return u + v < 1.0 && u > 0.0 && v > 0.0;
}
vec3 V_octapol(vec3 p, float w, int P, int A) {
  float polarWeight = P_(P, 0), s = abs(P_(P, 2)), t = abs(P_(P, 3)), h = 0.5 * s;
  float st = h + t, radius = 0.707106781 * s * abs(P_(P, 1));
  vec2 a = vec2(-h, h + t), b = vec2(h, h + t), c = vec2(t, h), d = vec2(t, -h), e = vec2(h, -h - t);
  vec2 f = vec2(-h, -h - t), g = vec2(-t, -h), hh = vec2(-t, h), i = vec2(-h, h), j = vec2(h, h);
  vec2 k = vec2(-h, -h), l = vec2(h, -h);
  vec2 q = p.xy * 0.15, add = vec2(0.0);
  bool clear = false;
  float r = length(q);
  if (radius > 0.0 && r <= radius) {
    // A polar weight of 0 leaves the point as it is, even at the origin (where ln 0 would make 0/0).
    float rd = polarWeight == 0.0 ? 0.0 : log((r / radius) * (r / radius)) * polarWeight;
    float phi = atan2c(q.y, q.x);
    add = w * (q + (vec2(phi, r) - q) * rd);
  } else if (abs(q.x) <= st && abs(q.y) <= st) {
    bool hit = sum3_inRect(hh, k, q) || sum3_inRect(j, d, q) || sum3_inRect(a, j, q) || sum3_inRect(k, e, q) ||
               sum3_inTriangle(i, a, hh, q) || sum3_inTriangle(j, b, c, q) || sum3_inTriangle(l, d, e, q) ||
               sum3_inTriangle(k, f, g, q);
    add = hit ? w * q : vec2(0.0);
    clear = !hit;
  } else {
    clear = true;
  }
  vec2 before = clear && gStage == 1 ? vec2(0.0) : gSum.xy;
  return vec3(before + add + w * q, gSum.z + w * p.z);
}
// Fractorium's 1 / scale with a zero scale taken as 1e-5.
float sum3_inverseScale(float scale) { return 1.0 / (scale == 0.0 ? 1e-5 : scale); }
// The colour of dc_bubble, dc_cylinder and dc_linear is taken at the new sum; a pre_ or post_ term's
// (whose sum starts at 0 on the CPU) at its input point plus its result.
vec2 sum3_colourAt(vec3 sum, vec3 p) { return sum.xy + (gStage == 1 ? vec2(0.0) : p.xy); }
vec3 V_dc_bubble(vec3 p, float w, int P, int A) {
  float cx = P_(P, 0), cy = P_(P, 1), inv = sum3_inverseScale(P_(P, 2));
  float r2 = p.x * p.x + p.y * p.y;
  float s = w / fractoriumZeps(r2 / 4.0 + 1.0);
  vec3 sum = gSum + vec3(s * p.xy, w * (2.0 / s - 1.0));
  vec2 at = sum3_colourAt(sum, p) + vec2(cx, cy);
  gColour = fmodc(abs(inv * dot(at, at)), 1.0);
  return sum;
}
// dc_linear's and dc_cylinder's colour: the position along the direction `angle`.
float sum3_linearColour(vec2 at, int P) {
  float offset = P_(P, 0), angle = P_(P, 1), inv = sum3_inverseScale(P_(P, 2));
  return fmodc(abs(0.5 * (inv * (cos(angle) * at.x + sin(angle) * at.y + offset) + 1.0)), 1.0);
}
vec3 V_dc_cylinder(vec3 p, float w, int P, int A) {
  float sx = P_(P, 3), sy = P_(P, 4), blur = P_(P, 5);
  float turn = psi() * kTwoPi;
  float r = blur * gaussPsi();
  // No weight on y, as Fractorium has it.
  vec3 sum = gSum + vec3(w * sin(p.x + r * sin(turn)) * sx, r + p.y * sy, w * cos(p.x + r * cos(turn)));
  gColour = sum3_linearColour(sum3_colourAt(sum, p), P);
  return sum;
}
vec3 V_dc_linear(vec3 p, float w, int P, int A) {
  vec3 sum = gSum + w * p;
  gColour = sum3_linearColour(sum3_colourAt(sum, p), P);
  return sum;
}
