// JWildfire's variations that lean on Java's integer arithmetic, and its crops.
// Each variation is a kernel below and one row of the table at the end (see variations.h for
// the notation and variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "core/flame/variation_kernels.h"
#include "core/vector_math.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// Bob Jenkins' integer hash as bezo97's pixel_flow uses it, scaled to about [−1, 1].
inline double pixelFlowHash(std::int32_t a) {
  a = (a ^ 61) ^ (a >> 16);
  a = wrapAdd(a, wrapMul(a, 8));
  a = a ^ (a >> 4);
  a = wrapMul(a, 0x27d4eb2d);
  a = a ^ (a >> 15);
  return static_cast<double>(a) / 2147483647.0;
}

// pixel_flow (bezo97's Apophysis plugin, as JWildfire ports it): a streak of length len in the
// direction `angle` (degrees) from the origin, faded by Ψ⁴ and by a length hashed from the point's
// block of a grid of 1/width cells (widths and lengths vary by `seed`). The point itself is not
// added: with linear it draws streaks from every point. With enable_dc the colour index becomes
// the fade's Ψ (the plugin's direct colour, as Fractorium and JWildfire have it).
VOXFLAME_VARIATION_TARGETS void pixelFlow(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                          double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double radians = P[0] * 0.0174532925;  // JWildfire's rounded π/180
  const double len = P[1], width = P[2];
  const std::int32_t seed = javaInt(std::floor(std::clamp(P[3], -2147483648.0, 2147483647.0) + 0.5));
  const double dirX = w * len * std::cos(radians), dirY = w * len * std::sin(radians);
  const bool direct = std::round(P[4]) != 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r01 = laneUniform(rnd[i]);
    colour[i] = direct ? r01 : colour[i];
    std::int32_t blockX = javaInt(std::floor(x[i] * width));
    blockX = javaInt(static_cast<double>(blockX) + (2.0 - 4.0 * pixelFlowHash(wrapAdd(wrapMul(blockX, seed), 1))));
    std::int32_t blockY = javaInt(std::floor(y[i] * width));
    blockY = javaInt(static_cast<double>(blockY) + (2.0 - 4.0 * pixelFlowHash(wrapAdd(wrapMul(blockY, seed), 1))));
    const double length = (pixelFlowHash(wrapAdd(blockY, wrapMul(blockX, wrapMul(seed, -1)))) +
                           pixelFlowHash(wrapAdd(blockX, wrapMul(blockY, seed) / 2))) *
                          0.5;
    const double fade = length * r01 * r01 * r01 * r01;
    outX[i] += dirX * fade;
    outY[i] += dirY * fade;
    outZ[i] += w * z[i];
  }
}

// vibration2 (FarDareisMai's Apophysis plugin, as JWildfire ports it): two sine waves across the
// plane, each along direction dir (dir2) and displacing the point at angle + dir from it, their
// direction, angle, phase and amplitude modulated by cosines along the wave (dm, tm, fm, am).
struct VibrationWave {
  double dir, angle, freq, amp, phase, dm, dmFreq, tm, tmFreq, fm, fmFreq, am, amFreq;
};

inline double vibrationModulate(double amp, double freq, double along) {
  return amp * std::cos(along * freq * kTwoPi);
}

inline void addVibration(const VibrationWave& v, double x, double y, double& px, double& py) {
  const double along = x * std::cos(v.dir) + y * std::sin(v.dir);
  const double dirL = v.dir + vibrationModulate(v.dm, v.dmFreq, along);
  const double angleL = v.angle + vibrationModulate(v.tm, v.tmFreq, along);
  const double phaseL = vibrationModulate(v.fm, v.fmFreq, along) / v.freq;
  const double ampL = v.amp + v.amp * vibrationModulate(v.am, v.amFreq, along);
  const double total = angleL + dirL;
  const double alongL = x * std::cos(dirL) + y * std::sin(dirL);
  const double local = ampL * std::sin(alongL * v.freq * kTwoPi + phaseL + kTwoPi * v.phase / v.freq);
  px += local * std::cos(total);
  py += local * std::sin(total);
}

VOXFLAME_VARIATION_TARGETS void vibration2(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const VibrationWave first{P[0], P[1], P[2], P[3], P[4], P[10], P[11], P[12], P[13], P[14], P[15], P[16], P[17]};
  const VibrationWave second{P[5], P[6], P[7], P[8], P[9], P[18], P[19], P[20], P[21], P[22], P[23], P[24], P[25]};
  for (std::size_t i = 0; i < n; ++i) {
    double px = x[i], py = y[i];
    addVibration(first, x[i], y[i], px, py);
    addVibration(second, x[i], y[i], px, py);
    outX[i] += w * px;
    outY[i] += w * py;
    outZ[i] += w * z[i];
  }
}

// truchet (as JWildfire has it): a Truchet tiling of quarter-circle arcs (of the superellipse with
// `exponent`) on the unit grid of the point scaled by (cos r − sin r)/w, r = −rotation; each
// tile's orientation is hashed from the point's rounded cell and `seed` (a linear congruence,
// iterated up to 1000 times when extended). A point on an arc is drawn at size · (its place in
// the tile + ⌊p⌋), once per arc it lies on; the weight only scales the grid, and z is carried
// (by the weight) only from the second arc, all as JWildfire does. Its direct colour is not
// applied; the importer says so when a file sets it.
inline double javaRound(double value) {
  return std::floor(value + 0.5);
}

VOXFLAME_VARIATION_TARGETS void truchet(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const bool extended = std::clamp(javaRound(P[0]), 0.0, 1.0) == 1.0;
  const double exponent = std::clamp(P[1], 0.001, 2.0), width = std::clamp(P[2], 0.001, 1.0);
  const double rotation = P[3], size = std::clamp(P[4], 0.001, 10.0);
  const double seed = std::abs(P[5]);
  const bool directColour = std::clamp(std::round(P[6]), 0.0, 1.0) == 1.0;  // Tools.FTOI
  const double seed2 = std::sqrt(seed + seed / 2.0 + 1e-300) / (seed * 0.5 + 1e-300) * 0.25;
  const double rMax = 0.5 * (std::pow(2.0, 1.0 / exponent) - 1.0) * width;
  const double scale = (std::cos(-rotation) - std::sin(-rotation)) / w;
  constexpr double kModBase = 65535.0, kMultiplier = 32747.0, kOffset = 12345.0;
  const auto norm = [&](double a, double b) {
    return std::pow(std::pow(std::abs(a), exponent) + std::pow(std::abs(b), exponent), 1.0 / exponent);
  };
  for (std::size_t i = 0; i < n; ++i) {
    double tx = x[i] * scale, ty = y[i] * scale;
    tx -= static_cast<double>(javaInt(javaRound(tx)));
    ty -= static_cast<double>(javaInt(javaRound(ty)));
    if (tx < 0.0) tx += 1.0;
    if (ty < 0.0) ty += 1.0;
    double tile = 0.0;
    if (seed == 1.0) {
      tile = 1.0;
    } else if (seed != 0.0) {
      double randint;
      if (!extended) {
        const double xr = javaRound(x[i]) * seed2, yr = javaRound(y[i]) * seed2;
        randint = (xr + yr + xr * yr + seed) * seed2 / 2.0;
        randint = std::fmod(randint * kMultiplier + kOffset, kModBase);
      } else {
        const std::int32_t xr = javaInt(javaRound(x[i])), yr = javaInt(javaRound(y[i]));
        const double iterations =
            std::min(std::abs(static_cast<double>(wrapAdd(wrapAdd(xr, yr), wrapMul(xr, yr)))), 1000.0);
        randint = std::floor(seed) + iterations;
        for (double k = 0.0; k < iterations; k += 1.0) randint = std::fmod(randint * kMultiplier + kOffset, kModBase);
      }
      tile = std::fmod(randint, 2.0);
    }
    const bool diagonal = extended ? tile == 1.0 : tile < 1.0;
    const double r0 = diagonal ? norm(tx, ty) : norm(tx - 1.0, ty);
    const double r1 = diagonal ? norm(tx - 1.0, ty - 1.0) : norm(tx, ty - 1.0);
    const double px = size * (tx + std::floor(x[i])), py = size * (ty + std::floor(y[i]));
    if (std::abs(r0 - 0.5) / rMax < 1.0) {
      if (directColour) colour[i] = std::clamp(r0, 0.0, 1.0);
      outX[i] += px;
      outY[i] += py;
    }
    if (std::abs(r1 - 0.5) / rMax < 1.0) {
      if (directColour) colour[i] = std::clamp(1.0 - r1, 0.0, 1.0);
      outX[i] += px;
      outY[i] += py;
      outZ[i] += w * z[i];
    }
  }
}

// Fractorium's nBlur: a blur filling a regular polygon of numEdges sides (its corners favoured by
// highlightEdges), optionally cut into numStripes stripes per side (negative: the other stripes)
// whose widths ratioStripes sets, with a hole of ratioHole, or its circumcircle. Fractorium's
// precomputed values are worked out per call; numEdges and numStripes are held within ±1000 here,
// as Fractorium's loops run once per edge and stripe, and exactCalc's rejection of points outside
// the ring gives up after 100 tries (keeping the last).
struct NBlurSetup {
  double numEdges, midAngle, angStart, angStripes, ratioStripes, ratioComplement, ratioHole, tan90m2, arcTan1, arcTan2,
      speedCalc1, speedCalc2, maxStripes;
  bool hasStripes, negStripes, circumCircle, equalBlur, exactCalc;
};

struct NBlurPoint {
  double x, y, lenXY, lenInner, lenOuter;
};

inline NBlurPoint nBlurRandomPoint(const NBlurSetup& s, std::uint32_t& random) {
  double angXY;
  if (s.exactCalc) {
    angXY = laneUniform(random) * kTwoPi;
  } else {
    const double t = laneUniform(random);
    const double edge = std::floor(laneUniform(random) * s.numEdges);
    angXY = (std::atan(s.arcTan1 * (t - 0.5)) / s.arcTan2 + 0.5 + edge) * s.midAngle;
  }
  double angMem = angXY;
  double px = std::sin(angXY), py = std::cos(angXY);
  while (angXY > s.midAngle) angXY -= s.midAngle;
  if (s.hasStripes) {
    int count = 0;
    double angTmp = s.angStart;
    while (angXY > angTmp) {
      angTmp += s.angStripes;
      if (angTmp > s.midAngle) angTmp = s.midAngle;
      ++count;
    }
    if (angTmp != s.midAngle) angTmp -= s.angStart;
    // The negative stripes are the positive ones' complement: the roles of odd and even stripes
    // and of the two ratios swap.
    const int drawn = s.negStripes ? 0 : 1;
    const double ratio = s.negStripes ? s.ratioComplement : s.ratioStripes;
    const double speed = s.negStripes ? s.speedCalc1 : s.speedCalc2;
    const auto turnTo = [&](double angle) {
      px = std::sin(angle);
      py = std::cos(angle);
    };
    if ((count & 1) == drawn) {
      if (angXY > angTmp && (!s.negStripes || count != s.maxStripes)) {
        angXY += s.angStart;
        angMem += s.angStart;
        turnTo(angMem);
        angTmp += s.angStripes;
        ++count;
      } else {
        angXY -= s.angStart;
        angMem -= s.angStart;
        turnTo(angMem);
        angTmp -= s.angStripes;
        --count;
      }
    }
    const int kept = 1 - drawn;
    if ((count & 1) == kept && ratio > 1.0) {
      if (angXY > angTmp && count != s.maxStripes) {
        angMem = angMem - angXY + angTmp + (angXY - angTmp) / s.angStart * ratio * s.angStart;
        angXY = angTmp + (angXY - angTmp) / s.angStart * ratio * s.angStart;
      } else {
        angMem = angMem - angXY + angTmp - (angTmp - angXY) / s.angStart * ratio * s.angStart;
        angXY = angTmp + (angXY - angTmp) / s.angStart * ratio * s.angStart;
      }
      turnTo(angMem);
    }
    if ((count & 1) == kept && ratio < 1.0) {
      const auto squeezeDown = [&] {
        if (angTmp - angXY > speed) {
          const double shift = (angTmp - speed - angXY) * speed / (s.angStart - speed);
          turnTo(angMem - angXY + angTmp - shift);
          angXY = angTmp - shift;
        }
      };
      if (std::abs(angXY - angTmp) > speed && count != s.maxStripes) {
        if (angXY - angTmp > speed) {
          const double shift = (angXY - (angTmp + speed)) * speed / (s.angStart - speed);
          turnTo(angMem - angXY + angTmp + shift);
          angXY = angTmp + shift;
        }
        squeezeDown();
      }
      if (count == s.maxStripes) {
        if (s.negStripes) angTmp = s.midAngle;
        squeezeDown();
      }
    }
  }
  const double outerX = s.tan90m2 / (s.tan90m2 - std::tan(angXY)), outerY = outerX * std::tan(angXY);
  NBlurPoint point{};
  point.lenOuter = std::sqrt(outerX * outerX + outerY * outerY);
  const auto draw = [&] { return s.equalBlur ? std::sqrt(laneUniform(random)) : laneUniform(random); };
  double radius = draw();
  if (!s.exactCalc && !s.circumCircle) radius *= point.lenOuter;
  point.lenInner = s.ratioHole * point.lenOuter;
  if (!s.exactCalc && radius < point.lenInner) {
    const double span = s.circumCircle ? 1.0 - point.lenInner + std::numeric_limits<double>::epsilon()
                                       : point.lenOuter - point.lenInner;
    radius = draw() * span + point.lenInner;
  }
  point.x = px * radius;
  point.y = py * radius;
  point.lenXY = std::sqrt(point.x * point.x + point.y * point.y);
  return point;
}

VOXFLAME_VARIATION_TARGETS void nBlur(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                      double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  NBlurSetup s{};
  s.numEdges = fractoriumInteger(P[0], 3.0, 1000.0);
  const double numStripes = fractoriumInteger(P[1], -1000.0, 1000.0);
  s.ratioStripes = std::clamp(P[2], 0.0, 2.0);
  s.ratioHole = std::clamp(P[3], 0.0, 1.0);
  s.circumCircle = fractoriumInteger(P[4], 0.0, 1.0) == 1.0;
  const bool adjustToLinear = fractoriumInteger(P[5], 0.0, 1.0) == 1.0;
  s.equalBlur = fractoriumInteger(P[6], 0.0, 1.0) == 1.0;
  s.exactCalc = fractoriumInteger(P[7], 0.0, 1.0) == 1.0;
  double highlight = P[8];
  s.hasStripes = numStripes != 0.0;
  s.negStripes = numStripes < 0.0;
  const double absStripes = std::abs(numStripes);
  s.midAngle = kTwoPi / s.numEdges;
  if (s.hasStripes) {
    s.angStripes = s.midAngle / (2.0 * absStripes);
    s.angStart = s.angStripes / 2.0;
    s.ratioComplement = 2.0 - s.ratioStripes;
  }
  if (s.ratioHole > 0.95 && s.exactCalc && !s.circumCircle) s.ratioHole = 0.95;
  s.tan90m2 = std::tan(kPi / 2.0 + s.midAngle / 2.0);
  const double sinA = std::sin(s.midAngle / 2.0), cosA = std::cos(s.midAngle / 2.0);
  if (!(highlight > 0.1)) highlight = 0.1;
  double adjusted = w;
  if (adjustToLinear) {
    const double turns = std::fmod(s.numEdges, 4.0) == 0.0 ? s.numEdges / 2.0 - 1.0 : std::floor(s.numEdges / 2.0);
    adjusted = w / fractoriumZeps(std::sqrt(2.0 - 2.0 * std::cos(s.midAngle * turns)) / 2.0);
  }
  if (s.circumCircle) {
    s.exactCalc = false;
    highlight = 0.1;
  }
  s.speedCalc1 = s.ratioComplement * s.angStart;
  s.speedCalc2 = s.ratioStripes * s.angStart;
  s.maxStripes = 2.0 * absStripes;
  s.arcTan1 = (s.negStripes ? 7.5 : 13.0) / std::pow(s.numEdges, 1.3) * highlight;
  s.arcTan2 = 2.0 * std::atan(s.arcTan1 / -2.0);
  for (std::size_t i = 0; i < n; ++i) {
    NBlurPoint point = nBlurRandomPoint(s, rnd[i]);
    for (int tries = 1; s.exactCalc && tries < 100 && (point.lenXY < point.lenInner || point.lenXY > point.lenOuter);
         ++tries)
      point = nBlurRandomPoint(s, rnd[i]);
    outX[i] += adjusted * (cosA * point.x - sinA * point.y);
    outY[i] += adjusted * (sinA * point.x + cosA * point.y);
    outZ[i] += w * z[i];
  }
}

// shredlin (as JWildfire has it): each axis cut into strips of width distance, each strip narrowed
// to `width` of itself about its middle. JWildfire assigns its x and y instead of adding them,
// which discards the terms before it on the same transform: the chaos game clears them first
// (VariationInfo::replaces), and the function adds to what is left.
VOXFLAME_VARIATION_TARGETS void shredlin(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                         double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double xDistance = P[0], xWidth = std::clamp(P[1], -1.0, 1.0);
  const double yDistance = P[2], yWidth = std::clamp(P[3], -1.0, 1.0);
  const auto shred = [](double v, double distance, double width) {
    const double range = v / distance;
    const double whole = static_cast<double>(javaInt(range));
    const double side = v < 0.0 ? 1.0 : 0.0;
    return distance * ((range - whole) * width + whole + (0.5 - side) * (1.0 - width));
  };
  for (std::size_t i = 0; i < n; ++i) {
    outX[i] += w * shred(x[i], xDistance, xWidth);
    outY[i] += w * shred(y[i], yDistance, yWidth);
    outZ[i] += w * z[i];
  }
}

// ---- crops ----------------------------------------------------------------------------------

// crop_trapezoid (Jesus Sosa's, as JWildfire has it): keeps the point inside the trapezoid of
// half-width base_sup at y = −height, base_inf at y = +height (its sides straight between), and
// drops the rest (NaN: JWildfire hides it); invert keeps the outside instead. Inside or outside is
// the sign of Inigo Quilez' signed distance to the trapezoid, the test JWildfire makes. JWildfire
// assigns x and y (VariationInfo::replaces); z is carried.
VOXFLAME_VARIATION_TARGETS void cropTrapezoid(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                              double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double r1 = P[0], r2 = P[1], he = P[2];
  const bool invert = std::clamp(P[3], 0.0, 1.0) >= 1.0;  // JWildfire's (int) of the clamped value
  // The slanted side from (r2, he) towards (r1, −he), as the vector k2 = (r2 − r1, 2 he).
  const double k2x = r2 - r1, k2y = 2.0 * he, k2k2 = k2x * k2x + k2y * k2y;
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < n; ++i) {
    const double px = std::abs(x[i]), py = y[i];
    // Beyond the flat sides (ca) and beyond the slanted one (cb).
    const double cax = std::max(0.0, px - (py < 0.0 ? r1 : r2)), cay = std::abs(py) - he;
    const double along = std::clamp(((r2 - px) * k2x + (he - py) * k2y) / k2k2, 0.0, 1.0);
    const double cbx = px - r2 + k2x * along, cby = py - he + k2y * along;
    const double sign = cbx < 0.0 && cay < 0.0 ? -1.0 : 1.0;
    const double d = sign * std::sqrt(std::min(cax * cax + cay * cay, cbx * cbx + cby * cby));
    const bool drop = invert ? d <= 0.0 : d > 0.0;
    outX[i] += drop ? kNaN : w * x[i];
    outY[i] += drop ? kNaN : w * y[i];
    outZ[i] += drop ? kNaN : w * z[i];
  }
}

}  // namespace

void variation_kernels::addJwildfireVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  [[maybe_unused]] const auto count = &CatalogueAdder::count;

  add("pixel_flow",
      "len · h Ψ⁴ (cos angle°, sin angle°), z: streaks, not the point; h the mean of two hashes (Bob Jenkins') of "
      "the point's block ⌊(x, y)·width⌋, each block shifted by up to ±2 by a hash with seed (bezo97's; files write "
      "the parameters bare: angle, len, width, seed, enable_dc); with enable_dc the colour index becomes Ψ",
      k2D, kRandom, &pixelFlow,
      {{"angle", 90.0, -360.0, 360.0},
       {"len", 0.1, -5.0, 5.0},
       {"width", 200.0, 1.0, 500.0},
       count("seed", 42.0, 0.0, 1000000.0),
       count("enable_dc", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  add("vibration2",
      "p + Σ over two waves a sin(2π freq d' + m_f/freq + 2π phase/freq) (cos(angle' + dir'), sin(angle' + dir')), z; "
      "d = x cos dir + y sin dir, dir' = dir + m_d, angle' = angle + m_t, a = amp (1 + m_a), d' = x cos dir' + y sin "
      "dir', each m = (dm, tm, fm, am) cos(2π d ·(dmfreq, …)); the second wave has the parameters ending in 2",
      k2D, kFixed, &vibration2,
      {{"dir", 0.0, -kPi, kPi},       {"angle", 1.5708, -kPi, kPi}, {"freq", 1.0, -5.0, 5.0},
       {"amp", 0.25, -1.0, 1.0},      {"phase", 0.0, -1.0, 1.0},    {"dir2", 1.5708, -kPi, kPi},
       {"angle2", 1.5708, -kPi, kPi}, {"freq2", 1.0, -5.0, 5.0},    {"amp2", 0.25, -1.0, 1.0},
       {"phase2", 0.0, -1.0, 1.0},    {"dm", 0.0, -1.0, 1.0},       {"dmfreq", 0.1, -1.0, 1.0},
       {"tm", 0.0, -1.0, 1.0},        {"tmfreq", 0.1, -1.0, 1.0},   {"fm", 0.0, -1.0, 1.0},
       {"fmfreq", 0.1, -1.0, 1.0},    {"am", 0.0, -1.0, 1.0},       {"amfreq", 0.1, -1.0, 1.0},
       {"d2m", 0.0, -1.0, 1.0},       {"d2mfreq", 0.1, -1.0, 1.0},  {"t2m", 0.0, -1.0, 1.0},
       {"t2mfreq", 0.1, -1.0, 1.0},   {"f2m", 0.0, -1.0, 1.0},      {"f2mfreq", 0.1, -1.0, 1.0},
       {"a2m", 0.0, -1.0, 1.0},       {"a2mfreq", 0.1, -1.0, 1.0}});
  add("truchet",
      "size (q + ⌊(x, y)⌋) once for each Truchet arc the point lies on (|‖q − corner‖_exponent − ½| < rmax), else "
      "nothing; q the point's place in its unit cell after scaling by (cos r − sin r)/w (r = −rotation, w the "
      "weight), the arcs round the corners (0, 0) and (1, 1) or (1, 0) and (0, 1) by a hash of the cell and seed, "
      "rmax = (2^(1/exponent) − 1) arc_width/2; z (w z from the second arc only); the weight is not applied "
      "otherwise; direct_color sets the colour index to ‖q − corner‖ on the first arc and 1 − ‖q − corner‖ on the "
      "second, held within 0…1 (JWildfire's)",
      k2D, kFixed, &truchet,
      {count("extended", 0.0, 0.0, 1.0),
       {"exponent", 2.0, 0.001, 2.0},
       {"arc_width", 0.5, 0.001, 1.0},
       {"rotation", 0.0, -kPi, kPi},
       {"size", 1.0, 0.001, 10.0},
       {"seed", 50.0, 0.0, 1000.0},
       count("direct_color", 0.0, 0.0, 1.0)});
  catalogue.back().directColour = true;
  add("nBlur",
      "a random point of a regular numEdges-gon (corners favoured by highlightEdges; its stripes with numStripes, "
      "their widths by ratioStripes; a hole of ratioHole; its circumcircle with circumCircle; uniform with "
      "equalBlur; exact rejection with exactCalc), turned by half a side's angle and scaled to linear's size with "
      "adjustToLinear, z (Fractorium's; numEdges and numStripes held within ±1000)",
      k2D, kRandom, &nBlur,
      {count("numEdges", 3.0, 3.0, 12.0),
       count("numStripes", 0.0, -20.0, 20.0),
       {"ratioStripes", 1.0, 0.0, 2.0},
       {"ratioHole", 0.0, 0.0, 1.0},
       count("circumCircle", 0.0, 0.0, 1.0),
       count("adjustToLinear", 1.0, 0.0, 1.0),
       count("equalBlur", 1.0, 0.0, 1.0),
       count("exactCalc", 0.0, 0.0, 1.0),
       {"highlightEdges", 1.0, 0.1, 4.0}});
  add("shredlin",
      "(xdistance ((u − [u]) xwidth + [u] + (½ − [x < 0])(1 − xwidth)), the same for y, z); u = x/xdistance, [u] "
      "its integer part (JWildfire's, whose x and y replace those of the terms before it)",
      k2D, kFixed, &shredlin,
      {{"xdistance", 1.0, 0.05, 4.0},
       {"xwidth", 0.5, -1.0, 1.0},
       {"ydistance", 1.0, 0.05, 4.0},
       {"ywidth", 0.5, -1.0, 1.0}});
  catalogue.back().replaces = VariationInfo::Replaces::XY;
  add("crop_trapezoid",
      "p where it lies inside the trapezoid of half-widths base_sup at y = −height and base_inf at y = height "
      "(outside with invert), else nothing (the point is dropped, as JWildfire hides it); x and y replace those of "
      "the terms before it (Jesus Sosa's, as JWildfire has it; files write base_sup as \"Base Sup.\" and base_inf "
      "as \"Base Inf.\")",
      k2D, kFixed, &cropTrapezoid,
      {{"base_sup", 0.5, 0.0, 2.0},
       {"base_inf", 0.2, 0.0, 2.0},
       {"height", 0.5, 0.0, 2.0},
       count("invert", 0.0, 0.0, 1.0)});
  catalogue.back().replaces = VariationInfo::Replaces::XY;
}

}  // namespace voxflame::core
