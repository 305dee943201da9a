// JWildfire's weighting fields on the GPU: core::weightFieldNoise (flame/weight_field.cpp, which
// stays the reference) in float, its lattice hashes to the bit. A kernel with a field puts the
// field's block in flameData at F (flame_kernel.cpp's fieldBlock):
//   F + 0   kind (1 noise, 2 fractal)        F + 5   octaves
//   F + 1   fractal (0 fbm, 1 billow, 2 rigid) F + 6 frequency
//   F + 2   noise (0 simplex, 1 perlin, 2 value, 3 cubic, 4 cellular, 5 white)
//   F + 3   cellular distance (0 euclidean, 1 manhattan, 2 natural)
//   F + 4   cellular return (core::CellReturn's order)
//   F + 7   gain, F + 8 lacunarity, F + 9 the seed's bits, F + 10 where the simplex tables lie
//   F + 11  for simplex noise: each octave's offset (x, y, z) in double, as two floats' bits each.

// core's latticeHash: murmur3's finaliser over a mix of the seed and the lattice point.
uint fieldHash(int seed, ivec3 c) {
  uint h = uint(seed) * 0x9E3779B1u;
  h ^= uint(c.x) * 0x85EBCA77u;
  h ^= uint(c.y) * 0xC2B2AE3Du;
  h ^= uint(c.z) * 0x27D4EB2Fu;
  h ^= h >> 16;
  h *= 0x85EBCA6Bu;
  h ^= h >> 13;
  h *= 0xC2B2AE35u;
  h ^= h >> 16;
  return h;
}

float fieldLatticeValue(int seed, ivec3 c) {
  // The hash's top 24 bits: float holds no more (the CPU's value to within 2⁻²³).
  return float(fieldHash(seed, c) >> 8) * (2.0 / 16777216.0) - 1.0;
}

// core's cell: the lattice coordinate, repeating past ±2³⁰; a point not finite reads the cell at 0.
int fieldCell(float v) {
  float f = floor(v);
  if (isinf(f) || isnan(f)) return 0;
  return int(f - 1073741824.0 * trunc(f / 1073741824.0));
}
ivec3 fieldCell3(vec3 v) {
  return ivec3(fieldCell(v.x), fieldCell(v.y), fieldCell(v.z));
}

vec3 fieldQuintic(vec3 t) {
  return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}

float fieldValueNoise(int seed, vec3 p) {
  ivec3 c = fieldCell3(p);
  vec3 f = fieldQuintic(p - floor(p));
  float a = mix(mix(fieldLatticeValue(seed, c), fieldLatticeValue(seed, c + ivec3(1, 0, 0)), f.x),
                mix(fieldLatticeValue(seed, c + ivec3(0, 1, 0)), fieldLatticeValue(seed, c + ivec3(1, 1, 0)), f.x), f.y);
  float b = mix(mix(fieldLatticeValue(seed, c + ivec3(0, 0, 1)), fieldLatticeValue(seed, c + ivec3(1, 0, 1)), f.x),
                mix(fieldLatticeValue(seed, c + ivec3(0, 1, 1)), fieldLatticeValue(seed, c + ivec3(1, 1, 1)), f.x), f.y);
  return mix(a, b, f.z);
}

// One of the 12 cube-edge directions, by the hash, dotted with the offset d.
float fieldGradientDot(uint hash, vec3 d) {
  switch (hash % 12u) {
    case 0u: return d.x + d.y;
    case 1u: return -d.x + d.y;
    case 2u: return d.x - d.y;
    case 3u: return -d.x - d.y;
    case 4u: return d.x + d.z;
    case 5u: return -d.x + d.z;
    case 6u: return d.x - d.z;
    case 7u: return -d.x - d.z;
    case 8u: return d.y + d.z;
    case 9u: return -d.y + d.z;
    case 10u: return d.y - d.z;
    default: return -d.y - d.z;
  }
}

float fieldPerlinCorner(int seed, ivec3 c, vec3 f, ivec3 corner) {
  return fieldGradientDot(fieldHash(seed, c + corner), f - vec3(corner));
}

float fieldPerlinNoise(int seed, vec3 p) {
  ivec3 c = fieldCell3(p);
  vec3 f = p - floor(p);
  vec3 u = fieldQuintic(f);
  float a = mix(mix(fieldPerlinCorner(seed, c, f, ivec3(0, 0, 0)), fieldPerlinCorner(seed, c, f, ivec3(1, 0, 0)), u.x),
                mix(fieldPerlinCorner(seed, c, f, ivec3(0, 1, 0)), fieldPerlinCorner(seed, c, f, ivec3(1, 1, 0)), u.x),
                u.y);
  float b = mix(mix(fieldPerlinCorner(seed, c, f, ivec3(0, 0, 1)), fieldPerlinCorner(seed, c, f, ivec3(1, 0, 1)), u.x),
                mix(fieldPerlinCorner(seed, c, f, ivec3(0, 1, 1)), fieldPerlinCorner(seed, c, f, ivec3(1, 1, 1)), u.x),
                u.y);
  return mix(a, b, u.z);
}

float fieldCubicBlend(vec4 v, float t) {
  float p = (v.w - v.z) - (v.x - v.y);
  return ((p * t + ((v.x - v.y) - p)) * t + (v.z - v.x)) * t + v.y;
}

// A cubic through four lattice values per axis, scaled by 1/1.5³. Loops, not arrays unrolled: the
// 64 hashes stay one loop body for the compiler.
float fieldCubicNoise(int seed, vec3 p) {
  ivec3 c = fieldCell3(p) - ivec3(1);
  vec3 f = p - floor(p);
  vec4 planes;
  for (int k = 0; k < 4; ++k) {
    vec4 rows;
    for (int j = 0; j < 4; ++j) {
      vec4 row = vec4(fieldLatticeValue(seed, c + ivec3(0, j, k)), fieldLatticeValue(seed, c + ivec3(1, j, k)),
                      fieldLatticeValue(seed, c + ivec3(2, j, k)), fieldLatticeValue(seed, c + ivec3(3, j, k)));
      rows[j] = fieldCubicBlend(row, f.x);
    }
    planes[k] = fieldCubicBlend(rows, f.y);
  }
  return fieldCubicBlend(planes, f.z) / (1.5 * 1.5 * 1.5);
}

// A value per point from its coordinates' single-precision bits.
float fieldWhiteNoise(int seed, vec3 p) {
  ivec3 bits = floatBitsToInt(p);
  return fieldLatticeValue(seed, bits ^ (bits >> 16));
}

// Worley noise: a feature point 0.45 from each lattice point in a direction from its hash, the
// nearest and second nearest of the 27 about the lattice point nearest p.
float fieldCellularNoise(int seed, int metric, int kind, vec3 p) {
  ivec3 r = fieldCell3(p + 0.5);
  float nearest = 3.402823466e38, second = nearest;
  ivec3 closest = ivec3(0);
  for (int i = -1; i <= 1; ++i)
    for (int j = -1; j <= 1; ++j)
      for (int k = -1; k <= 1; ++k) {
        ivec3 c = r + ivec3(i, j, k);
        uint h = fieldHash(seed, c);
        float cosTheta = float(h & 0xFFFFu) * (2.0 / 65535.0) - 1.0;
        float phi = float(h >> 16) * (2.0 * 3.14159265358979 / 65536.0);
        float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
        vec3 d = vec3(c) - p + 0.45 * vec3(sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
        float manhattan = abs(d.x) + abs(d.y) + abs(d.z);
        float squared = dot(d, d);
        float distance = metric == 0 ? squared : metric == 1 ? manhattan : manhattan + squared;
        if (distance < nearest) {
          second = nearest;
          nearest = distance;
          closest = c;
        } else if (distance < second) {
          second = distance;
        }
      }
  switch (kind) {
    case 0: return fieldLatticeValue(0, closest);
    case 1: return nearest - 1.0;
    case 2: return second - 1.0;
    case 3: return second + nearest - 1.0;
    case 4: return second - nearest - 1.0;
    case 5: return second * nearest - 1.0;
    default: return nearest / second - 1.0;
  }
}

double fieldDouble(int at) {
  return packDouble2x32(uvec2(floatBitsToUint(flameData[at]), floatBitsToUint(flameData[at + 1])));
}

// One octave's noise at p (already scaled by its frequency), with the octave's seed.
float fieldSingleNoise(int F, int octave, int seed, vec3 p) {
  switch (int(flameData[F + 2])) {
    case 0: {
      int at = F + 11 + 6 * octave;
      return simplexNoise3D(int(flameData[F + 10]),
                            dvec3(p) + dvec3(fieldDouble(at), fieldDouble(at + 2), fieldDouble(at + 4)));
    }
    case 1: return fieldPerlinNoise(seed, p);
    case 2: return fieldValueNoise(seed, p);
    case 3: return fieldCubicNoise(seed, p);
    case 4: return fieldCellularNoise(seed, int(flameData[F + 3]), int(flameData[F + 4]), p);
    default: return fieldWhiteNoise(seed, p);
  }
}

// n(p) of the field whose block is at F (core::weightFieldNoise): a noise, or FastNoise's fractal
// sums, octave k at seed + k.
float weightFieldNoise(int F, vec3 p) {
  float frequency = flameData[F + 6];
  int seed = floatBitsToInt(flameData[F + 9]);
  if (flameData[F + 0] == 1.0) return fieldSingleNoise(F, 0, seed, frequency * p);
  int fractal = int(flameData[F + 1]), octaves = int(flameData[F + 5]);
  float gain = flameData[F + 7], lacunarity = flameData[F + 8];
  float sum = 0.0, amplitude = 1.0, bound = 0.0;
  for (int octave = 0; octave < octaves; ++octave) {
    float n = fieldSingleNoise(F, octave, int(uint(seed) + uint(octave)), frequency * p);
    if (fractal == 0)
      sum += amplitude * n;
    else if (fractal == 1)
      sum += amplitude * (2.0 * abs(n) - 1.0);
    else
      sum += (octave == 0 ? 1.0 : -amplitude) * (1.0 - abs(n));
    bound += amplitude;
    amplitude *= gain;
    frequency *= lacunarity;
  }
  if (fractal == 2) return sum;
  return bound != 0.0 ? sum / bound : 0.0;
}
