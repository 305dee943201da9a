#include "attractor.h"

#include <algorithm>
#include <cmath>

#include "cpu_features.h"
#include "enum_names.h"
#include "error.h"
#include "vector_math.h"

namespace voxflame::core {

std::string_view toString(AttractorKind kind) {
  return kind == AttractorKind::Map ? "map" : "flow";
}
std::string_view toString(Integrator integrator) {
  return enumName(kIntegratorNames, integrator);
}

Integrator integratorFromString(std::string_view name) {
  if (const std::optional<Integrator> integrator = enumFromName<Integrator>(kIntegratorNames, name)) return *integrator;
  std::string message = "unknown integrator '";
  message.append(name).append("' (expected ").append(quotedChoices(kIntegratorNames)).append(")");
  throw Error(message);
}

std::vector<double> AttractorInfo::defaultParams() const {
  std::vector<double> values;
  values.reserve(params.size());
  for (const auto& p : params) values.push_back(p.defaultValue);
  return values;
}

int AttractorInfo::paramIndex(std::string_view paramName) const {
  for (std::size_t i = 0; i < params.size(); ++i)
    if (params[i].name == paramName) return static_cast<int>(i);
  return -1;
}

const NamedParams* AttractorInfo::alternative(std::string_view setName) const {
  for (const auto& set : alternatives)
    if (set.name == setName) return &set;
  return nullptr;
}

namespace {

// Forward-mode dual number with three derivative directions: evaluating a step on Dual inputs
// seeded with the unit vectors gives the step's exact Jacobian (no finite-difference noise).
struct Dual {
  double v = 0.0;
  double d[3] = {0.0, 0.0, 0.0};
  Dual() = default;
  Dual(double value) : v(value) {}  // NOLINT: constants promote implicitly, as doubles do
};

inline Dual operator+(const Dual& a, const Dual& b) {
  Dual r(a.v + b.v);
  for (int i = 0; i < 3; ++i) r.d[i] = a.d[i] + b.d[i];
  return r;
}
inline Dual operator-(const Dual& a, const Dual& b) {
  Dual r(a.v - b.v);
  for (int i = 0; i < 3; ++i) r.d[i] = a.d[i] - b.d[i];
  return r;
}
inline Dual operator-(const Dual& a) {
  Dual r(-a.v);
  for (int i = 0; i < 3; ++i) r.d[i] = -a.d[i];
  return r;
}
inline Dual operator*(const Dual& a, const Dual& b) {
  Dual r(a.v * b.v);
  for (int i = 0; i < 3; ++i) r.d[i] = a.d[i] * b.v + a.v * b.d[i];
  return r;
}
inline Dual operator/(const Dual& a, const Dual& b) {
  Dual r(a.v / b.v);
  for (int i = 0; i < 3; ++i) r.d[i] = (a.d[i] * b.v - a.v * b.d[i]) / (b.v * b.v);
  return r;
}
inline Dual& operator+=(Dual& a, const Dual& b) {
  return a = a + b;
}

// Elementary functions for both number types; systems call these unqualified.
inline Dual chain(const Dual& a, double value, double derivative) {
  Dual r(value);
  for (int i = 0; i < 3; ++i) r.d[i] = derivative * a.d[i];
  return r;
}
inline double fsin(double a) {
  return std::sin(a);
}
inline double fcos(double a) {
  return std::cos(a);
}
inline double fexp(double a) {
  return std::exp(a);
}
inline double fabsolute(double a) {
  return std::abs(a);
}
inline Dual fsin(const Dual& a) {
  return chain(a, std::sin(a.v), std::cos(a.v));
}
inline Dual fcos(const Dual& a) {
  return chain(a, std::cos(a.v), -std::sin(a.v));
}
inline Dual fexp(const Dual& a) {
  return chain(a, std::exp(a.v), std::exp(a.v));
}
inline Dual fabsolute(const Dual& a) {
  return chain(a, std::abs(a.v), a.v < 0.0 ? -1.0 : 1.0);
}

// A flow is given by its vector field; Euler and RK4 steppers are generated from it so each
// system is written once. `System::field` must be a pure function of its inputs.
template <class System, class T>
void eulerOne(const double* params, double h, T& x, T& y, T& z) {
  T dx, dy, dz;
  System::field(params, x, y, z, dx, dy, dz);
  x = x + h * dx;
  y = y + h * dy;
  z = z + h * dz;
}

template <class System, class T>
void rk4One(const double* params, double h, T& x, T& y, T& z) {
  T k1x, k1y, k1z, k2x, k2y, k2z, k3x, k3y, k3z, k4x, k4y, k4z;
  const double half = 0.5 * h;
  System::field(params, x, y, z, k1x, k1y, k1z);
  System::field(params, x + half * k1x, y + half * k1y, z + half * k1z, k2x, k2y, k2z);
  System::field(params, x + half * k2x, y + half * k2y, z + half * k2z, k3x, k3y, k3z);
  System::field(params, x + h * k3x, y + h * k3y, z + h * k3z, k4x, k4y, k4z);
  const double sixth = h / 6.0;
  x = x + sixth * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
  y = y + sixth * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
  z = z + sixth * (k1z + 2.0 * k2z + 2.0 * k3z + k4z);
}

template <class System, class T>
void mapOne(const double* params, double /*h*/, T& x, T& y, T& z) {
  T nx, ny, nz;
  System::map(params, x, y, z, nx, ny, nz);
  x = nx;
  y = ny;
  z = nz;
}

template <class System, template <class, class> class Stepper>
struct Kernels {
  // Plain loop over independent orbits: no aliasing between the three arrays (they are distinct
  // vectors in the accumulator), so GCC vectorises polynomial systems across orbits.
  [[gnu::always_inline]] static void advanceBody(const double* params, double h, double* __restrict x,
                                                 double* __restrict y, double* __restrict z, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) {
      double a = x[i], b = y[i], c = z[i];
      Stepper<System, double>::run(params, h, a, b, c);
      x[i] = a;
      y[i] = b;
      z[i] = c;
    }
  }
  static void advance(const double* params, double h, double* __restrict x, double* __restrict y, double* __restrict z,
                      std::size_t count) {
    advanceBody(params, h, x, y, z, count);
  }
#if defined(__x86_64__) && !defined(__AVX2__)
  // The same loop built for AVX2 (4 orbits per instruction), chosen at run time by pickAdvance.
  [[gnu::target("avx2")]] static void advanceAvx2(const double* params, double h, double* __restrict x,
                                                  double* __restrict y, double* __restrict z, std::size_t count) {
    advanceBody(params, h, x, y, z, count);
  }
#endif
  static AdvanceFn pickAdvance() {
#if defined(__x86_64__) && !defined(__AVX2__)
    if (cpuHasAvx2()) return &advanceAvx2;
#endif
    return &advance;
  }
  static void jacobian(const double* params, double h, double* state, double* jacobian) {
    Dual x(state[0]), y(state[1]), z(state[2]);
    x.d[0] = 1.0;
    y.d[1] = 1.0;
    z.d[2] = 1.0;
    Stepper<System, Dual>::run(params, h, x, y, z);
    const Dual* next[3] = {&x, &y, &z};
    for (int row = 0; row < 3; ++row) {
      state[row] = next[row]->v;
      for (int column = 0; column < 3; ++column) jacobian[3 * row + column] = next[row]->d[column];
    }
  }
};

template <class System, class T>
struct EulerStepper {
  static void run(const double* p, double h, T& x, T& y, T& z) { eulerOne<System, T>(p, h, x, y, z); }
};
template <class System, class T>
struct Rk4Stepper {
  static void run(const double* p, double h, T& x, T& y, T& z) { rk4One<System, T>(p, h, x, y, z); }
};
template <class System, class T>
struct MapStepper {
  static void run(const double* p, double h, T& x, T& y, T& z) { mapOne<System, T>(p, h, x, y, z); }
};

template <class System>
AttractorInfo flow(AttractorInfo info) {
  info.kind = AttractorKind::Flow;
  info.advanceEuler = Kernels<System, EulerStepper>::pickAdvance();
  info.advanceRk4 = Kernels<System, Rk4Stepper>::pickAdvance();
  info.jacobianEuler = &Kernels<System, EulerStepper>::jacobian;
  info.jacobianRk4 = &Kernels<System, Rk4Stepper>::jacobian;
  return info;
}

template <class System>
AttractorInfo map(AttractorInfo info) {
  info.kind = AttractorKind::Map;
  info.advanceEuler = info.advanceRk4 = Kernels<System, MapStepper>::pickAdvance();
  info.jacobianEuler = info.jacobianRk4 = &Kernels<System, MapStepper>::jacobian;
  info.defaultStep = 1.0;
  info.defaultIntegrator = Integrator::Euler;
  return info;
}

// A parameter whose slider spans a sensible neighbourhood of its literature value.
ParamInfo param(std::string name, double value) {
  const double span = std::max(0.5 * std::abs(value), 0.25);
  return {std::move(name), value, value - span, value + span};
}
ParamInfo param(std::string name, double value, double min, double max) {
  return {std::move(name), value, min, max};
}

// Every system below is written once over its number type T (double or Dual).
#define VOXFLAME_FIELD                                                                                          \
  template <class T>                                                                                            \
  static void field([[maybe_unused]] const double* p, [[maybe_unused]] const T& x, [[maybe_unused]] const T& y, \
                    [[maybe_unused]] const T& z, T& dx, T& dy, T& dz)
#define VOXFLAME_MAP \
  template <class T> \
  static void map(const double* p, const T& x, const T& y, const T& z, T& nx, T& ny, T& nz)

// --- the seed's six -----------------------------------------------------------------------------

struct Lorenz {
  VOXFLAME_FIELD {
    dx = p[0] * (y - x);
    dy = p[1] * x - y - z * x;
    dz = x * y - p[2] * z;
  }
};
// Lorenz-84: Lorenz's low-order model of the general atmospheric circulation.
struct Lorenz84 {
  VOXFLAME_FIELD {
    const double a = p[0], b = p[1], f = p[2], g = p[3];
    dx = -a * x - y * y - z * z + a * f;
    dy = -y + x * y - b * x * z + g;
    dz = -z + b * x * y + x * z;
  }
};
struct Pickover {
  VOXFLAME_MAP {
    nx = fsin(p[0] * y) - z * fcos(p[1] * x);
    ny = z * fsin(p[2] * x) - fcos(p[3] * y);
    nz = fsin(x);
  }
};
struct PolynomialA {
  VOXFLAME_MAP {
    nx = p[0] + y - z * y;
    ny = p[1] + z - x * z;
    nz = p[2] + x - y * x;
  }
};
struct PolynomialB {
  VOXFLAME_MAP {
    nx = p[0] + y - z * (p[1] + y);
    ny = p[2] + z - x * (p[3] + z);
    nz = p[4] + x - y * (p[5] + x);
  }
};
struct PolynomialC {
  VOXFLAME_MAP {
    nx = p[0] + x * (p[1] + p[2] * x + p[3] * y) + y * (p[4] + p[5] * y);
    ny = p[6] + y * (p[7] + p[8] * y + p[9] * z) + z * (p[10] + p[11] * z);
    nz = p[12] + z * (p[13] + p[14] * z + p[15] * x) + x * (p[16] + p[17] * x);
  }
};

// --- classic flows ------------------------------------------------------------------------------

struct Rossler {
  VOXFLAME_FIELD {
    dx = -y - z;
    dy = x + p[0] * y;
    dz = p[1] + z * (x - p[2]);
  }
};
struct Aizawa {
  VOXFLAME_FIELD {
    const double a = p[0], b = p[1], c = p[2], d = p[3], e = p[4], f = p[5];
    dx = (z - b) * x - d * y;
    dy = d * x + (z - b) * y;
    dz = c + a * z - z * z * z / 3.0 - (x * x + y * y) * (1.0 + e * z) + f * z * x * x * x;
  }
};
struct Thomas {
  VOXFLAME_FIELD {
    dx = fsin(y) - p[0] * x;
    dy = fsin(z) - p[0] * y;
    dz = fsin(x) - p[0] * z;
  }
};
struct Halvorsen {
  VOXFLAME_FIELD {
    dx = -p[0] * x - 4.0 * y - 4.0 * z - y * y;
    dy = -p[0] * y - 4.0 * z - 4.0 * x - z * z;
    dz = -p[0] * z - 4.0 * x - 4.0 * y - x * x;
  }
};
struct Chen {
  VOXFLAME_FIELD {
    dx = p[0] * (y - x);
    dy = (p[2] - p[0]) * x - x * z + p[2] * y;
    dz = x * y - p[1] * z;
  }
};
struct LuChen {
  VOXFLAME_FIELD {
    dx = p[0] * (y - x);
    dy = -x * z + p[2] * y;
    dz = x * y - p[1] * z;
  }
};
struct Dadras {
  VOXFLAME_FIELD {
    dx = y - p[0] * x + p[1] * y * z;
    dy = p[2] * y - x * z + z;
    dz = p[3] * x * y - p[4] * z;
  }
};
struct RabinovichFabrikant {
  VOXFLAME_FIELD {
    const double alpha = p[0], gamma = p[1];
    dx = y * (z - 1.0 + x * x) + gamma * x;
    dy = x * (3.0 * z + 1.0 - x * x) + gamma * y;
    dz = -2.0 * z * (alpha + x * y);
  }
};
struct Chua {
  VOXFLAME_FIELD {
    const double alpha = p[0], beta = p[1], m0 = p[2], m1 = p[3];
    const T diode = m1 * x + 0.5 * (m0 - m1) * (fabsolute(x + 1.0) - fabsolute(x - 1.0));
    dx = alpha * (y - x - diode);
    dy = x - y + z;
    dz = -beta * y;
  }
};
struct NoseHoover {
  VOXFLAME_FIELD {
    dx = y;
    dy = -x + y * z;
    dz = p[0] - y * y;
  }
};
struct Arneodo {
  VOXFLAME_FIELD {
    dx = y;
    dy = z;
    dz = -p[0] * x - p[1] * y - z + p[2] * x * x * x;
  }
};
struct BurkeShaw {
  VOXFLAME_FIELD {
    dx = -p[0] * (x + y);
    dy = -y - p[0] * x * z;
    dz = p[0] * x * y + p[1];
  }
};
struct DequanLi {
  VOXFLAME_FIELD {
    const double a = p[0], c = p[1], d = p[2], e = p[3], k = p[4], f = p[5];
    dx = a * (y - x) + d * x * z;
    dy = k * x + f * y - x * z;
    dz = c * z + x * y - e * x * x;
  }
};
struct FourWing {
  VOXFLAME_FIELD {
    dx = p[0] * x + y * z;
    dy = p[1] * x + p[2] * y - x * z;
    dz = -z - x * y;
  }
};
struct GenesioTesi {
  VOXFLAME_FIELD {
    dx = y;
    dy = z;
    dz = -p[2] * x - p[1] * y - p[0] * z + x * x;
  }
};
struct NewtonLeipnik {
  VOXFLAME_FIELD {
    dx = -p[0] * x + y + 10.0 * y * z;
    dy = -x - 0.4 * y + 5.0 * x * z;
    dz = p[1] * z - 5.0 * x * y;
  }
};
struct Rucklidge {
  VOXFLAME_FIELD {
    dx = -p[0] * x + p[1] * y - y * z;
    dy = x;
    dz = -z + y * y;
  }
};
struct ShimizuMorioka {
  VOXFLAME_FIELD {
    dx = y;
    dy = x - p[0] * y - x * z;
    dz = -p[1] * z + x * x;
  }
};
struct Sakarya {
  VOXFLAME_FIELD {
    dx = -x + y + y * z;
    dy = -x - y + p[0] * x * z;
    dz = z - p[1] * x * y;
  }
};
struct YuWang {
  VOXFLAME_FIELD {
    dx = p[0] * (y - x);
    dy = p[1] * x - p[2] * x * z;
    dz = fexp(x * y) - p[3] * z;
  }
};
// Sprott's simplest dissipative chaotic flow: the jerk equation x''' + a x'' - x'^2 + x = 0.
struct SprottJerk {
  VOXFLAME_FIELD {
    dx = y;
    dy = z;
    dz = -p[0] * z + y * y - x;
  }
};

// Sprott's 1994 survey of the simplest chaotic flows (cases B..S); the one constant that
// distinguishes each case is its parameter.
struct SprottB {
  VOXFLAME_FIELD {
    dx = p[0] * y * z;
    dy = x - y;
    dz = 1.0 - x * y;
  }
};
struct SprottC {
  VOXFLAME_FIELD {
    dx = p[0] * y * z;
    dy = x - y;
    dz = 1.0 - x * x;
  }
};
struct SprottD {
  VOXFLAME_FIELD {
    dx = -y;
    dy = x + z;
    dz = x * z + p[0] * y * y;
  }
};
struct SprottE {
  VOXFLAME_FIELD {
    dx = y * z;
    dy = x * x - y;
    dz = 1.0 - p[0] * x;
  }
};
struct SprottF {
  VOXFLAME_FIELD {
    dx = y + z;
    dy = -x + p[0] * y;
    dz = x * x - z;
  }
};
struct SprottG {
  VOXFLAME_FIELD {
    dx = p[0] * x + z;
    dy = x * z - y;
    dz = -x + y;
  }
};
struct SprottH {
  VOXFLAME_FIELD {
    dx = -y + z * z;
    dy = x + p[0] * y;
    dz = x - z;
  }
};
struct SprottL {
  VOXFLAME_FIELD {
    dx = y + p[0] * z;
    dy = p[1] * x * x - y;
    dz = 1.0 - x;
  }
};
struct SprottM {
  VOXFLAME_FIELD {
    dx = -z;
    dy = -x * x - y;
    dz = p[0] + p[0] * x + y;
  }
};
struct SprottN {
  VOXFLAME_FIELD {
    dx = -p[0] * y;
    dy = x + z * z;
    dz = 1.0 + y - 2.0 * z;
  }
};
struct SprottO {
  VOXFLAME_FIELD {
    dx = y;
    dy = x - z;
    dz = x + x * z + p[0] * y;
  }
};
struct SprottP {
  VOXFLAME_FIELD {
    dx = p[0] * y + z;
    dy = -x + y * y;
    dz = x + y;
  }
};
struct SprottQ {
  VOXFLAME_FIELD {
    dx = -z;
    dy = x - y;
    dz = p[0] * x + y * y + p[1] * z;
  }
};
struct SprottR {
  VOXFLAME_FIELD {
    dx = p[0] - y;
    dy = p[1] + z;
    dz = x * y - z;
  }
};
struct SprottS {
  VOXFLAME_FIELD {
    dx = -x - p[0] * y;
    dy = x + z * z;
    dz = 1.0 + x;
  }
};

// --- maps ---------------------------------------------------------------------------------------

// The Hénon map in (x, y) with a leaky memory of x in z: the Jacobian is block-triangular, so
// the spectrum is Hénon's two exponents plus log|c| — a textbook check for the Lyapunov code.
struct Henon3d {
  VOXFLAME_MAP {
    nx = 1.0 - p[0] * x * x + y;
    ny = p[1] * x;
    nz = p[2] * z + x;
  }
};
// Sprott's general 3D quadratic map: each coordinate is a full quadratic in (x, y, z).
struct SprottQuadratic {
  VOXFLAME_MAP {
    const auto quadratic = [&](const double* a) {
      return a[0] + x * (a[1] + a[2] * x + a[3] * y + a[4] * z) + y * (a[5] + a[6] * y + a[7] * z) +
             z * (a[8] + a[9] * z);
    };
    nx = quadratic(p);
    ny = quadratic(p + 10);
    nz = quadratic(p + 20);
  }
};

#undef VOXFLAME_FIELD
#undef VOXFLAME_MAP

constexpr const char* kSprott1994 = "J. C. Sprott, \"Some simple chaotic flows\", Phys. Rev. E 50, R647 (1994)";
constexpr const char* kSprottBook =
    "J. C. Sprott, \"Strange Attractors: Creating Patterns in Chaos\", M&T Books (1993)";
constexpr const char* kSeed = "voxflame seed catalogue";
// Found by voxflame's chaos search over random letter codes: chaotic (largest exponent ~0.11 per
// iteration) with a Kaplan-Yorke dimension ~2.4, so it fills a volume rather than a sheet.
constexpr const char* kSprottDefaultCode = "TXGJBUAELWVBHYVTGSPAVSHEPGMIGR";

// Builds "a1", "p0", ...; appending (rather than "a" + to_string) avoids a GCC 12 -Wrestrict
// false positive in std::string's operator+.
std::string indexedName(char prefix, std::size_t index) {
  std::string name(1, prefix);
  name += std::to_string(index);
  return name;
}

std::vector<ParamInfo> sprottQuadraticParams(const std::vector<double>& values) {
  std::vector<ParamInfo> params;
  for (std::size_t i = 0; i < values.size(); ++i)
    params.push_back(param(indexedName('a', i + 1), values[i], -1.2, 1.2));
  return params;
}

std::vector<ParamInfo> polynomialParams(const std::vector<double>& values, double span) {
  std::vector<ParamInfo> params;
  for (std::size_t i = 0; i < values.size(); ++i)
    params.push_back(param(indexedName('p', i), values[i], values[i] - span, values[i] + span));
  return params;
}

// One of Sprott's 1994 cases: integrated with RK4.
template <class System>
AttractorInfo sprottCase(char letter, std::vector<ParamInfo> params, glm::dvec3 start, double step,
                         std::string equations) {
  return flow<System>({.id = std::string("sprott_") + static_cast<char>(letter - 'A' + 'a'),
                       .name = std::string("Sprott case ") + letter,
                       .params = std::move(params),
                       .defaultStep = step,
                       .defaultIntegrator = Integrator::RK4,
                       .start = start,
                       .citation = kSprott1994,
                       .equations = std::move(equations)});
}

std::vector<AttractorInfo> makeCatalogue() {
  std::vector<AttractorInfo> c;
  // --- the seed's six: equations and (where the seed gave working ones) defaults as it had them.
  c.push_back(flow<Lorenz>({
      .id = "lorenz",
      .name = "Lorenz",
      .params = {param("a", 28.0, 1.0, 40.0), param("b", 46.92, 1.0, 80.0), param("c", 4.0, 0.5, 10.0)},
      .defaultStep = 0.01,
      .defaultIntegrator = Integrator::Euler,
      .start = {0.1, 0.1, 0.1},
      .citation = std::string("E. N. Lorenz, \"Deterministic nonperiodic flow\", J. Atmos. Sci. 20, 130 (1963); ") +
                  kSeed + " parameters",
      .equations = "x' = a(y - x); y' = b x - y - x z; z' = x y - c z",
      .alternatives =
          {{"classic", {10.0, 28.0, 8.0 / 3.0}, {1.0, 1.0, 1.0}, "Lorenz 1963: sigma 10, rho 28, beta 8/3"}},
  }));
  c.push_back(flow<Lorenz84>({
      .id = "lorenz84",
      .name = "Lorenz-84",
      .params = {{"a", 1.111, 0.5, 2.0}, {"b", 1.479, 0.5, 3.0}, {"f", 4.494, 1.0, 10.0}, {"g", 0.44, 0.0, 2.0}},
      .defaultStep = 0.135,
      .defaultIntegrator = Integrator::Euler,
      .start = {0.1, 0.1, 0.1},
      .citation = "E. N. Lorenz, \"Irregularity: a fundamental property of the atmosphere\", Tellus A 36 (1984)",
      .equations = "x' = -a x - y^2 - z^2 + a f; y' = -y + x y - b x z + g; z' = -z + b x y + x z",
  }));
  c.push_back(map<Pickover>({
      .id = "pickover",
      .name = "Pickover",
      .params = {param("a", -0.759494, -3.0, 3.0), param("b", 2.449367, -3.0, 3.0), param("c", 1.253165, -3.0, 3.0),
                 param("d", 1.5, -3.0, 3.0)},
      .start = {0.1, 0.1, 0.1},
      .citation = std::string("C. A. Pickover, \"Computers, Pattern, Chaos and Beauty\", St. Martin's Press (1990); ") +
                  kSeed + " parameters",
      .equations = "x' = sin(a y) - z cos(b x); y' = z sin(c x) - cos(d y); z' = sin(x)",
      .note = "weakly chaotic with the seed's defaults: largest exponent ~0.0095 per iteration (converged over 2e6 "
              "iterations)",
  }));
  c.push_back(map<PolynomialA>({
      .id = "polynomial_a",
      .name = "Polynomial A",
      .params = polynomialParams({1.586, 1.124, 0.281}, 0.5),
      .start = {-1.07, 1.01, -0.45},
      .citation = kSeed,
      .equations = "x' = p0 + y - z y; y' = p1 + z - x z; z' = p2 + x - y x",
      .note = "small basin: from (0.1, 0.1, 0.1) the orbit escapes; the start lies inside the basin",
  }));
  c.push_back(map<PolynomialB>({
      .id = "polynomial_b",
      .name = "Polynomial B",
      .params = polynomialParams({-0.1971, 0.4488, 0.4742, 0.3640, 0.0672, 0.3634}, 0.5),
      .start = {0.1, 0.1, 0.1},
      .citation = std::string(kSeed) + " (equations); defaults found by voxflame's chaos search",
      .equations = "x' = p0 + y - z (p1 + y); y' = p2 + z - x (p3 + z); z' = p4 + x - y (p5 + x)",
      .note = "the seed's defaults (-0.237, 0.453, 0.486, 0.616, 0.141, 0.483) escape to infinity; they are kept "
              "as the alternative 'seed'",
      .alternatives = {{"seed",
                        {-0.237, 0.453, 0.486, 0.616, 0.141, 0.483},
                        {0.1, 0.1, 0.1},
                        "the seed's set: every orbit escapes"}},
  }));
  c.push_back(map<PolynomialC>({
      .id = "polynomial_c",
      .name = "Polynomial C",
      .params = polynomialParams({0.9063, -0.3920, -0.3218, 0.1938, 0.8230, -0.7934, 1.0074, -0.2363, -0.0137, -0.4703,
                                  0.0344, 0.4084, 0.8729, -0.3048, -0.2293, -0.5225, 0.7094, 0.5239},
                                 0.5),
      .start = {-0.06, 0.43, 0.43},
      .citation = std::string(kSeed) + " (equations); defaults found by voxflame's chaos search",
      .equations = "x' = p0 + x (p1 + p2 x + p3 y) + y (p4 + p5 y); y' = p6 + y (p7 + p8 y + p9 z) + z (p10 + p11 z); "
                   "z' = p12 + z (p13 + p14 z + p15 x) + x (p16 + p17 x)",
  }));

  // --- well-known flows, integrated with RK4 --------------------------------------------------------
  const auto rk4Flow = [](AttractorInfo info) {
    info.defaultIntegrator = Integrator::RK4;
    return info;
  };
  c.push_back(flow<Rossler>(rk4Flow({
      .id = "rossler",
      .name = "Rössler",
      .params = {param("a", 0.2), param("b", 0.2), param("c", 5.7, 2.0, 12.0)},
      .defaultStep = 0.05,
      .start = {1.0, 1.0, 0.0},
      .citation = "O. E. Rössler, \"An equation for continuous chaos\", Phys. Lett. A 57, 397 (1976)",
      .equations = "x' = -y - z; y' = x + a y; z' = b + z (x - c)",
  })));
  c.push_back(flow<Aizawa>(rk4Flow({
      .id = "aizawa",
      .name = "Aizawa",
      .params = {param("a", 0.95), param("b", 0.7), param("c", 0.6), param("d", 3.5), param("e", 0.25),
                 param("f", 0.1)},
      .defaultStep = 0.01,
      .start = {0.1, 0.0, 0.0},
      .citation = "W. F. Langford, \"Numerical studies of torus bifurcations\" (1984); parameters after Y. Aizawa",
      .equations = "x' = (z - b) x - d y; y' = d x + (z - b) y; z' = c + a z - z^3/3 - (x^2 + y^2)(1 + e z) + f z x^3",
  })));
  c.push_back(flow<Thomas>(rk4Flow({
      .id = "thomas",
      .name = "Thomas (cyclically symmetric)",
      .params = {param("b", 0.18, 0.05, 0.33)},
      .defaultStep = 0.05,
      .start = {0.1, 0.0, 0.0},
      .citation =
          "R. Thomas, \"Deterministic chaos seen in terms of feedback circuits\", Int. J. Bif. Chaos 9, 1889 (1999)",
      .equations = "x' = sin y - b x; y' = sin z - b y; z' = sin x - b z",
      .note = "b = 0.208186, Thomas's value at the onset of chaos, is nearly periodic (largest exponent ~0.005); "
              "the default 0.18 is clearly chaotic",
      .alternatives = {{"onset", {0.208186}, {0.1, 0.0, 0.0}, "Thomas 1999: b = 0.208186, at the edge of chaos"}},
  })));
  c.push_back(flow<Halvorsen>(rk4Flow({
      .id = "halvorsen",
      .name = "Halvorsen",
      .params = {param("a", 1.4, 1.0, 2.0)},
      .defaultStep = 0.01,
      .start = {1.0, 0.0, 0.0},
      .citation = "J. C. Sprott, \"Elegant Chaos\", World Scientific (2010), after A. Halvorsen",
      .equations = "x' = -a x - 4 y - 4 z - y^2 (and cyclically)",
  })));
  c.push_back(flow<Chen>(rk4Flow({
      .id = "chen",
      .name = "Chen",
      .params = {param("a", 35.0), param("b", 3.0), param("c", 28.0)},
      .defaultStep = 0.002,
      .start = {-10.0, 0.0, 37.0},
      .citation = "G. Chen, T. Ueta, \"Yet another chaotic attractor\", Int. J. Bif. Chaos 9, 1465 (1999)",
      .equations = "x' = a (y - x); y' = (c - a) x - x z + c y; z' = x y - b z",
  })));
  c.push_back(flow<LuChen>(rk4Flow({
      .id = "lu_chen",
      .name = "Lü–Chen",
      .params = {param("a", 36.0), param("b", 3.0), param("c", 20.0)},
      .defaultStep = 0.005,
      .start = {1.0, 1.0, 1.0},
      .citation = "J. Lü, G. Chen, \"A new chaotic attractor coined\", Int. J. Bif. Chaos 12, 659 (2002)",
      .equations = "x' = a (y - x); y' = -x z + c y; z' = x y - b z",
  })));
  c.push_back(flow<Dadras>(rk4Flow({
      .id = "dadras",
      .name = "Dadras",
      .params = {param("a", 3.0), param("b", 2.7), param("c", 1.7), param("d", 2.0), param("e", 9.0)},
      .defaultStep = 0.01,
      .start = {1.0, 1.0, 0.0},
      .citation =
          "S. Dadras, H. R. Momeni, \"A novel three-dimensional autonomous chaotic system generating two, three "
          "and four-scroll attractors\", Phys. Lett. A 373, 3637 (2009)",
      .equations = "x' = y - a x + b y z; y' = c y - x z + z; z' = d x y - e z",
  })));
  c.push_back(flow<RabinovichFabrikant>(rk4Flow({
      .id = "rabinovich_fabrikant",
      .name = "Rabinovich–Fabrikant",
      .params = {param("alpha", 1.1, 0.05, 1.5), param("gamma", 0.87, 0.01, 1.2)},
      .defaultStep = 0.01,
      .start = {-1.0, 0.0, 0.5},
      .citation = "M. I. Rabinovich, A. L. Fabrikant, Sov. Phys. JETP 50, 311 (1979); parameters after Danca & Chen, "
                  "Int. J. Bif. Chaos 14, 3409 (2004)",
      .equations = "x' = y (z - 1 + x^2) + gamma x; y' = x (3 z + 1 - x^2) + gamma y; z' = -2 z (alpha + x y)",
  })));
  c.push_back(flow<Chua>(rk4Flow({
      .id = "chua",
      .name = "Chua's circuit (double scroll)",
      .params = {param("alpha", 15.6), param("beta", 28.0), param("m0", -1.143, -2.0, 0.0),
                 param("m1", -0.714, -2.0, 0.0)},
      .defaultStep = 0.01,
      .start = {0.7, 0.0, 0.0},
      .citation =
          "T. Matsumoto, L. O. Chua, M. Komuro, \"The double scroll\", IEEE Trans. Circuits Syst. 32, 797 (1985)",
      .equations = "x' = alpha (y - x - f(x)); y' = x - y + z; z' = -beta y; f(x) = m1 x + (m0 - m1)(|x + 1| - |x - "
                   "1|)/2",
  })));
  c.push_back(flow<NoseHoover>(rk4Flow({
      .id = "nose_hoover",
      .name = "Nosé–Hoover (Sprott A)",
      .params = {param("a", 1.0, 0.1, 3.0)},
      .defaultStep = 0.02,
      .start = {0.0, 5.0, 0.0},
      .citation = "W. G. Hoover, \"Canonical dynamics: equilibrium phase-space distributions\", Phys. Rev. A 31, 1695 "
                  "(1985); Sprott case A",
      .equations = "x' = y; y' = -x + y z; z' = a - y^2",
      .note = "conservative: the exponents sum to zero and the chaotic sea coexists with tori",
  })));
  c.push_back(flow<Arneodo>(rk4Flow({
      .id = "arneodo",
      .name = "Arneodo",
      .params = {param("a", -5.5), param("b", 3.5), param("c", -1.0)},
      .defaultStep = 0.01,
      .start = {0.1, 0.0, 0.0},
      .citation = "A. Arneodo, P. Coullet, C. Tresser, \"Possible new strange attractors with spiral structure\", "
                  "Commun. Math. Phys. 79, 573 (1981)",
      .equations = "x' = y; y' = z; z' = -a x - b y - z + c x^3",
  })));
  c.push_back(flow<BurkeShaw>(rk4Flow({
      .id = "burke_shaw",
      .name = "Burke–Shaw",
      .params = {param("s", 10.0), param("v", 4.272)},
      .defaultStep = 0.005,
      .start = {0.6, 0.0, 0.0},
      .citation = "R. Shaw, \"Strange attractors, chaotic behavior, and information flow\", Z. Naturforsch. 36a, 80 "
                  "(1981)",
      .equations = "x' = -s (x + y); y' = -y - s x z; z' = s x y + v",
  })));
  c.push_back(flow<DequanLi>(rk4Flow({
      .id = "dequan_li",
      .name = "Dequan Li (three-scroll)",
      .params = {param("a", 40.0), param("c", 1.833), param("d", 0.16), param("e", 0.65), param("k", 55.0),
                 param("f", 20.0)},
      .defaultStep = 0.001,
      .start = {0.349, 0.0, -0.16},
      .citation = "D. Li, \"A three-scroll chaotic attractor\", Phys. Lett. A 372, 387 (2008)",
      .equations = "x' = a (y - x) + d x z; y' = k x + f y - x z; z' = c z + x y - e x^2",
  })));
  c.push_back(flow<FourWing>(rk4Flow({
      .id = "four_wing",
      .name = "Four-wing",
      .params = {param("a", 0.2), param("b", 0.01), param("c", -0.4)},
      .defaultStep = 0.05,
      .start = {1.3, -0.18, 0.01},
      .citation = "G. Qi, G. Chen, et al., \"A four-wing chaotic attractor generated from a new 3-D quadratic "
                  "autonomous system\", Chaos Solitons Fractals 38, 705 (2008) (form as in Chaoscope)",
      .equations = "x' = a x + y z; y' = b x + c y - x z; z' = -z - x y",
  })));
  c.push_back(flow<GenesioTesi>(rk4Flow({
      .id = "genesio_tesi",
      .name = "Genesio–Tesi",
      .params = {param("a", 0.44), param("b", 1.1), param("c", 1.0)},
      .defaultStep = 0.02,
      .start = {0.1, 0.1, 0.1},
      .citation = "R. Genesio, A. Tesi, \"Harmonic balance methods for the analysis of chaotic dynamics in nonlinear "
                  "systems\", Automatica 28, 531 (1992)",
      .equations = "x' = y; y' = z; z' = -c x - b y - a z + x^2",
  })));
  c.push_back(flow<Lorenz84>(rk4Flow({
      .id = "hadley",
      .name = "Hadley circulation",
      .params = {param("a", 0.25), param("b", 4.0), param("f", 8.0), param("g", 1.0)},
      .defaultStep = 0.01,
      .start = {0.1, 0.0, 0.0},
      .citation = "E. N. Lorenz, Tellus A 36 (1984), with Lorenz's standard parameters a = 1/4, b = 4, F = 8, G = 1",
      .equations = "x' = -a x - y^2 - z^2 + a f; y' = -y + x y - b x z + g; z' = -z + b x y + x z",
  })));
  c.push_back(flow<NewtonLeipnik>(rk4Flow({
      .id = "newton_leipnik",
      .name = "Newton–Leipnik",
      .params = {param("a", 0.4), param("b", 0.175)},
      .defaultStep = 0.01,
      .start = {0.349, 0.0, -0.16},
      .citation = "R. B. Leipnik, T. A. Newton, \"Double strange attractors in rigid body motion with linear feedback "
                  "control\", Phys. Lett. A 86, 63 (1981)",
      .equations = "x' = -a x + y + 10 y z; y' = -x - 0.4 y + 5 x z; z' = b z - 5 x y",
  })));
  c.push_back(flow<Rucklidge>(rk4Flow({
      .id = "rucklidge",
      .name = "Rucklidge",
      .params = {param("kappa", 2.0), param("lambda", 6.7)},
      .defaultStep = 0.02,
      .start = {1.0, 0.0, 4.5},
      .citation = "A. M. Rucklidge, \"Chaos in models of double convection\", J. Fluid Mech. 237, 209 (1992)",
      .equations = "x' = -kappa x + lambda y - y z; y' = x; z' = -z + y^2",
  })));
  c.push_back(flow<ShimizuMorioka>(rk4Flow({
      .id = "shimizu_morioka",
      .name = "Shimizu–Morioka",
      .params = {param("a", 0.75), param("b", 0.45)},
      .defaultStep = 0.02,
      .start = {0.1, 0.0, 0.0},
      .citation = "T. Shimizu, N. Morioka, \"On the bifurcation of a symmetric limit cycle to an asymmetric one in a "
                  "simple model\", Phys. Lett. A 76, 201 (1980)",
      .equations = "x' = y; y' = x - a y - x z; z' = -b z + x^2",
  })));
  c.push_back(flow<Sakarya>(rk4Flow({
      .id = "sakarya",
      .name = "Sakarya",
      .params = {param("a", 0.4), param("b", 0.3)},
      .defaultStep = 0.01,
      .start = {1.0, -1.0, 1.0},
      .citation = "after the Sakarya attractor of Chaoscope (Li-Ou / Pehlivan-Uyaroğlu family)",
      .equations = "x' = -x + y + y z; y' = -x - y + a x z; z' = z - b x y",
  })));
  c.push_back(flow<YuWang>(rk4Flow({
      .id = "yu_wang",
      .name = "Yu–Wang",
      .params = {param("a", 10.0), param("b", 40.0), param("c", 2.0), param("d", 2.5)},
      .defaultStep = 0.002,
      .start = {0.1, 0.1, 0.1},
      .citation = "F. Yu, C. Wang, \"A novel three dimension autonomous chaotic system with a quadratic exponential "
                  "nonlinear term\", Eng. Technol. Appl. Sci. Res. 2, 209 (2012)",
      .equations = "x' = a (y - x); y' = b x - c x z; z' = exp(x y) - d z",
  })));
  c.push_back(flow<SprottJerk>(rk4Flow({
      .id = "sprott_jerk",
      .name = "Sprott's simplest jerk",
      .params = {param("a", 2.017, 1.8, 2.2)},
      .defaultStep = 0.02,
      .start = {-1.0, 0.0, 0.0},
      .citation = "J. C. Sprott, \"Simplest dissipative chaotic flow\", Phys. Lett. A 228, 271 (1997)",
      .equations = "x' = y; y' = z; z' = -a z + y^2 - x",
  })));
  c.push_back(
      sprottCase<SprottB>('B', {param("a", 1.0)}, {0.1, 0.1, 0.1}, 0.05, "x' = a y z; y' = x - y; z' = 1 - x y"));
  c.push_back(
      sprottCase<SprottC>('C', {param("a", 1.0)}, {0.1, 0.1, 0.1}, 0.05, "x' = a y z; y' = x - y; z' = 1 - x^2"));
  c.push_back(
      sprottCase<SprottD>('D', {param("a", 3.0)}, {0.1, 0.1, 0.1}, 0.05, "x' = -y; y' = x + z; z' = x z + a y^2"));
  c.push_back(
      sprottCase<SprottE>('E', {param("a", 4.0)}, {0.1, 0.1, 0.1}, 0.05, "x' = y z; y' = x^2 - y; z' = 1 - a x"));
  c.push_back(
      sprottCase<SprottF>('F', {param("a", 0.5)}, {0.1, 0.1, 0.1}, 0.05, "x' = y + z; y' = -x + a y; z' = x^2 - z"));
  c.push_back(
      sprottCase<SprottG>('G', {param("a", 0.4)}, {0.1, 0.1, 0.1}, 0.05, "x' = a x + z; y' = x z - y; z' = -x + y"));
  c.push_back(
      sprottCase<SprottH>('H', {param("a", 0.5)}, {0.1, 0.1, 0.1}, 0.05, "x' = -y + z^2; y' = x + a y; z' = x - z"));
  c.push_back(sprottCase<SprottL>('L', {param("a", 3.9), param("b", 0.9)}, {0.1, 0.1, 0.1}, 0.05,
                                  "x' = y + a z; y' = b x^2 - y; z' = 1 - x"));
  c.push_back(
      sprottCase<SprottM>('M', {param("a", 1.7)}, {0.1, 0.1, 0.1}, 0.05, "x' = -z; y' = -x^2 - y; z' = a + a x + y"));
  c.push_back(
      sprottCase<SprottN>('N', {param("a", 2.0)}, {0.1, 0.1, 0.1}, 0.05, "x' = -a y; y' = x + z^2; z' = 1 + y - 2 z"));
  c.push_back(
      sprottCase<SprottO>('O', {param("a", 2.7)}, {0.1, 0.1, 0.1}, 0.05, "x' = y; y' = x - z; z' = x + x z + a y"));
  c.push_back(
      sprottCase<SprottP>('P', {param("a", 2.7)}, {0.1, 0.1, 0.1}, 0.05, "x' = a y + z; y' = -x + y^2; z' = x + y"));
  c.push_back(sprottCase<SprottQ>('Q', {param("a", 3.1), param("b", 0.5)}, {0.1, 0.1, 0.1}, 0.05,
                                  "x' = -z; y' = x - y; z' = a x + y^2 + b z"));
  c.push_back(sprottCase<SprottR>('R', {param("a", 0.9), param("b", 0.4)}, {0.1, 0.1, 0.1}, 0.05,
                                  "x' = a - y; y' = b + z; z' = x y - z"));
  c.push_back(
      sprottCase<SprottS>('S', {param("a", 4.0)}, {0.1, 0.1, 0.1}, 0.05, "x' = -x - a y; y' = x + z^2; z' = 1 + x"));

  // --- maps -----------------------------------------------------------------------------------------
  c.push_back(map<Henon3d>({
      .id = "henon_3d",
      .name = "Hénon with a z memory",
      .params = {param("a", 1.4, 1.0, 1.45), param("b", 0.3, 0.0, 0.4), param("c", 0.5, -0.9, 0.9)},
      .start = {0.1, 0.1, 0.0},
      .citation =
          "M. Hénon, \"A two-dimensional mapping with a strange attractor\", Commun. Math. Phys. 50, 69 (1976); "
          "z' = c z + x added by voxflame",
      .equations = "x' = 1 - a x^2 + y; y' = b x; z' = c z + x",
  }));
  c.push_back(map<SprottQuadratic>({
      .id = "sprott_quadratic",
      .name = "Sprott's 3D quadratic map",
      .params = sprottQuadraticParams(sprottCodeToParams(kSprottDefaultCode)),
      .start = {0.1, 0.1, 0.1},
      .citation = kSprottBook,
      .equations = "x' = a1 + a2 x + a3 x^2 + a4 x y + a5 x z + a6 y + a7 y^2 + a8 y z + a9 z + a10 z^2; y' and z' "
                   "likewise with a11..a20 and a21..a30",
      .note = std::string("letter code ") + kSprottDefaultCode + " (A = -1.2 ... M = 0 ... Y = 1.2)",
  }));
  return c;
}

}  // namespace

const std::vector<AttractorInfo>& attractorCatalogue() {
  static const std::vector<AttractorInfo> catalogue = makeCatalogue();
  return catalogue;
}

const AttractorInfo* findAttractor(std::string_view id) {
  for (const auto& info : attractorCatalogue())
    if (info.id == id) return &info;
  return nullptr;
}

const AttractorInfo& attractorOrThrow(std::string_view id) {
  if (const AttractorInfo* info = findAttractor(id)) return *info;
  std::string known;
  for (const auto& info : attractorCatalogue()) known += (known.empty() ? "" : ", ") + info.id;
  throw Error("unknown attractor '" + std::string(id) + "' (known: " + known + ")");
}

std::vector<double> sprottCodeToParams(std::string_view code) {
  if (code.size() == 31 && (code[0] == 'I' || code[0] == 'i')) code.remove_prefix(1);
  if (code.size() != 30)
    throw Error("a 3D quadratic map code has 30 letters A..Y (optionally after the type letter I), not '" +
                std::string(code) + "'");
  std::vector<double> params;
  for (char letter : code) {
    const char upper = (letter >= 'a' && letter <= 'z') ? static_cast<char>(letter - 'a' + 'A') : letter;
    if (upper < 'A' || upper > 'Y')
      throw Error("letter '" + std::string(1, letter) + "' in the code '" + std::string(code) + "' is not in A..Y");
    params.push_back(static_cast<double>(upper - 'M') / 10.0);  // exact at the ends: -12 / 10 == -1.2
  }
  return params;
}

std::string paramsToSprottCode(const std::vector<double>& params) {
  std::string code;
  for (double value : params) {
    const long step = std::clamp(std::lround(value * 10.0), -12L, 12L);
    code.push_back(static_cast<char>('M' + step));
  }
  return code;
}

}  // namespace voxflame::core
