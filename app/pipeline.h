// The end-to-end path shared by the CLI and the explorer: Scene → mesh → inside mask →
// accumulation → snapshot → ray-marched image.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "core/accumulator.h"
#include "core/image_io.h"
#include "core/inside_mask.h"
#include "core/scene.h"

namespace voxflame::app {

// Builds the grid and inside mask for a scene's mesh (through the mask cache); refuses grids too
// large for this machine.
std::shared_ptr<const core::InsideMask> buildSceneMask(const core::Scene& scene);

// Refuses (core::Error saying how much it needs) a grid whose buffers would not fit in memory.
void checkGridFitsInMemory(const core::GridGeometry& grid);

struct StillOptions {
  int width = 1280;
  int height = 720;
  std::uint64_t points = 0;  // 0: the scene's own count
  int threads = 0;           // 0: all hardware threads
  double stepVoxels = 0.5;
  std::function<void(const core::AccumulatorStats&, std::uint64_t target)> progress;  // may be empty
};

struct StillResult {
  core::ImageRGBA image;
  core::AccumulatorStats stats;
  double accumulateSeconds = 0.0;
  double renderSeconds = 0.0;
  std::string renderer;  // GL_RENDERER
  std::string warning;   // e.g. fewer points landed inside the mesh than asked for
};

// Renders a still headless through EGL. Throws core::Error on anything the user can fix.
StillResult renderStill(const core::Scene& scene, const StillOptions& options);

// The PNG text chunks that make a render reproducible: the preset and render statistics.
core::TextChunks stillMetadata(const core::Scene& scene, const StillResult& result);

inline constexpr const char* kPresetChunkKey = "voxflame:preset";

}  // namespace voxflame::app
