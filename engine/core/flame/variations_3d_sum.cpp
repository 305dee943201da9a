// Fractorium's 3D variations that work on the running sum of their transform: an ordinary term of
// them reads the sum of the ordinary terms before it (which the output arrays hold when it is called,
// VariationInfo::readsSum) and may rewrite it, while its pre_ and post_ forms read the point they
// map instead (in.stage tells which). Each variation is a kernel below and one row of the table at
// the end (see variations.h for the notation and variation_kernels.h for what the files share).
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/flame/variation_kernels.h"

namespace voxflame::core {

namespace {

using namespace variation_kernels;

// cubic3D's and cubicLattice_3D's spread: xpand/2, or √xpand/2 beyond ±1.
inline double latticeFill(double xpand) {
  return std::abs(xpand) <= 1.0 ? xpand * 0.5 : std::sqrt(xpand) * 0.5;
}

// One of the cube's eight corners (±1, ±1, ±1), picked by ⌊8Ψ⌋ in Fractorium's order: x is + for
// the first four, y − for the odd ones, z − for 2, 3, 6, 7.
struct Corner {
  double x, y, z;
};
[[gnu::always_inline]] inline Corner cubeCorner(double u) {
  const double node = std::floor(u * 8.0);
  const double half = node - 4.0 * std::floor(node / 4.0);  // node mod 4
  return {node < 4.0 ? 1.0 : -1.0, half == 1.0 || half == 3.0 ? -1.0 : 1.0, half >= 2.0 ? -1.0 : 1.0};
}

// cubic3D: the sum before it s (the point itself for a pre_ or post_ term) pulled towards the point p
// by the fill (smooth (1 − fill) and smooth fill, smooth = 2w up to ½, shaped by style through the
// angles atan2(x, z) and atan2(y, z)), plus w/2 towards a random corner of the cube. An ordinary term
// thus adds to the sum a copy of itself so moved.
VOXFLAME_VARIATION_TARGETS void cubic3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double fill = latticeFill(P[0]), style = P[1];
  const double smooth = std::abs(w) <= 0.5 ? w * 2.0 : 1.0;
  const double smoothStyle =
      std::abs(style) <= 1.0 ? style : (style > 1.0 ? 1.0 + (style - 1.0) * 0.25 : (style + 1.0) * 0.25 - 1.0);
  const double smoothFill = smooth * fill, smoothRest = smooth * (1.0 - fill), half = w * 0.5;
  const bool sum = in.stage == VariationStage::Normal;
  for (std::size_t i = 0; i < n; ++i) {
    const Corner k = cubeCorner(laneUniform(rnd[i]));
    const double ex = 1.0 - smoothStyle * (1.0 - std::cos(std::atan2(x[i], z[i])));
    const double ey = 1.0 - smoothStyle * (1.0 - std::sin(std::atan2(y[i], z[i])));
    const double mean = smoothStyle > 1.0 ? (ex + ey) / 2.0 * smoothStyle : (ex + ey) * 0.5;
    const double ez = 1.0 - smoothStyle * (1.0 - mean);
    const double px = sum ? outX[i] : x[i], py = sum ? outY[i] : y[i], pz = sum ? outZ[i] : z[i];
    outX[i] += px - smoothRest * px * ex + x[i] * smoothFill * ex + k.x * half;
    outY[i] += py - smoothRest * py * ey + y[i] * smoothFill * ey + k.y * half;
    outZ[i] += pz - smoothRest * pz * ez + z[i] * smoothFill * ez + k.z * half;
  }
}

// cubicLattice_3D: (s + p) fill, s the sum before it (the point itself for a pre_ or post_ term),
// plus w towards a random corner of the cube; style 2 scales the three coordinates by cos atan2(x,
// z), sin atan2(y, z) and their mean.
VOXFLAME_VARIATION_TARGETS void cubicLattice3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                               double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double fill = latticeFill(P[0]);
  const bool shaped = fractoriumInteger(P[1], 1.0, 2.0) == 2.0;
  const bool sum = in.stage == VariationStage::Normal;
  for (std::size_t i = 0; i < n; ++i) {
    const Corner k = cubeCorner(laneUniform(rnd[i]));
    const double ex = shaped ? std::cos(std::atan2(x[i], z[i])) : 1.0;
    const double ey = shaped ? std::sin(std::atan2(y[i], z[i])) : 1.0;
    const double ez = shaped ? (ex + ey) * 0.5 : 1.0;
    const double px = sum ? outX[i] : x[i], py = sum ? outY[i] : y[i], pz = sum ? outZ[i] : z[i];
    outX[i] += (px + x[i]) * fill * ex + k.x * w;
    outY[i] += (py + y[i]) * fill * ey + k.y * w;
    outZ[i] += (pz + z[i]) * fill * ez + k.z * w;
  }
}

// popcorn2_3D: popcorn2 at half weight in x and y; z is v z sin(tan c) t, t = z or, where z is 0,
// v sin(tan c) φ; plus v sin(tan c) φ where the z of the sum before it (of the point for a pre_ or
// post_ term) is 0. v = w|w| up to |w| = 1, w beyond.
VOXFLAME_VARIATION_TARGETS void popcorn23D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                           double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double px = P[0], py = P[1], pz = P[2], c = P[3];
  const double sinTanC = std::sin(std::tan(c)), half = w * 0.5, v = std::abs(w) <= 1.0 ? std::abs(w) * w : w;
  const bool sum = in.stage == VariationStage::Normal;
  for (std::size_t i = 0; i < n; ++i) {
    const double lift = v * sinTanC * std::atan2(y[i], x[i]);
    const double t = z[i] == 0.0 ? lift : z[i];
    const double other = sum ? outZ[i] : z[i];
    outX[i] += half * (x[i] + px * std::sin(std::tan(c * y[i])));
    outY[i] += half * (y[i] + py * std::sin(std::tan(c * x[i])));
    outZ[i] += (other == 0.0 ? lift : 0.0) + v * (pz * sinTanC * t);
  }
}

// roundspher3D: w² (x, y, t)/(d e), d = r² + t², e = 1/d + (2/π)², t = z or cos r where z is 0; the z
// of the sum before it (of the point for a pre_ or post_ term), or cos r where that is 0, is kept in
// z: an ordinary term replaces the sum's z by it plus its own.
VOXFLAME_VARIATION_TARGETS void roundspher3D(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                             double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  constexpr double kTwoOverPi = 2.0 / kPi;
  const bool sum = in.stage == VariationStage::Normal;
  for (std::size_t i = 0; i < n; ++i) {
    const double r2 = x[i] * x[i] + y[i] * y[i], cosR = std::cos(std::sqrt(r2));
    const double t = z[i] == 0.0 ? cosR : z[i];
    const double other = sum ? outZ[i] : z[i];
    const double keep = other == 0.0 ? cosR : other;
    const double d = r2 + t * t, e = 1.0 / d + kTwoOverPi * kTwoOverPi;
    outX[i] += w * (w / d * x[i] / e);
    outY[i] += w * (w / d * y[i] / e);
    outZ[i] = (sum ? 0.0 : outZ[i]) + keep + w * (w / d * t / e);
  }
}

// extrude: z becomes max(w, 0) with the chance root_face, else w Ψ₂. An ordinary term adds nothing
// to x and y and replaces the z of the terms before it (Replaces::Z); a pre_ or post_ term keeps x
// and y.
VOXFLAME_VARIATION_TARGETS void extrude(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const double rootFace = P[0], top = std::max(w, 0.0);
  const double keep = in.stage == VariationStage::Normal ? 0.0 : 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double u1 = laneUniform(rnd[i]), u2 = laneUniform(rnd[i]);
    outX[i] += keep * x[i];
    outY[i] += keep * y[i];
    outZ[i] += u1 < rootFace ? top : w * u2;
  }
}

// octapol's shape: an octagon of squares and triangles about the origin (s the inner square's side, t
// the arms), Fractorium's corner names. Its rectangles are given top-left and bottom-right with y
// growing upwards, so that for positive s and t they hold no point: only the triangles and the disc
// catch points, as in Fractorium.
struct Pt {
  double x, y;
};
struct Octapol {
  double polarWeight, st, radius;
  Pt a, b, c, d, e, f, g, h, i, j, k, l;
};
inline Octapol octapolShape(const double* P) {
  const double s = std::abs(P[2]), t = std::abs(P[3]), h = 0.5 * s;
  Octapol o{};
  o.polarWeight = P[0];
  o.st = h + t;
  o.radius = 0.707106781 * s * std::abs(P[1]);
  o.a = {-h, h + t};
  o.b = {h, h + t};
  o.c = {t, h};
  o.d = {t, -h};
  o.e = {h, -h - t};
  o.f = {-h, -h - t};
  o.g = {-t, -h};
  o.h = {-t, h};
  o.i = {-h, h};
  o.j = {h, h};
  o.k = {-h, -h};
  o.l = {h, -h};
  return o;
}
// Fractorium's HitsRect(top-left, bottom-right, p).
inline bool inRect(Pt tl, Pt br, Pt p) {
  return p.x >= tl.x && p.y >= tl.y && p.x <= br.x && p.y <= br.y;
}
// Whether p lies strictly inside the triangle (a, b, c), by its barycentric coordinates.
inline bool inTriangle(Pt a, Pt b, Pt c, Pt p) {
  const double v0x = c.x - a.x, v0y = c.y - a.y, v1x = b.x - a.x, v1y = b.y - a.y, v2x = p.x - a.x, v2y = p.y - a.y;
  const double d00 = v0x * v0x + v0y * v0y, d01 = v0x * v1x + v0y * v1y, d02 = v0x * v2x + v0y * v2y;
  const double d11 = v1x * v1x + v1y * v1y, d12 = v1x * v2x + v1y * v2y;
  const double denom = d00 * d11 - d01 * d01;
  if (denom == 0.0) return false;
  const double u = (d11 * d02 - d01 * d12) / denom, v = (d00 * d12 - d01 * d02) / denom;
  return u + v < 1.0 && u > 0.0 && v > 0.0;
}

// octapol: q = 0.15 (x, y); within the disc of radius s |radius|/√2, w q plus w lerp(q, (φ, r),
// polarweight ln (r/R)²); within the octagon's triangles, 2 w q; elsewhere w q, and an ordinary term
// discards the x and y of the terms before it there. z is w z.
VOXFLAME_VARIATION_TARGETS void octapol(const VariationInput& in, double* __restrict ox, double* __restrict oy,
                                        double* __restrict oz) {
  VOXFLAME_VARIATION_BEGIN(in, ox, oy, oz)
  const Octapol o = octapolShape(P);
  const bool sum = in.stage == VariationStage::Normal;
  for (std::size_t i = 0; i < n; ++i) {
    const double qx = x[i] * 0.15, qy = y[i] * 0.15;
    double addX = 0.0, addY = 0.0;
    bool clear = false;
    const double r = std::sqrt(qx * qx + qy * qy);
    if (o.radius > 0.0 && r <= o.radius) {
      // A polar weight of 0 leaves the point as it is, even at the origin (where ln 0 would make 0/0).
      const double rd = o.polarWeight == 0.0 ? 0.0 : std::log((r / o.radius) * (r / o.radius)) * o.polarWeight;
      const double phi = std::atan2(qy, qx);
      addX = w * (qx + (phi - qx) * rd);
      addY = w * (qy + (r - qy) * rd);
    } else if (std::abs(qx) <= o.st && std::abs(qy) <= o.st) {
      const Pt q{qx, qy};
      const bool hit = inRect(o.h, o.k, q) || inRect(o.j, o.d, q) || inRect(o.a, o.j, q) || inRect(o.k, o.e, q) ||
                       inTriangle(o.i, o.a, o.h, q) || inTriangle(o.j, o.b, o.c, q) || inTriangle(o.l, o.d, o.e, q) ||
                       inTriangle(o.k, o.f, o.g, q);
      addX = hit ? w * qx : 0.0;
      addY = hit ? w * qy : 0.0;
      clear = !hit;
    } else {
      clear = true;
    }
    if (clear && sum) {
      outX[i] = 0.0;
      outY[i] = 0.0;
    }
    outX[i] += addX + w * qx;
    outY[i] += addY + w * qy;
    outZ[i] += w * z[i];
  }
}

}  // namespace

void variation_kernels::addFractorium3DSumVariations(std::vector<VariationInfo>& catalogue) {
  const CatalogueAdder add(catalogue);
  [[maybe_unused]] constexpr bool k2D = CatalogueAdder::k2D, k3D = CatalogueAdder::k3D,
                                  kRandom = CatalogueAdder::kRandom, kFixed = CatalogueAdder::kFixed;
  add("cubic3D",
      "s − σ(1 − f) s e + σ f p e + (w/2) k: s the sum before it (p for pre_/post_), f = xpand/2 (√xpand/2 beyond 1), "
      "σ = min(2w, 1), e = (1 − ς(1 − cos atan2(x, z)), 1 − ς(1 − sin atan2(y, z)), their blend), ς from style, k a "
      "random corner (±1, ±1, ±1) (Fractorium's)",
      k3D, kRandom, &cubic3D, {{"xpand", 0.25, -1.0, 4.0}, {"style", 0.0, -2.0, 2.0}});
  catalogue.back().readsSum = true;
  add("cubicLattice_3D",
      "(s + p) f e + w k: s the sum before it (p for pre_/post_), f = xpand/2 (√xpand/2 beyond 1), e = 1 or for style "
      "2 "
      "(cos atan2(x, z), sin atan2(y, z), their mean), k a random corner (±1, ±1, ±1) (Fractorium's)",
      k3D, kRandom, &cubicLattice3D, {{"xpand", 0.2, -1.0, 4.0}, CatalogueAdder::count("style", 1.0, 1.0, 2.0)});
  catalogue.back().readsSum = true;
  add("popcorn2_3D",
      "(w/2 (x + x' sin tan(c y)), w/2 (y + y' sin tan(c x)), v z' sin(tan c) t + [s_z = 0] v sin(tan c) φ), t = z or "
      "v "
      "sin(tan c) φ where z = 0, s_z the sum's z before it (z for pre_/post_), v = w |w| up to 1 (Fractorium's; x', "
      "y', z' its parameters x, y, z)",
      k3D, kFixed, &popcorn23D,
      {{"x", 0.1, -1.0, 1.0}, {"y", 0.1, -1.0, 1.0}, {"z", 0.1, -1.0, 1.0}, {"c", 3.0, -10.0, 10.0}});
  catalogue.back().readsSum = true;
  add("roundspher3D",
      "w² (x, y, t)/(d e) + (0, 0, s_z or cos r where it is 0), d = r² + t², e = 1/d + (2/π)², t = z (cos r where z = "
      "0), s_z the sum's z before it, replaced (z for pre_/post_) (Fractorium's)",
      k3D, kFixed, &roundspher3D);
  catalogue.back().readsSum = true;
  add("extrude",
      "z = max(w, 0) when Ψ₁ < root_face, else w Ψ₂, replacing the z of the terms before it; x and y kept by a pre_ or "
      "post_ term, nothing added to them by an ordinary one (Fractorium's)",
      k3D, kRandom, &extrude, {{"root_face", 0.5, 0.0, 1.0}});
  catalogue.back().replaces = VariationInfo::Replaces::Z;
  add("octapol",
      "w q + w lerp(q, (φ, r), polarweight ln(r/R)²) within r ≤ R = s |radius|/√2, 2 w q within the octagon's "
      "triangles "
      "(s, t), else w q with the sum's x and y before it discarded; q = 0.15 (x, y), z = w z (Fractorium's)",
      k2D, kFixed, &octapol,
      {{"polarweight", 0.0, -1.0, 1.0}, {"radius", 1.0, 0.0, 4.0}, {"s", 0.5, 0.0, 2.0}, {"t", 0.5, 0.0, 2.0}});
  catalogue.back().readsSum = true;
}

}  // namespace voxflame::core
