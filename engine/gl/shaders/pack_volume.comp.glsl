// The GPU backend's pack for the renderer (gpu_volume.h): the grid's sums become the textures the
// ray-marcher samples, as core::packVolume makes them on the CPU, one pass per define.
//   PACK_VOXELS: each voxel's density relative to the mesh's mean, and the bricks within one voxel
//     of a voxel with density marked occupied (distance 0) in the distance buffer.
//   PACK_CELLS: each colour cell's mean colour times its voxels' mean density, and that density.
//   EMPTY_DISTANCE: one axis of the bricks' Chebyshev distance to the nearest occupied brick. It is
//     separable: along each axis in turn, d(p) = min over q of max(|p - q|, d_before(q)), so three
//     passes give the exact distance the CPU's chamfer passes give (capped at 255 alike).
layout(local_size_x = 256) in;

layout(std430, binding = 1) readonly buffer Cells { uvec4 cells[]; };  // red, green, blue, count
#ifndef HITS_IN_CELLS
layout(std430, binding = 2) readonly buffer Hits { uint hits[]; };
#endif
layout(std430, binding = 10) buffer DistanceIn { uint distanceIn[]; };
layout(std430, binding = 11) buffer DistanceOut { uint distanceOut[]; };
layout(r16f, binding = 0) writeonly uniform image3D uDensity;
layout(rgba16f, binding = 1) writeonly uniform image3D uColour;
layout(r8ui, binding = 2) writeonly uniform uimage3D uEmptyDistance;

uniform ivec3 uSize;        // voxels
uniform ivec3 uColourSize;  // colour cells
uniform int uColourShift;   // a colour cell spans 2^uColourShift voxels along each axis
uniform ivec3 uBricks;      // bricks of 4³ voxels
uniform float uInverseScale;  // 1 / the hits one unit of texel density stands for
uniform int uAxis;            // EMPTY_DISTANCE: 0, 1, 2
uniform bool uLastAxis;       // EMPTY_DISTANCE: write the texture instead of distanceOut

const uint kOutsideBit = 0x80000000u;
const float kLargestHalf = 65504.0;  // a voxel denser than that is saturated, not infinite
const int kBrickShift = 2;
const uint kMaxEmptyDistance = 255u;
const uint kColourCountLimit = 1u << 24;

uint hitsOf(int voxel) {
#ifdef HITS_IN_CELLS
  return cells[voxel].w & ~kOutsideBit;
#else
  return hits[voxel] & ~kOutsideBit;
#endif
}

// As the CPU computes it, operation for operation, so the two packs agree to the half float.
float weightOf(uint count) {
  return count == 0u ? 0.0 : min(float(count) * uInverseScale, kLargestHalf);
}

int voxelIndex(ivec3 v) {
  return v.x + uSize.x * (v.y + uSize.y * v.z);
}

int brickIndex(ivec3 b) {
  return b.x + uBricks.x * (b.y + uBricks.y * b.z);
}

void main() {
  const int id = int(gl_GlobalInvocationID.x);
#ifdef PACK_VOXELS
  if (id >= uSize.x * uSize.y * uSize.z) return;
  const ivec3 v = ivec3(id % uSize.x, (id / uSize.x) % uSize.y, id / (uSize.x * uSize.y));
  const uint count = hitsOf(id);
  imageStore(uDensity, v, vec4(weightOf(count)));
  if (count == 0u) return;
  // Trilinear filtering reaches a voxel's density from one voxel away, so every brick within one
  // voxel of it is marched.
  const ivec3 first = max(v - 1, ivec3(0)) >> kBrickShift, last = min(v + 1, uSize - 1) >> kBrickShift;
  for (int z = first.z; z <= last.z; ++z)
    for (int y = first.y; y <= last.y; ++y)
      for (int x = first.x; x <= last.x; ++x) distanceIn[brickIndex(ivec3(x, y, z))] = 0u;
#endif
#ifdef PACK_CELLS
  if (id >= uColourSize.x * uColourSize.y * uColourSize.z) return;
  const ivec3 c = ivec3(id % uColourSize.x, (id / uColourSize.x) % uColourSize.y, id / (uColourSize.x * uColourSize.y));
  const int span = 1 << uColourShift;
  float weights = 0.0;
  for (int z = 0; z < span; ++z)
    for (int y = 0; y < span; ++y)
      for (int x = 0; x < span; ++x) {
        const ivec3 v = c * span + ivec3(x, y, z);
        if (all(lessThan(v, uSize))) weights += weightOf(hitsOf(voxelIndex(v)));
      }
  // The cell's weight is its voxels' mean density: what the trilinear blend between neighbouring
  // cells weighs their colours by.
  const float weight = min(weights * (1.0 / float(span * span * span)), kLargestHalf);
  const uvec4 cell = cells[id];
  const uint points = min(cell.w & ~kOutsideBit, kColourCountLimit);
  if (weight <= 0.0 || points == 0u) {
    imageStore(uColour, c, vec4(0.0));
    return;
  }
  const float toMean = (1.0 / 255.0) / float(points);
  imageStore(uColour, c, vec4(weight * (vec3(cell.xyz) * toMean), weight));
#endif
#ifdef EMPTY_DISTANCE
  if (id >= uBricks.x * uBricks.y * uBricks.z) return;
  const ivec3 b = ivec3(id % uBricks.x, (id / uBricks.x) % uBricks.y, id / (uBricks.x * uBricks.y));
  const int length = uBricks[uAxis];
  const int here = b[uAxis];
  uint best = distanceIn[id];
  // Brick q at |here - q| = r gives max(r, d(q)) >= r: nothing farther than the best so far beats it.
  for (int r = 1; uint(r) < best && (here - r >= 0 || here + r < length); ++r) {
    ivec3 q = b;
    if (here - r >= 0) {
      q[uAxis] = here - r;
      best = min(best, max(uint(r), distanceIn[brickIndex(q)]));
    }
    if (here + r < length) {
      q[uAxis] = here + r;
      best = min(best, max(uint(r), distanceIn[brickIndex(q)]));
    }
  }
  best = min(best, kMaxEmptyDistance);
  if (uLastAxis)
    imageStore(uEmptyDistance, b, uvec4(best));
  else
    distanceOut[id] = best;
#endif
}
