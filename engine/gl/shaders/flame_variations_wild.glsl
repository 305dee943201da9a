// The variations of core/flame/variations_jwildfire_wild.cpp (JWildfire's mandelbrot, invsquircular, sph3D,
// colorscale_wf, bubble_wf, bwraps2, invpolar, threeply, spligon, lazysensen, disc3 and cpow3_wf) in float, as
// flame_variations.glsl describes, and variations_jwildfire_holdout.cpp's dc_portal, dc_menger and dc_tesla;
// the CPU kernels are the reference and say what each does.

// JWildfire's Tools.FTOI (half away from 0) in double, held in Java's int range.
double wild_javaInt(double v) {
  return clamp(sign(v) * floor(abs(v) + 0.5lf), -2147483648.0lf, 2147483647.0lf);
}
float wild_nan() { return uintBitsToFloat(0x7fc00000u); }
// One uniform in [0, 1) from a hash state, as core::laneUniform advances it.
float wild_uniform(inout uint h) {
  h ^= h << 13;
  h ^= h >> 17;
  h ^= h << 5;
  return float(h >> 8) * (1.0 / 16777216.0);
}

// mandelbrot in double throughout (its parameters in double after its 12 and the memory slot): where a start
// falls and how long its orbit stays decide which starts are kept and how many draws a call makes. The
// lane's memory: the last kept start and its height.
vec3 V_mandelbrot(vec3 p, float w, int P, int A) {
  int M = int(P_(P, 12));
  double iter = min(wild_javaInt(paramDouble(P + 13, 0)), 10000.0lf);
  double xmin = paramDouble(P + 13, 1), xmax = paramDouble(P + 13, 2);
  double ymin = paramDouble(P + 13, 3), ymax = paramDouble(P + 13, 4);
  double invert = wild_javaInt(paramDouble(P + 13, 5)), skin = paramDouble(P + 13, 6);
  double maxPoints = wild_javaInt(paramDouble(P + 13, 9));
  if (maxPoints > 0.0lf && maxPoints < 100.0lf) maxPoints = 100.0lf;
  uint seed = uint(int(wild_javaInt(paramDouble(P + 13, 10))));
  double zRange = paramDouble(P + 13, 11);
  float cx = P_(P, 7), cy = P_(P, 8);
  precise double x0 = gLane[M], y0 = gLane[M + 1], z0 = gLane[M + 2];
  precise double x1 = x0, zx = x0, y1 = y0, zy = y0;
  bool inverted = double(psi()) < invert;
  double steps = inverted ? 0.0lf : iter;
  int k = 0;
  while (k++ < 10 &&
         (inverted ? steps < iter : (steps >= iter || (skin < 1.0lf && steps < 0.1lf * iter * (1.0lf - skin))))) {
    if (x0 == 0.0lf && y0 == 0.0lf) {
      if (maxPoints > 0.0lf) {
        double pick = min(floor(double(psi()) * maxPoints), maxPoints - 1.0lf);
        uint h = seed * 0x9E3779B1u ^ (uint(pick) + 1u) * 0x85EBCA77u;
        h ^= h >> 16;
        h *= 0x7FEB352Du;
        h ^= h >> 15;
        h *= 0x846CA68Bu;
        h ^= h >> 16;
        if (h == 0u) h = 0x6D2B79F5u;
        double u = double(wild_uniform(h)), v = double(wild_uniform(h)), t = double(wild_uniform(h));
        x0 = (xmax - xmin) * u + xmin;
        y0 = (ymax - ymin) * v + ymin;
        z0 = t * zRange;
      } else {
        x0 = (xmax - xmin) * double(psi()) + xmin;
        y0 = (ymax - ymin) * double(psi()) + ymin;
        z0 = double(psi()) * zRange;
      }
    } else {
      x0 = (skin + 0.001lf) * (double(psi()) - 0.5lf) + x0;
      y0 = (skin + 0.001lf) * (double(psi()) - 0.5lf) + y0;
    }
    x1 = x0;
    zx = x0;
    y1 = y0;
    zy = y0;
    steps = 0.0lf;
    for (;;) {
      precise double size = zx * zx + zy * zy;
      if (!(size < 4.0lf && steps < iter)) break;
      precise double next = zx * zx - zy * zy + x0;
      zy = 2.0lf * zx * zy + y0;
      zx = next;
      steps += 1.0lf;
    }
    if (steps >= iter || skin == 1.0lf || steps < 0.1lf * (iter * (1.0lf - skin))) {
      x0 = 0.0lf;
      y0 = 0.0lf;
    }
  }
  if (k >= 10) {
    x1 = 50000.0lf - double(psi()) * 100000.0lf;
    y1 = x1;
  }
  gLane[M] = x0;
  gLane[M + 1] = y0;
  gLane[M + 2] = z0;
  return vec3(w * (float(x1) + cx * float(zx)), w * (float(y1) + cy * float(zy)), float(z0));
}

vec3 V_invsquircular(vec3 p, float w, int P, int A) {
  vec2 q = vec2(0.0);
  if (w != 0.0) {
    float u = p.x, v = p.y;
    float r = u * u + v * v;
    float r2 = sqrt(r * (w * w * r - 4.0 * u * u * v * v) / w);
    float rho = sqrt(r - r2) / 1.4142135623730951;
    q = vec2(rho / u, rho / v);
  }
  if (isnan(q.x) || isinf(q.x) || isnan(q.y) || isinf(q.y)) return vec3(wild_nan());
  return vec3(q, w * p.z);
}

vec3 V_sph3D(vec3 p, float w, int P, int A) {
  float px = P_(P, 0), py = P_(P, 1);
  vec3 s = vec3(px * p.x, py * p.y, px * p.z);
  return p * (w / (dot(s, s) + 1e-29));
}

// Reads the sum before it (gSum) and returns the new one.
vec3 V_colorscale_wf(vec3 p, float w, int P, int A) {
  float draw = psi();
  float dz = gColour * P_(P, 2) * w + P_(P, 3);
  vec3 s = gSum;
  s.x += w * P_(P, 0) * p.x;
  s.y += w * P_(P, 1) * p.y;
  s.z = P_(P, 4) > 0.0 ? dz : s.z + (P_(P, 5) > 0.0 ? dz * draw : dz);
  return s;
}

vec3 V_bubble_wf(vec3 p, float w, int P, int A) {
  float r = (p.x * p.x + p.y * p.y) / 4.0 + 1.0;
  float side = psi() < 0.5 ? -1.0 : 1.0;
  return vec3(p.xy * (w / r), side * (w * (2.0 / r - 1.0)));
}

vec3 V_bwraps2(vec3 p, float w, int P, int A) {
  float cellsize = P_(P, 0), space = P_(P, 1), gain = P_(P, 2), innerTwist = P_(P, 3), outerTwist = P_(P, 4);
  float radius = 0.5 * (cellsize / (1.0 + space * space));
  float g2 = gain * gain / cellsize + 1e-6;
  float maxBubble = g2 * radius;
  maxBubble = maxBubble > 2.0 ? 1.0 : maxBubble * (1.0 / (maxBubble * maxBubble / 4.0 + 1.0));
  float r2 = radius * radius, rfactor = radius / maxBubble;
  vec2 q = p.xy;
  if (cellsize != 0.0) {  // float holds no |cellsize| below the CPU's 1e-300 but 0
    vec2 centre = (floor(p.xy / cellsize) + 0.5) * cellsize;
    vec2 l = p.xy - centre;
    if (!(dot(l, l) > r2)) {
      l *= g2;
      l *= rfactor / (dot(l, l) / 4.0 + 1.0);
      float t = r2 > 0.0 ? dot(l, l) / r2 : 0.0;
      float theta = innerTwist * (1.0 - t) + outerTwist * t;
      float s = sin(theta), c = cos(theta);
      q = vec2(centre.x + c * l.x + s * l.y, centre.y - s * l.x + c * l.y);
    }
  }
  return w * vec3(q, p.z);
}

vec3 V_invpolar(vec3 p, float w, int P, int A) {
  float ny = 1.0 + p.y;
  return vec3(w * ny * sin(p.x * kPi), w * ny * cos(p.x * kPi), w * p.z);
}

// A point of the orbit's table (after its 3 parameters), Ψ picking which, as on the CPU.
vec3 V_threeply(vec3 p, float w, int P, int A) {
  int count = tableSize(P, 3) / 2;
  return vec3(0.001 * tablePoint(P, 3, tableIndex(psi(), count)) * w, w * p.z);
}

vec3 V_spligon(vec3 p, float w, int P, int A) {
  float sides = roundHalfAway(P_(P, 0)) == 0.0 ? 1.0 : P_(P, 0), r = P_(P, 1);
  float th = sides / kTwoPi, thi = 1.0 / th;
  float j = kPi * P_(P, 2) / (-2.0 * sides);
  float t = thi * floor(atan2c(p.y, p.x) * th) + j;
  return vec3(w * (p.x + cos(t) * r), w * (p.y + sin(t) * r), w * p.z);
}

float wild_lazysensenFlip(float v, float s) {
  if (s == 0.0) return v;
  float m = floor(v * s);
  if (isnan(m)) return v;
  m = clamp(m, -2147483648.0, 2147483647.0);
  float odd = m - 2.0 * trunc(m / 2.0);  // Java's %: the sign of m
  return (m >= 0.0 ? odd == 1.0 : odd == 0.0) ? -v : v;
}
vec3 V_lazysensen(vec3 p, float w, int P, int A) {
  return w * vec3(wild_lazysensenFlip(p.x, P_(P, 0)), wild_lazysensenFlip(p.y, P_(P, 1)),
                  wild_lazysensenFlip(p.z, P_(P, 2)));
}

vec3 V_disc3(vec3 p, float w, int P, int A) {
  float rho = kPi * sqrt(p.x * P_(P, 3) * p.x * P_(P, 4) + p.y * P_(P, 5) * p.y * P_(P, 6));
  float r = w * atan2c(p.x, p.y) / kPi * P_(P, 2);
  return vec3(sin(rho) * P_(P, 0) * P_(P, 7) * r, cos(rho) * P_(P, 1) * P_(P, 7) * r, w * p.z);
}

vec3 V_cpow3_wf(vec3 p, float w, int P, int A) {
  float divisor = P_(P, 2), spread = P_(P, 3), spread2 = P_(P, 5), offset2 = P_(P, 6);
  float ang = kTwoPi / divisor;
  float c = P_(P, 0) * cos(kPi / 2.0 * P_(P, 1)) / divisor, d = P_(P, 0) * sin(kPi / 2.0 * P_(P, 1)) / divisor;
  float a = atan2c(p.y, p.x);
  float turns = psi() * spread;
  if (P_(P, 4) >= 1.0) turns = trunc(turns);
  if (a < 0.0) turns += 1.0;
  a += kTwoPi * turns;
  if (cos(a * (0.5 / spread)) < psi() * 2.0 - 1.0) a -= kTwoPi * spread;
  float lnr2 = log(p.x * p.x + p.y * p.y);
  float r = w * exp(c / 2.0 * lnr2 - d * a);
  float alpha = c * a * (d / 2.0) * lnr2 * ang * (psi() * spread2 + offset2);
  return vec3(r * cos(alpha), r * sin(alpha), w * p.z);
}

// dc_portal in double (time, waves and zoom too, after its 9 parameters, the memory slot and the palette's
// place): the sine's argument is some thousand radians, where a float's rounding moves the colour.
vec3 V_dc_portal(vec3 p, float w, int P, int A) {
  const int D = P + 11;
  double t = 1000.0lf + paramDouble(D, 1), waves = paramDouble(D, 2), zoom = paramDouble(D, 3);
  dvec2 q = rgb_dcPoint(p, P, 4, 0.5lf);
  precise double ux = q.x * zoom, uy = q.y * zoom;
  precise double d = 1.0lf + sqrt(sqrt(ux * ux + uy * uy)) / waves;
  precise double c = dsin(d * t + t * 0.125lf * dcos(ux) * dcos(uy)) * 3.0lf;
  double a = abs(c);
  dvec3 colour = c > 0.0lf ? dvec3(a - 1.0lf, a - 1.5lf, a - 2.0lf) : dvec3(a - 1.5lf);
  return rgb_dcFinish(p, w, P, 4, 9, q, colour);
}

// dc_menger: the carpet's cells in double, as the CPU's (a point on a cell's edge is either colour).
vec3 V_dc_menger(vec3 p, float w, int P, int A) {
  double zoom = double(P_(P, 0)), level = double(rgb_limitedInt(P_(P, 1), 1.0, 5.0));
  dvec2 q = rgb_dcPoint(p, P, 2, 0.5lf);
  precise double qx = q.x * zoom * 1.3lf, qy = q.y * zoom * 1.3lf;
  precise double bx = abs(qx) - 1.0lf, by = abs(qy) - 1.0lf;
  precise double ox = max(bx, 0.0lf), oy = max(by, 0.0lf);
  precise double d = sqrt(ox * ox + oy * oy) + min(max(bx, by), 0.0lf);
  double s = 1.0lf;
  for (double k = 0.0lf; k < level; k += 1.0lf) {
    precise double ax = qx * s - 2.0lf * floor(qx * s / 2.0lf) - 1.0lf;
    precise double ay = qy * s - 2.0lf * floor(qy * s / 2.0lf) - 1.0lf;
    precise double rx = 1.0lf - abs(ax) * 3.0lf, ry = 1.0lf - abs(ay) * 3.0lf;
    s *= 3.0lf;
    d = max(d, (min(abs(rx), abs(ry)) - 1.0lf) / s);
  }
  double c = d > 0.0lf ? 0.0lf : 1.0lf;
  return rgb_dcFinish(p, w, P, 2, 7, q, dvec3(c));
}

// e^v in double for |v| ≤ 1 (its Taylor series), dc_tesla's ½^|sin(time/8)|.
double wild_dexpSmall(double v) {
  precise double term = 1.0lf, sum = 1.0lf;
  for (int k = 1; k < 24; ++k) {
    term *= v / double(k);
    sum += term;
  }
  return sum;
}
// dc_tesla: the orbit in double (it is chaotic: a float's rounding moves its colour), with time, style and
// zoom in double (after its 10 parameters, the memory slot and the palette's place); each step's weight in
// float.
vec3 V_dc_tesla(vec3 p, float w, int P, int A) {
  const int D = P + 12;
  double levels = double(rgb_limitedInt(P_(P, 0), 1.0, 25.0));
  double style = isnan(paramDouble(D, 1)) ? paramDouble(D, 1) : clamp(paramDouble(D, 1), 5.0lf, 100.0lf);
  double time = paramDouble(D, 3), zoom = paramDouble(D, 4);
  precise double wave = 4500.0lf * dsin(time * 10.0lf);
  float strength = float(20.0lf + 0.03lf * rgb_dlog(1e-6lf + (wave - floor(wave))));
  double shrink = wild_dexpSmall(-abs(dsin(time / 8.0lf)) * 0.69314718055994531lf);
  double lift = -0.23456lf * abs(dsin(time));
  dvec2 q = rgb_dcPoint(p, P, 5, 0.5lf);
  precise double vx = q.x * zoom, vy = q.y * zoom, vz = 1.0lf, previous = 0.0lf;
  float accum = 1.5, tw = 0.0;
  for (double k = 0.0lf; k < levels; k += 1.0lf) {
    precise double mag = (vx * vx + vy * vy + vz * vz) * shrink;
    vx = abs(vx) / mag - 0.9lf;
    vy = abs(vy) / mag + lift;
    vz = abs(vz) / mag - 1.0lf;
    float weight = exp(float(-k / style));
    // The first step's ratio is infinite on the CPU (m' = 0, m > 0): its term is 0.
    if (previous != 0.0lf) accum += weight * exp(-strength * pow(abs(float(mag / previous)), 1.2));
    tw += weight * weight;
    previous = mag;
  }
  double grey = double(max(0.0, 6.0 * accum / tw - 2.0));
  return rgb_dcFinish(p, w, P, 5, 10, q, dvec3(grey));
}

// variations_jwildfire_rare.cpp's polarplot3d_wf, sunflower, dc_warping and isosfplot3d_wf.

// A range as JWildfire's init takes it, (min, max − min), the bounds swapped where min > max.
vec2 rare_range(float a, float b) { return a > b ? vec2(b, a - b) : vec2(a, b - a); }
// polarplot3d_wf: r from the kernel's parplot surface `which` (after its 19 parameters; −1, a formula
// that does not compile or none, adds nothing), the surface's x being r(t, u); drawn in spherical or
// cylindrical coordinates, the colour as the CPU's polarplot3dWf.
vec3 V_polarplot3d_wf(vec3 p, float w, int P, int A) {
  int which = int(P_(P, 19));
  if (which < 0) return vec3(0.0);
  vec2 t = rare_range(P_(P, 1), P_(P, 2)), u = rare_range(P_(P, 3), P_(P, 4)), r = rare_range(P_(P, 5), P_(P, 6));
  bool spherical = roundHalfAway(P_(P, 7)) == 0.0;
  float mode = roundHalfAway(P_(P, 9));
  bool setsColour = roundHalfAway(P_(P, 8)) > 0.0 && mode >= 1.0 && mode <= 4.0;
  float ti = t.x + psi() * t.y;
  float ui = u.x + psi() * u.y;
  float ri = parplotSurface(which, ti, ui, P + 13).x;
  if (setsColour) {
    float ct = (ti - t.x) / t.y, cu = (ui - u.x) / u.y;
    float c = mode == 1.0 ? ct : mode == 2.0 ? cu : mode == 3.0 ? (ri - r.x) / r.y : ct * cu;
    gColour = isnan(c) ? 0.0 : clamp(c, 0.0, 1.0);
  }
  if (spherical) return w * ri * vec3(sin(ui) * cos(ti), sin(ui) * sin(ti), cos(ui));
  return w * vec3(ri * cos(ti), ri * sin(ti), ui);
}

// sunflower: seed k (Ψ) at ρ (cos θ, sin θ), θ in double (k · angle (3 − √5) degrees reach thousands of
// radians), drawn as an nBlur polygon of `shape` sides with a hole of fill, scaled by scale · s.
vec3 V_sunflower(vec3 p, float w, int P, int A) {
  float count = rgb_limitedInt(P_(P, 0), 10.0, 1000.0), sides = rgb_limitedInt(P_(P, 1), 3.0, 20.0);
  float scale = isnan(P_(P, 2)) ? P_(P, 2) : clamp(P_(P, 2), 0.0, 100.0);
  double angle = isnan(P_(P, 3)) ? double(P_(P, 3)) : clamp(double(P_(P, 3)), 0.0lf, 360.0lf);
  float fill = isnan(P_(P, 5)) ? P_(P, 5) : clamp(P_(P, 5), 0.0, 1.0);
  bool invert = rgb_limitedInt(P_(P, 6), 0.0, 1.0) == 1.0;
  // Ψ · count in double, as on the CPU (a float product may round up to the next seed).
  float k = float(min(floor(double(psi()) * double(count)), double(count) - 1.0lf)) + 1.0;
  float rho = sqrt(k) / 30.0 / (sqrt(count + 1.0) / 30.0);
  dvec2 sc = dsinCos(double(k) * (angle * (3.0lf - 2.2360679774997898lf)) * 3.14159265358979323846lf / 180.0lf);
  float s = invert ? rho : 1.0 - rho;
  // The polygon: nBlur's sector, its spread inside one, the edge and the radius (DrawFunc's).
  float sector = kTwoPi / sides, edgeTan = tan(kPi / 2.0 + sector / 2.0);
  float spread = 13.0 / pow(sides, 1.3), spreadNorm = 2.0 * atan(spread / -2.0);
  float along = psi();
  float edge = float(uint(floor(double(psi()) * 32767.0lf)) % uint(sides));
  float a = (atan(spread * (along - 0.5)) / spreadNorm + 0.5 + edge) * sector;
  vec2 q = vec2(sin(a), cos(a));
  for (int j = 0; j < 20 && a > sector; ++j) a -= sector;
  float tangent = tan(a);
  float ex = edgeTan / (edgeTan - tangent), ey = ex * tangent;
  float outer = sqrt(ex * ex + ey * ey), inner = fill * outer;
  q *= inner + sqrt(psi()) * (outer - inner);
  q = vec2(cos(sector / 2.0) * q.x - sin(sector / 2.0) * q.y, sin(sector / 2.0) * q.x + cos(sector / 2.0) * q.y);
  gColour = s;
  float size = scale * s;
  return vec3(w * (q.x * size + rho * float(sc.y)), w * (q.y * size + rho * float(sc.x)), w * p.z);
}

// dc_warping in double throughout, its zoom and shifts too (after its 9 parameters, the memory slot and the
// palette's place): its hash keeps the fraction of 43758.5 sin(·), and the warps feed the noise back into the
// places the hash reads, so a float's rounding anywhere changes the colour.
double rare_fract(double v) { return v - floor(v); }
double rare_mix(double a, double b, double t) { return a * (1.0lf - t) + b * t; }
double rare_smoothstep(double e0, double e1, double v) {
  double t = clamp((v - e0) / (e1 - e0), 0.0lf, 1.0lf);
  return t * t * (3.0lf - 2.0lf * t);
}
double rare_warpHash(double x, double y) {
  return -1.0lf + 2.0lf * rare_fract(dsin(x * 127.1lf + y * 311.7lf) * 43758.5453123lf);
}
double rare_warpNoise(dvec2 p) {
  dvec2 i = floor(p);
  precise dvec2 f = p - i;
  precise dvec2 u = f * f * f;  // JWildfire's CPU code: (3 − 2) f where the shader has 3 − 2f
  return rare_mix(rare_mix(rare_warpHash(i.x, i.y), rare_warpHash(i.x + 1.0lf, i.y), u.x),
                  rare_mix(rare_warpHash(i.x, i.y + 1.0lf), rare_warpHash(i.x + 1.0lf, i.y + 1.0lf), u.x), u.y);
}
dvec2 rare_warpTurn(dvec2 p, double scale) {
  precise dvec2 s = p * scale;
  return dvec2(0.8lf * s.x - 0.6lf * s.y, 0.6lf * s.x + 0.8lf * s.y);
}
double rare_warpFbm(dvec2 p) {
  precise double f = 0.5lf * rare_warpNoise(p);
  p = rare_warpTurn(p, 2.02lf);
  f += 0.25lf * rare_warpNoise(p);
  p = rare_warpTurn(p, 2.03lf);
  f += 0.125lf * rare_warpNoise(p);
  p = rare_warpTurn(p, 2.01lf);
  f += 0.0625lf * rare_warpNoise(p);
  return f / 0.9375lf;
}
dvec2 rare_warpFbm2(dvec2 p) { return dvec2(rare_warpFbm(p), rare_warpFbm(p.yx)); }
dvec3 rare_warpMap(dvec2 p) {
  p *= 0.7lf;
  dvec2 inner = rare_warpFbm2(p * 4.0lf);
  dvec2 middle = rare_warpFbm2((p + inner) * 2.0lf);
  dvec2 outer = rare_warpFbm2(p + middle);
  double bl = rare_smoothstep(-0.8lf, 0.8lf, outer.x - outer.y);
  double ti = rare_smoothstep(-1.0lf, 1.0lf, rare_warpFbm(p));
  return dvec3(rare_mix(rare_mix(0.5lf, 1.0lf, ti), 0.0lf, bl), rare_mix(rare_mix(0.0lf, 0.75lf, ti), 0.0lf, bl),
               rare_mix(rare_mix(0.0lf, 0.35lf, ti), 0.02lf, bl));
}
double rare_grey(dvec3 c) { return c.x * 0.333lf + c.y * 0.333lf + c.z * 0.333lf; }
vec3 V_dc_warping(vec3 p, float w, int P, int A) {
  const int D = P + 11;
  double zoom = paramDouble(D, 1), x0 = paramDouble(D, 2), y0 = paramDouble(D, 3);
  dvec2 q = rgb_dcPoint(p, P, 4, 0.5lf);
  const double e = 0.0045lf;
  dvec2 at = dvec2(q.x * zoom + x0, q.y * zoom + y0);
  dvec3 c = rare_warpMap(at);
  double gc = rare_grey(c), ga = rare_grey(rare_warpMap(at + dvec2(e, 0.0lf))),
         gb = rare_grey(rare_warpMap(at + dvec2(0.0lf, e)));
  double nx = ga - gc, nz = gb - gc;
  double ny = e / sqrt(nx * nx + e * e + nz * nz);
  double edge = 8.0lf * abs(2.0lf * gc - ga - gb);
  double lift = 1.0lf + 0.2lf * ny * ny, sheen = 0.05lf * ny * ny * ny;
  double qx = (q.x + 1.0lf) / 2.0lf, qy = (q.y + 1.0lf) / 2.0lf;
  // (A negative base, the point read outside the square, gives NaN as C's pow does.)
  float base = float(16.0lf * qx * qy * (1.0lf - qx) * (1.0lf - qy));
  double vignette = base < 0.0 ? rgb_nan() : double(pow(base, 0.1));
  dvec3 colour = (dvec3(c.x + edge, c.y + 0.7lf * edge, c.z + 0.6lf * edge) * lift + sheen) * vignette;
  return rgb_dcFinish(p, w, P, 4, 9, q, colour);
}

// isosfplot3d_wf: up to max_iter points of the box until |F(x, y, z)| ≤ thickness, F from the kernel's parplot
// surface `which` (after its 18 parameters; −1, a formula that does not compile, adds nothing) with z in
// gParplotThird; with none the point is hidden and nothing is added. The colour as the CPU's isosfplot3dWf.
vec3 V_isosfplot3d_wf(vec3 p, float w, int P, int A) {
  int which = int(P_(P, 18));
  if (which < 0) return vec3(0.0);
  vec2 bx = rare_range(P_(P, 1), P_(P, 2)), by = rare_range(P_(P, 3), P_(P, 4)), bz = rare_range(P_(P, 5), P_(P, 6));
  float thickness = P_(P, 7) < 1e-10 ? 1e-10 : P_(P, 7);
  float iterations = isnan(P_(P, 8)) ? 1.0 : clamp(roundHalfAway(P_(P, 8)), 1.0, 100000.0);
  float mode = roundHalfAway(P_(P, 10));
  bool setsColour = roundHalfAway(P_(P, 9)) > 0.0 && mode >= 3.0;
  vec3 q = vec3(0.0);
  bool found = false;
  for (float k = 0.0; k < iterations && !found; k += 1.0) {
    q.x = bx.x + psi() * bx.y;
    q.y = by.x + psi() * by.y;
    q.z = bz.x + psi() * bz.y;
    gParplotThird = q.z;
    found = abs(parplotSurface(which, q.x, q.y, P + 12).x) <= thickness;
  }
  gHidden = !found;
  if (!found) return vec3(0.0);
  if (setsColour) {
    vec3 c = (q - vec3(bx.x, by.x, bz.x)) / vec3(bx.y, by.y, bz.y);
    float v = mode == 3.0   ? c.x
              : mode == 4.0 ? c.y
              : mode == 5.0 ? c.z
              : mode == 6.0 ? c.x * c.y
              : mode == 7.0 ? c.y * c.z
              : mode == 8.0 ? c.z * c.x
                            : c.x * c.y * c.z;
    gColour = isnan(v) ? 0.0 : clamp(v, 0.0, 1.0);
  }
  return w * q;
}

// sym_bg2, sym_ng11, sym_ng15 (JWildfire's symmetry groups): one of a fixed set of maps, picked by ⌊count Ψ⌋ in
// double as on the CPU; each linear part as (a, b, d, e).
vec3 V_sym_bg2(vec3 p, float w, int P, int A) {
  float stepX = P_(P, 0), stepY = P_(P, 1);
  vec2 q = tableIndex(psi(), 2) == 0 ? vec2(p.x - stepX / 2.0 - 1.0, p.y - stepY / 2.0)
                                     : vec2(p.x + stepX / 2.0, -p.y + stepY / 2.0 + 1.0);
  return w * vec3(q, p.z);
}
vec3 V_sym_ng11(vec3 p, float w, int P, int A) {
  const vec4 linear[8] = vec4[8](vec4(1, 0, 0, 1), vec4(-1, 0, 0, -1), vec4(0, 1, -1, 0), vec4(0, -1, 1, 0),
                                 vec4(-1, 0, 0, 1), vec4(0, -1, -1, 0), vec4(0, 1, 1, 0), vec4(1, 0, 0, -1));
  // The translations' signs: (of spacex, of stepx/2, of spacey, of stepy/2).
  const vec4 signs[8] = vec4[8](vec4(1, 1, 1, 1), vec4(-1, 1, -1, 1), vec4(1, 1, -1, 1), vec4(-1, 1, 1, 1),
                                vec4(-1, -1, 1, -1), vec4(-1, -1, -1, -1), vec4(1, -1, 1, -1), vec4(1, -1, -1, -1));
  float space = P_(P, 0), spaceX = P_(P, 1), spaceY = P_(P, 2), halfX = P_(P, 3) / 2.0, halfY = P_(P, 4) / 2.0;
  int k = tableIndex(psi(), 8);
  vec4 m = linear[k], s = signs[k];
  vec2 q = p.xy + space;
  float c = s.x * spaceX + s.y * halfX, f = s.z * spaceY + s.w * halfY;
  return w * vec3(m.x * q.x + m.y * q.y + c, m.z * q.x + m.w * q.y + f, p.z);
}
vec3 V_sym_ng15(vec3 p, float w, int P, int A) {
  const vec4 linear[6] = vec4[6](vec4(0.0, 1.0, -1.0, 0.0), vec4(0.0, -1.0, -1.0, 0.0), vec4(0.866, -0.5, 0.5, 0.866),
                                 vec4(0.866, 0.5, 0.5, -0.866), vec4(-0.866, -0.5, 0.5, -0.866),
                                 vec4(-0.866, 0.5, 0.5, 0.866));
  float shift = sqrt(P_(P, 0) * P_(P, 0) / 2.0), halfX = P_(P, 1) / 2.0, halfY = P_(P, 2) / 2.0;
  int k = tableIndex(psi(), 12);
  vec4 m = linear[k % 6];
  float s = k < 6 ? -1.0 : 1.0;
  vec2 q = p.xy + shift;
  return w * vec3(m.x * q.x + m.y * q.y + s * halfX, m.z * q.x + m.w * q.y + s * halfY, p.z);
}

// flam3's original secant: y is not scaled by the weight.
vec3 V_secant(vec3 p, float w, int P, int A) {
  float r = w * sqrt(p.x * p.x + p.y * p.y);
  return vec3(w * p.x, 1.0 / cos(r), w * p.z);
}

// julian2dc: julian2, and the colour index from the result's radius and angle.
vec3 V_julian2dc(vec3 p, float w, int P, int A) {
  float powerN = countParam(P_(P, 0)), exponent = P_(P, 1) / powerN * 0.5, rootCount = abs(powerN);
  float col = P_(P, 2);
  float a = P_(P, 3), b = P_(P, 4), c = P_(P, 5), d = P_(P, 6), e = P_(P, 7), f = P_(P, 8);
  float px = a * p.x + b * p.y + e, py = c * p.x + d * p.y + f;
  float root = trunc(rootCount * psi());
  float angle = (atan2c(py, px) + kTwoPi * root) / powerN;
  float r = w * pow(px * px + py * py, exponent);
  gColour = fmodc(abs(r * col + angle / kTwoPi * (1.0 - col)), 1.0);
  return vec3(r * cos(angle), r * sin(angle), w * p.z);
}

// shape (cyberxaos'): a blur filling the superformula's curve along the point's direction.
vec3 V_shape(vec3 p, float w, int P, int A) {
  float quarterM = P_(P, 0) / 4.0, negInvN1 = -1.0 / P_(P, 1), n2 = P_(P, 2), n3 = P_(P, 3);
  float a = P_(P, 4), b = P_(P, 5), holes = P_(P, 6);
  float theta = quarterM * atan2c(p.y, p.x);
  float t1 = pow(abs(cos(theta) / a), n2), t2 = pow(abs(sin(theta) / b), n3);
  float r = sqrt(p.x * p.x + p.y * p.y);
  float scale = w * (psi() - holes) * pow(t1 + t2, negInvN1) / (r + kEpsilon);
  return vec3(scale * p.x, scale * p.y, w * p.z);
}

// glsl_circlesblue: the bubbles in double (their places and colours turn on sines of k and of time up to 1000,
// which float's trig does not hold), as the CPU's.
vec3 V_glsl_circlesblue(vec3 p, float w, int P, int A) {
  const double kHeight = 1000000.0lf;
  float pw = P_(P, 0), pt = P_(P, 2), pr = P_(P, 3), pb = P_(P, 4), pg = P_(P, 5);
  double width = max(isnan(pw) ? 0.0lf : trunc(clamp(double(pw), 100.0lf, 10000000.0lf)), 100.0lf);
  double time = isnan(pt) ? double(pt) : clamp(double(pt), 1.0lf, 1000.0lf);
  double radius = isnan(pr) ? double(pr) : clamp(double(pr), 0.0lf, 1.0lf);
  int count = isnan(pb) ? 0 : int(trunc(clamp(pb, 1.0, 100.0)));
  bool index = !isnan(pg) && trunc(clamp(pg, 0.0, 1.0)) == 1.0;
  double pi = trunc(double(psi()) * width), pj = trunc(double(psi()) * kHeight);
  vec3 o = vec3(w * float(pi / width - 0.5lf), w * float(pj / kHeight - 0.5lf), w * p.z);
  precise double u = 2.0lf * (pi + 0.5lf) / width - 1.0lf, v = 2.0lf * (pj + 0.5lf) / kHeight - 1.0lf;
  precise dvec3 sum = dvec3(0.0lf);
  for (int k = 0; k < count; ++k) {
    double kd = double(k);
    dvec2 sc = dsinCos(kd * 6.0lf + 1.0lf);
    precise double pha = sc.x / sc.y * 0.5lf + 0.5lf;
    precise double base = dcos(kd * 2.4lf + 5.0lf) * 0.5lf + 0.5lf;
    precise double siz = base * base * (base * base);
    double pox = dcos(kd * 3.55lf + 4.1lf);
    precise double rad = radius + dsin(kd) * 0.12lf + 0.08lf;
    precise double rise = pha + 0.1lf * (time / 5.0lf) * (0.2lf + 0.8lf * siz);
    precise double mixA = 0.5lf + 0.5lf * dsin(kd * dsin(time * pox * 0.03lf) + 1.9lf);
    precise double bx = pox + dsin(time / 15.0lf + pha + siz);
    precise double by = -1.0lf - rad + (2.0lf + 2.0lf * rad) * (rise - floor(rise));
    precise double inner = rad * (0.65lf + 0.20lf * dsin(pox * time));
    precise double fade = 1.0lf - dcos(pox * time);
    precise dvec3 col = dvec3(0.1lf, 0.2lf, 0.8lf) * (1.0lf - mixA) + dvec3(0.2lf, 0.8lf, 0.6lf) * mixA;
    precise double dx = u - bx, dy = v - by;
    precise double t = min(max((sqrt(dx * dx + dy * dy) - inner) / (rad - inner), 0.0lf), 1.0lf);
    precise double cover = 1.0lf - t * t * (3.0lf - 2.0lf * t);
    sum += col * cover * fade;
  }
  sum *= 0.3lf;
  if (index) {
    float c = sin(float(sum.x / (sum.x + sum.y + sum.z)));
    if (!isnan(c)) gColour = c;
  } else {
    gRgb = kRgbPainted | uint(rgb_byte(sum.x)) | uint(rgb_byte(sum.y)) << 8 | uint(rgb_byte(sum.z)) << 16;
  }
  return o;
}

// glsl_grid3D: kabuto's ray-marched grid through the pixel, in double (30 steps of a march that folds the ray's
// point by fract three times a step), as the CPU's; it always paints.
vec3 V_glsl_grid3D(vec3 p, float w, int P, int A) {
  const double kHeight = 1000000.0lf;
  float pw = P_(P, 0), pt = P_(P, 2);
  double width = isnan(pw) ? 100.0lf : trunc(clamp(double(pw), 100.0lf, 10000000.0lf));
  double time = isnan(pt) ? double(pt) : clamp(double(pt), 1.0lf, 1000.0lf);
  double pi = trunc(double(psi()) * width), pj = trunc(double(psi()) * kHeight);
  vec3 o = vec3(w * float(pi / width - 0.5lf), w * float(pj / kHeight - 0.5lf), w * p.z);
  precise dvec3 d = dvec3((pi + 0.5lf) / width - 0.5lf, (pj + 0.5lf) / kHeight - 0.5lf, 1.0lf);
  d /= sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  dvec2 sc = dsinCos(time * 0.021lf);
  precise double y1 = d.y * sc.y - d.z * sc.x, z1 = d.y * sc.x + d.z * sc.y;
  precise double x2 = d.x * sc.y - z1 * sc.x, z2 = d.x * sc.x + z1 * sc.y;
  d = dvec3(x2, y1, z2);
  precise dvec3 pos = dvec3(0.0lf, time * 0.1lf, 0.0lf), sum = dvec3(0.0lf);
  for (int step = 0; step < 30; ++step) {
    precise dvec3 q = pos * 0.1lf;
    for (int k = 0; k < 3; ++k) {
      q = q.yzx;
      q = abs(q - floor(q) - 0.5lf) * 2.0lf;
    }
    q *= q;
    precise dvec3 f = sqrt(q + q.yzx) / 0.8lf - 0.05lf;
    pos += d * min(min(f.x, f.y), f.z);
    sum += double(30 - step) / (f + 0.1lf);
  }
  precise dvec3 c = 1.0lf - 1.0lf / (1.0lf + sum * (0.09lf / 900.0lf));
  uint grey = uint(rgb_byte(c.x + c.y + c.z));
  gRgb = kRgbPainted | grey | grey << 8 | grey << 16;
  return o;
}

// glsl_mandala: Sosa's kaleidoscope in double (its up to 73 folds p → |p/(p·p) − c| part float's rounding), with
// JWildfire's approximate G.atan2, as the CPU's.
double wild_glslAtan2(double y, double x) {
  const double c1 = 0.78539816339744831lf, c2 = 3.0lf * c1;
  double ay = abs(y);
  precise double angle = x >= 0.0lf ? c1 - c1 * ((x - ay) / (x + ay)) : c2 - c1 * ((x + ay) / (ay - x));
  return y < 0.0lf ? -angle : angle;
}
dvec2 wild_kscope(dvec2 q, double k) {
  precise double a = wild_glslAtan2(q.y, q.x), m = 2.0lf * k;
  precise double angle = abs(a - m * floor(a / m) - k);
  precise double len = sqrt(q.x * q.x + q.y * q.y);
  dvec2 sc = dsinCos(angle);
  return dvec2(len * sc.y, len * sc.x);
}
vec3 V_glsl_mandala(vec3 p, float w, int P, int A) {
  const double kHeight = 1000000.0lf;
  float pw = P_(P, 0), pg = P_(P, 10);
  double width = isnan(pw) ? 100.0lf : trunc(clamp(double(pw), 100.0lf, 10000000.0lf));
  bool index = !isnan(pg) && trunc(clamp(pg, 0.0, 1.0)) == 1.0;
  double pi = trunc(double(psi()) * width), pj = trunc(double(psi()) * kHeight);
  vec3 o = vec3(w * float(pi / width - 0.5lf), w * float(pj / kHeight - 0.5lf), w * p.z);
  double mX = double(P_(P, 1)), mY = double(P_(P, 2)), zoom = 5.5lf - double(P_(P, 3));
  double k = 3.14159265358979323846lf / floor(double(P_(P, 4)));
  double multiply = double(P_(P, 5)), last = floor(double(P_(P, 6)));
  precise dvec2 s = wild_kscope(dvec2(zoom * (2.0lf * (pi + 0.5lf) / width - 1.0lf),
                                      zoom * (2.0lf * (pj + 0.5lf) / kHeight - 1.0lf)), k);
  precise dvec2 t = wild_kscope(s, k);
  precise double v = t.x * s.x + t.y * s.y;
  double c = dcos(v);
  precise dvec2 u = s * (1.0lf - c) + t * c;
  if (multiply > 0.001lf) {
    double m = floor(multiply);
    precise dvec2 t2 = dvec2(u.y - m * floor(u.y / m), u.x - m * floor(u.x / m));
    precise dvec2 t3 = -u;
    precise dvec2 t5 = dvec2(u.y + (t2.x - t3.x * floor(t2.x / t3.x)), u.x + (t2.y - t3.y * floor(t2.y / t3.y)));
    u = t5.yx;
  }
  precise dvec3 q = dvec3(u, mX * v);
  double shift = mY * 0.318309886183791lf;
  for (int l = 0; l < 73; ++l) {
    if (double(l) > last) break;
    precise double d = q.x * q.x + q.y * q.y + q.z * q.z;
    precise dvec3 a = abs(abs(q) / d - dvec3(1.0lf, 1.02lf, shift));
    q = dvec3(1.3lf * a.x, 0.678lf * a.z, 0.999lf * a.y);
  }
  float fr = P_(P, 7), fg = P_(P, 8), fb = P_(P, 9);
  if (!isnan(fr) && trunc(clamp(fr, 0.0, 1.0)) == 1.0) q.x = 1.0lf - q.x;
  if (!isnan(fg) && trunc(clamp(fg, 0.0, 1.0)) == 1.0) q.y = 1.0lf - q.y;
  if (!isnan(fb) && trunc(clamp(fb, 0.0, 1.0)) == 1.0) q.z = 1.0lf - q.z;
  if (index) {
    float grey = float(q.x * q.y);
    if (!isnan(grey)) gColour = grey;
  } else {
    gRgb = kRgbPainted | uint(rgb_byte(q.x)) | uint(rgb_byte(q.y)) << 8 | uint(rgb_byte(q.z)) << 16;
  }
  return o;
}

// glsl_acrilic: Sosa's acrylic pour in double (its warps take sines of k p1 y + time, far beyond what float's trig
// holds), as the CPU's.
vec3 V_glsl_acrilic(vec3 p, float w, int P, int A) {
  const double kHeight = 1000000.0lf;
  float pw = P_(P, 0), pg = P_(P, 13), ps = P_(P, 3);
  double width = isnan(pw) ? 100.0lf : trunc(clamp(double(pw), 100.0lf, 10000000.0lf));
  bool index = !isnan(pg) && trunc(clamp(pg, 0.0, 1.0)) == 1.0;
  double pi = trunc(double(psi()) * width), pj = trunc(double(psi()) * kHeight);
  vec3 o = vec3(w * float(pi / width - 0.5lf), w * float(pj / kHeight - 0.5lf), w * p.z);
  int steps = isnan(ps) ? 0 : int(trunc(clamp(ps, 3.0, 100.0)));
  double time = double(P_(P, 2)), q[6];
  for (int k = 0; k < 6; ++k) {
    float v = P_(P, 4 + k);
    q[k] = isnan(v) ? double(v) : clamp(double(v), 1.0lf, 100.0lf);
  }
  precise double x = 0.7lf * (pi + 0.5lf) / width, y = 0.7lf * (pj + 0.5lf) / kHeight;
  precise dvec3 c;
  for (int ch = 0; ch < 3; ++ch) {
    for (int k = 1; k < steps; ++k) {
      double kd = double(k);
      precise double step = 0.1lf / double(k + ch);
      x += step * dsin(kd * q[0] * y + time + dcos((time / (q[1] * kd)) * kd + double(ch)));
      y += step * dcos(kd * q[2] * x + time + dsin((time / (q[3] * kd)) * kd + double(ch)));
    }
    c[ch] = dsin(q[4] * (x * x)) + dsin(q[5] * (y * y));
  }
  for (int ch = 0; ch < 3; ++ch) {
    float f = P_(P, 10 + ch);
    double factor = isnan(f) ? double(f) : clamp(double(f), 0.0lf, 5.0lf);
    c[ch] = dcos(c[ch] * factor);
  }
  if (index) {
    float grey = sin(float(c.x / (c.x + c.y + c.z)));
    if (!isnan(grey)) gColour = grey;
  } else {
    gRgb = kRgbPainted | uint(rgb_byte(c.x)) | uint(rgb_byte(c.y)) << 8 | uint(rgb_byte(c.z)) << 16;
  }
  return o;
}
