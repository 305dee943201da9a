// Fractorium's 3D variations of simple shape (most of them from Apophysis 3D plug-ins and JWildfire): blades, blobs,
// bubbles, discs, ovoids, sphere and torus maps, helices, per-axis powers, and two 3D blurs. The formulas follow
// Fractorium's classes of the same name (Variations02.h–07.h), with Fractorium's guard Zeps (a zero divisor taken as
// the double's epsilon). Each variation is a kernel below and one row of the table at the end (see variations.h for
// the notation and variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// blade3D: blade's (x (cos t + sin t), x (cos t − sin t)) with z (sin t − cos t), t = Ψ w r; the y output reads x,
// as blade does.
VOXFLAME_VARIATION_TARGETS void blade3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double t = laneUniform(rnd[i]) * w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double s = std::sin(t), c = std::cos(t);
    outX[i] += w * x[i] * (c + s);
    outY[i] += w * x[i] * (c - s);
    outZ[i] += w * z[i] * (s - c);
  }
}

// blob3D: blob's radius, low + (high − low)(½ + ½ sin(waves θ)), and z the same wave times that radius. Like
// Fractorium, x and y take the direction (x, y)/r where JWildfire's plug-in took sin and cos of θ.
VOXFLAME_VARIATION_TARGETS void blob3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double low = P[0], diff = P[1] - P[0], waves = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double rho = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double wave = std::sin(waves * std::atan2(x[i], y[i]));
    const double r = rho * (low + diff * (0.5 + 0.5 * wave));
    const double inverse = 1.0 / fractoriumZeps(rho);
    outX[i] += w * x[i] * inverse * r;
    outY[i] += w * y[i] * inverse * r;
    outZ[i] += w * wave * r;
  }
}

// bubble2: bubble scaled per axis, with z pushed away from the plane z = 0 by the z parameter.
VOXFLAME_VARIATION_TARGETS void bubble2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1], sz = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = w / fractoriumZeps(0.25 * (x[i] * x[i] + y[i] * y[i] + z[i] * z[i]) + 1.0);
    outX[i] += x[i] * r * sx;
    outY[i] += y[i] * r * sy;
    outZ[i] += w * (z[i] >= 0.0 ? z[i] + sz : z[i] - sz) + z[i] * r * sz;
  }
}

VOXFLAME_VARIATION_TARGETS void disc3d(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double pi = P[0], scale = w / fractoriumZeps(P[0]);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double v = scale * std::atan2(x[i], y[i]);
    outX[i] += v * std::sin(r * pi);
    outY[i] += v * std::cos(r * pi);
    outZ[i] += v * r * std::cos(z[i]);
  }
}

VOXFLAME_VARIATION_TARGETS void ovoid3d(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1], sz = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double r = w / fractoriumZeps(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
    outX[i] += x[i] * r * sx;
    outY[i] += y[i] * r * sy;
    outZ[i] += z[i] * r * sz;
  }
}

// sphyp3D: spherical with a separate power of r² per axis; with zOn 0 z is carried (voxflame's rule for a term that
// leaves z alone: Fractorium would repeat the previous term's z there).
VOXFLAME_VARIATION_TARGETS void sphyp3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double px = P[0], py = P[1], pz = P[2];
  const bool zOn = std::round(P[3]) == 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = fractoriumZeps(x[i] * x[i] + y[i] * y[i] + z[i] * z[i]);
    outX[i] += x[i] * w / std::pow(t, px);
    outY[i] += y[i] * w / std::pow(t, py);
    outZ[i] += zOn ? z[i] * w / std::pow(t, pz) : w * z[i];
  }
}

// spherivoid: the point's spherical coordinates with the radius grown by the radius parameter (a void at the centre).
VOXFLAME_VARIATION_TARGETS void spherivoid(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radius = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double rho = std::sqrt(x[i] * x[i] + y[i] * y[i]);
    const double zr = std::sqrt(z[i] * z[i] + rho * rho);
    const double polar = std::acos(std::clamp(z[i] / zr, -1.0, 1.0));
    const double inverse = 1.0 / fractoriumZeps(rho);
    const double s = w * std::sin(polar) * (zr + radius);
    outX[i] += x[i] * inverse * s;
    outY[i] += y[i] * inverse * s;
    outZ[i] += w * std::cos(polar) * (zr + radius);
  }
}

// psphere: the plane wrapped onto a sphere by the angles wπx, wπy. As in Fractorium, the weight scales the angles,
// not the result, and z is cos(wπy)·zscale.
VOXFLAME_VARIATION_TARGETS void psphere(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double zscale = P[0], vpi = w * kPi;
  for (std::size_t i = 0; i < n; ++i) {
    const double c0 = x[i] * vpi, c1 = y[i] * vpi;
    const double cos1 = std::cos(c1);
    outX[i] += -std::cos(c0) * std::sin(c1);
    outY[i] += std::sin(c0) * cos1;
    outZ[i] += cos1 * zscale;
  }
}

// svf: the plane mapped onto a sphere (x as longitude, y as latitude) modulated by cos(n y).
VOXFLAME_VARIATION_TARGETS void svf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                    double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double freq = P[0];
  for (std::size_t i = 0; i < n; ++i) {
    const double cn = std::cos(freq * y[i]), cy = std::cos(y[i]);
    outX[i] += w * cy * cn * std::cos(x[i]);
    outY[i] += w * cy * cn * std::sin(x[i]);
    outZ[i] += w * std::sin(y[i]) * cn;
  }
}

// taurus: a torus from x and y. As in Fractorium, the (1 − sor) y part of z is outside the weight.
VOXFLAME_VARIATION_TARGETS void taurus(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                       double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double r = P[0], freq = P[1], inv = P[2], sor = P[3];
  const double invTimesR = inv * r, oneMinusInv = 1.0 - inv, oneMinusSor = 1.0 - sor;
  for (std::size_t i = 0; i < n; ++i) {
    const double sy = std::sin(y[i]);
    const double ir = invTimesR + oneMinusInv * r * std::cos(freq * x[i]);
    outX[i] += w * std::cos(x[i]) * (ir + sy);
    outY[i] += w * std::sin(x[i]) * (ir + sy);
    outZ[i] += w * sor * std::cos(y[i]) + oneMinusSor * y[i];
  }
}

VOXFLAME_VARIATION_TARGETS void helix(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double freq = P[0] * kTwoPi, width = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double t = z[i] * freq;
    outX[i] += w * (x[i] + std::cos(t) * width);
    outY[i] += w * (y[i] + std::sin(t) * width);
    outZ[i] += w * z[i];
  }
}

VOXFLAME_VARIATION_TARGETS void helicoid(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double freq = P[0] * kTwoPi;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = z[i] * freq + std::atan2(y[i], x[i]);
    const double wr = w * std::sqrt(x[i] * x[i] + y[i] * y[i]);
    outX[i] += wr * std::cos(t);
    outY[i] += wr * std::sin(t);
    outZ[i] += w * z[i];
  }
}

// linearT3D: each coordinate's magnitude raised to its own power, its sign kept.
VOXFLAME_VARIATION_TARGETS void linearT3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double px = P[0], py = P[1], pz = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += (x[i] < 0.0 ? -w : w) * std::pow(std::abs(x[i]), px);
    outY[i] += (y[i] < 0.0 ? -w : w) * std::pow(std::abs(y[i]), py);
    outZ[i] += (z[i] < 0.0 ? -w : w) * std::pow(std::abs(z[i]), pz);
  }
}

// ho: powers of cos x cos y, sin x cos y and sin y plus their multiples and a quarter of the angles atan2(y², z²),
// atan2(x², z²). Fractorium raises the magnitudes (the plug-in's pow of a negative number was NaN).
VOXFLAME_VARIATION_TARGETS void ho(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                   double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double px = P[0], py = P[1], pz = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    const double uu = x[i] * x[i], vv = y[i] * y[i], ww = z[i] * z[i];
    const double cv = std::cos(y[i]), sv = std::sin(y[i]);
    const double cucv = std::cos(x[i]) * cv, sucv = std::sin(x[i]) * cv;
    outX[i] += w * (std::pow(std::abs(cucv), px) + cucv * px + 0.25 * std::atan2(vv, ww));
    outY[i] += w * (std::pow(std::abs(sucv), py) + sucv * py + 0.25 * std::atan2(uu, ww));
    outZ[i] += w * (std::pow(std::abs(sv), pz) + sv * pz);
  }
}

VOXFLAME_VARIATION_TARGETS void splits3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1], sz = P[2];
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (x[i] >= 0.0 ? x[i] + sx : x[i] - sx);
    outY[i] += w * (y[i] >= 0.0 ? y[i] + sy : y[i] - sy);
    outZ[i] += w * (z[i] >= 0.0 ? z[i] + sz : z[i] - sz);
  }
}

// waves2_3D: waves2 with z waved by the mean of x and y.
VOXFLAME_VARIATION_TARGETS void waves23D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double freq = P[0], scale = P[1];
  for (std::size_t i = 0; i < n; ++i) {
    const double mean = (x[i] + y[i]) * 0.5;
    outX[i] += w * (x[i] + scale * std::sin(y[i] * freq));
    outY[i] += w * (y[i] + scale * std::sin(x[i] * freq));
    outZ[i] += w * (z[i] + scale * std::sin(mean * freq));
  }
}

// xerf: the error function of each coordinate, or for a coordinate of magnitude ≥ 2 that coordinate over |p|².
VOXFLAME_VARIATION_TARGETS void xerf(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                     double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i] + z[i] * z[i];
    outX[i] += w * (std::abs(x[i]) >= 2.0 ? x[i] / r2 : std::erf(x[i]));
    outY[i] += w * (std::abs(y[i]) >= 2.0 ? y[i] / r2 : std::erf(y[i]));
    outZ[i] += w * (std::abs(z[i]) >= 2.0 ? z[i] / r2 : std::erf(z[i]));
  }
}

// bubbleT3D: bubble's sphere (the inverse stereographic projection, z = 2/rad^exponentZ − 1) cut into stripes of
// longitude (number_of_stripes of them, the share ratio_of_stripes kept; negative counts invert which part) and
// with a hole around the pole of angle angle_of_hole degrees (negative: around the other pole; symmetryZ: at both).
// What is cut goes to the origin, or with modusBlur is turned onto the kept part (Fractorium's).
VOXFLAME_VARIATION_TARGETS void bubbleT3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double stripes = std::floor(P[0] + 0.5), absStripes = std::abs(stripes);
  const bool invStripes = stripes < 0.0;
  const double ratio = std::clamp(std::clamp(P[1], 0.0, 2.0), 0.01, 1.99);
  const double hole = std::clamp(P[2], -360.0, 360.0), exponentZ = P[3];
  const bool symmetryZ = fractoriumInteger(P[4], 0.0, 1.0) == 1.0, blur = fractoriumInteger(P[5], 0.0, 1.0) == 1.0;
  const double angStrip = absStripes != 0.0 ? kPi / absStripes : 0.0, strip2 = 2.0 * angStrip;
  const double sn = std::sin(angStrip), cs = std::cos(angStrip), strip1 = fractoriumZeps(ratio * angStrip);
  double holeAngle = symmetryZ ? (hole < 0.0 ? std::abs(hole) : std::min(hole, 179.9)) : hole;
  const bool invHole = holeAngle < 0.0;
  holeAngle = invHole ? std::abs(hole) / 360.0 * kTwoPi / 2.0 : kPi - holeAngle / 360.0 * kTwoPi / 2.0;
  const double holeComp = kPi - holeAngle;
  const bool pushesHole = blur && exponentZ == 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    double px = x[i], py = y[i], pz = z[i];
    const double rad = fractoriumZeps((px * px + py * py) / 4.0 + 1.0);
    if (absStripes != 0.0) {
      double a = std::atan2(px, py);
      if (a < 0.0) a += kTwoPi;
      // Fractorium subtracts 2π/|stripes| while the angle exceeds it: the remainder in (0, 2π/|stripes|].
      if (a > strip2) {
        a = laneFmod(a, strip2);
        if (a == 0.0) a = strip2;
      }
      const bool cut = invStripes ? a < strip1 : a > strip1;
      if (cut && !blur) {
        px = 0.0;
        py = 0.0;
      } else if (cut) {
        double c = cs, s = sn;
        const bool single = invStripes ? absStripes == 1.0 : ratio == 1.0;
        if (!single) {
          const double turn = invStripes ? a - (a - strip1) / strip1 * (strip2 - strip1)
                                         : a - (a - strip1) / fractoriumZeps(strip2 - strip1) * strip1;
          c = std::cos(turn);
          s = std::sin(turn);
        }
        const double tx = c * px - s * py, ty = s * px + c * py;
        px = tx;
        py = ty;
      }
    }
    px /= rad;
    py /= rad;
    double angZ = 0.0;
    if (px != 0.0 || py != 0.0) {
      pz = 2.0 / std::pow(rad, exponentZ) - 1.0;
      const double q = px * px + py * py;
      angZ = exponentZ <= 2.0 ? kPi - std::acos(pz / (q + pz * pz)) : kPi - std::atan2(q * q, pz);
    } else {
      pz = 0.0;
    }
    bool cut = false;
    double angTmp = 0.0;
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
      const double from = angZ - kPi / 2.0;
      const double fac = std::cos(angTmp) / std::cos(from);
      px *= fac;
      py *= fac;
      pz *= std::sin(angTmp) / std::sin(from);
    }
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * pz;
  }
}

// ---- 3D blurs ------------------------------------------------------------------------------------

VOXFLAME_VARIATION_TARGETS void square3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * (laneUniform(rnd[i]) - 0.5);
    outY[i] += w * (laneUniform(rnd[i]) - 0.5);
    outZ[i] += w * (laneUniform(rnd[i]) - 0.5);
  }
}

// farblur: a blur in a random direction whose size grows with the squared distance from the origin parameters.
VOXFLAME_VARIATION_TARGETS void farblur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double sx = P[0], sy = P[1], sz = P[2], x0 = P[3], y0 = P[4], z0 = P[5];
  for (std::size_t i = 0; i < n; ++i) {
    const double dx = x[i] - x0, dy = y[i] - y0, dz = z[i] - z0;
    const double r = w * (dx * dx + dy * dy + dz * dz) * laneGauss(rnd[i]);
    const double u = laneUniform(rnd[i]) * kTwoPi;
    const double v = laneUniform(rnd[i]) * kTwoPi;
    const double sv = std::sin(v);
    outX[i] += sx * r * sv * std::cos(u);
    outY[i] += sy * r * sv * std::sin(u);
    outZ[i] += sz * r * std::cos(v);
  }
}

// sphereblur: a point in the ball, uniform in direction, at radius (acos(2Ψ^power − 1)/π)^(2/3). A power below 0
// counts as 0 (Fractorium's), which puts every point on the sphere of radius (½)^(2/3).
VOXFLAME_VARIATION_TARGETS void sphereblur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double power = std::max(P[0], 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = laneUniform(rnd[i]) * kTwoPi;
    const double polar = std::acos(laneUniform(rnd[i]) * 2.0 - 1.0);
    const double q = std::acos(std::pow(laneUniform(rnd[i]), power) * 2.0 - 1.0) / kPi;
    const double r = w * std::cbrt(q * q);
    const double sz = std::sin(polar);
    outX[i] += r * std::cos(angle) * sz;
    outY[i] += r * std::sin(angle) * sz;
    outZ[i] += r * std::cos(polar);
  }
}

}  // namespace

void variation_kernels::addFractorium3DShapeVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  constexpr bool k3D = CatalogueAdder::k3D, kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  const auto count = &CatalogueAdder::count;
  add("blade3D", "(x (cos t + sin t), x (cos t − sin t), z (sin t − cos t)); t = Ψ w r (w the weight)", k3D, kRandom,
      &blade3D);
  add("blob3D", "ρ (x/r, y/r, s); s = sin(waves θ), ρ = r (low + (high − low)(½ + ½ s)) (Fractorium's)", k3D, kFixed,
      &blob3D, {{"low", 0.0, -1.0, 2.0}, {"high", 1.0, -1.0, 2.0}, {"waves", 1.0, -10.0, 10.0}});
  add("bubble2", "(x·x', y·y', z z') / (|p|²/4 + 1) + (z ± z', sign of z); x', y', z' the parameters x, y, z", k3D,
      kFixed, &bubble2, {{"x", 1.0, -2.0, 2.0}, {"y", 1.0, -2.0, 2.0}, {"z", 0.0, -2.0, 2.0}});
  add("disc3d", "(θ/pi)(sin(pi r), cos(pi r), r cos z); pi the parameter", k3D, kFixed, &disc3d,
      {{"pi", kPi, -6.0, 6.0}});
  add("ovoid3d", "(x·x', y·y', z·z') / |p|²; x', y', z' the parameters x, y, z", k3D, kFixed, &ovoid3d,
      {{"x", 1.0, -2.0, 2.0}, {"y", 1.0, -2.0, 2.0}, {"z", 1.0, -2.0, 2.0}});
  add("sphyp3D", "(x / t^stretchX, y / t^stretchY, z / t^stretchZ), t = |p|²; with zOn 0 z is carried", k3D, kFixed,
      &sphyp3D,
      {{"stretchX", 1.0, -2.0, 2.0},
       {"stretchY", 1.0, -2.0, 2.0},
       {"stretchZ", 1.0, -2.0, 2.0},
       count("zOn", 1.0, 0.0, 1.0)});
  add("spherivoid", "(x/r sin σ, y/r sin σ, cos σ)(|p| + radius); σ = acos(z/|p|) (Fractorium's)", k3D, kFixed,
      &spherivoid, {{"radius", 0.0, -2.0, 2.0}});
  add("psphere",
      "(−cos(wπx) sin(wπy), sin(wπx) cos(wπy), zscale cos(wπy)), the weight w inside the angles only (Fractorium's)",
      k3D, kFixed, &psphere, {{"zscale", 0.0, -2.0, 2.0}});
  add("svf", "cos(n y) (cos y cos x, cos y sin x, sin y)", k3D, kFixed, &svf, {{"n", 2.0, -10.0, 10.0}});
  add("taurus",
      "((R + sin y) cos x, (R + sin y) sin x, sor cos y) + (0, 0, (1 − sor) y / w), R = inv r + (1 − inv) r cos(n x) "
      "(w the weight; Fractorium's)",
      k3D, kFixed, &taurus,
      {{"r", 3.0, -5.0, 5.0}, {"n", 5.0, -10.0, 10.0}, {"inv", 1.5, -3.0, 3.0}, {"sor", 1.0, -2.0, 2.0}});
  add("helix", "(x + width cos(2π frequency z), y + width sin(2π frequency z), z)", k3D, kFixed, &helix,
      {{"frequency", 1.0, -5.0, 5.0}, {"width", 0.5, -2.0, 2.0}});
  add("helicoid", "r (cos(φ + 2π frequency z), sin(φ + 2π frequency z)), z", k3D, kFixed, &helicoid,
      {{"frequency", 1.0, -5.0, 5.0}});
  add("linearT3D", "(±|x|^powX, ±|y|^powY, ±|z|^powZ), each with its coordinate's sign", k3D, kFixed, &linearT3D,
      {{"powX", 1.0, -3.0, 3.0}, {"powY", 1.0, -3.0, 3.0}, {"powZ", 1.0, -3.0, 3.0}});
  add("ho",
      "(|cu|^xpow + xpow cu + ¼ atan2(y², z²), |su|^ypow + ypow su + ¼ atan2(x², z²), |sin y|^zpow + zpow sin y); cu = "
      "cos x cos y, su = sin x cos y",
      k3D, kFixed, &ho, {{"xpow", 3.0, -5.0, 5.0}, {"ypow", 3.0, -5.0, 5.0}, {"zpow", 3.0, -5.0, 5.0}});
  add("splits3D", "(x ± x', y ± y', z ± z'), ± each coordinate's sign; x', y', z' the parameters x, y, z", k3D, kFixed,
      &splits3D, {{"x", 0.0, -2.0, 2.0}, {"y", 0.0, -2.0, 2.0}, {"z", 0.0, -2.0, 2.0}});
  add("waves2_3D", "(x + scale sin(freq y), y + scale sin(freq x), z + scale sin(freq (x + y)/2))", k3D, kFixed,
      &waves23D, {{"freq", 2.0, -10.0, 10.0}, {"scale", 1.0, -2.0, 2.0}});
  add("xerf", "each coordinate u: erf(u), or u/|p|² where |u| ≥ 2", k3D, kFixed, &xerf);
  add("bubbleT3D",
      "bubble's sphere (x/ρ, y/ρ, 2/ρ^exponentZ − 1), ρ = r²/4 + 1, cut into |number_of_stripes| stripes of "
      "longitude of which the share ratio_of_stripes is kept (the rest for a negative count), with a hole of "
      "angle_of_hole degrees around the pole (the other pole when negative, both with symmetryZ); what is cut goes "
      "to the origin, or with modusBlur is turned onto what is kept (Fractorium's)",
      k3D, kFixed, &bubbleT3D,
      {count("number_of_stripes", 0.0, -20.0, 20.0),
       {"ratio_of_stripes", 1.0, 0.0, 2.0},
       {"angle_of_hole", 0.0, -360.0, 360.0},
       {"exponentZ", 1.0, -3.0, 3.0},
       count("symmetryZ", 0.0, 0.0, 1.0),
       count("modusBlur", 0.0, 0.0, 1.0)});
  add("square3D", "(Ψ₁ − ½, Ψ₂ − ½, Ψ₃ − ½): the unit cube", k3D, kRandom, &square3D);
  add("farblur",
      "(x' sin v cos u, y' sin v sin u, z' cos v) |p − o|² (Ψ₁ + Ψ₂ + Ψ₃ + Ψ₄ − 2); u = 2πΨ₅, v = 2πΨ₆; x', y', z' the "
      "parameters x, y, z, o = (x_origin, y_origin, z_origin)",
      k3D, kRandom, &farblur,
      {{"x", 1.0, -2.0, 2.0},
       {"y", 1.0, -2.0, 2.0},
       {"z", 1.0, -2.0, 2.0},
       {"x_origin", 0.0, -2.0, 2.0},
       {"y_origin", 0.0, -2.0, 2.0},
       {"z_origin", 0.0, -2.0, 2.0}});
  add("sphereblur",
      "ρ (cos a sin σ, sin a sin σ, cos σ); a = 2πΨ₁, σ = acos(2Ψ₂ − 1), ρ = (acos(2Ψ₃^power − 1)/π)^(2/3), power "
      "below 0 taken as 0",
      k3D, kRandom, &sphereblur, {{"power", 1.0, 0.0, 5.0}});
}

}  // namespace voxflame::core
