// The log image (flame_finisher.h), one pixel per density pixel: with density estimation on, the
// scattered target's pixel, plus its padding folded onto the image's edge pixels (core's
// estimator piles weight that falls outside the image on the edge pixel), plus the pixel's own
// value when its kernel is one pixel (not scattered); with it off, the pixel's log value. Its
// stage (fragment or compute) comes from finish_stage.glsl, which calls foldPixel.

uniform sampler2D uDensity;
uniform sampler2D uScatter;  // padded by uPad on every side
uniform ivec2 uOrigin;       // of the density region in the full image
uniform ivec2 uFullSize;     // of the full (supersampled) image
uniform int uPad;
uniform bool uEstimate;
uniform float uHitsPerUnit;
uniform float uBrightness;
const int kMaxKernels = 192;
uniform vec4 uKernels[kMaxKernels];

// The log image's pixel q (of the region, bottom-left origin).
vec4 foldPixel(ivec2 q) {
  vec4 own = texelFetch(uDensity, q, 0);
  if (!uEstimate) {
    return own * logScale(own.a, uBrightness);
  }
  vec4 sum = vec4(0.0);
  if (own.a > 0.0 && uKernels[kernelIndex(own.a * uHitsPerUnit)].z == 0.0) sum = own * logScale(own.a, uBrightness);
  ivec2 full = q + uOrigin;
  ivec2 lo = q + uPad, hi = q + uPad;
  if (full.x == 0) lo.x -= uPad;
  if (full.x == uFullSize.x - 1) hi.x += uPad;
  if (full.y == 0) lo.y -= uPad;
  if (full.y == uFullSize.y - 1) hi.y += uPad;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) sum += texelFetch(uScatter, ivec2(x, y), 0);
  return sum;
}
