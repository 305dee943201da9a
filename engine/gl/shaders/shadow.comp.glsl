// The shadow volume (core/shadow_volume.h) on the GPU, from the density texture the ray-marcher
// reads, for volumes that never were in host memory (gpu_volume.h). The same sweep as the CPU's,
// one pass per define:
//   SIGMA: each cell's extinction per cell edge, from its voxels' densities.
//   SWEEP: one slice of cells, away from the light: the light reaching each cell's centre is what
//     reached the previous slice one step toward the light (read bilinearly), less the extinction
//     between the two centres. One dispatch a slice, each after the last.
//   TRANSMITTANCE: exp(-depth) into the R8 texture the march reads.
layout(local_size_x = 256) in;

layout(std430, binding = 12) buffer Sigma { float sigma[]; };
layout(std430, binding = 13) buffer Depth { float depth[]; };
uniform sampler3D uDensity;  // relative density per voxel (in alpha where uDensityInAlpha)
uniform bool uDensityInAlpha;
layout(r8, binding = 3) writeonly uniform image3D uShadow;

uniform ivec3 uVoxels;     // the grid
uniform ivec3 uCells;      // shadow cells, each uDownsample³ voxels
uniform int uDownsample;
uniform float uPerVoxelWeight;  // toRelative × extinction per voxel × voxels per cell edge ÷ voxels per cell
uniform int uAxis, uU, uV;      // the sweep's axis (the light's most aligned) and the slice's two others
uniform int uSlice;             // SWEEP: this slice
uniform int uPrevious;          // SWEEP: the slice one step toward the light (-1: none)
uniform vec2 uShift;            // SWEEP: where the previous slice is read, in cells along u and v
uniform float uPathPerSlice;    // SWEEP: cell edges crossed per slice

int cellIndex(ivec3 c) {
  return c.x + uCells.x * (c.y + uCells.y * c.z);
}

float field(bool ofDepth, int slice, int p, int q) {
  ivec3 d;
  d[uAxis] = slice;
  d[uU] = p;
  d[uV] = q;
  if (p < 0 || q < 0 || p >= uCells[uU] || q >= uCells[uV]) return 0.0;
  const int index = cellIndex(d);
  return ofDepth ? depth[index] : sigma[index];
}

float bilinear(bool ofDepth, int slice, int p0, int q0, float fu, float fv) {
  return (1.0 - fu) * (1.0 - fv) * field(ofDepth, slice, p0, q0) + fu * (1.0 - fv) * field(ofDepth, slice, p0 + 1, q0) +
         (1.0 - fu) * fv * field(ofDepth, slice, p0, q0 + 1) + fu * fv * field(ofDepth, slice, p0 + 1, q0 + 1);
}

void main() {
  const int id = int(gl_GlobalInvocationID.x);
#ifdef SIGMA
  if (id >= uCells.x * uCells.y * uCells.z) return;
  const ivec3 c = ivec3(id % uCells.x, (id / uCells.x) % uCells.y, id / (uCells.x * uCells.y));
  float sum = 0.0;
  for (int z = 0; z < uDownsample; ++z)
    for (int y = 0; y < uDownsample; ++y)
      for (int x = 0; x < uDownsample; ++x) {
        const ivec3 v = c * uDownsample + ivec3(x, y, z);
        if (any(greaterThanEqual(v, uVoxels))) continue;
        const vec4 texel = texelFetch(uDensity, v, 0);
        const float normalised = uDensityInAlpha ? texel.a : texel.r;
        if (normalised > 0.0) sum += normalised * uPerVoxelWeight;
      }
  sigma[id] = sum;
#endif
#ifdef SWEEP
  const int width = uCells[uU];
  if (id >= width * uCells[uV]) return;
  const int p = id % width, q = id / width;
  float before = 0.0, sigmaBefore = 0.0;
  if (uPrevious >= 0) {
    const vec2 at = vec2(p, q) + uShift;
    const ivec2 at0 = ivec2(floor(at));
    const vec2 f = at - vec2(at0);
    before = bilinear(true, uPrevious, at0.x, at0.y, f.x, f.y);
    sigmaBefore = bilinear(false, uPrevious, at0.x, at0.y, f.x, f.y);
  }
  ivec3 c;
  c[uAxis] = uSlice;
  c[uU] = p;
  c[uV] = q;
  const int index = cellIndex(c);
  depth[index] = before + 0.5 * (sigmaBefore + sigma[index]) * uPathPerSlice;
#endif
#ifdef TRANSMITTANCE
  if (id >= uCells.x * uCells.y * uCells.z) return;
  const ivec3 c = ivec3(id % uCells.x, (id / uCells.x) % uCells.y, id / (uCells.x * uCells.y));
  imageStore(uShadow, c, vec4(round(255.0 * exp(-depth[id])) / 255.0));
#endif
}
