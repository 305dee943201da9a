// Density estimation's table of sprites (flame_finisher.h): every pixel writes (its index, its
// kernel) into its own slot, or marks it empty when its kernel is one pixel wide or it holds
// nothing, so the scatter needs no read-back to size its draw and adds its floats in pixel order.
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler2D uDensity;
uniform ivec2 uSize;
uniform float uHitsPerUnit;
const int kMaxKernels = 192;
uniform vec4 uKernels[kMaxKernels];

layout(std430, binding = 0) buffer Command {
  uint vertexCount;  // DrawArraysIndirectCommand
  uint instanceCount;
  uint first;
  uint baseInstance;
};
const uint kNoSprite = 0xFFFFFFFFu;
layout(std430, binding = 1) writeonly buffer Sprites {
  uvec2 sprites[];  // pixel index (x + y · width), kernel index
};

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= uSize.x || p.y >= uSize.y) return;
  // Each pixel has its own slot, in pixel order: an appended list's order would change from run
  // to run, and with it the order the scatter adds floats in, so two finishes of the same sums
  // would differ in their last bits. Pixels that scatter nothing are marked for the vertex stage
  // to drop.
  uint slot = uint(p.y * uSize.x + p.x);
  float density = texelFetch(uDensity, p, 0).a;
  int kernel = density > 0.0 ? kernelIndex(density * uHitsPerUnit) : 0;
  bool drawn = density > 0.0 && uKernels[kernel].z != 0.0;  // one pixel: the fold pass adds it in place
  sprites[slot] = uvec2(slot, drawn ? uint(kernel) : kNoSprite);
}
