#include "attractor.h"

#include "error.h"

namespace voxflame::core {

std::string_view toString(AttractorKind kind) {
  return kind == AttractorKind::Map ? "map" : "flow";
}
std::string_view toString(Integrator integrator) {
  return integrator == Integrator::RK4 ? "rk4" : "euler";
}

Integrator integratorFromString(std::string_view name) {
  if (name == "euler") return Integrator::Euler;
  if (name == "rk4") return Integrator::RK4;
  throw Error("unknown integrator '" + std::string(name) + "' (expected 'euler' or 'rk4')");
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

namespace {

// A flow is given by its vector field; Euler and RK4 steppers are generated from it so each
// system is written once. `System::field` must be a pure function of its inputs.
template <class System>
void eulerStep(const double* params, double h, double* x, double* y, double* z, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    double dx, dy, dz;
    System::field(params, x[i], y[i], z[i], dx, dy, dz);
    x[i] += h * dx;
    y[i] += h * dy;
    z[i] += h * dz;
  }
}

template <class System>
void rk4Step(const double* params, double h, double* x, double* y, double* z, std::size_t count) {
  for (std::size_t i = 0; i < count; ++i) {
    double k1x, k1y, k1z, k2x, k2y, k2z, k3x, k3y, k3z, k4x, k4y, k4z;
    System::field(params, x[i], y[i], z[i], k1x, k1y, k1z);
    System::field(params, x[i] + 0.5 * h * k1x, y[i] + 0.5 * h * k1y, z[i] + 0.5 * h * k1z, k2x, k2y, k2z);
    System::field(params, x[i] + 0.5 * h * k2x, y[i] + 0.5 * h * k2y, z[i] + 0.5 * h * k2z, k3x, k3y, k3z);
    System::field(params, x[i] + h * k3x, y[i] + h * k3y, z[i] + h * k3z, k4x, k4y, k4z);
    x[i] += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    y[i] += h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
    z[i] += h / 6.0 * (k1z + 2.0 * k2z + 2.0 * k3z + k4z);
  }
}

template <class System>
AttractorInfo flow(AttractorInfo info) {
  info.kind = AttractorKind::Flow;
  info.advanceEuler = &eulerStep<System>;
  info.advanceRk4 = &rk4Step<System>;
  return info;
}

// Lorenz-84: Lorenz's low-order model of the general atmospheric circulation.
struct Lorenz84 {
  static void field(const double* p, double x, double y, double z, double& dx, double& dy, double& dz) {
    const double a = p[0], b = p[1], f = p[2], g = p[3];
    dx = -a * x - y * y - z * z + a * f;
    dy = -y + x * y - b * x * z + g;
    dz = -z + b * x * y + x * z;
  }
};

std::vector<AttractorInfo> makeCatalogue() {
  std::vector<AttractorInfo> catalogue;
  catalogue.push_back(flow<Lorenz84>({
      .id = "lorenz84",
      .name = "Lorenz-84",
      .params = {{"a", 1.111, 0.5, 2.0}, {"b", 1.479, 0.5, 3.0}, {"f", 4.494, 1.0, 10.0}, {"g", 0.44, 0.0, 2.0}},
      .defaultStep = 0.135,
      .defaultIntegrator = Integrator::Euler,
      .start = {0.1, 0.1, 0.1},
      .citation = "E. N. Lorenz, \"Irregularity: a fundamental property of the atmosphere\", Tellus A 36 (1984)",
  }));
  return catalogue;
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

}  // namespace voxflame::core
