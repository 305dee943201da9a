// The GPU backend's grid passes besides the chaos step (gpu_accumulator.h), one per define:
// CLEAR_GRID empties the grid for a new generation, writing each voxel's outside flag from the
// inside mask's bits; SAMPLE_DENSITY gathers the hit counts of every uStride-th voxel for the
// convergence meter, so it reads back kilobytes instead of the grid.
layout(local_size_x = 256) in;

layout(std430, binding = 1) buffer Cells { uvec4 cells[]; };
#ifndef HITS_IN_CELLS
layout(std430, binding = 2) buffer Hits { uint hits[]; };
#endif
layout(std430, binding = 6) readonly buffer MaskBits { uint insideBits[]; };  // bit v: voxel v is inside
layout(std430, binding = 7) buffer Sample { uint sampled[]; };

uniform uint uCount;   // voxels (CLEAR_GRID: cells too, in the same pass), or sampled voxels
uniform uint uCellCount;
uniform uint uStride;  // SAMPLE_DENSITY: every uStride-th voxel

const uint kOutsideBit = 0x80000000u;

uint hitsOf(uint voxel) {
#ifdef HITS_IN_CELLS
  return cells[voxel].w;
#else
  return hits[voxel];
#endif
}

void main() {
  uint i = gl_GlobalInvocationID.x;
#ifdef CLEAR_GRID
  if (i < uCount) {
    bool inside = (insideBits[i >> 5] & (1u << (i & 31u))) != 0u;
    uint flag = inside ? 0u : kOutsideBit;
#ifdef HITS_IN_CELLS
    cells[i] = uvec4(0u, 0u, 0u, flag);
#else
    hits[i] = flag;
#endif
  }
#ifndef HITS_IN_CELLS
  if (i < uCellCount) cells[i] = uvec4(0u);
#endif
#endif
#ifdef SAMPLE_DENSITY
  if (i < uCount) sampled[i] = hitsOf(i * uStride) & ~kOutsideBit;
#endif
}
