#include "shadow_volume.h"

#include <algorithm>
#include <cmath>

namespace voxflame::core {

glm::dvec3 lightDirection(double azimuthDeg, double elevationDeg) {
  const double azimuth = azimuthDeg * 3.14159265358979323846 / 180.0;
  const double elevation = elevationDeg * 3.14159265358979323846 / 180.0;
  return {std::cos(elevation) * std::sin(azimuth), std::sin(elevation), std::cos(elevation) * std::cos(azimuth)};
}

ShadowSweep shadowSweep(glm::dvec3 towardLight) {
  const glm::dvec3 light =
      glm::length(towardLight) > 0.0 ? towardLight / glm::length(towardLight) : glm::dvec3(0, 1, 0);
  const glm::dvec3 magnitude = glm::abs(light);
  ShadowSweep sweep;
  sweep.axis = magnitude.x >= magnitude.y && magnitude.x >= magnitude.z ? 0 : (magnitude.y >= magnitude.z ? 1 : 2);
  sweep.u = (sweep.axis + 1) % 3;
  sweep.v = (sweep.axis + 2) % 3;
  const double along = light[sweep.axis];
  sweep.towardLightStep = along >= 0.0 ? 1 : -1;
  sweep.shift = {light[sweep.u] / std::abs(along), light[sweep.v] / std::abs(along)};
  sweep.pathPerSlice = 1.0 / std::abs(along);
  return sweep;
}

bool computeShadowVolume(const PackedVolume& volume, glm::dvec3 towardLight, double extinctionScale, int downsample,
                         ShadowVolume& out, std::stop_token stop) {
  const GridGeometry& g = volume.geometry;
  downsample = std::max(1, downsample);
  out.size = (g.size + (downsample - 1)) / downsample;
  const std::size_t cells = static_cast<std::size_t>(out.size.x) * out.size.y * out.size.z;
  auto cellIndex = [&](int i, int j, int k) {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(out.size.x) * (j + static_cast<std::size_t>(out.size.y) * k);
  };

  // Extinction per cell edge: the mean of its voxels' densities relative to the mesh's mean
  // density, per grid side, as the renderer absorbs (flame/image.h): nothing log-scaled per voxel.
  std::vector<float> sigma(cells, 0.0f);
  const float toRelative = static_cast<float>(volume.texelDensity / std::max(volume.referenceDensity, 1e-30));
  const float perVoxel = static_cast<float>(extinctionScale / std::max({g.size.x, g.size.y, g.size.z, 1}));
  const float cellVoxels = static_cast<float>(downsample);
  const float voxelsPerCell = cellVoxels * cellVoxels * cellVoxels;
  for (int k = 0; k < g.size.z; ++k) {
    if (stop.stop_requested()) return false;
    for (int j = 0; j < g.size.y; ++j)
      for (int i = 0; i < g.size.x; ++i) {
        const float normalised = halfToFloat(volume.density[g.index(i, j, k)]);
        if (normalised <= 0.0f) continue;
        sigma[cellIndex(i / downsample, j / downsample, k / downsample)] +=
            normalised * toRelative * perVoxel * cellVoxels / voxelsPerCell;
      }
  }

  // Sweep along the axis the light is most aligned with, from the light's side.
  const ShadowSweep sweep = shadowSweep(towardLight);
  const int axis = sweep.axis, u = sweep.u, v = sweep.v, towardLightStep = sweep.towardLightStep;
  const double shiftU = sweep.shift.x, shiftV = sweep.shift.y;
  const auto pathPerSlice = static_cast<float>(sweep.pathPerSlice);

  std::vector<float> depth(cells, 0.0f);
  const int slices = out.size[axis];
  for (int step = 0; step < slices; ++step) {
    if (stop.stop_requested()) return false;
    const int a = towardLightStep > 0 ? slices - 1 - step : step;
    const int previous = a + towardLightStep;
    for (int q = 0; q < out.size[v]; ++q)
      for (int p = 0; p < out.size[u]; ++p) {
        glm::ivec3 c;
        c[axis] = a;
        c[u] = p;
        c[v] = q;
        // Light reaching this cell's centre: what reached the previous slice's centre one slice
        // toward the light (read bilinearly), less the extinction between the two centres.
        float before = 0.0f, sigmaBefore = 0.0f;
        if (previous >= 0 && previous < slices) {
          const double pu = p + shiftU, pv = q + shiftV;
          const int pu0 = static_cast<int>(std::floor(pu)), pv0 = static_cast<int>(std::floor(pv));
          const float fu = static_cast<float>(pu - pu0), fv = static_cast<float>(pv - pv0);
          auto bilinear = [&](const std::vector<float>& field) {
            auto at = [&](int pp, int qq) -> float {
              if (pp < 0 || qq < 0 || pp >= out.size[u] || qq >= out.size[v]) return 0.0f;
              glm::ivec3 d;
              d[axis] = previous;
              d[u] = pp;
              d[v] = qq;
              return field[cellIndex(d.x, d.y, d.z)];
            };
            return (1 - fu) * (1 - fv) * at(pu0, pv0) + fu * (1 - fv) * at(pu0 + 1, pv0) +
                   (1 - fu) * fv * at(pu0, pv0 + 1) + fu * fv * at(pu0 + 1, pv0 + 1);
          };
          before = bilinear(depth);
          sigmaBefore = bilinear(sigma);
        }
        const std::size_t index = cellIndex(c.x, c.y, c.z);
        depth[index] = before + 0.5f * (sigmaBefore + sigma[index]) * pathPerSlice;
      }
  }
  out.transmittance.resize(cells);
  for (std::size_t i = 0; i < cells; ++i)
    out.transmittance[i] = static_cast<std::uint8_t>(std::lround(255.0f * std::exp(-depth[i])));
  return true;
}

}  // namespace voxflame::core
