// More of Fractorium's 3D variations: quaternion Möbius maps, 3D julia roots, spherical heat waves, the hyperbolic
// tiling in 3D, lines, rings and scry/loonie 3D. The formulas follow Fractorium's classes of the same name
// (Variations02.h–07.h), with Fractorium's guard Zeps (a zero divisor taken as the double's epsilon). Each variation
// is a kernel below and one row of the table at the end (see variations.h for the notation and variation_kernels.h
// for what the files share).
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// mobiq: the quaternion Möbius map (A q + B)/(C q + D) of q = x + y i + z j, with A … D quaternions (t + x i + y j +
// z k) from the parameters; the quotient's k part is dropped (Fractorium's).
VOXFLAME_VARIATION_TARGETS void mobiq(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double at = P[0], ax = P[1], ay = P[2], az = P[3], bt = P[4], bx = P[5], by = P[6], bz = P[7];
  const double ct = P[8], cx = P[9], cy = P[10], cz = P[11], dt = P[12], dx = P[13], dy = P[14], dz = P[15];
  for (std::size_t i = 0; i < n; ++i) {
    const double qt = x[i], qx = y[i], qy = z[i];
    const double nt = at * qt - ax * qx - ay * qy + bt;
    const double nx = at * qx + ax * qt - az * qy + bx;
    const double ny = at * qy + ay * qt + az * qx + by;
    const double nz = az * qt + ax * qy - ay * qx + bz;
    const double et = ct * qt - cx * qx - cy * qy + dt;
    const double ex = ct * qx + cx * qt - cz * qy + dx;
    const double ey = ct * qy + cy * qt + cz * qx + dy;
    const double ez = cz * qt + cx * qy - cy * qx + dz;
    const double ni = w / (et * et + ex * ex + ey * ey + ez * ez);
    outX[i] += (nt * et + nx * ex + ny * ey + nz * ez) * ni;
    outY[i] += (nx * et - nt * ex - ny * ez + nz * ey) * ni;
    outZ[i] += (ny * et - nt * ey - nz * ex + nx * ez) * ni;
  }
}

// julia3Dq: julia3D's root with a divisor: the angle φ·divisor/power plus a random one of the power branches 2πk/power,
// the radius (r² + (z·|divisor/power|)²)^(divisor/power/2 − ½). Fractorium picks k as a random integer below 32767;
// k below |power| gives the same branches.
VOXFLAME_VARIATION_TARGETS void julia3Dq(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = countParam(P[0]), divisor = countParam(P[1]);
  const double invPower = divisor / power, absInvPower = std::abs(invPower);
  const double halfInvPower = 0.5 * invPower - 0.5, branch = kTwoPi / power, branches = std::abs(power);
  for (std::size_t i = 0; i < n; ++i) {
    const double k = std::floor(laneUniform(rnd[i]) * branches);
    const double t = std::atan2(y[i], x[i]) * invPower + k * branch;
    const double pz = z[i] * absInvPower;
    const double r2 = x[i] * x[i] + y[i] * y[i];
    const double r = w * std::pow(r2 + pz * pz, halfInvPower);
    const double rs = r * std::sqrt(r2);
    outX[i] += rs * std::cos(t);
    outY[i] += rs * std::sin(t);
    outZ[i] += r * pz;
  }
}

// heat: the point in spherical coordinates (ρ, azimuth φ, polar σ), each shifted by a sine wave of the radius:
// ρ' = ρ + w r_amp sin(2π ρ/r_period + r_phase/r_period), and likewise φ (theta_*) and σ (phi_*) from ρ'. As in
// Fractorium, ρ = √|x² + y² + z| (z, not z²), and a period of 0 stops its wave.
VOXFLAME_VARIATION_TARGETS void heat(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const auto inverse = [](double period) { return period == 0.0 ? 0.0 : 1.0 / period; };
  const double tx = inverse(P[0]), px = inverse(P[3]), rx = inverse(P[6]);
  const double at = w * P[2], bt = kTwoPi * tx, ct = P[1] * tx;
  const double ap = w * P[5], bp = kTwoPi * px, cp = P[4] * px;
  const double ar = w * P[8], br = kTwoPi * rx, cr = P[7] * rx;
  for (std::size_t i = 0; i < n; ++i) {
    double r = std::sqrt(std::abs(x[i] * x[i] + y[i] * y[i] + z[i]));
    r += ar * std::sin(br * r + cr);
    if (r == 0.0) r = kFractoriumEps;
    const double azimuth = at * std::sin(bt * r + ct) + std::atan2(y[i], x[i]);
    const double polar = ap * std::sin(bp * r + cp) + std::acos(std::clamp(z[i] / r, -1.0, 1.0));
    const double sp = std::sin(polar);
    outX[i] += r * std::cos(azimuth) * sp;
    outY[i] += r * std::sin(azimuth) * sp;
    outZ[i] += r * std::cos(polar);
  }
}

// hypertile3D: hypertile's Möbius step of the {p, q} tiling extended to z. As in Fractorium, |p|² is taken as x² + y²
// + z (z, not z²).
VOXFLAME_VARIATION_TARGETS void hypertile3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  constexpr double kMaxCount = 2147483647.0;
  const double p = fractoriumInteger(P[0], 3.0, kMaxCount), q = fractoriumInteger(P[1], 3.0, kMaxCount);
  const double tile = std::floor(P[2] + 0.5);
  const double pa = kTwoPi / p, qa = kTwoPi / q;
  double r = -(std::cos(pa) - 1.0) / fractoriumZeps(std::cos(pa) + std::cos(qa));
  r = r > 0.0 ? 1.0 / fractoriumZeps(std::sqrt(1.0 + r)) : 1.0;
  const double cx = r * std::cos(tile * pa), cy = r * std::sin(tile * pa);
  const double c2 = cx * cx + cy * cy, c2x = 2.0 * cx, c2y = 2.0 * cy;
  const double s2x = 1.0 + cx * cx - cy * cy, s2y = 1.0 + cy * cy - cx * cx, s2z = 1.0 - cy * cy - cx * cx;
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i] + z[i];
    const double x2cx = c2x * x[i], y2cy = c2y * y[i];
    const double d = w / fractoriumZeps(c2 * r2 + x2cx - y2cy + 1.0);
    outX[i] += d * (x[i] * s2x - cx * (y2cy - r2 - 1.0));
    outY[i] += d * (y[i] * s2y + cy * (-x2cx - r2 - 1.0));
    outZ[i] += d * z[i] * s2z;
  }
}

// loonie_3D: loonie in 3D, with z replaced by φ where it is 0, and z halved.
VOXFLAME_VARIATION_TARGETS void loonie3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double vv = w * w;
  for (std::size_t i = 0; i < n; ++i) {
    const double pz = z[i] == 0.0 ? std::atan2(y[i], x[i]) : z[i];
    const double r2 = x[i] * x[i] + y[i] * y[i] + pz * pz;
    const double r = r2 < vv ? w * std::sqrt(vv / r2 - 1.0) : w;
    outX[i] += r * x[i];
    outY[i] += r * y[i];
    outZ[i] += r * pz * 0.5;
  }
}

// scry_3D: scry in 3D, with z replaced by φ where it is 0; the weight enters only as 1/w, as in scry.
VOXFLAME_VARIATION_TARGETS void scry3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double invWeight = 1.0 / fractoriumZeps(w);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    const double r = 1.0 / fractoriumZeps(std::sqrt(t) * (t + invWeight));
    const double pz = z[i] == 0.0 ? std::atan2(y[i], x[i]) : z[i];
    outX[i] += x[i] * r;
    outY[i] += y[i] * r;
    outZ[i] += pz * r;
  }
}

// line: a random point on the segment from the origin to w·u, u the unit vector at azimuth delta·π and elevation phi·π.
VOXFLAME_VARIATION_TARGETS void line(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  double ux = std::cos(P[0] * kPi) * std::cos(P[1] * kPi);
  double uy = std::sin(P[0] * kPi) * std::cos(P[1] * kPi);
  double uz = std::sin(P[1] * kPi);
  const double length = std::sqrt(ux * ux + uy * uy + uz * uz);
  ux /= length;
  uy /= length;
  uz /= length;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = laneUniform(rnd[i]) * w;
    outX[i] += ux * r;
    outY[i] += uy * r;
    outZ[i] += uz * r;
  }
}

// concentric: rings of a random level ⌊Ψ density⌋/density, at radius level·radius (blurred by R_blur), sunk to
// z = −level (blurred by Z_blur). Fractorium discards the terms summed before it as an ordinary term (and adds it as a
// pre_/post_ term), and so does the chaos game here.
VOXFLAME_VARIATION_TARGETS void concentric(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = P[0], density = P[1], rBlur = P[2], zBlur = P[3];
  const double inverseDensity = 1.0 / fractoriumZeps(density);
  for (std::size_t i = 0; i < n; ++i) {
    const double level = std::floor(laneUniform(rnd[i]) * density) * inverseDensity;
    const double angle = laneUniform(rnd[i]) * kTwoPi;
    double ring = level * radius;
    if (rBlur != 0.0) ring += (std::sqrt(laneUniform(rnd[i])) * 2.0 - 1.0) * rBlur;
    const double zb = zBlur != 0.0 ? (laneUniform(rnd[i]) * 2.0 - 1.0) * zBlur : 0.0;
    outX[i] += ring * std::cos(angle) * w;
    outY[i] += ring * std::sin(angle) * w;
    outZ[i] += (zb - level) * w;
  }
}

// hypercrop: n discs at the corners of a regular n-gon (radius rad, scaled to touch its sides) cut out of the plane:
// a point inside one goes to that disc's centre (zero > 1.5), to the origin (zero > 0.5) or to the disc's edge,
// with z 0; other points stay (Fractorium's).
VOXFLAME_VARIATION_TARGETS void hypercrop(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sides = fractoriumZeps(P[0]), zero = P[2];
  const double coeff = fractoriumZeps(sides * 0.5 / kPi), a0 = kPi / sides;
  const double length = 1.0 / fractoriumZeps(std::cos(a0)), d = P[1] * std::sin(a0) * length;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = std::floor(std::atan2(y[i], x[i]) * coeff) / coeff + a0;
    const double x0 = std::cos(angle) * length, y0 = std::sin(angle) * length;
    const double dx = x[i] - x0, dy = y[i] - y0;
    double fx = x[i], fy = y[i], fz = z[i];
    if (std::sqrt(dx * dx + dy * dy) < d) {
      if (zero > 1.5) {
        fx = x0;
        fy = y0;
      } else if (zero > 0.5) {
        fx = 0.0;
        fy = 0.0;
      } else {
        const double edge = std::atan2(dy, dx);
        fx = x0 + std::cos(edge) * d;
        fy = y0 + std::sin(edge) * d;
      }
      fz = 0.0;
    }
    outX[i] += fx * w;
    outY[i] += fy * w;
    outZ[i] += fz * w;
  }
}

// hypershift2: an inversion, a shift by the {p, q} tiling's offset, a second inversion and shift, then a turn by a
// random odd multiple of π/p; z scaled by the second inversion. Fractorium's flam3-compatible mode discards the terms
// summed before it (as an ordinary term), and so does the chaos game here.
VOXFLAME_VARIATION_TARGETS void hypershift2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                            double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double p = std::max(P[0], 2.0), q = std::max(P[1], 2.0);
  const double pq = kPi / q, pp = kPi / p, spq = std::sin(pq), spp = std::sin(pp);
  const double shift = std::sin(kPi * 0.5 - pq - pp) / std::sqrt(1.0 - spq * spq - spp * spp);
  const double lifted = std::sin(kPi / 2.0 + pp);
  const double scale2 = 1.0 / std::sqrt(lifted * lifted / (spq * spq) - 1.0) * (lifted / spq - 1.0);
  const double scale = 1.0 - shift * shift;
  for (std::size_t i = 0; i < n; ++i) {
    const double fx = x[i] * scale2, fy = y[i] * scale2;
    double rad = 1.0 / fractoriumZeps(fx * fx + fy * fy);
    const double sx = rad * fx + shift, sy = rad * fy;
    rad = w * scale / fractoriumZeps(sx * sx + sy * sy);
    const double angle = (std::floor(laneUniform(rnd[i]) * p) * 2.0 + 1.0) * kPi / p;
    const double X = rad * sx + shift, Y = rad * sy;
    const double c = std::cos(angle), s = std::sin(angle);
    outX[i] += c * X - s * Y;
    outY[i] += s * X + c * Y;
    outZ[i] += z[i] * rad;
  }
}

// SuperShape3D: a random point of Gielis' superformula surface: ρ and ϕ random angles (ρ in [0, rho·2/π), ϕ in
// ±[0, phi·2/π), Fractorium's M_2_PI), r_i = (a_i |cos(m_i/4 angle)|^n2_i + b_i |sin(m_i/4 angle)|^n3_i)^n1_i with a_i
// = |1/a|^n2 and b_i = |1/b|^n3 (Fractorium's exponents, as it has them), r1 plus spiral·ρ; a sphere-like product or,
// with toroidmap, a torus. Fractorium's random sign bit is Ψ < ½ here.
VOXFLAME_VARIATION_TARGETS void superShape3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double rho2pi = P[0] * (2.0 / kPi), phi2pi = P[1] * (2.0 / kPi), m41 = P[2] / 4.0, m42 = P[3] / 4.0;
  const double an21 = std::pow(std::abs(1.0 / P[4]), P[10]), an22 = std::pow(std::abs(1.0 / P[5]), P[11]);
  const double bn31 = std::pow(std::abs(1.0 / P[6]), P[12]), bn32 = std::pow(std::abs(1.0 / P[7]), P[13]);
  const double n11 = P[8], n12 = P[9], n21 = P[10], n22 = P[11], n31 = P[12], n32 = P[13], spiral = P[14];
  const bool toroid = std::floor(P[15] + 0.5) == 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double rho = laneUniform(rnd[i]) * rho2pi;
    double phi = laneUniform(rnd[i]) * phi2pi;
    if (laneUniform(rnd[i]) < 0.5) phi = -phi;
    const double sr = std::sin(rho), cr = std::cos(rho), sp = std::sin(phi), cp = std::cos(phi);
    const double pr1 =
        an21 * std::pow(std::abs(std::cos(m41 * rho)), n21) + bn31 * std::pow(std::abs(std::sin(m41 * rho)), n31);
    const double pr2 =
        an22 * std::pow(std::abs(std::cos(m42 * phi)), n22) + bn32 * std::pow(std::abs(std::sin(m42 * phi)), n32);
    const double r1 = std::pow(std::abs(pr1), n11) + spiral * rho;
    const double r2 = std::pow(std::abs(pr2), n12);
    const double ring = toroid ? r1 + r2 * cp : r1 * r2 * cp;
    outX[i] += w * cr * ring;
    outY[i] += w * sr * ring;
    outZ[i] += w * r2 * sp;
  }
}

// pRose3D: a rose curve of k petals, l cos(k φ + c) (cos φ, sin φ)/2, lifted to z by a waggle of the radius (a blend
// of sine terms chosen by opt, optSc and opt3) and a wiggle of the angle; with transp (squared) a random share of
// the points, half of them, becomes a mirrored "ghost" petal below, scaled by refSc. The ghost needs opt or opt3
// negative (Fractorium's).
VOXFLAME_VARIATION_TARGETS void pRose3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double l = P[0], k = P[1], c = P[2], z1 = P[3], z2 = P[4], refSc = P[5], opt = P[6], optSc = P[7];
  const double opt3 = P[8], transp = P[9], dist = P[10], wagsc = P[11], crvsc = P[12], f = P[13], wigsc = P[14];
  const double offset = P[15];
  const double cycle = kTwoPi / fractoriumZeps(k);
  // Fractorium takes the sign of the previous k here (its precalc sets it after use); the current k's is meant.
  const double petals = std::abs(k) < 0.0001 ? std::copysign(0.0001, k) : k;
  const double freq = f * kTwoPi, wigScale = wigsc * 0.5;
  const double smooth12 = std::min(std::abs(opt), 2.0), smooth3 = std::min(std::abs(opt3), 1.0);
  const double absOptSc = std::abs(optSc), antiOpt1 = 2.0 - smooth12;
  const double optDir = opt3 < 0.0 ? -1.0 : std::copysign(1.0, opt);
  const double ghost = optDir > 0.0 ? 0.0 : transp * transp;
  for (std::size_t i = 0; i < n; ++i) {
    const bool negative = laneUniform(rnd[i]) < 0.5;
    const bool ghostly = laneUniform(rnd[i]) < ghost;
    const double rad = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double curve1 = rad / l, curve2 = curve1 * curve1, curve3 = (rad - l * 0.5) / l, curve4 = curve2 * curve2;
    const double th = std::atan2(y[i], x[i]);
    const double wig = th / fractoriumZeps(cycle) * freq * 0.5 + offset * cycle;
    const double sin2 = std::sin(curve2 * kPi), cos3 = std::cos(curve3 * kPi);
    const double wag =
        std::sin(curve1 * kPi * absOptSc) + wagsc * 0.4 * rad + crvsc * 0.5 * (optDir < 0.0 ? sin2 : cos3);
    const double wag3 =
        std::sin(curve4 * kPi * absOptSc) + wagsc * rad * rad * 0.4 + crvsc * 0.5 * (optDir < 0.0 ? cos3 : sin2);
    const double wag2 = std::sin(curve2 * kPi * absOptSc) + wagsc * 0.4 * rad + crvsc * 0.5 * cos3;
    double wag12 = 0.0;
    if (smooth12 <= 1.0)
      wag12 = wag;
    else if (smooth12 <= 2.0)
      wag12 = wag2 * (1.0 - antiOpt1) + wag * antiOpt1;
    double waggle = 0.0;
    if (smooth3 == 0.0)
      waggle = wag12;
    else if (smooth3 > 0.0)
      waggle = wag12 * (1.0 - smooth3) + wag3 * smooth3;
    const bool mirrored = ghostly && negative;
    const double petal = w * 0.5 * (mirrored ? refSc : 1.0) * l * std::cos(petals * th + c);
    const double lift = (mirrored ? z2 : z1) * waggle + rad * 0.5 * rad * 0.5 * std::sin(wig) * wigScale + dist;
    outX[i] += petal * std::cos(th);
    outY[i] += petal * std::sin(th);
    outZ[i] += w * (mirrored ? -0.5 : 0.5) * lift;
  }
}

}  // namespace

void variation_kernels::addFractorium3DMoreVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  constexpr bool k3D = CatalogueAdder::k3D, kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  const auto count = &CatalogueAdder::count;
  add("mobiq",
      "(A q + B)/(C q + D) for q = x + y i + z j, A = at + ax i + ay j + az k and likewise B, C, D; the result's real, "
      "i "
      "and j parts (Fractorium's)",
      k3D, kFixed, &mobiq,
      {{"at", 1.0, -2.0, 2.0},
       {"ax", 0.0, -2.0, 2.0},
       {"ay", 0.0, -2.0, 2.0},
       {"az", 0.0, -2.0, 2.0},
       {"bt", 0.0, -2.0, 2.0},
       {"bx", 0.0, -2.0, 2.0},
       {"by", 0.0, -2.0, 2.0},
       {"bz", 0.0, -2.0, 2.0},
       {"ct", 0.0, -2.0, 2.0},
       {"cx", 0.0, -2.0, 2.0},
       {"cy", 0.0, -2.0, 2.0},
       {"cz", 0.0, -2.0, 2.0},
       {"dt", 1.0, -2.0, 2.0},
       {"dx", 0.0, -2.0, 2.0},
       {"dy", 0.0, -2.0, 2.0},
       {"dz", 0.0, -2.0, 2.0}});
  add("julia3Dq",
      "ρ (r cos t, r sin t, z'); m = divisor/power, z' = |m| z, ρ = (r² + z'²)^(m/2 − ½), t = m φ + 2π ⌊Ψ |power|⌋ / "
      "power",
      k3D, kRandom, &julia3Dq, {count("power", 3.0, -10.0, 10.0), count("divisor", 2.0, -10.0, 10.0)});
  add("heat",
      "ρ' (cos a sin s, sin a sin s, cos s); ρ = √|r² + z|, ρ' = ρ + w r_amp sin(2π ρ/r_period + r_phase/r_period), a "
      "= "
      "φ + w theta_amp sin(2π ρ'/theta_period + theta_phase/theta_period), s = acos(z/ρ') + w phi_amp sin(2π "
      "ρ'/phi_period + phi_phase/phi_period); a period of 0 stops its wave (w the weight; Fractorium's)",
      k3D, kFixed, &heat,
      {{"theta_period", 1.0, -5.0, 5.0},
       {"theta_phase", 0.0, -5.0, 5.0},
       {"theta_amp", 1.0, -5.0, 5.0},
       {"phi_period", 1.0, -5.0, 5.0},
       {"phi_phase", 0.0, -5.0, 5.0},
       {"phi_amp", 0.0, -5.0, 5.0},
       {"r_period", 1.0, -5.0, 5.0},
       {"r_phase", 0.0, -5.0, 5.0},
       {"r_amp", 0.0, -5.0, 5.0}});
  add("hypertile3D",
      "(x s_x − c_x (2 c_y y − t − 1), y s_y − c_y (2 c_x x + t + 1), z s_z) / (|c|² t + 2 c_x x − 2 c_y y + 1); t = "
      "r² "
      "+ z, c the {p, q} tiling's centre of tile n, s_x = 1 + c_x² − c_y², s_y = 1 + c_y² − c_x², s_z = 1 − |c|² "
      "(Fractorium's)",
      k3D, kFixed, &hypertile3D,
      {count("p", 3.0, 3.0, 12.0), count("q", 7.0, 3.0, 12.0), count("n", 0.0, -10.0, 10.0)});
  add("loonie_3D",
      "k (x, y, z'/2); z' = z, or φ where z = 0; k = √(w²/(r² + z'²) − 1) inside the sphere of radius |w|, else 1 (w "
      "the weight)",
      k3D, kFixed, &loonie3D);
  add("scry_3D", "(x, y, z') / (|p| (|p|² + 1/w)), the weight w applied only there; z' = z, or φ where z = 0", k3D,
      kFixed, &scry3D);
  add("line", "Ψ u; u the unit vector (cos δ cos ϕ, sin δ cos ϕ, sin ϕ), δ = π delta, ϕ = π phi", k3D, kRandom, &line,
      {{"delta", 0.0, -1.0, 1.0}, {"phi", 0.0, -1.0, 1.0}});
  add("concentric",
      "(ρ cos a, ρ sin a, b − l); l = ⌊Ψ₁ density⌋/density, a = 2πΨ₂, ρ = l radius + (2√Ψ₃ − 1) R_blur (Ψ₃ drawn "
      "only when R_blur ≠ 0), b = (2Ψ₄ − 1) Z_blur (drawn only when Z_blur ≠ 0); discards the terms before it "
      "(Fractorium's)",
      k3D, kRandom, &concentric,
      {{"radius", 1.0, -2.0, 2.0},
       {"density", 10.0, 1.0, 50.0},
       {"R_blur", 0.0, -1.0, 1.0},
       {"Z_blur", 0.0, -1.0, 1.0}});
  catalogue.back().replaces = VariationInfo::Replaces::XYZ;
  add("hypercrop",
      "p, except inside the n discs of radius rad·sin(π/n)/cos(π/n) centred at c = (cos a, sin a)/cos(π/n), a = "
      "⌊φ n/2π⌋ 2π/n + π/n: there (c, 0) with zero > 1.5, (0, 0, 0) with zero > 0.5, else the nearest point of the "
      "disc's edge with z 0 (Fractorium's)",
      k3D, kFixed, &hypercrop, {{"n", 4.0, 1.0, 12.0}, {"rad", 1.0, 0.0, 2.0}, {"zero", 0.0, 0.0, 2.0}});
  add("hypershift2",
      "R((2⌊Ψ p⌋ + 1)π/p) (s (u, v)/|(u, v)|² + (h, 0)), z s/|(u, v)|²; (u, v) = q/|q|² + (h, 0), q = k (x, y), h, k "
      "and "
      "s = 1 − h² from the {p, q} tiling (p, q at least 2); discards the terms before it (Fractorium's, flam3 mode)",
      k3D, kRandom, &hypershift2, {{"p", 3.0, 2.0, 12.0}, {"q", 7.0, 2.0, 12.0}});
  catalogue.back().replaces = VariationInfo::Replaces::XYZ;
  add("SuperShape3D",
      "(cos ρ · R, sin ρ · R, r2 sin ϕ); ρ = Ψ₁ rho·2/π, ϕ = ±Ψ₂ phi·2/π (− when Ψ₃ < ½), r1 = |A₁|cos(m1 ρ/4)|^n2_1 + "
      "B₁|sin(m1 ρ/4)|^n3_1|^n1_1 + spiral ρ, r2 likewise from ϕ with the _2 parameters (no spiral), A_i = "
      "|1/a_i|^n2_i, "
      "B_i = |1/b_i|^n3_i; R = r1 r2 cos ϕ, or r1 + r2 cos ϕ with toroidmap (Fractorium's)",
      k3D, kRandom, &superShape3D,
      {{"rho", 9.9, -20.0, 20.0},
       {"phi", 2.5, -20.0, 20.0},
       {"m1", 6.0, -20.0, 20.0},
       {"m2", 3.0, -20.0, 20.0},
       {"a1", 1.0, -5.0, 5.0},
       {"a2", 1.0, -5.0, 5.0},
       {"b1", 1.0, -5.0, 5.0},
       {"b2", 1.0, -5.0, 5.0},
       {"n1_1", 1.0, -5.0, 5.0},
       {"n1_2", 1.0, -5.0, 5.0},
       {"n2_1", 1.0, -5.0, 5.0},
       {"n2_2", 1.0, -5.0, 5.0},
       {"n3_1", 1.0, -5.0, 5.0},
       {"n3_2", 1.0, -5.0, 5.0},
       {"spiral", 0.0, -2.0, 2.0},
       count("toroidmap", 0.0, 0.0, 1.0)});
  add("pRose3D",
      "(R cos φ, R sin φ, (z1 g + (r/2)² sin(v) wigsc/2 + dist)/2), R = l cos(k φ + c)/2; g the waggle, sin(π optSc "
      "r/l) + 0.4 wagsc r + crvsc/2 cos(π (r − l/2)/l) (sin(π r²/l²) for the last term when opt or opt3 < 0), blended "
      "toward its r²/l² and r⁴/l⁴ forms by |opt| ∈ [1, 2] and |opt3| ∈ [0, 1]; v = φ k f/2 + 2π offset/k; when opt or "
      "opt3 < 0, with probability transp²/2 (Ψ₁ < ½ and Ψ₂ < transp²) a ghost petal: R times refSc and z = −(z2 g + "
      "…)/2 (Fractorium's)",
      k3D, kRandom, &pRose3D,
      {{"l", 1.0, 0.1, 3.0},
       {"k", 3.0, -10.0, 10.0},
       {"c", 0.0, -3.0, 3.0},
       {"z1", 1.0, -2.0, 2.0},
       {"z2", 1.0, -2.0, 2.0},
       {"refSc", 1.0, -2.0, 2.0},
       {"opt", 1.0, -2.0, 2.0},
       {"optSc", 1.0, -2.0, 2.0},
       {"opt3", 0.0, -1.0, 1.0},
       {"transp", 0.5, 0.0, 1.0},
       {"dist", 1.0, -2.0, 2.0},
       {"wagsc", 0.0, -2.0, 2.0},
       {"crvsc", 0.0, -2.0, 2.0},
       {"f", 3.0, -10.0, 10.0},
       {"wigsc", 0.0, -2.0, 2.0},
       {"offset", 0.0, -2.0, 2.0}});
}

}  // namespace voxflame::core
