// JWildfire's solid rendering in the flat view (FlatSolidSettings): the pieces of its shading
// model that the flat render and the tests share.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "core/flame/image.h"
#include "core/scene.h"

namespace voxflame::core {

// The direction towards a distant light, in flame coordinates (JWildfire's LightViewCalculator):
// with a = −altitude and b = −azimuth, (cos a sin b, −sin a, −cos a cos b). Normals facing the
// viewer point along −z in JWildfire's convention, so altitude 0, azimuth 0 lights them head-on.
glm::dvec3 solidLightDirection(const SolidLight& light);

// The material for a point's material index (JWildfire's getInterpolatedMaterial): none (null)
// below 0 or without materials; past the last, the last; otherwise materials ⌊m⌋ and ⌊m⌋ + 1
// (wrapping to 0) blended by the fraction, snapped to either within 0.01.
struct SolidMaterialPick {
  bool valid = false;
  SolidMaterial from, to;
  double blend = 0.0;  // 0: `from` alone
};
SolidMaterialPick pickSolidMaterial(const FlatSolidSettings& solid, double index);

// The shaded colour (0–1 display values, not clamped) of a point of colour `object` with unit
// normal n, its material pick, its ambient occlusion ao (0: none) and each light's visibility
// (1: lit, null: all lit), as JWildfire's LogDensityFilter.addSolidColors computes it; a point
// without a material takes the background times its lights' summed visibility (clamped to 1).
glm::dvec3 shadeSolid(const FlatSolidSettings& solid, const glm::dvec3& object, const glm::dvec3& normal,
                      const SolidMaterialPick& material, double ao, const double* visibility,
                      const glm::dvec3& background);

// The nearest point of each supersampled pixel: depth (larger is nearer; kSolidEmpty where no
// point fell), its flame coordinates before the camera, its palette colour and material index.
inline constexpr float kSolidEmpty = -3.4e38f;
struct SolidTexel {
  float depth = kSolidEmpty;
  float x = 0.0f, y = 0.0f, z = 0.0f;
  float r = 0.0f, g = 0.0f, b = 0.0f;
  float material = 0.0f;
};
struct SolidRaster {
  int width = 0, height = 0;
  std::vector<SolidTexel> texels;  // rows top to bottom
  void resize(int w, int h);
  SolidTexel& at(int x, int y) {
    return texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
  const SolidTexel& at(int x, int y) const {
    return texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)];
  }
  // Keeps the nearer point (threads keep rasters of their own, merged afterwards).
  void deposit(int x, int y, const SolidTexel& t) {
    SolidTexel& s = at(x, y);
    if (t.depth > s.depth) s = t;
  }
};

// A light's shadow map (JWildfire's ShadowCalculator): points turned into the light's view
// (rows of its projection), framed by the bounds of the first points seen (3% margin), each texel
// the largest depth along the light. Texels are written by many threads (atomic maximum).
struct SolidShadowMap {
  bool active = false;
  std::array<glm::dvec3, 3> rows{};
  int size = 0;
  double scaleX = 1.0, scaleY = 1.0, centreX = 0.0, centreY = 0.0;
  std::vector<float> depth;
  glm::dvec3 project(const glm::dvec3& p) const;
  // The texel of a projected point, or −1 outside the map.
  std::int64_t texel(const glm::dvec3& projected) const;
  void deposit(const glm::dvec3& p);  // thread-safe
};

// The shadow maps of the lights that cast shadows (others inactive); `bounds` are flame points to
// frame them with (JWildfire frames them with its first 40960 points).
std::vector<SolidShadowMap> makeSolidShadowMaps(const FlatSolidSettings& solid, const std::vector<glm::dvec3>& bounds);

// Normals, ambient occlusion, shadows and shading of every supersampled pixel: (r, g, b, 1) where
// the pixel has a normal, 0 elsewhere. `depthScale` turns depths into supersampled pixels
// (JWildfire's ambient occlusion searches the depth buffer in pixels).
DensityImage shadeSolidRaster(const FlatSolidSettings& solid, const SolidRaster& raster,
                              const std::vector<SolidShadowMap>& shadowMaps, double depthScale,
                              const glm::dvec3& background);

}  // namespace voxflame::core
