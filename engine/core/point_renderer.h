// The points method: every point a pattern's chaos game accepts inside the mesh is projected
// through the camera into a supersampled screen histogram, as flam3 does in 2D, so filaments are
// pixel-fine at any image size and no voxel shows. The grid still gives depth: each point is
// dimmed by the camera's transmittance through the accumulated volume in front of it (a
// view-aligned transmittance volume, built once per image) and, with lighting, by the light's
// shadow volume. Optional depth of field (a thin lens) and depth fog. The histogram is a
// DensityImage in the same units as the volume method's, so flame/image.h finishes both alike.
// Memory grows with the image, not with the grid.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "chunk_sums.h"
#include "camera.h"
#include "core/flame/image.h"
#include "core/refinement/refinement_backend.h"
#include "inside_mask.h"
#include "packed_volume.h"
#include "shadow_volume.h"

namespace voxflame::core {

// Transmittance from the eye to any point of the view frustum that crosses the grid: cells across
// the image (u, v in [0, 1], top-left origin) and slices of view depth between nearDepth and farDepth.
struct ViewTransmittance {
  int width = 0, height = 0, depth = 0;
  double nearDepth = 0.0, farDepth = 1.0;  // view depth (distance along the camera's forward axis)
  // Per cell, depth + 1 values at the slice boundaries, depth fastest: a lookup reads one cache line.
  std::vector<float> values;

  // Linear along depth; across, the cell that contains (u, v) moved by (jitterU, jitterV) cells.
  // With jitters uniform in [-0.5, 0.5) the expected value is the bilinear interpolation between
  // cell centres at the cost of one lookup: a plain nearest cell would print the cells' edges
  // onto the image as a lattice wherever the transmittance changes fast. 1 in front of the grid,
  // the last slice behind it, 1 when empty.
  float at(float u, float v, float viewDepth, float jitterU = 0.0f, float jitterV = 0.0f) const {
    float fraction = 0.0f;
    const std::size_t index = lookup(u, v, viewDepth, jitterU, jitterV, fraction);
    return index == kNoLookup ? 1.0f : values[index] + fraction * (values[index + 1] - values[index]);
  }
  // at() in two halves, so a caller can prefetch values[index] before reading it: the slice
  // boundary below the depth and the fraction towards the next, or kNoLookup where it is 1.
  static constexpr std::size_t kNoLookup = ~std::size_t{0};
  std::size_t lookup(float u, float v, float viewDepth, float jitterU, float jitterV, float& fraction) const {
    if (values.empty() || viewDepth <= nearDepth) return kNoLookup;
    const int x = std::clamp(static_cast<int>(std::floor(u * static_cast<float>(width) + jitterU)), 0, width - 1);
    const int y = std::clamp(static_cast<int>(std::floor(v * static_cast<float>(height) + jitterV)), 0, height - 1);
    const float z = std::min((viewDepth - static_cast<float>(nearDepth)) * depthScale, static_cast<float>(depth));
    const int z0 = std::min(static_cast<int>(z), depth - 1);
    fraction = z - static_cast<float>(z0);
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
               static_cast<std::size_t>(depth + 1) +
           static_cast<std::size_t>(z0);
  }
  float depthScale = 1.0f;  // slices per unit of view depth
};

// `absorption` is the extinction per unit of column density (tone.opacity × kAbsorptionPerDensity).
ViewTransmittance buildViewTransmittance(const PackedVolume& volume, const CameraFrame& camera, double absorption,
                                         int width, int height, int depth);

struct PointProjection {
  GridGeometry grid;
  CameraFrame camera;
  int width = 0, height = 0;                         // supersampled image pixels
  double totalPoints = 1.0;                          // points the pass will project (sets each point's share of D)
  double insideVoxels = 1.0;                         // voxels inside the mesh
  const ViewTransmittance* transmittance = nullptr;  // null: nothing dims
  const ShadowVolume* shadow = nullptr;              // light transmittance, null: unlit
  int shadowDownsample = 1;
  double lightStrength = 0.8;
  double dofAperture = 0.0;    // lens radius, world units (0: pinhole)
  double dofFocusDepth = 1.0;  // view depth in focus, world units
  double fog = 0.0;            // extinction per grid side of depth behind fogStart
  double fogStart = 0.0;       // view depth where fog begins (the front of the grid)
  std::uint64_t seed = 1;      // for the lens samples
};

// What one point adds: its D in its pixel at unit view depth (over depth² in perspective), the D
// one count of the histogram stands for, and the fog's extinction per unit of view depth. The CPU's
// projector and the GPU's share it.
struct PointScale {
  double pointDensity = 1.0;
  double unit = 1.0;
  double fogPerDepth = 0.0;
};
PointScale pointScale(const PointProjection& projection);

// A PointSink that projects points into one histogram per worker thread. The histograms count in
// fixed-point units (unit(): up to a 1024th of what a point adds at the grid centre's depth), each point's share
// rounded up or down at random in proportion, so the rounding adds no bias. Integer sums are the
// same in any order, and every random number a point draws (lens, jitters, rounding) comes from its
// seed stream's own generator: the sums depend on the seed and the points alone, never on which
// thread projected what. That is what lets a still be split into chunks (chunk_sums.h).
class PointProjector : public PointSink {
 public:
  PointProjector(const PointProjection& projection, int threads);
  void consume(int thread, const AcceptedPoints& points) override;
  // Sums the threads' histograms into the image, giving up their memory as it goes. Call once,
  // when no more points arrive.
  DensityImage merge();
  // The sums so far, and the histograms start again from zero: a finished chunk's own sums. Call
  // when no points arrive.
  ImageSums takeSums();
  double unit() const { return scale_.unit; }
  std::uint64_t projected() const { return projected_.load(); }

 private:
  PointProjection p_;
  PointScale scale_;
  // Fixed-point counts (uint32 bit patterns in float storage, so merge turns them into the image's
  // floats in place: a 16K print has no room for a second full-size copy).
  std::vector<std::vector<float>> histograms_;
  // A generator per seed stream, in the slot of its stream number modulo the streams of a chunk
  // (a stream belongs to one thread at a time, and chunks run one after another).
  struct StreamRandom {
    std::uint64_t stream = ~std::uint64_t{0};
    std::uint64_t state = 0;
  };
  std::vector<StreamRandom> streamRandom_;
  // Per thread, the points of one consume call after projection, before they touch the large
  // histogram and transmittance: a second pass reads them with prefetches running ahead, so the
  // cache misses of many points overlap instead of following one another.
  struct Projected {
    std::uint32_t pixel;        // index into the histogram (in pixels)
    float weight;               // counts the point adds, before the camera's transmittance
    std::size_t transmittance;  // ViewTransmittance::lookup's index, kNoLookup for none
    float fraction;
    std::uint32_t rgb;
    float dither;  // in [0, 1): where the fixed-point rounding goes up
  };
  std::vector<std::vector<Projected>> scratch_;
  std::atomic<std::uint64_t> projected_{0};
};

// A refinement backend that projects its accepted points into a screen histogram of its own, in
// PointProjector's units and layout (pointScale), instead of handing them to a PointSink: the GPU's,
// whose points never leave the device.
class ProjectingBackend {
 public:
  virtual ~ProjectingBackend() = default;
  virtual RefinementBackend& backend() = 0;
  // The sums since the last call (ImageSums's points and iterations left 0), and the histogram
  // starts again from zero. Call while the backend is held.
  virtual ImageSums takeSums() = 0;
};

// The density the histogram's counts stand for, as merge and a chunked render's finish both make it.
inline float densityOfCount(std::uint32_t count, double unit) {
  return static_cast<float>(static_cast<double>(count) * unit);
}

// The whole points pass: the scene's layers iterated by an Accumulator over `mask` until
// `points` lie inside, each projected. `volume` (the grid of the same scene) gives the camera's
// transmittance and the light's shadow. `width` × `height` are supersampled pixels. `progress`
// gets the fraction done about four times a second and may throw to stop.
struct PointsPassOptions {
  std::uint64_t points = 0;  // 0: the scene's count
  int threads = 0;
  int transmittanceCells = 4;  // image pixels per transmittance cell along each axis
  std::function<void(double)> progress;
  double progressInterval = 0.25;         // seconds between progress calls (a live picture stops sooner with less)
  std::uint64_t* pointsInside = nullptr;  // when set, receives how many points landed inside the mesh
  std::uint64_t* iterations = nullptr;    // when set, receives the orbit steps taken
  // The points split into `chunks` chunks (chunkPoints), each iterating its own seed streams
  // (Accumulator::setChunk); the sums depend only on the scene, the size and `chunks`.
  int chunks = 1;
  std::optional<std::vector<int>> chunkList;  // the chunks to render, in this order (none: all)
  // When set, each chunk's own sums are handed here as it finishes (a checkpoint keeps them), and
  // the image is made from them plus earlierSums (chunks rendered before, in another run).
  std::function<void(int chunk, const ImageSums& sums)> chunkDone;
  const ImageSums* earlierSums = nullptr;
  bool makeImage = true;  // false: only render the chunks (a farm task); the result is empty
  std::function<void(int chunksDone)> chunkFinished;  // after each chunk (may be empty)
  // When set, makes the backend that iterates and projects the points itself (the GPU's:
  // gl/gpu_points.h); when empty, a CPU Accumulator feeds a PointProjector.
  std::function<std::unique_ptr<ProjectingBackend>(std::shared_ptr<const InsideMask> mask,
                                                   const PointProjection& projection, int threads)>
      projectingBackend;
};
// Chunk `chunk`'s share of `points` split into `chunks` (the first points % chunks get one more).
std::uint64_t chunkPoints(std::uint64_t points, int chunks, int chunk);
DensityImage projectScenePoints(const Scene& scene, std::shared_ptr<const InsideMask> mask, const PackedVolume& volume,
                                const CameraFrame& camera, int width, int height, const PointsPassOptions& options);

}  // namespace voxflame::core
