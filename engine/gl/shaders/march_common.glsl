// The ray marcher's body (VolumeRenderer::march), shared by its compute and fragment stages:
// integrates emission–absorption through the density volume from the near plane to the far plane,
// leaping over empty bricks, with an optional light-transmittance (shadow) lookup. Gives linear
// sums, not a picture: rgb = colour × absorbed density, a = column density; flame_image.h makes
// the picture.

uniform mat4 uInverseViewProjection;
uniform vec2 uTargetSize;
uniform vec3 uGridOrigin;
uniform vec3 uGridExtent;
uniform ivec3 uGridSize;
uniform float uVoxelSize;
uniform float uStepVoxels;
uniform sampler3D uVolume;      // per colour cell: rgb = colour × normalised density, a = normalised density
uniform vec3 uColourScale;      // voxel coordinates → uVolume's texture coordinates
uniform sampler3D uDensity;     // normalised density alone, tested before the colour is fetched
uniform usampler3D uOccupancy;  // 1 per brick that holds density
uniform ivec3 uBrickCount;
uniform int uBrickSize;
uniform usampler3D uCoarseOccupancy;  // 1 per group of kCoarseBricks³ bricks with any density
uniform ivec3 uCoarseCount;
uniform int uCoarseSize;              // voxels along a coarse brick
uniform float uToRelative;      // texture density (a fraction of the densest voxel) → relative to the mesh's mean
uniform float uStepUnits;       // one step's length in grid sides
uniform float uAbsorption;      // extinction per unit of column density (tone.opacity × kAbsorptionPerDensity)
uniform uint uSample;
uniform ivec2 uPixelOffset;     // this tile's place in the whole image, so jitter ignores tiling
uniform sampler3D uShadow;      // light transmittance, when lighting is on
uniform bool uLighting;
uniform vec3 uShadowScale;      // voxel coordinates to shadow texture coordinates
uniform float uLightStrength;

// A per-pixel, per-sample jitter of the first step hides the wood-grain banding of fixed steps.
float hash(uvec3 v) {
  v = v * 1664525u + 1013904223u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  v ^= v >> 16u;
  v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
  return float(v.x & 0x00ffffffu) / 16777216.0;
}

// The sums of the ray through the pixel whose centre is `pixelCentre` (window coordinates).
vec4 marchRay(vec2 pixelCentre) {
  vec2 ndc = pixelCentre / uTargetSize * 2.0 - 1.0;
  vec4 nearPoint = uInverseViewProjection * vec4(ndc, -1.0, 1.0);
  vec4 farPoint = uInverseViewProjection * vec4(ndc, 1.0, 1.0);
  nearPoint /= nearPoint.w;
  farPoint /= farPoint.w;
  vec3 origin = nearPoint.xyz;
  vec3 direction = farPoint.xyz - origin;
  float rayLength = length(direction);
  direction /= rayLength;
  // Rays run from the near plane to the far plane, so both clip every sample.
  vec3 inverseDirection = 1.0 / direction;
  vec3 t0 = (uGridOrigin - origin) * inverseDirection;
  vec3 t1 = (uGridOrigin + uGridExtent - origin) * inverseDirection;
  vec3 tLow = min(t0, t1);
  vec3 tHigh = max(t0, t1);
  float tEnter = max(max(tLow.x, tLow.y), max(tLow.z, 0.0));
  float tExit = min(min(tHigh.x, tHigh.y), min(tHigh.z, rayLength));

  // Emission–absorption on raw density: D sums the density seen along the ray (relative to the
  // mesh's mean, per grid side) and radiance the colour it carries; the log and gamma come later,
  // per pixel (flame_image.h), exactly as flam3 sums hits before it takes the log.
  vec3 radiance = vec3(0.0);
  float columnDensity = 0.0;
  float transmittance = 1.0;
  if (tExit > tEnter) {
    float stepLength = uStepVoxels * uVoxelSize;
    float t = tEnter + stepLength * hash(uvec3(uvec2(ivec2(pixelCentre) + uPixelOffset), uSample));
    vec3 toVoxel = vec3(1.0 / uVoxelSize);
    vec3 toTexture = 1.0 / vec3(uGridSize);
    vec3 exitSide = step(vec3(0.0), direction);
    while (t < tExit) {
      vec3 position = origin + t * direction;
      vec3 voxel = (position - uGridOrigin) * toVoxel;
      ivec3 voxelIndex = ivec3(floor(voxel));
      // Two levels of empty space: a coarse brick, then a brick; either leaps to the first step
      // past its far side, staying on the jittered step lattice.
      ivec3 coarse = clamp(voxelIndex / uCoarseSize, ivec3(0), uCoarseCount - 1);
      int leapVoxels = 0;
      ivec3 leapCell;
      if (texelFetch(uCoarseOccupancy, coarse, 0).r == 0u) {
        leapVoxels = uCoarseSize;
        leapCell = coarse;
      } else {
        ivec3 brick = clamp(voxelIndex / uBrickSize, ivec3(0), uBrickCount - 1);
        if (texelFetch(uOccupancy, brick, 0).r == 0u) {
          leapVoxels = uBrickSize;
          leapCell = brick;
        }
      }
      if (leapVoxels > 0) {
        float cellLength = float(leapVoxels) * uVoxelSize;
        vec3 cellMin = uGridOrigin + vec3(leapCell) * cellLength;
        vec3 tCell = (cellMin + exitSide * cellLength - origin) * inverseDirection;
        float tLeave = min(tCell.x, min(tCell.y, tCell.z));
        t += max(ceil((tLeave - t) / stepLength), 1.0) * stepLength;
        continue;
      }
      // Explicit LOD: there are no mipmaps, and implicit derivatives are undefined in this loop.
      float density = textureLod(uDensity, voxel * toTexture, 0.0).r;
      if (density > 0.0) {
        vec4 texel = textureLod(uVolume, voxel * uColourScale, 0.0);
        float dD = density * uToRelative * uStepUnits;
        float lit = uLighting ? mix(1.0, textureLod(uShadow, voxel * uShadowScale, 0.0).r, uLightStrength) : 1.0;
        // The step's exact integral for constant density: T (1 − e^(−a dD)) / a, or T dD without absorption.
        float passed = exp(-uAbsorption * dD);
        float emitted = (uAbsorption > 0.0 ? transmittance * (1.0 - passed) / uAbsorption : transmittance * dD) * lit;
        columnDensity += emitted;
        radiance += emitted * (texel.rgb / max(texel.a, 1e-8));
        transmittance *= passed;
        if (transmittance < 0.002) break;
      }
      t += stepLength;
    }
  }
  return vec4(radiance, columnDensity);
}
