// The attractor catalogue: every strange attractor voxflame knows, as data (id, name, kind,
// parameters with defaults and slider ranges, step, citation) plus the code that advances a
// batch of orbits. The accumulator calls advance once per step for a whole batch, so the
// per-point loop inside is plain arithmetic over arrays that the compiler vectorises, with no
// indirect call or branch per point.
//
// Each system is written once, as a function template over its number type: instantiated with
// double it advances orbits; instantiated with a forward-mode dual number it yields the exact
// Jacobian of one integrator step, which the Lyapunov spectrum and the chaos search need.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace voxflame::core {

enum class AttractorKind { Map, Flow };
enum class Integrator { Euler, RK4 };
inline constexpr std::string_view kIntegratorNames[] = {"euler", "rk4"};

std::string_view toString(AttractorKind kind);
std::string_view toString(Integrator integrator);
Integrator integratorFromString(std::string_view name);  // throws core::Error on unknown names

// The largest magnitude a preset may give an attractor's parameter, far beyond any slider: the
// preset reader and the keyframe addressing both refuse beyond it.
inline constexpr double kAttractorParameterLimit = 1e6;

struct ParamInfo {
  std::string name;
  double defaultValue = 0.0;
  double sliderMin = 0.0;
  double sliderMax = 1.0;
};

// A named parameter set besides the defaults (the classic Lorenz values, the seed's escaping
// polynomial_b set, ...), with a start point in its basin.
struct NamedParams {
  std::string name;
  std::vector<double> values;
  glm::dvec3 start{0.1, 0.1, 0.1};
  std::string note;
};

// Advances `count` orbits (structure of arrays) by one map iteration or one integrator step.
using AdvanceFn = void (*)(const double* params, double step, double* x, double* y, double* z, std::size_t count);
// Advances one orbit in place (state[3]) and writes the Jacobian of that step, row-major
// jacobian[3 * row + column] = d next[row] / d state[column].
using StepJacobianFn = void (*)(const double* params, double step, double* state, double* jacobian);

struct AttractorInfo {
  std::string id{};
  std::string name{};
  AttractorKind kind = AttractorKind::Flow;
  std::vector<ParamInfo> params{};
  double defaultStep = 0.01;  // flows only; maps ignore the step
  Integrator defaultIntegrator = Integrator::Euler;
  glm::dvec3 start{0.1, 0.1, 0.1};  // a point in the basin of attraction for the defaults
  std::string citation{};
  std::string equations{};  // human-readable, for `voxflame list` and the UI
  std::string note{};       // honest remarks (e.g. a conservative system with a weak exponent)
  std::vector<NamedParams> alternatives{};
  AdvanceFn advanceEuler = nullptr;  // for maps: the map itself
  AdvanceFn advanceRk4 = nullptr;    // for maps: the map itself
  StepJacobianFn jacobianEuler = nullptr;
  StepJacobianFn jacobianRk4 = nullptr;

  AdvanceFn advance(Integrator integrator) const { return integrator == Integrator::RK4 ? advanceRk4 : advanceEuler; }
  StepJacobianFn stepJacobian(Integrator integrator) const {
    return integrator == Integrator::RK4 ? jacobianRk4 : jacobianEuler;
  }
  std::vector<double> defaultParams() const;
  int paramIndex(std::string_view paramName) const;                // -1 when absent
  const NamedParams* alternative(std::string_view setName) const;  // nullptr when absent
};

const std::vector<AttractorInfo>& attractorCatalogue();
const AttractorInfo* findAttractor(std::string_view id);     // nullptr when unknown
const AttractorInfo& attractorOrThrow(std::string_view id);  // core::Error listing known ids

// Sprott's letter code for the 30 coefficients of the general 3D quadratic map
// (`sprott_quadratic`): each letter A..Y stands for -1.2..+1.2 in steps of 0.1 (M is 0).
// A leading 'I' (Sprott's type letter for 3D quadratic maps) is accepted and ignored.
std::vector<double> sprottCodeToParams(std::string_view code);      // throws core::Error
std::string paramsToSprottCode(const std::vector<double>& params);  // nearest letters, no type letter

}  // namespace voxflame::core
