#include "core/flame/flame.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/flame/variations.h"

namespace voxflame::core {

namespace {

bool finite(double v) {
  return std::isfinite(v);
}

// Rotation by `angle` about the unit vector `axis` (Rodrigues), as an affine map without offset.
Affine3 rotationAbout(glm::dvec3 axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  const double x = axis.x, y = axis.y, z = axis.z;
  Affine3 a;
  a.m = {t * x * x + c,     t * x * y - s * z, t * x * z + s * y, 0.0,  //
         t * x * y + s * z, t * y * y + c,     t * y * z - s * x, 0.0,  //
         t * x * z - s * y, t * y * z + s * x, t * z * z + c,     0.0};
  return a;
}

// Reflection across the plane through the origin with unit normal `normal`.
Affine3 reflectionAcross(glm::dvec3 normal) {
  const double x = normal.x, y = normal.y, z = normal.z;
  Affine3 a;
  a.m = {1 - 2 * x * x, -2 * x * y,    -2 * x * z,    0.0,  //
         -2 * x * y,    1 - 2 * y * y, -2 * y * z,    0.0,  //
         -2 * x * z,    -2 * y * z,    1 - 2 * z * z, 0.0};
  return a;
}

// The mirror plane contains the axis: its normal is the world axis most perpendicular to it
// (x unless the axis is close to x), made exactly perpendicular.
glm::dvec3 mirrorNormal(glm::dvec3 axis) {
  const glm::dvec3 helper = std::abs(axis.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  return glm::normalize(helper - glm::dot(helper, axis) * axis);
}

void validateXform(const FlameXform& xform, const std::string& where) {
  const auto fail = [&](const std::string& reason) { throw Error(where + " " + reason); };
  if (!finite(xform.weight) || xform.weight < 0.0 || xform.weight > kFlameCoefficientLimit)
    fail("has weight " + std::to_string(xform.weight) + "; a weight must be a finite number from 0 to 1e6");
  for (const double v : xform.affine.m)
    if (!finite(v) || std::abs(v) > kFlameCoefficientLimit)
      fail("has an affine coefficient that is not finite or beyond ±1e6");
  if (xform.hasPost)
    for (const double v : xform.post.m)
      if (!finite(v) || std::abs(v) > kFlameCoefficientLimit)
        fail("has a post-affine coefficient that is not finite or beyond ±1e6");
  if (!finite(xform.color) || xform.color < 0.0 || xform.color > 1.0) fail("has a colour outside [0, 1]");
  if (!finite(xform.colorSpeed) || xform.colorSpeed < 0.0 || xform.colorSpeed > 1.0)
    fail("has a colour speed outside [0, 1]");
  if (!finite(xform.opacity) || xform.opacity < 0.0 || xform.opacity > 1.0) fail("has an opacity outside [0, 1]");
  if (!finite(xform.directColor) || xform.directColor < 0.0 || xform.directColor > 1.0)
    fail("has a direct colour outside [0, 1]");
  if (xform.fieldKind != WeightFieldKind::None) {
    for (const double v :
         {xform.fieldAmount, xform.fieldGain, xform.fieldLacunarity, xform.fieldColor, xform.fieldJitter,
          xform.fieldParam1Intensity, xform.fieldParam2Intensity, xform.fieldParam3Intensity})
      if (!finite(v) || std::abs(v) > kFlameCoefficientLimit)
        fail("has a weighting field amount, gain, lacunarity or intensity that is not finite or beyond ±1e6");
    // A parameter the field scales: a variation may be named that the transform lacks (JWildfire
    // then scales nothing), but a known variation's parameter must be one it has.
    for (const FlameXform::FieldParam& p : xform.fieldParams()) {
      const VariationInfo* info = p.variation.empty() ? nullptr : findVariation(p.variation);
      if (info && p.name != "amount" && info->paramIndex(p.name) < 0)
        fail("has a weighting field that scales '" + p.name + "', which variation " + p.variation +
             " does not have (its parameters, or `amount`)");
    }
    if (!finite(xform.fieldFrequency) || xform.fieldFrequency < 0.0 || xform.fieldFrequency > kFlameCoefficientLimit)
      fail("has a weighting field frequency that is not a number from 0 to 1e6");
    if (xform.fieldOctaves < 1 || xform.fieldOctaves > kMaxWeightFieldOctaves)
      fail("has a weighting field of " + std::to_string(xform.fieldOctaves) + " octaves; from 1 to " +
           std::to_string(kMaxWeightFieldOctaves) + " are allowed");
  }
  if (xform.xaos.size() > kMaxFlameXforms)
    fail("has " + std::to_string(xform.xaos.size()) + " xaos factors; at most one per transform (" +
         std::to_string(kMaxFlameXforms) + ")");
  for (const double v : xform.xaos)
    if (!finite(v) || v < 0.0 || v > kFlameCoefficientLimit)
      fail("has a xaos factor that is not a number from 0 to 1e6");
  if (xform.variations.size() > kMaxXformVariations)
    fail("has " + std::to_string(xform.variations.size()) + " variations; at most " +
         std::to_string(kMaxXformVariations) + " are allowed");
  for (const VariationTerm& term : xform.variations) {
    const VariationInfo* info = findVariation(term.name);
    if (!info) {
      try {
        variationOrThrow(term.name);
      } catch (const Error& e) {
        fail(std::string("uses ") + e.what());
      }
    }
    if (!finite(term.weight) || std::abs(term.weight) > kFlameCoefficientLimit)
      fail("gives variation '" + term.name + "' a weight that is not finite or beyond ±1e6");
    if (term.params.size() != info->params.size())
      fail("gives variation '" + term.name + "' " + std::to_string(term.params.size()) + " parameters; it takes " +
           std::to_string(info->params.size()));
    for (std::size_t i = 0; i < term.params.size(); ++i)
      if (!finite(term.params[i]) || std::abs(term.params[i]) > kFlameCoefficientLimit)
        fail("gives parameter '" + info->params[i].name + "' of variation '" + term.name +
             "' a value that is not finite or beyond ±1e6");
  }
}

}  // namespace

bool hasXaos(const FlameGenome& genome) {
  for (const FlameXform& x : genome.xforms)
    for (const double v : x.xaos)
      if (v != 1.0) return true;
  return false;
}

std::vector<FlameXform> expandSymmetry(const FlameGenome& genome) {
  std::vector<FlameXform> xforms = genome.xforms;
  const FlameSymmetry& s = genome.symmetry;
  const int turns = std::max(1, s.rotational);
  if (turns == 1 && !s.mirror) return xforms;
  double total = 0.0;
  for (const FlameXform& x : genome.xforms) total += x.weight;
  const int extra = (turns - 1) + (s.mirror ? 1 : 0);
  const double share = total / static_cast<double>(extra);
  glm::dvec3 axis = glm::length(s.axis) > 1e-12 ? glm::normalize(s.axis) : glm::dvec3(0.0, 0.0, 1.0);
  const auto symmetryXform = [&](const Affine3& map) {
    FlameXform x;
    x.weight = share;
    x.affine = map;
    x.variations = {{"linear", 1.0, {}}};
    x.colorSpeed = 0.0;  // a symmetry copy keeps the colour of the point it turns
    return x;
  };
  for (int k = 1; k < turns; ++k)
    xforms.push_back(symmetryXform(rotationAbout(axis, 2.0 * std::numbers::pi * k / turns)));
  if (s.mirror) {
    xforms.push_back(symmetryXform(reflectionAcross(mirrorNormal(axis))));
  }
  return xforms;
}

std::vector<Affine3> symmetryGroup(const FlameSymmetry& s) {
  const int turns = std::max(1, s.rotational);
  const glm::dvec3 axis = glm::length(s.axis) > 1e-12 ? glm::normalize(s.axis) : glm::dvec3(0.0, 0.0, 1.0);
  std::vector<Affine3> group;
  for (int k = 0; k < turns; ++k) group.push_back(rotationAbout(axis, 2.0 * std::numbers::pi * k / turns));
  if (s.mirror) {
    const Affine3 reflection = reflectionAcross(mirrorNormal(axis));
    for (int k = 0; k < turns; ++k) {
      const Affine3& r = group[static_cast<std::size_t>(k)];
      Affine3 both;
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) {
          double sum = 0.0;
          for (int i = 0; i < 3; ++i)
            sum += r.m[static_cast<std::size_t>(4 * row + i)] * reflection.m[static_cast<std::size_t>(4 * i + col)];
          both.m[static_cast<std::size_t>(4 * row + col)] = sum;
        }
      group.push_back(both);
    }
  }
  return group;
}

std::vector<Affine3> postSymmetryMaps(const FlamePostSymmetry& s) {
  const double cx = s.centerX, cy = s.centerY;
  // p ↦ the turn by `radians` about the centre of (sx · p + (tx, ty)), in the plane; z is kept.
  const auto map = [&](double radians, double sx, double sy, double tx, double ty) {
    const double c = std::cos(radians), n = std::sin(radians);
    // q = (sx x + tx − cx, sy y + ty − cy), turned, then moved back by the centre.
    const double qx = tx - cx, qy = ty - cy;
    Affine3 a;
    a.m[0] = c * sx;
    a.m[1] = -n * sy;
    a.m[3] = c * qx - n * qy + cx;
    a.m[4] = n * sx;
    a.m[5] = c * sy;
    a.m[7] = n * qx + c * qy + cy;
    return a;
  };
  std::vector<Affine3> maps;
  const double half = 0.5 * s.distance, turn = s.rotationDeg * std::numbers::pi / 180.0;
  switch (s.kind) {
    case PostSymmetryKind::None:
      break;
    case PostSymmetryKind::Point:
      if (s.order <= 1) break;
      maps.push_back(Affine3{});  // JWildfire draws the point, then all its turns from the 0° one
      for (int k = 0; k < s.order; ++k) maps.push_back(map(-2.0 * std::numbers::pi * k / s.order, 1.0, 1.0, 0.0, 0.0));
      break;
    case PostSymmetryKind::XAxis:
      maps.push_back(map(-turn, 1.0, 1.0, half, 0.0));
      maps.push_back(map(turn, -1.0, 1.0, 2.0 * cx - half, 0.0));
      break;
    case PostSymmetryKind::YAxis:
      maps.push_back(map(-turn, 1.0, 1.0, 0.0, half));
      maps.push_back(map(turn, 1.0, -1.0, 0.0, 2.0 * cy - half));
      break;
  }
  return maps;
}

void validateFlame(const FlameGenome& genome, const std::string& where) {
  const std::string allowed = "1 to " + std::to_string(kMaxFlameXforms);
  if (genome.xforms.empty()) throw Error(where + " is a flame without transforms; it needs " + allowed);
  if (genome.xforms.size() > kMaxFlameXforms)
    throw Error(where + " has " + std::to_string(genome.xforms.size()) + " transforms; a flame takes " + allowed);
  double total = 0.0;
  for (std::size_t i = 0; i < genome.xforms.size(); ++i) {
    validateXform(genome.xforms[i], where + " transform " + std::to_string(i));
    total += genome.xforms[i].weight;
  }
  if (!(total > 0.0)) throw Error(where + " has only transforms of weight 0; at least one needs a positive weight");
  if (genome.hasFinal) validateXform(genome.finalXform, where + " final transform");
  if (genome.chainedFinals.size() > kMaxChainedFinals)
    throw Error(where + " chains " + std::to_string(genome.chainedFinals.size()) +
                " final transforms after the first; at most " + std::to_string(kMaxChainedFinals) + " are allowed");
  for (std::size_t i = 0; i < genome.chainedFinals.size(); ++i)
    validateXform(genome.chainedFinals[i], where + " chained final transform " + std::to_string(i + 1));
  if (genome.backgroundXforms.size() > kMaxFlameXforms)
    throw Error(where + " has " + std::to_string(genome.backgroundXforms.size()) + " background transforms; at most " +
                std::to_string(kMaxFlameXforms) + " are allowed");
  for (std::size_t i = 0; i < genome.backgroundXforms.size(); ++i)
    validateXform(genome.backgroundXforms[i], where + " background transform " + std::to_string(i + 1));
  if (!(genome.backgroundZoom > 0.0) || !finite(genome.backgroundZoom))
    throw Error(where + " has a background zoom that is not a positive finite number");
  const FlameSymmetry& s = genome.symmetry;
  if (s.rotational < 1 || s.rotational > kMaxFlameSymmetry)
    throw Error(where + " has rotational symmetry " + std::to_string(s.rotational) + "; it must be 1 to " +
                std::to_string(kMaxFlameSymmetry));
  if (!finite(s.axis.x) || !finite(s.axis.y) || !finite(s.axis.z) || glm::length(s.axis) < 1e-12)
    throw Error(where + " has a symmetry axis that is not a finite, non-zero vector");
  const FlamePostSymmetry& post = genome.postSymmetry;
  if (post.order < 1 || post.order > kMaxPostSymmetryOrder)
    throw Error(where + " has a post symmetry of order " + std::to_string(post.order) + "; it must be 1 to " +
                std::to_string(kMaxPostSymmetryOrder));
  for (const double v : {post.centerX, post.centerY, post.distance, post.rotationDeg})
    if (!finite(v) || std::abs(v) > kFlameCoefficientLimit)
      throw Error(where + " has a post symmetry value that is not finite or beyond ±1e6");
}

void validateQuaternionJulia(const QuaternionJuliaSettings& q, const std::string& where) {
  for (int i = 0; i < 4; ++i)
    if (!finite(q.c[i]) || std::abs(q.c[i]) > 10.0)
      throw Error(where + " has a Julia constant component that is not finite or beyond ±10");
  if (!finite(q.turnDeg) || std::abs(q.turnDeg) > 3600.0) throw Error(where + " has a turn outside ±3600°");
  if (!finite(q.sliceW) || std::abs(q.sliceW) > 10.0) throw Error(where + " has a slice outside ±10");
  if (!finite(q.thickness) || q.thickness <= 0.0 || q.thickness > 10.0)
    throw Error(where + " has a slice thickness outside (0, 10]");
}

FlameGenome defaultFlame() {
  // Three transforms: a spherical fold, a julia swirl and a sinusoidal sweep, each turned a
  // little out of the plane so the attractor is a volume, not a sheet.
  FlameGenome g;
  FlameXform a;
  a.weight = 0.5;
  a.affine.m = {0.56, -0.32, 0.18, 0.25, 0.31, 0.58, -0.12, -0.12, -0.15, 0.16, 0.62, 0.2};
  a.variations = {{"spherical", 0.6, {}}, {"linear", 0.4, {}}};
  a.color = 0.0;
  FlameXform b;
  b.weight = 0.3;
  b.affine.m = {-0.48, 0.22, -0.2, -0.4, -0.18, -0.52, 0.21, 0.3, 0.22, -0.14, 0.55, -0.25};
  b.variations = {{"julia", 0.7, {}}, {"spherical3D", 0.3, {}}};
  b.color = 0.55;
  FlameXform c;
  c.weight = 0.2;
  c.affine.m = {0.4, 0.35, 0.0, 0.1, -0.35, 0.4, 0.1, 0.5, 0.05, -0.2, 0.5, 0.0};
  c.variations = {{"sinusoidal", 0.8, {}}, {"linear", 0.2, {}}};
  c.color = 1.0;
  g.xforms = {a, b, c};
  return g;
}

}  // namespace voxflame::core
