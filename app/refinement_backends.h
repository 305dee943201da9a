// Which refinement backend (core/refinement/refinement_backend.h) refines a pattern: the user's
// choice (`--backend cpu|gpu|auto`, the explorer's setting) resolved against the pattern and the
// machine, and the backend made for it. Here, above core and gl, because choosing needs both.
#pragma once

#include <memory>
#include <string_view>
#include <vector>

#include "core/core_budget.h"
#include "core/inside_mask.h"
#include "core/refinement/refinement_backend.h"
#include "core/scene.h"
#include "gl/headless_context.h"

namespace voxflame::app {

enum class BackendChoice { Cpu, Gpu, Auto };
inline constexpr std::string_view kBackendChoiceNames[] = {"cpu", "gpu", "auto"};
std::string_view toString(BackendChoice choice);
BackendChoice backendChoiceFromString(std::string_view name);  // throws core::Error listing the choices

// The backend `choice` gives these layers. Cpu is the CPU. Gpu is the GPU, or a core::Error saying
// why it cannot be (a layer it does not run, no OpenGL 4.3). Under the points method it also
// projects the points (core::PointsPassOptions::projectingBackend).
// Auto takes the GPU when the machine's GL renderer is a hardware one and the GPU runs the pattern,
// else the CPU. Asking about the hardware makes a GL context once per process.
core::BackendKind resolveBackend(BackendChoice choice, const std::vector<core::PatternLayer>& layers);

// A backend of `kind` on `mask`. threads and cores are the CPU's (0: every hardware thread).
// `renderer`: the context of the renderer that will draw the grid (gl::currentShareGroup() on its
// thread; empty: none, or another process's). A GPU backend sharing it hands its grid to the
// renderer on the GPU (RefinementBackend::packOnDevice).
std::unique_ptr<core::RefinementBackend> makeBackend(core::BackendKind kind,
                                                     std::shared_ptr<const core::InsideMask> mask, int threads = 0,
                                                     std::shared_ptr<core::CoreBudget> cores = nullptr,
                                                     gl::ShareGroup renderer = {});

}  // namespace voxflame::app
