// The attractor catalogue: every strange attractor voxflame knows, as data (id, name, kind,
// parameters with defaults and slider ranges, step, citation) plus the code that advances a
// batch of orbits. The accumulator calls advance once per step for a whole batch, so the
// per-point loop inside is plain arithmetic over arrays that the compiler vectorises, with no
// indirect call or branch per point.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <glm/vec3.hpp>

namespace voxflame::core {

enum class AttractorKind { Map, Flow };
enum class Integrator { Euler, RK4 };

std::string_view toString(AttractorKind kind);
std::string_view toString(Integrator integrator);
Integrator integratorFromString(std::string_view name);  // throws core::Error on unknown names

struct ParamInfo {
  std::string name;
  double defaultValue = 0.0;
  double sliderMin = 0.0;
  double sliderMax = 1.0;
};

// Advances `count` orbits (structure of arrays) by one map iteration or one integrator step.
using AdvanceFn = void (*)(const double* params, double step, double* x, double* y, double* z, std::size_t count);

struct AttractorInfo {
  std::string id;
  std::string name;
  AttractorKind kind = AttractorKind::Flow;
  std::vector<ParamInfo> params;
  double defaultStep = 0.01;  // flows only; maps ignore the step
  Integrator defaultIntegrator = Integrator::Euler;
  glm::dvec3 start{0.1, 0.1, 0.1};  // a point in the basin of attraction for the defaults
  std::string citation;
  AdvanceFn advanceEuler = nullptr;  // for maps: the map itself
  AdvanceFn advanceRk4 = nullptr;    // for maps: the map itself

  AdvanceFn advance(Integrator integrator) const { return integrator == Integrator::RK4 ? advanceRk4 : advanceEuler; }
  std::vector<double> defaultParams() const;
  int paramIndex(std::string_view paramName) const;  // -1 when absent
};

const std::vector<AttractorInfo>& attractorCatalogue();
const AttractorInfo* findAttractor(std::string_view id);     // nullptr when unknown
const AttractorInfo& attractorOrThrow(std::string_view id);  // core::Error listing known ids

}  // namespace voxflame::core
