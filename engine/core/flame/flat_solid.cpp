#include "core/flame/flat_solid.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "core/random.h"
#include "core/task_scheduler.h"

namespace voxflame::core {

namespace {

constexpr double kEpsilon = 1e-6;  // JWildfire's MathLib.EPSILON

double diffuseResponse(SolidDiffuseResponse response, double cosa) {
  switch (response) {
    case SolidDiffuseResponse::CosaSquare:
      return cosa * cosa;
    case SolidDiffuseResponse::CosaHalve:
      return 0.5 * cosa + 0.5;
    case SolidDiffuseResponse::CosaHalveSquare:
      return (0.5 * cosa + 0.5) * (0.5 * cosa + 0.5);
    case SolidDiffuseResponse::Cosa:
      break;
  }
  return cosa;
}

// JWildfire's light matrix A (LightViewCalculator): its rows turn a flame point into the light's
// view, the third being the depth along the light.
std::array<glm::dvec3, 3> lightRows(const SolidLight& light) {
  const double a = -light.altitudeDeg * std::numbers::pi / 180.0, b = -light.azimuthDeg * std::numbers::pi / 180.0;
  const double sa = std::sin(a), ca = std::cos(a), sb = std::sin(b), cb = std::cos(b);
  return {glm::dvec3(cb, 0.0, sb), glm::dvec3(sa * sb, ca, -sa * cb), glm::dvec3(-ca * sb, sa, ca * cb)};
}

// flam3's and JWildfire's Gaussian filter kernel, support 1.5.
double gaussian(double x) {
  return std::exp(-2.0 * x * x) * std::sqrt(2.0 / std::numbers::pi);
}

bool hasPoint(const SolidTexel& t) {
  return t.depth != kSolidEmpty;
}

}  // namespace

glm::dvec3 solidLightDirection(const SolidLight& light) {
  return -lightRows(light)[2];
}

SolidMaterialPick pickSolidMaterial(const FlatSolidSettings& solid, double index) {
  SolidMaterialPick pick;
  const auto& materials = solid.materials;
  if (!(index >= 0.0) || materials.empty()) return pick;
  pick.valid = true;
  const auto count = static_cast<double>(materials.size());
  if (index >= count) {
    pick.from = pick.to = materials.back();
    return pick;
  }
  const auto from = static_cast<std::size_t>(index);
  const std::size_t to = from + 1 < materials.size() ? from + 1 : 0;
  const double fraction = index - std::floor(index);
  constexpr double kSnap = 0.01;
  pick.from = materials[fraction > 1.0 - kSnap ? to : from];
  pick.to = materials[to];
  pick.blend = fraction < kSnap || fraction > 1.0 - kSnap ? 0.0 : fraction;
  return pick;
}

glm::dvec3 shadeSolid(const FlatSolidSettings& solid, const glm::dvec3& object, const glm::dvec3& normal,
                      const SolidMaterialPick& pick, double ao, const double* visibility,
                      const glm::dvec3& background) {
  const std::size_t lights = solid.lights.size();
  double averageVisibility = 1.0;
  if (visibility && lights > 0) {
    averageVisibility = 0.0;
    for (std::size_t i = 0; i < lights; ++i) averageVisibility += visibility[i];
    averageVisibility /= static_cast<double>(lights);
  }
  const auto lightVisibility = [&](std::size_t i) {
    return visibility && solid.lights[i].castShadows ? visibility[i] : averageVisibility;
  };
  if (!pick.valid) {
    double sum = 0.0;
    for (std::size_t i = 0; i < lights; ++i) sum += lightVisibility(i);
    return background * std::clamp(sum, 0.0, 1.0);
  }
  // A blend of two materials mixes their numbers and their diffuse responses, as JWildfire's
  // morphMaterial does (its diffuse takes the reflection map's intensity there, a slip not followed).
  const double t = pick.blend;
  const auto mix = [t](double a, double b) { return a + (b - a) * t; };
  const SolidMaterial& m0 = pick.from;
  const SolidMaterial& m1 = pick.to;
  const double aoIntensity = std::clamp(solid.aoIntensity, 0.0, 4.0);
  const double ambient = mix(m0.ambient, m1.ambient), diffuse = mix(m0.diffuse, m1.diffuse);
  const double ambientI = std::max(0.0, solid.aoEnabled ? ambient - ao * aoIntensity : ambient);
  const double diffuseI = std::max(0.0, solid.aoEnabled ? diffuse - ao * aoIntensity * solid.aoAffectDiffuse : diffuse);
  const double phong = mix(m0.phong, m1.phong), phongSize = mix(m0.phongSize, m1.phongSize);
  const glm::dvec3 phongColor = m0.phongColor + (m1.phongColor - m0.phongColor) * t;
  const auto response = [&](double cosa) {
    return mix(diffuseResponse(m0.diffuseResponse, cosa), diffuseResponse(m1.diffuseResponse, cosa));
  };
  glm::dvec3 raw = object * (ambientI * averageVisibility);
  const glm::dvec3 view(0.0, 0.0, 1.0);
  for (std::size_t i = 0; i < lights; ++i) {
    const SolidLight& light = solid.lights[i];
    const glm::dvec3 l = solidLightDirection(light);
    const double v = lightVisibility(i);
    const double cosa = glm::dot(l, normal);
    // JWildfire adds a third of the ambient object colour to the light's colour here.
    if (cosa > kEpsilon)
      raw += (light.color + object * (ambientI / 3.0)) * (v * response(cosa) * diffuseI * light.intensity);
    if (phong > kEpsilon) {
      const glm::dvec3 r = l - 2.0 * glm::dot(l, normal) * normal;
      const double vr = glm::dot(view, r);
      if (vr < kEpsilon) raw += phongColor * (v * std::pow(response(-vr), phongSize) * phong * light.intensity);
    }
  }
  return raw;
}

void SolidRaster::resize(int w, int h) {
  width = w;
  height = h;
  texels.assign(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), SolidTexel{});
}

glm::dvec3 SolidShadowMap::project(const glm::dvec3& p) const {
  return {glm::dot(rows[0], p), glm::dot(rows[1], p), glm::dot(rows[2], p)};
}

std::int64_t SolidShadowMap::texel(const glm::dvec3& q) const {
  const double fx = scaleX * q.x + centreX + 0.5, fy = scaleY * q.y + centreY + 0.5;
  if (!(fx >= 0.0 && fy >= 0.0 && fx < size && fy < size)) return -1;  // NaN too
  return static_cast<std::int64_t>(fy) * size + static_cast<std::int64_t>(fx);
}

void SolidShadowMap::deposit(const glm::dvec3& p) {
  const glm::dvec3 q = project(p);
  const std::int64_t i = texel(q);
  if (i < 0) return;
  std::atomic_ref<float> cell(depth[static_cast<std::size_t>(i)]);
  const auto z = static_cast<float>(q.z);
  float seen = cell.load(std::memory_order_relaxed);
  while (z > seen && !cell.compare_exchange_weak(seen, z, std::memory_order_relaxed)) {
  }
}

std::vector<SolidShadowMap> makeSolidShadowMaps(const FlatSolidSettings& solid, const std::vector<glm::dvec3>& bounds) {
  std::vector<SolidShadowMap> maps(solid.lights.size());
  if (solid.shadowType == SolidShadowType::Off || bounds.empty()) return maps;
  for (std::size_t i = 0; i < maps.size(); ++i) {
    if (!solid.lights[i].castShadows) continue;
    SolidShadowMap& map = maps[i];
    map.active = true;
    map.rows = lightRows(solid.lights[i]);
    map.size = std::clamp(solid.shadowmapSize, 64, 8192);
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (const glm::dvec3& p : bounds) {
      const glm::dvec3 q = map.project(p);
      x0 = std::min(x0, q.x);
      x1 = std::max(x1, q.x);
      y0 = std::min(y0, q.y);
      y1 = std::max(y1, q.y);
    }
    const double margin = 0.03, dx0 = x1 - x0, dy0 = y1 - y0;
    x0 -= margin * dx0;
    y0 -= margin * dy0;
    const double dx = std::max((x1 + margin * dx0) - x0, 0.001), dy = std::max((y1 + margin * dy0) - y0, 0.001);
    map.scaleX = map.size / dx;
    map.scaleY = map.size / dy;
    map.centreX = -x0 * map.scaleX;
    map.centreY = -y0 * map.scaleY;
    map.depth.assign(static_cast<std::size_t>(map.size) * static_cast<std::size_t>(map.size), kSolidEmpty);
  }
  return maps;
}

namespace {

// JWildfire's NormalsCalculator: the cross products of the vectors to two neighbours, over up to
// eight of sixteen pairs of neighbours that hold points, summed and normalised.
constexpr int kNormalPairs[16][4] = {{0, 1, 1, 0},    {1, 0, 0, -1},   {0, -1, -1, 0},  {-1, 0, 0, 1},
                                     {-1, 1, 1, 1},   {1, 1, 1, -1},   {1, -1, -1, -1}, {-1, -1, -1, 1},
                                     {0, 1, 1, 1},    {1, 1, 1, 0},    {1, 0, 1, -1},   {1, -1, 0, -1},
                                     {0, -1, -1, -1}, {-1, -1, -1, 0}, {-1, 0, -1, 1},  {-1, 1, 0, 1}};
constexpr int kMaxNormalSamples = 8;

bool normalAt(const SolidRaster& raster, int x, int y, glm::dvec3& normal) {
  const SolidTexel& c = raster.at(x, y);
  if (!hasPoint(c)) return false;
  const glm::dvec3 p(c.x, c.y, c.z);
  glm::dvec3 sum(0.0);
  int samples = 0;
  for (const auto& pair : kNormalPairs) {
    const int ax = x + pair[0], ay = y + pair[1], bx = x + pair[2], by = y + pair[3];
    if (ax < 0 || ay < 0 || bx < 0 || by < 0 || ax >= raster.width || bx >= raster.width || ay >= raster.height ||
        by >= raster.height)
      continue;
    const SolidTexel& a = raster.at(ax, ay);
    const SolidTexel& b = raster.at(bx, by);
    if (!hasPoint(a) || !hasPoint(b)) continue;
    sum += glm::cross(p - glm::dvec3(a.x, a.y, a.z), p - glm::dvec3(b.x, b.y, b.z));
    if (++samples >= kMaxNormalSamples) break;
  }
  const double length = glm::length(sum);
  if (samples == 0 || !(length > kEpsilon)) return false;
  normal = sum / length;
  return true;
}

// JWildfire's AOCalculator: along directions around each pixel, the rise of the depth buffer's
// horizon above the surface's tangent plane, weighted by exp(−falloff · (r / radius)²), then
// blurred (and then scaled by 0.1) when the blur is at least 0.42 pixels. It reads the tangent
// direction from the sample's position rather than its offset, as JWildfire does.
std::vector<float> ambientOcclusion(const FlatSolidSettings& solid, const SolidRaster& raster,
                                    const std::vector<glm::dvec3>& normals, const std::vector<std::uint8_t>& hasNormal,
                                    double depthScale) {
  const int w = raster.width, h = raster.height;
  std::vector<float> ao(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0.0f);
  const double imageSize = std::sqrt(static_cast<double>(w) * w + static_cast<double>(h) * h);
  const double radius = std::clamp(solid.aoSearchRadius, 0.25, 120.0) * imageSize / 500.0;
  const int radiusSamples = std::clamp(solid.aoRadiusSamples, 1, 128);
  const int azimuthSamples = std::clamp(solid.aoAzimuthSamples, 1, 128);
  const double radiusStep = radius / radiusSamples, azimuthStep = 2.0 * std::numbers::pi / azimuthSamples;
  const double jitter = radiusStep / 10.0, falloff = std::clamp(solid.aoFalloff, 0.0, 10.0);
  const auto depthAt = [&](double x, double y) {
    const int xi = std::clamp(static_cast<int>(x), 0, w - 1), yi = std::clamp(static_cast<int>(y), 0, h - 1);
    const float d = raster.at(xi, yi).depth;
    return d == kSolidEmpty ? static_cast<double>(kSolidEmpty) : d * depthScale;
  };
  parallelFor(static_cast<std::size_t>(h), 4, [&](std::size_t begin, std::size_t end) {
    for (std::size_t row = begin; row < end; ++row) {
      SplitMix64 rng(0x5eed0a0ULL + row);
      const int i = static_cast<int>(row);
      for (int j = 0; j < w; ++j) {
        const std::size_t index = row * static_cast<std::size_t>(w) + static_cast<std::size_t>(j);
        if (!hasNormal[index]) continue;
        const double z0 = raster.at(j, i).depth * depthScale;
        const glm::dvec3 n = normals[index];
        double angle = (0.5 - rng.uniform()) * azimuthStep / 4.0;
        double sum = 0.0;
        for (int k = 0; k < azimuthSamples; ++k, angle += azimuthStep) {
          const double dx = std::cos(angle), dy = std::sin(angle);
          double r0 = radiusStep, previous = 0.0;
          for (int l = 0; l < radiusSamples; ++l, r0 += radiusStep) {
            const double r = r0 + (0.5 - rng.uniform()) * jitter;
            const double x = j + r * dx + (0.5 - rng.uniform()) * jitter;
            const double y = i + r * dy + (0.5 - rng.uniform()) * jitter;
            const double horizon = std::atan2(depthAt(x, y) - z0, r) + 0.001;
            const double rr = std::hypot(x, y);
            const double rx = x / rr, ry = y / rr;
            const double tt = n.x * rx + ry * n.y;
            const double tx = -(ry * n.x * n.y - rx * n.y * n.y - rx * n.z * n.z) / tt;
            const double ty = (ry * n.x * n.x + ry * n.z * n.z - n.x * rx * n.y) / tt;
            const double tz = (-ry * n.y * n.z - n.x * rx * n.z) / tt;
            const double tangent = std::atan2(tz, std::hypot(tx, ty));
            const double occlusion = std::sin(horizon) - std::sin(tangent);
            if (occlusion > previous) {  // NaN (a degenerate tangent) adds nothing
              previous = occlusion;
              const double dist = r / radius;
              sum += occlusion * std::exp(-dist * dist * falloff) * 0.5;
            }
          }
        }
        ao[index] = static_cast<float>(sum);
      }
    }
  });
  const double blur = std::clamp(solid.aoBlurRadius, 0.25, 10.0) * imageSize / 500.0;
  if (blur < 0.42) return ao;
  DensityImage in, out;
  in.resize(w, h);
  for (std::size_t p = 0; p < ao.size(); ++p) in.values[4 * p + 3] = ao[p];
  spatialFilter(in, 1, blur, out);
  for (std::size_t p = 0; p < ao.size(); ++p) ao[p] = 0.1f * out.values[4 * p + 3];
  return ao;
}

// Shadow visibility per pixel and light (JWildfire's ShadowCalculator): 1 lit, 0 shadowed, −1
// where the pixel's point falls outside the light's map (its shadows are not known there).
std::vector<float> shadowSteps(const SolidRaster& raster, const SolidShadowMap& map, double bias) {
  std::vector<float> steps(raster.texels.size(), -1.0f);
  parallelFor(static_cast<std::size_t>(raster.height), 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t y = begin; y < end; ++y)
      for (int x = 0; x < raster.width; ++x) {
        const SolidTexel& t = raster.at(x, static_cast<int>(y));
        if (!hasPoint(t)) continue;
        const glm::dvec3 q = map.project(glm::dvec3(t.x, t.y, t.z));
        const std::int64_t i = map.texel(q);
        if (i < 0) continue;
        steps[y * static_cast<std::size_t>(raster.width) + static_cast<std::size_t>(x)] =
            q.z < map.depth[static_cast<std::size_t>(i)] - bias ? 0.0f : 1.0f;
      }
  });
  return steps;
}

}  // namespace

DensityImage shadeSolidRaster(const FlatSolidSettings& solid, const SolidRaster& raster,
                              const std::vector<SolidShadowMap>& shadowMaps, double depthScale,
                              const glm::dvec3& background) {
  const int w = raster.width, h = raster.height;
  const std::size_t pixels = raster.texels.size();
  std::vector<glm::dvec3> normals(pixels);
  std::vector<std::uint8_t> hasNormal(pixels, 0);
  parallelFor(static_cast<std::size_t>(h), 16, [&](std::size_t begin, std::size_t end) {
    for (std::size_t y = begin; y < end; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = y * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
        hasNormal[i] = normalAt(raster, x, static_cast<int>(y), normals[i]) ? 1 : 0;
      }
  });
  const std::vector<float> ao =
      solid.aoEnabled ? ambientOcclusion(solid, raster, normals, hasNormal, depthScale) : std::vector<float>();

  // Shadows: only when some light casts them; then every light has a visibility.
  const std::size_t lights = solid.lights.size();
  std::vector<std::vector<float>> steps(lights);
  bool shadows = false;
  for (std::size_t l = 0; l < lights && l < shadowMaps.size(); ++l)
    if (shadowMaps[l].active) {
      steps[l] = shadowSteps(raster, shadowMaps[l], solid.shadowmapBias);
      shadows = true;
    }
  const double diagonal = std::sqrt(static_cast<double>(w) * w + static_cast<double>(h) * h);
  const int smoothRadius = std::min(
      128, static_cast<int>(std::max(
               0.0, solid.shadowSmoothRadius < kEpsilon ? 0.0 : solid.shadowSmoothRadius * 6.0 * diagonal / 1000.0)));
  const bool smooth = solid.shadowType == SolidShadowType::Smooth && smoothRadius >= 1;

  DensityImage out;
  out.resize(w, h);
  parallelFor(static_cast<std::size_t>(h), 8, [&](std::size_t begin, std::size_t end) {
    std::vector<double> visibility(lights, 1.0);
    for (std::size_t y = begin; y < end; ++y)
      for (int x = 0; x < w; ++x) {
        const std::size_t i = y * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
        if (!hasNormal[i]) continue;
        for (std::size_t l = 0; l < lights; ++l) {
          visibility[l] = 1.0;
          if (steps[l].empty()) continue;
          double v = 1.0;
          if (!smooth) {
            if (steps[l][i] >= 0.0f) v = steps[l][i];
          } else {
            // JWildfire's smooth shadows: a Gaussian-weighted mean of the steps around, sampled
            // every radius / 8 + 1 pixels (its sum starts at 1, as JWildfire's does).
            const int step = smoothRadius / 8 + 1;
            const double inverse = 1.5 / smoothRadius;
            double total = 0.0;
            for (int k = -smoothRadius; k <= smoothRadius; k += step) {
              const int sx = x + k;
              if (sx < 0 || sx >= w) continue;
              for (int m = -smoothRadius; m <= smoothRadius; m += step) {
                const int sy = static_cast<int>(y) + m;
                if (sy < 0 || sy >= h) continue;
                const float s =
                    steps[l][static_cast<std::size_t>(sy) * static_cast<std::size_t>(w) + static_cast<std::size_t>(sx)];
                if (s < 0.0f) continue;
                const double weight = gaussian(std::hypot(k * inverse, m * inverse));
                total += weight;
                v += s * weight;
              }
            }
            if (total > kEpsilon) v /= total;
          }
          visibility[l] = std::clamp(v + 1.0 - std::clamp(solid.lights[l].shadowIntensity, 0.0, 1.0), 0.0, 1.0);
        }
        const SolidTexel& t = raster.at(x, static_cast<int>(y));
        const glm::dvec3 c =
            shadeSolid(solid, glm::dvec3(t.r, t.g, t.b), normals[i], pickSolidMaterial(solid, t.material),
                       ao.empty() ? 0.0 : ao[i], shadows ? visibility.data() : nullptr, background);
        float* o = out.at(x, static_cast<int>(y));
        o[0] = static_cast<float>(c.r);
        o[1] = static_cast<float>(c.g);
        o[2] = static_cast<float>(c.b);
        o[3] = 1.0f;
      }
  });
  return out;
}

}  // namespace voxflame::core
