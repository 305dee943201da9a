// Density estimation's list of sprites (flame_finisher.h): every pixel whose kernel is wider than a
// pixel appends (its index, its kernel) to a list and counts itself into the indirect draw's vertex
// count, so the scatter's vertex stage (one thread on llvmpipe) runs only for the pixels it draws,
// and nothing is read back to size the draw.
layout(local_size_x = 8, local_size_y = 8) in;

uniform sampler2D uDensity;
uniform ivec2 uSize;
uniform float uHitsPerUnit;
uniform uint uVerticesPerSprite;  // 1 for a point, 6 for a quad
const int kMaxKernels = 192;
uniform vec4 uKernels[kMaxKernels];

layout(std430, binding = 0) buffer Command {
  uint vertexCount;  // DrawArraysIndirectCommand
  uint instanceCount;
  uint first;
  uint baseInstance;
};
layout(std430, binding = 1) writeonly buffer Sprites {
  uvec2 sprites[];  // pixel index (x + y · width), kernel index
};

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= uSize.x || p.y >= uSize.y) return;
  float density = texelFetch(uDensity, p, 0).a;
  if (density <= 0.0) return;
  int kernel = kernelIndex(density * uHitsPerUnit);
  if (uKernels[kernel].z == 0.0) return;  // one pixel: the fold pass adds it in place
  uint slot = atomicAdd(vertexCount, uVerticesPerSprite) / uVerticesPerSprite;
  sprites[slot] = uvec2(uint(p.y * uSize.x + p.x), uint(kernel));
}
