// Density estimation's sprite list packed for the scatter (flame_finisher.h): the per-pixel table
// finish_compact.comp.glsl made holds a slot for every pixel, most of them empty, and a software
// rasteriser runs its whole vertex stage for every slot drawn, dropped or not. Three passes move
// the drawn slots to the front, still in pixel order (so the sprites add their floats in the same
// order every time): each chunk of kChunk slots counts its drawn ones (COUNT), one invocation turns
// the counts into offsets and sets the draw's count (OFFSETS), each chunk copies its drawn slots to
// its offset (WRITE). The defines pick the pass.
#ifdef OFFSETS
layout(local_size_x = 1) in;
#else
layout(local_size_x = 64) in;
#endif

const uint kChunk = 64u;
const uint kNoSprite = 0xFFFFFFFFu;
uniform uint uSlots;   // pixels in the table
uniform uint uChunks;  // (uSlots + kChunk − 1) / kChunk
uniform uint uVerticesPerSprite;

layout(std430, binding = 0) buffer Command {
  uint vertexCount;  // DrawArraysIndirectCommand
  uint instanceCount;
  uint first;
  uint baseInstance;
};
layout(std430, binding = 1) readonly buffer Sprites {
  uvec2 sprites[];  // per pixel: (pixel index, kernel index or kNoSprite)
};
layout(std430, binding = 2) buffer Chunks {
  uint chunks[];  // per chunk: its drawn slots (COUNT), then where they go (OFFSETS)
};
layout(std430, binding = 3) writeonly buffer Packed {
  uvec2 packedSprites[];
};

void main() {
#ifdef OFFSETS
  uint total = 0u;
  for (uint c = 0u; c < uChunks; ++c) {
    uint count = chunks[c];
    chunks[c] = total;
    total += count;
  }
  vertexCount = total * uVerticesPerSprite;
#else
  uint chunk = gl_GlobalInvocationID.x;
  if (chunk >= uChunks) return;
  uint begin = chunk * kChunk, end = min(begin + kChunk, uSlots);
#ifdef COUNT
  uint count = 0u;
  for (uint slot = begin; slot < end; ++slot)
    if (sprites[slot].y != kNoSprite) ++count;
  chunks[chunk] = count;
#else
  uint next = chunks[chunk];
  for (uint slot = begin; slot < end; ++slot) {
    uvec2 sprite = sprites[slot];
    if (sprite.y != kNoSprite) packedSprites[next++] = sprite;
  }
#endif
#endif
}
