// The ray marcher's body (VolumeRenderer::march), shared by its compute and fragment stages:
// integrates emission–absorption through the density volume from the near plane to the far plane,
// leaping over empty space, with an optional light-transmittance (shadow) lookup. Gives linear
// sums, not a picture: rgb = colour × absorbed density, a = column density; flame_image.h makes
// the picture. Defines pick the variant (VolumeRenderer::MarchVariant): LIGHTING adds the shadow
// lookup; DENSITY_IN_COLOUR takes the density from the colour texel's alpha (where colour cells
// are voxels) instead of testing the density texture first.

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
uniform usampler3D uEmptyDistance;  // per brick: 0 if it holds density, else bricks to the nearest that does
uniform ivec3 uBrickCount;
uniform int uBrickShift;  // log2 of a brick's side in voxels (software GL scalarises integer division)
uniform float uToRelative;      // texture density (a fraction of the densest voxel) → relative to the mesh's mean
uniform float uStepUnits;       // one step's length in grid sides
uniform float uAbsorption;      // extinction per unit of column density (tone.opacity × kAbsorptionPerDensity)
uniform uint uSample;
uniform ivec2 uPixelOffset;     // this tile's place in the whole image, so jitter ignores tiling
uniform sampler3D uShadow;      // light transmittance (LIGHTING)
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
    // Divisions hoisted out of the loop (a software rasteriser divides each lane slowly).
    float inverseStep = 1.0 / stepLength;
    float densityToStep = uToRelative * uStepUnits;
    float inverseAbsorption = uAbsorption > 0.0 ? 1.0 / uAbsorption : 0.0;
    float t = tEnter + stepLength * hash(uvec3(uvec2(ivec2(pixelCentre) + uPixelOffset), uSample));
    // The walk runs in voxel coordinates: a step is then one multiply-add to its voxel.
    vec3 voxelOrigin = (origin - uGridOrigin) / uVoxelSize;
    vec3 voxelDirection = direction / uVoxelSize;
    vec3 inverseVoxelDirection = inverseDirection * uVoxelSize;
    vec3 toTexture = 1.0 / vec3(uGridSize);
    vec3 exitSide = step(vec3(0.0), direction);
    float brickVoxels = float(1 << uBrickShift);
    while (t < tExit) {
      vec3 voxel = voxelOrigin + t * voxelDirection;
      ivec3 brick = min(ivec3(max(voxel, 0.0)) >> uBrickShift, uBrickCount - 1);
      uint emptyDistance = texelFetch(uEmptyDistance, brick, 0).r;
      if (emptyDistance > 0u) {
        // The cube of bricks within emptyDistance − 1 of this one holds no density: leap to the
        // first step past its far side, staying on the jittered step lattice.
        float reach = float(emptyDistance) - 1.0;
        vec3 farSide = (vec3(brick) - reach + exitSide * (2.0 * reach + 1.0)) * brickVoxels;
        vec3 tSide = (farSide - voxelOrigin) * inverseVoxelDirection;
        float tLeave = min(tSide.x, min(tSide.y, tSide.z));
        t += max(ceil((tLeave - t) * inverseStep), 1.0) * stepLength;
        continue;
      }
      // Explicit LOD: there are no mipmaps, and implicit derivatives are undefined in this loop.
#ifdef DENSITY_IN_COLOUR
      vec4 texel = textureLod(uVolume, voxel * uColourScale, 0.0);
      float density = texel.a;
      if (density > 0.0) {
#else
      float density = textureLod(uDensity, voxel * toTexture, 0.0).r;
      if (density > 0.0) {
        vec4 texel = textureLod(uVolume, voxel * uColourScale, 0.0);
#endif
        float dD = density * densityToStep;
#ifdef LIGHTING
        float lit = mix(1.0, textureLod(uShadow, voxel * uShadowScale, 0.0).r, uLightStrength);
#else
        float lit = 1.0;
#endif
        // The step's exact integral for constant density: T (1 − e^(−a dD)) / a, or T dD without absorption.
        float passed = exp(-uAbsorption * dD);
        float emitted = (uAbsorption > 0.0 ? transmittance * (1.0 - passed) * inverseAbsorption : transmittance * dD) * lit;
        columnDensity += emitted;
        radiance += (emitted / max(texel.a, 1e-8)) * texel.rgb;
        transmittance *= passed;
        if (transmittance < 0.002) break;
      }
      t += stepLength;
    }
  }
  return vec4(radiance, columnDensity);
}
