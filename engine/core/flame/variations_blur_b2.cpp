// Fractorium's random 2D variations: curve blurs (Lissajous, Spirograph), star blurs, radial blurs, point symmetries,
// squares squished onto their perimeter, and a logarithm with random branches. The formulas follow Fractorium's classes
// of the same name (Variations03.h–07.h); z is carried as w·z (voxflame's rule for 2D variations, where Fractorium
// writes 0). Each variation is a kernel below and one row of the table at the end (see variations.h for the notation
// and variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// Lissajous: a random point of the curve (sin(a t + d), sin(b t)) for t in [tmin, tmax], moved along the diagonal by
// c t and by e times a uniform number in [−½, ½). The point itself is not used.
VOXFLAME_VARIATION_2D(lissajous, {
  const double t = (P[1] - P[0]) * laneUniform(rnd[i]) + P[0];
  const double spread = laneUniform(rnd[i]) - 0.5;
  const double shift = P[4] * t + P[6] * spread;
  outX[i] += w * (std::sin(P[2] * t + P[5]) + shift);
  outY[i] += w * (std::sin(P[3] * t) + shift);
})

// Spirograph: a random point of the epitrochoid ((a + b) cos t − c1 cos((a + b) t/b) + d cos t, …) for t in [tmin,
// tmax], moved along the diagonal by a uniform number in [ymin, ymax].
VOXFLAME_VARIATION_2D(spirograph, {
  const double a = P[0], b = P[1], d = P[2], tMin = P[3], yMin = P[4], tMax = P[5], yMax = P[6];
  const double t = (tMax - tMin) * laneUniform(rnd[i]) + tMin;
  const double shift = (yMax - yMin) * laneUniform(rnd[i]) + yMin;
  const double ab = a + b, inner = ab / b * t;
  outX[i] += w * (ab * std::cos(t) - P[7] * std::cos(inner) + d * std::cos(t) + shift);
  outY[i] += w * (ab * std::sin(t) - P[8] * std::sin(inner) + d * std::sin(t) + shift);
})

// point_symmetry: the point, scaled by the weight about the centre, turned by a random multiple of 2π/order about it.
// The centre itself is not scaled.
VOXFLAME_VARIATION_TARGETS void pointSymmetry(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                              double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cx = P[0], cy = P[1], order = P[2], step = kTwoPi / fractoriumZeps(P[2]);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = std::floor(laneUniform(rnd[i]) * order) * step;
    const double dx = (x[i] - cx) * w, dy = (y[i] - cy) * w;
    const double c = std::cos(angle), s = std::sin(angle);
    outX[i] += cx + dx * c + dy * s;
    outY[i] += cy + dy * c - dx * s;
    outZ[i] += w * z[i];
  }
}

// rblur: a square blur whose size grows with the distance from the centre beyond the offset.
VOXFLAME_VARIATION_TARGETS void rblur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double s2 = 2.0 * P[0], offset = P[1], cx = P[2], cy = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double sx = x[i] - cx, sy = y[i] - cy;
    double r = std::sqrt(sx * sx + sy * sy) - offset;
    r = (r < 0.0 ? 0.0 : r) * s2;
    outX[i] += w * (x[i] + (laneUniform(rnd[i]) - 0.5) * r);
    outY[i] += w * (y[i] + (laneUniform(rnd[i]) - 0.5) * r);
    outZ[i] += w * z[i];
  }
}

// spher: outside the unit circle, spherical or linear at random (Ψ < ½ spherical); inside, the origin. Fractorium
// draws Ψ only outside; here every lane draws, so the loop stays branch-free and the lane's sequence does not depend
// on where its point fell.
VOXFLAME_VARIATION_2D(spher, {
  const double u = laneUniform(rnd[i]);
  const double r2 = fractoriumZeps(x[i] * x[i] + y[i] * y[i]);
  const double k = r2 > 1.0 ? (u < 0.5 ? w / r2 : w) : 0.0;
  outX[i] += k * x[i];
  outY[i] += k * y[i];
})

// squish: the point moved onto the square of half-side max(|x|, |y|) at its perimeter position, which is divided by
// power and shifted by a random one of power eighths of the perimeter (lazysusan-like). Fractorium keeps power ≥ 2.
VOXFLAME_VARIATION_TARGETS void squish(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = std::max(P[0], 2.0), invPower = 1.0 / power;
  for (std::size_t i = 0; i < n; ++i) {
    const double ax = std::abs(x[i]), ay = std::abs(y[i]);
    double s = 0.0, p = 0.0;
    if (ax > ay) {
      s = ax;
      p = x[i] > 0.0 ? y[i] : 4.0 * s - y[i];
    } else {
      s = ay;
      p = y[i] > 0.0 ? 2.0 * s - x[i] : 6.0 * s + x[i];
    }
    p = invPower * (p + 8.0 * s * std::floor(power * laneUniform(rnd[i])));
    double px = 0.0, py = 0.0;
    if (p <= s) {
      px = s;
      py = p;
    } else if (p <= 3.0 * s) {
      px = 2.0 * s - p;
      py = s;
    } else if (p <= 5.0 * s) {
      px = -s;
      py = 4.0 * s - p;
    } else if (p <= 7.0 * s) {
      px = -(6.0 * s - p);
      py = -s;
    } else {
      px = s;
      py = 8.0 * s - p;
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// sschecks: checks' chequerboard of shifts (cells of side size, parity of the rounded coordinates' sum) added to
// sin x, sin y scaled by w/r², with a random jitter rnd on one coordinate. The weight enters twice, as in Fractorium.
VOXFLAME_VARIATION_TARGETS void sschecks(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double cx = P[0], cy = P[1], invSize = 1.0 / fractoriumZeps(P[2]), jitter = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double u = laneUniform(rnd[i]);
    const double r = w / fractoriumZeps(x[i] * x[i] + y[i] * y[i]);
    // Apophysis' rounding (half away from zero) of each, summed; odd or even.
    const double cell = std::round(x[i] * invSize) + std::round(y[i] * invSize);
    const bool odd = laneFmod(cell, 2.0) != 0.0;
    const double dx = odd ? -cx + jitter * u : cx;
    const double dy = odd ? -cy : cy + jitter * u;
    outX[i] += w * (std::sin(x[i]) * r + dx);
    outY[i] += w * (std::sin(y[i]) * r + dy);
    outZ[i] += w * z[i];
  }
}

// starblur: a random point inside a star of power points whose inner corners lie at range.
VOXFLAME_VARIATION_TARGETS void starblur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = P[0], range = P[1];
  const double halfAngle = kPi / power;
  const double length = std::sqrt(1.0 + range * range - 2.0 * range * std::cos(halfAngle));
  const double alpha = std::asin(std::sin(halfAngle) * range / length);
  const double sinAlpha = std::sin(alpha), cosAlpha = std::cos(alpha), sector = kTwoPi / power;
  for (std::size_t i = 0; i < n; ++i) {
    double f = laneUniform(rnd[i]) * power * 2.0;
    const double edge = std::trunc(f);  // which edge of the star: Fractorium's int(f)
    f -= edge;
    const double px = f * length;
    double d = std::sqrt(1.0 + px * px - 2.0 * px * cosAlpha);
    const double turn = std::asin(sinAlpha * px / d);
    const bool odd = laneFmod(edge, 2.0) != 0.0;
    const double angle = sector * std::trunc(edge / 2.0) + (odd ? turn : -turn) - kPi / 2.0;
    d *= std::sqrt(laneUniform(rnd[i]));
    outX[i] += w * d * std::cos(angle);
    outY[i] += w * d * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

// log_db: log with the angle moved by a random number of periods: seven draws of an integer in [−5, 4], each kept
// only when its magnitude is below 3, summed and times π·fix_period.
VOXFLAME_VARIATION_TARGETS void logDb(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double base = P[0], fixPeriod = P[1];
  const double denominator = w * (base > kFractoriumEps ? 0.5 / std::log(std::numbers::e * base) : 0.5);
  const double period = fixPeriod > kFractoriumEps ? kPi * fixPeriod : kPi;
  for (std::size_t i = 0; i < n; ++i) {
    double turns = 0.0;
    for (int k = 0; k < 7; ++k) {
      const double adp = std::floor(laneUniform(rnd[i]) * 10.0) - 5.0;
      turns += std::abs(adp) >= 3.0 ? 0.0 : adp;
    }
    outX[i] += denominator * std::log(x[i] * x[i] + y[i] * y[i]);
    outY[i] += w * (std::atan2(y[i], x[i]) + turns * period);
    outZ[i] += w * z[i];
  }
}

// starblur2: starblur with a hole (radii from hole to 1), stripes across each edge (width their share) and Zeps
// guards (Fractorium's).
VOXFLAME_VARIATION_TARGETS void starblur2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = P[0], range = P[1], width = P[4];
  const double p = fractoriumZeps(power), halfAngle = kPi / p;
  const double length = std::sqrt(1.0 + range * range - 2.0 * range * std::cos(halfAngle));
  const double alpha = std::asin(std::sin(halfAngle) * range / fractoriumZeps(length));
  const double hole = std::min(std::abs(P[2]), 1.0), holeSq = hole * hole, oneMinusHoleSq = 1.0 - holeSq;
  const double stripes = fractoriumZeps(std::abs(P[3]));
  const double sector = kTwoPi / p, power2 = power * 2.0;
  const double sinAlpha = std::sin(alpha), cosAlpha2 = std::cos(alpha) * 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double k = laneUniform(rnd[i]) * power2;
    const double edge = std::floor(k);
    const double f = k - edge;
    const double fs = std::trunc(f * stripes);
    const bool even = laneFmod(edge, 2.0) == 0.0;
    const double dif = even ? width * (f * stripes - fs) : 1.0 - width * (f * stripes - fs);
    const double ff = (dif + fs) / stripes;
    const double px = ff * length;
    const double d = fractoriumZeps(std::sqrt(1.0 + px * px - px * cosAlpha2));
    const double sign = edge - std::floor(k / 2.0) * 2.0 == 1.0 ? 1.0 : -1.0;
    const double angle = sector * std::trunc(edge / 2.0) + sign * std::asin(sinAlpha * px / d) - kPi / 2.0;
    const double scaled = w * d * std::sqrt(laneUniform(rnd[i]) * oneMinusHoleSq + holeSq);
    outX[i] += std::cos(angle) * scaled;
    outY[i] += std::sin(angle) * scaled;
    outZ[i] += w * z[i];
  }
}

// SphericalN: spherical with a power: 1/r^Dist at the angle φ plus a random one of ⌊Power⌋ turns. Fractorium's
// flam3-compatible branch (cos, sin) is followed; its other branch swaps them.
VOXFLAME_VARIATION_TARGETS void sphericalN(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = P[0], dist = P[1], turn = kTwoPi / fractoriumZeps(std::floor(P[0]));
  for (std::size_t i = 0; i < n; ++i) {
    const double r = fractoriumZeps(std::pow(std::sqrt(x[i] * x[i] + y[i] * y[i]), dist));
    const double k = std::floor(power * laneUniform(rnd[i]));
    const double alpha = std::atan2(y[i], x[i]) + k * turn;
    outX[i] += w * std::cos(alpha) / r;
    outY[i] += w * std::sin(alpha) / r;
    outZ[i] += w * z[i];
  }
}

// SplitBrdr: bubble plus the point's unit cell, its offset from the cell centre halved and, three times in four
// (Ψ < ¾), pushed toward the cell's border along the offset's larger coordinate, plus (px x, py y) outside the weight.
// Which of x and y each push uses is Fractorium's, kept as it is.
VOXFLAME_VARIATION_TARGETS void splitBrdr(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1], px = P[2], py = P[3];
  for (std::size_t i = 0; i < n; ++i) {
    const double b = w / ((x[i] * x[i] + y[i] * y[i]) * 0.25 + 1.0);
    const double roundX = std::nearbyint(x[i]), roundY = std::nearbyint(y[i]);
    const double offX = x[i] - roundX, offY = y[i] - roundY;
    double ax = offX * 0.5 + roundX, ay = offY * 0.5 + roundY;
    if (laneUniform(rnd[i]) < 0.75) {
      if (std::abs(offX) >= std::abs(offY)) {
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
    outX[i] += x[i] * b + w * ax + x[i] * px;
    outY[i] += y[i] * b + w * ay + y[i] * py;
    outZ[i] += w * z[i];
  }
}

// npolar: a julia-like root of the point (odd parity) or of its log-polar image (even parity), n branches chosen at
// random. Fractorium's flam3-compatible branch is followed: the odd root is scaled by parity, and the even one
// returns to the plane through ln of the squared radius.
VOXFLAME_VARIATION_TARGETS void npolar(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double parity = P[0], nnz = P[1] == 0.0 ? 1.0 : P[1];
  const double vvar = w / kPi, vvar2 = vvar * 0.5, absN = std::abs(nnz), cn = 1.0 / nnz / 2.0;
  const bool odd = std::fmod(std::abs(parity), 2.0) != 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double turn = kTwoPi * std::floor(laneUniform(rnd[i]) * absN);
    const double r2 = x[i] * x[i] + y[i] * y[i];
    double px = 0.0, py = 0.0;
    if (odd) {
      const double angle = (std::atan2(y[i], x[i]) + turn) / nnz;
      const double r = w * std::pow(r2, cn) * parity;
      px = std::cos(angle) * r;
      py = std::sin(angle) * r;
    } else {
      const double lx = vvar * std::atan2(x[i], y[i]), ly = vvar2 * std::log(r2);
      const double angle = (std::atan2(ly, lx) + turn) / nnz;
      const double r = w * std::pow(lx * lx + ly * ly, cn);
      const double s = std::sin(angle) * r, c = std::cos(angle) * r;
      px = vvar2 * std::log(c * c + s * s);
      py = vvar * std::atan2(c, s);
    }
    outX[i] += px;
    outY[i] += py;
    outZ[i] += w * z[i];
  }
}

// phoenix_julia: julian of the distorted point (x (1 + x_distort), y (1 + y_distort)) for its angle, the undistorted
// radius. Fractorium's flam3-compatible branch draws the branch as a random integer below 32767 (so a power that is
// not whole spreads the angles), and so does this.
VOXFLAME_VARIATION_TARGETS void phoenixJulia(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = fractoriumZeps(P[0]), invN = P[1] / power, inv2PiN = kTwoPi / power, cn = invN / 2.0;
  const double dx = P[2] + 1.0, dy = P[3] + 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double k = std::floor(laneUniform(rnd[i]) * 32767.0);
    const double t = std::atan2(y[i] * dy, x[i] * dx) * invN + k * inv2PiN;
    const double r = w * std::pow(x[i] * x[i] + y[i] * y[i], cn);
    outX[i] += r * std::cos(t);
    outY[i] += r * std::sin(t);
    outZ[i] += w * z[i];
  }
}

// MobiusN: a Möbius map between a power and its root: u = ρ^(4 Dist/Power) (cos Power φ, sin Power φ), v = (A u +
// B)/(C u + D), then the Power/(4 Dist)-th power of |v| at the angle (arg v + 2π k)/⌊Power⌋, k = ⌊Ψ Power⌋. Power
// below 1 in magnitude counts as 1 (Fractorium's).
VOXFLAME_VARIATION_TARGETS void mobiusN(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double reA = P[0], imA = P[1], reB = P[2], imB = P[3], reC = P[4], imC = P[5], reD = P[6], imD = P[7];
  const double power = std::abs(P[8]) < 1.0 ? 1.0 : P[8];
  const double exponent = 4.0 * P[9] / power, root = 1.0 / exponent, whole = std::floor(power);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::pow(std::sqrt(x[i] * x[i] + y[i] * y[i]), exponent);
    const double alpha = std::atan2(y[i], x[i]) * power;
    const double ux = r * std::cos(alpha), uy = r * std::sin(alpha);
    const double reU = reA * ux - imA * uy + reB, imU = reA * uy + imA * ux + imB;
    const double reV = reC * ux - imC * uy + reD, imV = reC * uy + imC * ux + imD;
    const double radV = reV * reV + imV * imV;
    const double vx = (reU * reV + imU * imV) / radV, vy = (imU * reV - reU * imV) / radV;
    const double rr = std::pow(std::sqrt(vx * vx + vy * vy), root);
    const double k = std::floor(power * laneUniform(rnd[i]));
    const double angle = (std::atan2(vy, vx) + k * kTwoPi) / whole;
    outX[i] += w * rr * std::cos(angle);
    outY[i] += w * rr * std::sin(angle);
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addFractoriumRandom2DVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  constexpr bool k2D = CatalogueAdder::k2D, kRandom = CatalogueAdder::kRandom;
  add("Lissajous",
      "(sin(a t + d) + c t + e u, sin(b t) + c t + e u), z; t = tmin + (tmax − tmin)Ψ₁, u = Ψ₂ − ½ (Fractorium's)", k2D,
      kRandom, &lissajous,
      {{"tmin", -kPi, -10.0, 10.0},
       {"tmax", kPi, -10.0, 10.0},
       {"a", 3.0, -10.0, 10.0},
       {"b", 2.0, -10.0, 10.0},
       {"c", 0.0, -2.0, 2.0},
       {"d", 0.0, -5.0, 5.0},
       {"e", 0.0, -2.0, 2.0}});
  add("Spirograph",
      "((a + b) cos t − c1 cos((a + b) t/b) + d cos t + u, (a + b) sin t − c2 sin((a + b) t/b) + d sin t + u), z; t = "
      "tmin + (tmax − tmin)Ψ₁, u = ymin + (ymax − ymin)Ψ₂ (Fractorium's)",
      k2D, kRandom, &spirograph,
      {{"a", 3.0, -10.0, 10.0},
       {"b", 2.0, -10.0, 10.0},
       {"d", 1.0, -5.0, 5.0},
       {"tmin", -1.0, -10.0, 10.0},
       {"ymin", -1.0, -5.0, 5.0},
       {"tmax", 1.0, -10.0, 10.0},
       {"ymax", 1.0, -5.0, 5.0},
       {"c1", 0.0, -5.0, 5.0},
       {"c2", 0.0, -5.0, 5.0}});
  add("point_symmetry",
      "c + R(−α)(w (x, y) − w c), z; c = (centre_x, centre_y), α = 2π ⌊Ψ order⌋/order; the weight w is applied "
      "there only (Fractorium's)",
      k2D, kRandom, &pointSymmetry,
      {{"centre_x", 0.15, -2.0, 2.0}, {"centre_y", 0.5, -2.0, 2.0}, {"order", 3.0, 1.0, 12.0}});
  add("rblur", "(x, y) + 2 strength max(0, |(x, y) − c| − offset) (Ψ₁ − ½, Ψ₂ − ½), z; c = (center_x, center_y)", k2D,
      kRandom, &rblur,
      {{"strength", 1.0, -2.0, 2.0},
       {"offset", 1.0, -2.0, 2.0},
       {"center_x", 0.0, -2.0, 2.0},
       {"center_y", 0.0, -2.0, 2.0}});
  add("spher", "where r² > 1: (x, y)/r² when Ψ < ½, else (x, y); inside the unit circle (0, 0); z", k2D, kRandom,
      &spher);
  add("squish",
      "the point moved along the square of half-side s = max(|x|, |y|) to perimeter position (p + 8 s ⌊Ψ "
      "power⌋)/power, "
      "p its own (power at least 2; Fractorium's)",
      k2D, kRandom, &squish, {{"power", 2.0, 2.0, 10.0}});
  add("sschecks",
      "(sin x w/r² + dx, sin y w/r² + dy), z; (dx, dy) = (x', y' + rnd Ψ) on the cells (of side size) whose "
      "rounded coordinates sum to an even number, (−x' + rnd Ψ, −y') on the others; x', y' the parameters x, y (w the "
      "weight)",
      k2D, kRandom, &sschecks,
      {{"x", 0.5, -2.0, 2.0}, {"y", 0.5, -2.0, 2.0}, {"size", 0.5, 0.01, 2.0}, {"rnd", 0.0, -1.0, 1.0}});
  add("starblur",
      "a random point in the star of power points with inner corners at range: d √Ψ₂ (cos a, sin a), where edge k = "
      "⌊2 power Ψ₁⌋, f = 2 power Ψ₁ − k, l = f L, d = √(1 + l² − 2 l cos α), a = 2π ⌊k/2⌋/power ± asin(l sin α / d) − "
      "π/2 (+ for odd k); L = √(1 + range² − 2 range cos(π/power)), α = asin(sin(π/power) range/L); z",
      k2D, kRandom, &starblur, {{"power", 5.0, 2.0, 12.0}, {"range", 0.4016228317, 0.0, 1.0}});
  add("log_db",
      "(ln r² / (2 ln(e base)), φ + π fix_period Σ₇ k), z; each k = ⌊10Ψ⌋ − 5 where that is within ±2, else 0; base ≤ "
      "0 gives ½ ln r², fix_period ≤ 0 a period of π (Fractorium's)",
      k2D, kRandom, &logDb, {{"base", 1.0, 0.0, 5.0}, {"fix_period", 1.0, 0.0, 5.0}});
  add("starblur2",
      "starblur's star (power points, inner corners at range) with a hole: radius d √(Ψ₂ (1 − h²) + h²), h = "
      "min(|hole|, 1); each edge's position f split into |stripes| stripes, of which the share width is kept (from "
      "the edge's start on even edges, its end on odd ones); z (Fractorium's)",
      k2D, kRandom, &starblur2,
      {{"power", 5.0, 2.0, 12.0},
       {"range", 0.40162283177245455973959534526548, 0.0, 1.0},
       {"hole", 0.5, 0.0, 1.0},
       {"stripes", 5.0, 0.0, 20.0},
       {"width", 0.2, 0.0, 1.0}});
  add("SphericalN", "(cos a, sin a)/r^Dist, z; a = φ + 2π ⌊Ψ Power⌋/⌊Power⌋ (Fractorium's flam3-compatible form)", k2D,
      kRandom, &sphericalN, {{"Power", 1.0, 1.0, 12.0}, {"Dist", 1.0, -3.0, 3.0}});
  add("SplitBrdr",
      "(x, y)/(r²/4 + 1) + (o/2 + ⌊p⌉) + e + (px x, py y)/w, z; ⌊p⌉ the nearest whole point, o = p − ⌊p⌉, e = 0 when Ψ "
      "≥ ¾, "
      "else along o's larger coordinate: o_x ≥ |o_y|: (x', y' o_y/o_x), o_x ≤ −|o_y|: (−y', −y' o_y/o_x), o_y > 0: "
      "(y' o_x/o_y, y'), o_y < 0: (−x' o_x/o_y, −y'); x', y' the parameters x, y (w the weight; Fractorium's)",
      k2D, kRandom, &splitBrdr,
      {{"x", 0.25, -1.0, 1.0}, {"y", 0.25, -1.0, 1.0}, {"px", 0.0, -1.0, 1.0}, {"py", 0.0, -1.0, 1.0}});
  add("npolar",
      "odd parity: parity ρ^(1/n) (cos a, sin a), a = (φ + 2π ⌊Ψ|n|⌋)/n; even: (ln|s|²/(2π), atan2(s_x, s_y)/π) of s = "
      "|l|^(1/n) (cos b, sin b), l = (θ/π, ln r²/(2π)), b = (∠l + 2π ⌊Ψ|n|⌋)/n; n 0 taken as 1; z (Fractorium's "
      "flam3-compatible form)",
      k2D, kRandom, &npolar, {{"parity", 0.0, -5.0, 5.0}, {"n", 1.0, -10.0, 10.0}});
  add("phoenix_julia",
      "r^(dist/power) (cos t, sin t), z; t = (dist/power) atan2(y (1 + y_distort), x (1 + x_distort)) + 2π k/power, k "
      "= ⌊32767 Ψ⌋ (Fractorium's flam3-compatible form)",
      k2D, kRandom, &phoenixJulia,
      {{"power", 2.0, -10.0, 10.0},
       {"dist", 1.0, -5.0, 5.0},
       {"x_distort", -0.5, -2.0, 2.0},
       {"y_distort", 0.0, -2.0, 2.0}});
  add("MobiusN",
      "|v|^(1/e) (cos a, sin a), z; u = r^e (cos(Power φ), sin(Power φ)), e = 4 Dist/Power, v = (A u + B)/(C u + D) "
      "with A = Re_A + i Im_A and likewise, a = (arg v + 2π ⌊Ψ Power⌋)/⌊Power⌋; Power within ±1 taken as 1 "
      "(Fractorium's; files write MobiusNRe_A … and MobiusN_Power, MobiusN_Dist)",
      k2D, kRandom, &mobiusN,
      {{"Re_A", 1.0, -2.0, 2.0},
       {"Im_A", 0.0, -2.0, 2.0},
       {"Re_B", 0.0, -2.0, 2.0},
       {"Im_B", 0.0, -2.0, 2.0},
       {"Re_C", 0.0, -2.0, 2.0},
       {"Im_C", 0.0, -2.0, 2.0},
       {"Re_D", 1.0, -2.0, 2.0},
       {"Im_D", 0.0, -2.0, 2.0},
       {"Power", 2.0, 1.0, 10.0},
       {"Dist", 1.0, -3.0, 3.0}});
}

}  // namespace voxflame::core
