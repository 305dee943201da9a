// Density estimation, gathered (flame_finisher.h): each pixel of the target padded by the widest
// kernel's radius sums the shares that the wide kernels around it give it, where the scatter
// (finish_scatter.*.glsl) draws sprites that add them by blending. The loop takes the source
// pixels in the order the scatter draws them (bottom row first, left to right) and computes each
// share as it does, so both give the same floats. A compute pass that gathers keeps every
// multiprocessor of a compute GPU busy; the sprites' rasterising and blending run on the few
// that do graphics work (H100, H200), while a software rasteriser scatters faster.
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler2D uDensity;      // sums: red·D, green·D, blue·D, D
uniform usamplerBuffer uSprites; // per source pixel (finish_compact.comp.glsl): its index, its kernel or none
uniform ivec2 uSize;             // of the density image
uniform int uPad;                // the widest kernel's radius
uniform float uBrightness;
const int kMaxKernels = 192;
uniform vec4 uKernels[kMaxKernels];  // exponent per squared pixel, 1 / sum of its weights, radius, largest dx² + dy² inside
layout(rgba32f) writeonly uniform image2D uTarget;  // padded by uPad on every side

const uint kNoSprite = 0xFFFFFFFFu;

void main() {
  ivec2 q = ivec2(gl_GlobalInvocationID.xy);
  ivec2 padded = uSize + 2 * uPad;
  if (q.x >= padded.x || q.y >= padded.y) return;
  ivec2 centre = q - uPad;  // in the density image's pixels (may lie outside it)
  ivec2 lo = max(centre - uPad, ivec2(0));
  ivec2 hi = min(centre + uPad, uSize - 1);
  vec4 sum = vec4(0.0);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      uint kernelIndex = texelFetch(uSprites, y * uSize.x + x).y;
      if (kernelIndex == kNoSprite) continue;
      vec4 kernel = uKernels[kernelIndex];
      vec2 d = vec2(centre - ivec2(x, y));
      float d2 = dot(d, d);
      if (d2 > kernel.w) continue;  // outside the disc core::estimateDensity gives the kernel
      vec4 sums = texelFetch(uDensity, ivec2(x, y), 0);
      sum += (sums * logScale(sums.a, uBrightness)) * (exp(d2 * kernel.x) * kernel.y);
    }
  }
  imageStore(uTarget, q, sum);
}
