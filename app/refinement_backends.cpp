#include "refinement_backends.h"

#include <optional>
#include <string>
#include <utility>

#include "core/enum_names.h"
#include "core/error.h"
#include "core/refinement/accumulator.h"
#include "gl/gpu_accumulator.h"

namespace voxflame::app {

std::string_view toString(BackendChoice choice) {
  return core::enumName(kBackendChoiceNames, choice);
}

BackendChoice backendChoiceFromString(std::string_view name) {
  if (const std::optional<BackendChoice> choice = core::enumFromName<BackendChoice>(kBackendChoiceNames, name))
    return *choice;
  std::string message = "unknown refinement backend '";
  message.append(name).append("' (expected ").append(core::quotedChoices(kBackendChoiceNames)).append(")");
  throw core::Error(message);
}

core::BackendKind resolveBackend(BackendChoice choice, const std::vector<core::PatternLayer>& layers) {
  if (choice == BackendChoice::Cpu) return core::BackendKind::Cpu;
  const std::string unsupported = gl::gpuUnsupportedReason(layers);
  if (choice == BackendChoice::Gpu) {
    if (!unsupported.empty()) throw core::Error(unsupported + " (--backend cpu or auto)");
    return core::BackendKind::Gpu;
  }
  if (!unsupported.empty()) return core::BackendKind::Cpu;
  // The answer does not change while the process runs; a context costs tens of milliseconds.
  static const bool hardware = gl::hardwareGpuAvailable();
  return hardware ? core::BackendKind::Gpu : core::BackendKind::Cpu;
}

std::unique_ptr<core::RefinementBackend> makeBackend(core::BackendKind kind,
                                                     std::shared_ptr<const core::InsideMask> mask, int threads,
                                                     std::shared_ptr<core::CoreBudget> cores, gl::ShareGroup renderer) {
  if (kind == core::BackendKind::Gpu) return std::make_unique<gl::GpuAccumulator>(std::move(mask), renderer);
  return std::make_unique<core::Accumulator>(std::move(mask), threads, std::move(cores));
}

}  // namespace voxflame::app
