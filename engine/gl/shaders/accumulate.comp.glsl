// The GPU backend's chaos step (gpu_accumulator.h): one invocation per orbit, uSteps steps of the
// layer's attractor (attractors.glsl, put before this file) or, with CHAOS_GAME, of its flame or
// quaternion Julia set (flame_variations.glsl and the layer's generated chaosStep, flame_kernel.h)
// per dispatch, each point classified the
// way core::Accumulator's classify pass does it (escape test, colour, a jittered voxel, the inside
// flag) and added to the grid with integer atomics, so the sums come out the same in any order.
// The grid's layout is the CPU's: hit counts carry the outside flag in their top bit; colour cells
// hold red, green, blue and a count, and where a cell is one voxel (HITS_IN_CELLS) its count is
// the voxel's hits.
#ifdef GROUP_CHOICE
// A flame's transforms are branches: orbits side by side in one SIMD group that take different
// transforms run each other's code, so a 50-transform flame ran at a fiftieth of its speed. With
// GROUP_CHOICE (flame_kernel.h: flames without xaos) each group of kGroupSize orbits takes one
// transform per step, drawn from its weights, and after every step the workgroup's points are dealt
// to other lanes by a random affine permutation (cuburn's way): each point's transforms are still
// drawn independently from the weights, and points that shared a step part at the next.
layout(local_size_x = 256) in;
const uint kGroupSize = 32u;
shared uint groupChoice[256 / 32];
shared uvec2 dealing;             // the permutation's multiplier (odd) and offset
shared vec4 dealtChaos[256];      // the chaos state
shared vec4 dealtPosition[256];   // xyz: the point drawn last, w: its colour index
shared vec4 dealtLastStep[256];   // xyz: the step before, w: the orbit's age (its bits)
#else
layout(local_size_x = 64) in;
#endif

struct Orbit {
  vec4 position;  // w: unused
  vec4 previous;  // the position one step before
  vec4 lastStep;  // the step before that (curvature colouring)
  uvec4 state;    // x: jitter stream (xorshift32, never 0), y: age (kUnseeded: to be seeded), z: reseeds
#ifdef CHAOS_GAME
  CHAOS_STATE chaos;  // the iterated state (a quaternion's fourth component in w; dvec4 for one); position is what is drawn
  vec4 chaosColour;   // x: flam3's colour index, 0–1
  // x: the chaos stream (xorshift32, never 0), y: 1 + the transform taken last (xaos), z: JWildfire's
  // doHide (gHidden)
  uvec4 chaosStream;
#endif
};
layout(std430, binding = 0) buffer Orbits { Orbit orbits[]; };
layout(std430, binding = 1) buffer Cells { uvec4 cells[]; };  // red, green, blue, count
#ifndef HITS_IN_CELLS
layout(std430, binding = 2) buffer Hits { uint hits[]; };
#endif
layout(std430, binding = 3) readonly buffer Seeds { vec4 seeds[]; };  // points on the attractor
layout(std430, binding = 4) buffer Counters { uint counters[]; };     // inside, outside, escapes
layout(std430, binding = 5) readonly buffer Palette { uint palette[]; };  // 256 linear RGB8
#ifdef LANE_MEMORY
// What the flame's variations keep per orbit from step to step (flame_variations.glsl's gLane).
layout(std430, binding = 13) buffer LaneMemory { double laneMemory[]; };
#endif

uniform uint uOrbitCount;
uniform int uSteps;
uniform float uStep;           // the integrator's step (flows)
uniform uint uStreamSeed;      // the pattern's seed, chunk and layer, mixed
uniform uint uSeedCount;
uniform float uHair;           // a flow's orbits start this far (relative) off their seed
uniform mat3 uToGrid;          // attractor → voxel coordinates
uniform vec3 uGridOffset;
uniform ivec3 uGridSize;
uniform int uColourShift;
uniform ivec2 uCellStrides;    // colour cells along x, along x·y
uniform float uEscapeRadius;
uniform float uAlongStep;      // 1 for flows: a point lands at a random spot of its last step
uniform int uColorMode;        // core::ColorMode: 0 speed, 1 curvature, 2 time, 3 axis, 4 distance, 5 index
uniform float uIndexDither;    // index: 1 takes the next palette entry with the fraction's chance (linear)
uniform float uColorScale;
uniform float uInversePeriod;
uniform vec3 uAxis;
uniform float uAxisOffset;
uniform vec3 uCenter;
uniform bool uJittered;        // core::Deposit::Jittered (else Nearest)


const int kTransientSteps = 32;
const uint kUnseeded = 0xFFFFFFFFu;
const uint kAgeLimit = 1u << 30;
const uint kOutsideBit = 0x80000000u;
const uint kColourCountLimit = 1u << 24;

// PCG's output permutation as a hash (Jarzynski and Olano, "Hash Functions for GPU Rendering",
// JCGT 2020): seeds and reseeds draw from it, so each orbit's stream depends on its index alone.
uint pcgHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
uint xorshift32(uint r) {
  r ^= r << 13;
  r ^= r >> 17;
  r ^= r << 5;
  return r;
}
// The top 24 bits as a uniform offset in [-0.5, 0.5), as the CPU's jitter takes them.
float jitterOffset(uint r) { return float(r >> 8) * (1.0 / 16777216.0) - 0.5; }
float symmetric(uint r) { return float(r >> 8) * (2.0 / 16777216.0) - 1.0; }

// One point's colour into its cell: the count goes on, the sums stop at kColourCountLimit points
// (the CPU's rule, so the sums stay below 2^32 and the long-converged mean stays put).
void addColour(uint cell, uint colour) {
  uint before = atomicAdd(cells[cell].w, 1u);
  if (before < kColourCountLimit) {
    atomicAdd(cells[cell].x, colour & 0xffu);
    atomicAdd(cells[cell].y, (colour >> 8) & 0xffu);
    atomicAdd(cells[cell].z, (colour >> 16) & 0xffu);
  }
}

#ifdef PROJECT_POINTS
// The points method (core/point_renderer.h, core::PointProjector, stays the reference): each accepted
// point is projected through the camera into a supersampled screen histogram instead of the grid,
// dimmed by the camera's transmittance through the volume in front of it, by the light's shadow and
// by fog, its share rounded to whole counts at random in proportion (so no bias), and added with
// integer atomics: 4 counts per pixel (red, green, blue, density), saturating at 2^32 - 1.
layout(std430, binding = 12) buffer Screen { uint screen[]; };
// core::ViewTransmittance's values as a texture: x the slice boundary (depth + 1 of them), y and z
// the cell across and down; its layout is the CPU array's.
uniform sampler3D uViewTransmittance;
uniform sampler3D uLightTransmittance;  // core::ShadowVolume, 0–1
uniform mat4 uView;
uniform mat4 uProjection;
uniform vec3 uOrigin;            // the grid's, world units
uniform float uVoxelSize;
uniform bool uOrthographic;
uniform float uNearPlane;
uniform ivec2 uScreenSize;       // supersampled pixels
uniform float uPointCounts;      // counts one point adds at unit view depth (core::PointScale)
uniform float uAperture;         // thin lens radius, world units (0: pinhole)
uniform float uFocus;            // view depth in focus
uniform float uFogPerDepth;
uniform float uFogStart;
uniform bool uDimmed;            // a view transmittance is bound
uniform ivec3 uViewCells;        // its cells across, down, and slices
uniform float uViewNear;
uniform float uViewDepthScale;   // slices per unit of view depth
uniform bool uLit;               // a shadow volume is bound
uniform ivec3 uShadowSize;
uniform float uShadowToCell;     // 1 / the shadow's downsample
uniform float uLightStrength;

// Two 16-bit uniforms in [-0.5, 0.5) from one 32-bit draw (the CPU takes four from 64 bits).
float halfJitter(uint r, int part) { return float((r >> (16 * part)) & 0xffffu) * (1.0 / 65536.0) - 0.5; }
uint countOf(float value, float dither) { return uint(clamp(value + dither, 0.0, 4294967040.0)); }
void addCount(uint index, uint add) {
  if (add == 0u) return;
  uint before = atomicAdd(screen[index], add);
  if (before + add < before) atomicMax(screen[index], 0xffffffffu);  // wrapped: saturate
}

void projectPoint(vec3 g, uint colour, inout uint r) {
  vec4 eye = uView * vec4(uOrigin + uVoxelSize * g, 1.0);
  float depth = -eye.z;
  if (depth <= uNearPlane) return;
  if (uAperture > 0.0) {
    // A thin lens: seen from a random point of the lens disc, refocused at uFocus.
    r = xorshift32(r);
    float radius = uAperture * sqrt(float(r >> 8) * (1.0 / 16777216.0));
    r = xorshift32(r);
    float angle = 6.28318530718 * float(r >> 8) * (1.0 / 16777216.0);
    eye.xy += radius * vec2(cos(angle), sin(angle)) * (depth / uFocus - 1.0);
  }
  vec4 clip = uProjection * eye;
  float u = clip.x / clip.w * 0.5 + 0.5, v = 0.5 - clip.y / clip.w * 0.5;
  float px = u * float(uScreenSize.x), py = v * float(uScreenSize.y);
  if (!(px >= 0.0 && py >= 0.0 && px < float(uScreenSize.x) && py < float(uScreenSize.y))) return;
  float weight = uOrthographic ? uPointCounts : uPointCounts / (depth * depth);
  if (uDimmed && depth > uViewNear) {
    // A jittered nearest cell across, linear along depth: the expected value interpolates between
    // cell centres (core::ViewTransmittance::at).
    r = xorshift32(r);
    int x = clamp(int(floor(u * float(uViewCells.x) + halfJitter(r, 0))), 0, uViewCells.x - 1);
    int y = clamp(int(floor(v * float(uViewCells.y) + halfJitter(r, 1))), 0, uViewCells.y - 1);
    float z = min((depth - uViewNear) * uViewDepthScale, float(uViewCells.z));
    int z0 = min(int(z), uViewCells.z - 1);
    float front = texelFetch(uViewTransmittance, ivec3(z0, x, y), 0).r;
    float back = texelFetch(uViewTransmittance, ivec3(z0 + 1, x, y), 0).r;
    weight *= front + (z - float(z0)) * (back - front);
  }
  if (uLit) {
    r = xorshift32(r);
    uint first = r;
    r = xorshift32(r);
    vec3 jitter = vec3(halfJitter(first, 0), halfJitter(first, 1), halfJitter(r, 0));
    ivec3 cell = clamp(ivec3(floor(g * uShadowToCell + jitter)), ivec3(0), uShadowSize - 1);
    weight *= 1.0 + uLightStrength * (texelFetch(uLightTransmittance, cell, 0).r - 1.0);
  }
  if (uFogPerDepth > 0.0) weight *= exp(-uFogPerDepth * max(0.0, depth - uFogStart));
  r = xorshift32(r);
  float dither = float(r >> 8) * (1.0 / 16777216.0);
  uint at = 4u * (uint(py) * uint(uScreenSize.x) + uint(px));
  addCount(at, countOf(weight * float(colour & 0xffu) * (1.0 / 255.0), dither));
  addCount(at + 1u, countOf(weight * float((colour >> 8) & 0xffu) * (1.0 / 255.0), dither));
  addCount(at + 2u, countOf(weight * float((colour >> 16) & 0xffu) * (1.0 / 255.0), dither));
  addCount(at + 3u, countOf(weight, dither));
}
#endif

void seedOrbit(inout Orbit o, uint index) {
  uint h = pcgHash(uStreamSeed ^ pcgHash(index * 2654435761u + o.state.z * 40503u));
#ifdef CHAOS_GAME
  // As core::ChaosGame::seedLane: anywhere in [-1, 1]³ (and w), any colour; the transient finds the set.
  uint a = pcgHash(h), b = pcgHash(a), c = pcgHash(b), d = pcgHash(c), e = pcgHash(d);
  o.chaos = CHAOS_STATE(symmetric(a), symmetric(b), symmetric(c), symmetric(d));
  o.chaosColour = vec4(float(e >> 8) * (1.0 / 16777216.0), 0.0, 0.0, 0.0);
  gChaosRandom = pcgHash(e) | 1u;
  o.chaosStream = uvec4(gChaosRandom, 0u, 0u, 0u);
#ifdef HIDES_POINTS
  gHidden = false;  // as the CPU's seedLane
#endif
  vec3 start = vec3(o.chaos.xyz);
#else
  vec3 s = seeds[h % max(uSeedCount, 1u)].xyz;
  uint a = pcgHash(h), b = pcgHash(a), c = pcgHash(b);
  vec3 start = s + uHair * (1.0 + abs(s)) * vec3(symmetric(a), symmetric(b), symmetric(c));
#endif
  o.position = vec4(start, 0.0);
  o.previous = o.position;
  o.lastStep = vec4(0.0);
  o.state.y = 0u;
  o.state.z += 1u;
  if (o.state.x == 0u) o.state.x = pcgHash(c) | 1u;
}

void main() {
  uint index = gl_GlobalInvocationID.x;
  if (index >= uOrbitCount) return;
  Orbit o = orbits[index];
  if (o.state.y == kUnseeded) {
    o.state.z = 0u;
    o.state.x = 0u;
    seedOrbit(o, index);
  }
  uint inside = 0u, outside = 0u, escapes = 0u;
#ifdef CHAOS_GAME
  gChaosRandom = o.chaosStream.x;
#ifdef HIDES_POINTS
  gHidden = o.chaosStream.z != 0u;
#endif
#ifdef LANE_MEMORY
  for (int i = 0; i < LANE_MEMORY; ++i) gLane[i] = laneMemory[index * uint(LANE_MEMORY) + uint(i)];
#endif
#else
  real3 state = real3(o.position.xyz);
#endif
#ifdef GROUP_CHOICE
  uint lane = gl_LocalInvocationIndex;
#endif
  for (int step = 0; step < uSteps; ++step) {
#ifdef GROUP_CHOICE
    if (lane % kGroupSize == 0u) {
      psi();
      groupChoice[lane / kGroupSize] = pickTransform(gChaosRandom);
    }
    if (lane == 0u) {
      psi();
      // An odd multiplier of at least 33 sends the 32 orbits of a group into every group.
      dealing = uvec2(33u + 2u * (gChaosRandom % 112u), gChaosRandom >> 8);
    }
    memoryBarrierShared();
    barrier();
    vec3 q;
    float drawnColour;
    bool visible = chaosStepWith(groupChoice[lane / kGroupSize], o.chaos, o.chaosColour.x, q, drawnColour);
#elif defined(CHAOS_GAME)
    vec3 q;
    float drawnColour;
    bool visible = chaosStep(o.chaos, o.chaosColour.x, o.chaosStream.y, q, drawnColour);
#else
    const bool visible = true;
    real3 next = advance(state, uStep);
    vec3 q = vec3(next);
#endif
    bool finite = all(lessThan(abs(q), vec3(uEscapeRadius)));  // false for NaN
    vec3 d = q - o.previous.xyz;
    float value;
    if (uColorMode == 0) {
      value = length(d);
    } else if (uColorMode == 1) {
      vec3 s = o.lastStep.xyz;
      value = length(cross(d, s)) / (sqrt(dot(d, d) * dot(s, s)) + 1e-30);
    } else if (uColorMode == 2) {
      float cycles = float(o.state.y) * uInversePeriod;
      value = cycles - floor(cycles);
    } else if (uColorMode == 3) {
      value = dot(q, uAxis) - uAxisOffset;
    } else if (uColorMode == 4) {
      value = length(q - uCenter);
    } else {
#ifdef CHAOS_GAME
      value = drawnColour;
#else
      value = 0.0;
#endif
    }
    float t = value * uColorScale * 255.0;
    uint r = o.state.x;
    if (uColorMode == 5 && uIndexDither > 0.0) {
      r = xorshift32(r);
      t += uIndexDither * (jitterOffset(r) + 0.5);
    }
    t = finite ? clamp(t, 0.0, 255.0) : 0.0;
    uint colour = palette[uint(t)];
#ifdef PAINTS_RGB
    if ((gPointRgb & kRgbPainted) != 0u) colour = gPointRgb & 0xffffffu;  // a variation's true colour
#endif

    r = xorshift32(r);
    float along = uAlongStep * (jitterOffset(r) + 0.5);
    vec3 g = uToGrid * (q - along * d) + uGridOffset;
#ifdef PROJECT_POINTS
    // The points method projects the exact position, and tests the voxel it lies in.
    if (false) {
#else
    if (uJittered) {
#endif
      r = xorshift32(r);
      g.x += jitterOffset(r);
      r = xorshift32(r);
      g.y += jitterOffset(r);
      r = xorshift32(r);
      g.z += jitterOffset(r);
    }
    bool inGrid = finite && all(greaterThanEqual(g, vec3(0.0))) && all(lessThan(g, vec3(uGridSize)));
    // A point its transform's opacity (or a quaternion slice) hides is not a point at all.
    bool settled = finite && visible && o.state.y > uint(kTransientSteps);
    if (settled) {
      if (!inGrid) {
        ++outside;
      } else {
        ivec3 v = ivec3(g);
        uint voxel = uint(v.x + uGridSize.x * (v.y + uGridSize.y * v.z));
        ivec3 c = v >> uColourShift;
        uint cell = uint(c.x + uCellStrides.x * c.y + uCellStrides.y * c.z);
#ifdef HITS_IN_CELLS
        // The flag never changes within a generation, so a plain read of it is exact.
        if ((cells[cell].w & kOutsideBit) != 0u) {
          ++outside;
        } else {
#ifdef PROJECT_POINTS
          projectPoint(g, colour, r);
#else
          addColour(cell, colour);  // the cell's count is the voxel's hits
#endif
          ++inside;
        }
#else
        if ((hits[voxel] & kOutsideBit) != 0u) {
          ++outside;
        } else {
#ifdef PROJECT_POINTS
          projectPoint(g, colour, r);
#else
          atomicAdd(hits[voxel], 1u);
          addColour(cell, colour);
#endif
          ++inside;
        }
#endif
      }
    }
    o.state.x = r;
    if (!finite) {
      ++escapes;
      seedOrbit(o, index);
#ifndef CHAOS_GAME
      state = real3(o.position.xyz);
#endif
    } else {
#ifndef CHAOS_GAME
      state = next;
#endif
      o.lastStep = vec4(d, 0.0);
      o.previous = vec4(q, 0.0);
      o.position = vec4(q, 0.0);
      if (o.state.y < kAgeLimit) ++o.state.y;
    }
#ifdef GROUP_CHOICE
    // Deal the points: what travels is the orbit (state, colour, last point and step, age); the
    // lane keeps its random streams and reseed count.
    uint slot = (lane * dealing.x + dealing.y) & 255u;
    dealtChaos[slot] = o.chaos;
    dealtPosition[slot] = vec4(o.position.xyz, o.chaosColour.x);
    dealtLastStep[slot] = vec4(o.lastStep.xyz, uintBitsToFloat(o.state.y));
    memoryBarrierShared();
    barrier();
    o.chaos = dealtChaos[lane];
    o.position = vec4(dealtPosition[lane].xyz, 0.0);
    o.previous = o.position;
    o.chaosColour.x = dealtPosition[lane].w;
    o.lastStep = vec4(dealtLastStep[lane].xyz, 0.0);
    o.state.y = floatBitsToUint(dealtLastStep[lane].w);
    memoryBarrierShared();
    barrier();
#endif
  }
#ifdef CHAOS_GAME
  o.chaosStream.x = gChaosRandom;
#ifdef HIDES_POINTS
  o.chaosStream.z = gHidden ? 1u : 0u;
#endif
#ifdef LANE_MEMORY
  for (int i = 0; i < LANE_MEMORY; ++i) laneMemory[index * uint(LANE_MEMORY) + uint(i)] = gLane[i];
#endif
#endif
  orbits[index] = o;
  if (inside != 0u) atomicAdd(counters[0], inside);
  if (outside != 0u) atomicAdd(counters[1], outside);
  if (escapes != 0u) atomicAdd(counters[2], escapes);
}
