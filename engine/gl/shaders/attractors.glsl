// The attractor catalogue (core/attractor.cpp) in GLSL, for the GPU backend (gpu_accumulator.h):
// the same fields and maps, one selected per program by a SYSTEM_<ID> define, in float. p(i) is
// the layer's parameter i. core/attractor.cpp stays the reference: a test steps every system here
// and there from the same points and compares.

uniform float uParams[32];

// Every system runs in float: a GPU's double rate is a thirty-second of its float rate or less on
// most cards, and the agreement test finds float's attractors the CPU's within sampling noise.
// (`real` names the state's type in one place, should a system ever need more.)
#define real float
#define real3 vec3
float p(int i) { return uParams[i]; }

#if defined(SYSTEM_PICKOVER) || defined(SYSTEM_POLYNOMIAL_A) || defined(SYSTEM_POLYNOMIAL_B) || \
    defined(SYSTEM_POLYNOMIAL_C) || defined(SYSTEM_HENON_3D) || defined(SYSTEM_SPROTT_QUADRATIC)
#define SYSTEM_IS_MAP 1
#endif

#ifdef SYSTEM_IS_MAP
real3 mapStep(real3 s) {
  real x = s.x, y = s.y, z = s.z;
#if defined(SYSTEM_PICKOVER)
  return vec3(sin(p(0) * y) - z * cos(p(1) * x), z * sin(p(2) * x) - cos(p(3) * y), sin(x));
#elif defined(SYSTEM_POLYNOMIAL_A)
  return real3(p(0) + y - z * y, p(1) + z - x * z, p(2) + x - y * x);
#elif defined(SYSTEM_POLYNOMIAL_B)
  return real3(p(0) + y - z * (p(1) + y), p(2) + z - x * (p(3) + z), p(4) + x - y * (p(5) + x));
#elif defined(SYSTEM_POLYNOMIAL_C)
  return real3(p(0) + x * (p(1) + p(2) * x + p(3) * y) + y * (p(4) + p(5) * y),
              p(6) + y * (p(7) + p(8) * y + p(9) * z) + z * (p(10) + p(11) * z),
              p(12) + z * (p(13) + p(14) * z + p(15) * x) + x * (p(16) + p(17) * x));
#elif defined(SYSTEM_HENON_3D)
  return real3(1.0 - p(0) * x * x + y, p(1) * x, p(2) * z + x);
#elif defined(SYSTEM_SPROTT_QUADRATIC)
  real3 n;
  for (int c = 0; c < 3; ++c) {
    int a = 10 * c;
    n[c] = p(a) + x * (p(a + 1) + p(a + 2) * x + p(a + 3) * y + p(a + 4) * z) + y * (p(a + 5) + p(a + 6) * y + p(a + 7) * z) +
           z * (p(a + 8) + p(a + 9) * z);
  }
  return n;
#endif
}
#else
vec3 field(vec3 s) {
  float x = s.x, y = s.y, z = s.z;
#if defined(SYSTEM_LORENZ)
  return vec3(p(0) * (y - x), p(1) * x - y - z * x, x * y - p(2) * z);
#elif defined(SYSTEM_LORENZ84) || defined(SYSTEM_HADLEY)
  return vec3(-p(0) * x - y * y - z * z + p(0) * p(2), -y + x * y - p(1) * x * z + p(3), -z + p(1) * x * y + x * z);
#elif defined(SYSTEM_ROSSLER)
  return vec3(-y - z, x + p(0) * y, p(1) + z * (x - p(2)));
#elif defined(SYSTEM_AIZAWA)
  return vec3((z - p(1)) * x - p(3) * y, p(3) * x + (z - p(1)) * y,
              p(2) + p(0) * z - z * z * z / 3.0 - (x * x + y * y) * (1.0 + p(4) * z) + p(5) * z * x * x * x);
#elif defined(SYSTEM_THOMAS)
  return vec3(sin(y) - p(0) * x, sin(z) - p(0) * y, sin(x) - p(0) * z);
#elif defined(SYSTEM_HALVORSEN)
  return vec3(-p(0) * x - 4.0 * y - 4.0 * z - y * y, -p(0) * y - 4.0 * z - 4.0 * x - z * z,
              -p(0) * z - 4.0 * x - 4.0 * y - x * x);
#elif defined(SYSTEM_CHEN)
  return vec3(p(0) * (y - x), (p(2) - p(0)) * x - x * z + p(2) * y, x * y - p(1) * z);
#elif defined(SYSTEM_LU_CHEN)
  return vec3(p(0) * (y - x), -x * z + p(2) * y, x * y - p(1) * z);
#elif defined(SYSTEM_DADRAS)
  return vec3(y - p(0) * x + p(1) * y * z, p(2) * y - x * z + z, p(3) * x * y - p(4) * z);
#elif defined(SYSTEM_RABINOVICH_FABRIKANT)
  return vec3(y * (z - 1.0 + x * x) + p(1) * x, x * (3.0 * z + 1.0 - x * x) + p(1) * y, -2.0 * z * (p(0) + x * y));
#elif defined(SYSTEM_CHUA)
  float diode = p(3) * x + 0.5 * (p(2) - p(3)) * (abs(x + 1.0) - abs(x - 1.0));
  return vec3(p(0) * (y - x - diode), x - y + z, -p(1) * y);
#elif defined(SYSTEM_NOSE_HOOVER)
  return vec3(y, -x + y * z, p(0) - y * y);
#elif defined(SYSTEM_ARNEODO)
  return vec3(y, z, -p(0) * x - p(1) * y - z + p(2) * x * x * x);
#elif defined(SYSTEM_BURKE_SHAW)
  return vec3(-p(0) * (x + y), -y - p(0) * x * z, p(0) * x * y + p(1));
#elif defined(SYSTEM_DEQUAN_LI)
  return vec3(p(0) * (y - x) + p(2) * x * z, p(4) * x + p(5) * y - x * z, p(1) * z + x * y - p(3) * x * x);
#elif defined(SYSTEM_FOUR_WING)
  return vec3(p(0) * x + y * z, p(1) * x + p(2) * y - x * z, -z - x * y);
#elif defined(SYSTEM_GENESIO_TESI)
  return vec3(y, z, -p(2) * x - p(1) * y - p(0) * z + x * x);
#elif defined(SYSTEM_NEWTON_LEIPNIK)
  return vec3(-p(0) * x + y + 10.0 * y * z, -x - 0.4 * y + 5.0 * x * z, p(1) * z - 5.0 * x * y);
#elif defined(SYSTEM_RUCKLIDGE)
  return vec3(-p(0) * x + p(1) * y - y * z, x, -z + y * y);
#elif defined(SYSTEM_SHIMIZU_MORIOKA)
  return vec3(y, x - p(0) * y - x * z, -p(1) * z + x * x);
#elif defined(SYSTEM_SAKARYA)
  return vec3(-x + y + y * z, -x - y + p(0) * x * z, z - p(1) * x * y);
#elif defined(SYSTEM_YU_WANG)
  return vec3(p(0) * (y - x), p(1) * x - p(2) * x * z, exp(x * y) - p(3) * z);
#elif defined(SYSTEM_SPROTT_JERK)
  return vec3(y, z, -p(0) * z + y * y - x);
#elif defined(SYSTEM_SPROTT_B)
  return vec3(p(0) * y * z, x - y, 1.0 - x * y);
#elif defined(SYSTEM_SPROTT_C)
  return vec3(p(0) * y * z, x - y, 1.0 - x * x);
#elif defined(SYSTEM_SPROTT_D)
  return vec3(-y, x + z, x * z + p(0) * y * y);
#elif defined(SYSTEM_SPROTT_E)
  return vec3(y * z, x * x - y, 1.0 - p(0) * x);
#elif defined(SYSTEM_SPROTT_F)
  return vec3(y + z, -x + p(0) * y, x * x - z);
#elif defined(SYSTEM_SPROTT_G)
  return vec3(p(0) * x + z, x * z - y, -x + y);
#elif defined(SYSTEM_SPROTT_H)
  return vec3(-y + z * z, x + p(0) * y, x - z);
#elif defined(SYSTEM_SPROTT_L)
  return vec3(y + p(0) * z, p(1) * x * x - y, 1.0 - x);
#elif defined(SYSTEM_SPROTT_M)
  return vec3(-z, -x * x - y, p(0) + p(0) * x + y);
#elif defined(SYSTEM_SPROTT_N)
  return vec3(-p(0) * y, x + z * z, 1.0 + y - 2.0 * z);
#elif defined(SYSTEM_SPROTT_O)
  return vec3(y, x - z, x + x * z + p(0) * y);
#elif defined(SYSTEM_SPROTT_P)
  return vec3(p(0) * y + z, -x + y * y, x + y);
#elif defined(SYSTEM_SPROTT_Q)
  return vec3(-z, x - y, p(0) * x + y * y + p(1) * z);
#elif defined(SYSTEM_SPROTT_R)
  return vec3(p(0) - y, p(1) + z, x * y - z);
#elif defined(SYSTEM_SPROTT_S)
  return vec3(-x - p(0) * y, x + z * z, 1.0 + x);
#else
#error "no SYSTEM_<ID> defined, or one this file does not know"
#endif
}
#endif

// One map iteration, or one step of the layer's integrator.
real3 advance(real3 s, float h) {
#ifdef SYSTEM_IS_MAP
  return mapStep(s);
#elif defined(INTEGRATOR_RK4)
  vec3 k1 = field(s);
  vec3 k2 = field(s + 0.5 * h * k1);
  vec3 k3 = field(s + 0.5 * h * k2);
  vec3 k4 = field(s + h * k3);
  return s + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
#else
  return s + h * field(s);
#endif
}
