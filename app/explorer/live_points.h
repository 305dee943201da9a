// The points method in the live view: once the camera and the pattern are still, the scene's
// points are projected into a screen histogram of the view's camera at the view's full size,
// exactly as `voxflame render --method points` projects them (core::projectScenePoints: the same
// projection, transmittance through the grid, light and lens), on a thread of its own. The points
// come in chunks; after each, the picture so far is published, scaled to the whole count so its
// brightness never changes as it fills in, and with the density estimation's hit counts of the
// points it holds, so it is the export of that many points. No GL: the live view uploads what it
// takes (gl::FrameTarget::setSums) and finishes it on the GPU like a marched picture.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "core/camera.h"
#include "core/flame/image.h"
#include "core/inside_mask.h"
#include "core/packed_volume.h"
#include "core/refinement/refinement_backend.h"
#include "core/scene.h"

namespace voxflame::app {

struct LivePointsRequest {
  core::Scene scene;  // its points and seed, layers, render and tone settings
  std::shared_ptr<const core::InsideMask> mask;
  std::shared_ptr<const core::PackedVolume> volume;  // the grid the points are dimmed by
  core::CameraFrame camera;
  int width = 0, height = 0;  // supersampled pixels: the view's size times the oversample
  int threads = 0;            // 0: one per hardware thread
  // The GPU projects the points on the device (gl::makeGpuProjectingBackend) where the session
  // refines on it; else the CPU's accumulation workers do.
  core::BackendKind backend = core::BackendKind::Cpu;
};

struct LivePointsProgress {
  std::uint64_t points = 0;  // projected into the newest picture
  std::uint64_t target = 0;  // the scene's count
  bool finished = false;     // every chunk is in: the picture is the export's
  std::string error;         // why it stopped early (the pattern escaped ...), else empty
};

class LivePoints {
 public:
  // Chunks of the points (core::PointsPassOptions::chunks): a picture is published after each.
  // Enough that the first comes within a fraction of a second, few enough that holding the
  // workers between chunks costs little. Each chunk starts its orbits afresh, which a flow's
  // picture shows (its export, in one chunk, draws fewer, longer orbits).
  static constexpr int kChunks = 32;

  LivePoints() = default;
  ~LivePoints();  // stops and joins every run
  LivePoints(const LivePoints&) = delete;
  LivePoints& operator=(const LivePoints&) = delete;

  // Starts projecting `request`'s points, stopping any run under way. Never waits for it.
  void start(LivePointsRequest request);
  // Stops the run under way without waiting for it: its thread is joined once it has noticed
  // (within progressInterval), by a later call or the destructor. A frame never blocks on it.
  void stop();
  // A run is under way and has not finished, or a stopped one has not yet noticed: a thread of
  // ours may be using the cores.
  bool working() const;
  // Swaps the newest picture into `out` when one newer than the last taken is ready.
  bool takeIfNewer(core::DensityImage& out);
  LivePointsProgress progress() const;

 private:
  struct Run;
  void joinFinished();
  std::shared_ptr<Run> run_;
  std::jthread thread_;
  std::vector<std::pair<std::shared_ptr<Run>, std::jthread>> stopping_;
};

}  // namespace voxflame::app
