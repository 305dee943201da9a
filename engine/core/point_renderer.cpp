#include "point_renderer.h"

#include "core/refinement/accumulator.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <thread>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "error.h"
#include "random.h"
#include "task_scheduler.h"

namespace voxflame::core {

namespace {

// Relative density (to the mesh's mean) of every voxel, for trilinear sampling.
std::vector<float> relativeDensity(const PackedVolume& volume) {
  const float toRelative = static_cast<float>(volume.texelDensity / std::max(volume.referenceDensity, 1e-30));
  std::vector<float> density(volume.density.size());
  for (std::size_t v = 0; v < density.size(); ++v) density[v] = halfToFloat(volume.density[v]) * toRelative;
  return density;
}

float trilinear(const std::vector<float>& field, const GridGeometry& g, glm::dvec3 voxel) {
  // Voxel values sit at voxel centres.
  const glm::dvec3 p = voxel - 0.5;
  const glm::ivec3 i0(glm::floor(p));
  const glm::dvec3 f = p - glm::dvec3(i0);
  float sum = 0.0f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::ivec3 c = i0 + glm::ivec3(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
    if (c.x < 0 || c.y < 0 || c.z < 0 || c.x >= g.size.x || c.y >= g.size.y || c.z >= g.size.z) continue;
    const double w = ((corner & 1) ? f.x : 1.0 - f.x) * (((corner >> 1) & 1) ? f.y : 1.0 - f.y) *
                     (((corner >> 2) & 1) ? f.z : 1.0 - f.z);
    sum += static_cast<float>(w) * field[g.index(c.x, c.y, c.z)];
  }
  return sum;
}

// View depth of a world point (the camera looks down -z in view space).
double viewDepth(const CameraFrame& camera, glm::dvec3 world) {
  return -(camera.view * glm::dvec4(world, 1.0)).z;
}

}  // namespace

ViewTransmittance buildViewTransmittance(const PackedVolume& volume, const CameraFrame& camera, double absorption,
                                         int width, int height, int depth) {
  ViewTransmittance t;
  t.width = std::max(1, width);
  t.height = std::max(1, height);
  t.depth = std::max(1, depth);
  const GridGeometry& g = volume.geometry;
  const Box box = g.box();
  // The depth range the grid's corners span, in front of the eye.
  double nearest = 1e300, farthest = -1e300;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::dvec3 p((corner & 1) ? box.max.x : box.min.x, ((corner >> 1) & 1) ? box.max.y : box.min.y,
                       ((corner >> 2) & 1) ? box.max.z : box.min.z);
    const double d = viewDepth(camera, p);
    nearest = std::min(nearest, d);
    farthest = std::max(farthest, d);
  }
  t.nearDepth = std::max(nearest, camera.nearPlane);
  t.farDepth = std::max(farthest, t.nearDepth + 1e-9);
  t.depthScale = static_cast<float>(t.depth / (t.farDepth - t.nearDepth));
  t.values.assign(static_cast<std::size_t>(t.width) * t.height * (t.depth + 1), 1.0f);
  if (absorption <= 0.0 || volume.density.empty()) return t;

  const std::vector<float> density = relativeDensity(volume);
  const double side = g.voxelSize * std::max({g.size.x, g.size.y, g.size.z, 1});
  const glm::dmat4 inverse = glm::inverse(camera.projection * camera.view);
  const glm::dmat4 projection = camera.projection;
  // NDC depth of a view depth: the ray's world points at the range's two ends.
  auto ndcDepth = [&](double d) {
    const glm::dvec4 clip = projection * glm::dvec4(0.0, 0.0, -d, 1.0);
    return clip.z / clip.w;
  };
  const double ndcNear = ndcDepth(t.nearDepth), ndcFar = ndcDepth(t.farDepth);
  const double sliceDepth = (t.farDepth - t.nearDepth) / t.depth;
  // Sub-steps per slice so no voxel is skipped.
  const int subSteps = std::max(1, static_cast<int>(std::ceil(sliceDepth / (0.5 * g.voxelSize))));
  // A row of rays is thousands of trilinear samples: worth a task of its own.
  parallelFor(static_cast<std::size_t>(t.height), 1, [&](std::size_t begin, std::size_t end) {
    for (int y = static_cast<int>(begin); y < static_cast<int>(end); ++y)
      for (int x = 0; x < t.width; ++x) {
        const double ndcX = (x + 0.5) / t.width * 2.0 - 1.0, ndcY = 1.0 - (y + 0.5) / t.height * 2.0;
        glm::dvec4 a = inverse * glm::dvec4(ndcX, ndcY, ndcNear, 1.0);
        glm::dvec4 b = inverse * glm::dvec4(ndcX, ndcY, ndcFar, 1.0);
        const glm::dvec3 start = glm::dvec3(a) / a.w, finish = glm::dvec3(b) / b.w;
        // World length per unit of view depth along this ray.
        const double lengthPerDepth = glm::length(finish - start) / (t.farDepth - t.nearDepth);
        const double stepUnits = lengthPerDepth * sliceDepth / subSteps / side;
        double opticalDepth = 0.0;
        for (int k = 1; k <= t.depth; ++k) {
          for (int s = 0; s < subSteps; ++s) {
            const double fraction = ((k - 1) + (s + 0.5) / subSteps) / t.depth;
            const glm::dvec3 world = start + fraction * (finish - start);
            opticalDepth += absorption * stepUnits * trilinear(density, g, (world - g.origin) / g.voxelSize);
          }
          t.values[(static_cast<std::size_t>(y) * static_cast<std::size_t>(t.width) + static_cast<std::size_t>(x)) *
                       static_cast<std::size_t>(t.depth + 1) +
                   static_cast<std::size_t>(k)] = static_cast<float>(std::exp(-opticalDepth));
        }
      }
  });
  return t;
}

PointProjector::PointProjector(const PointProjection& projection, int threads) : p_(projection) {
  if (p_.width <= 0 || p_.height <= 0) throw Error("the points image must have a positive size");
  threads = std::max(1, threads);
  const std::size_t pixels = static_cast<std::size_t>(p_.width) * static_cast<std::size_t>(p_.height);
  // Each made in place: assign(n, value) would hold one more full-size histogram while it copies.
  histograms_.resize(static_cast<std::size_t>(threads));
  for (std::vector<float>& histogram : histograms_) histogram.assign(4 * pixels, 0.0f);
  streamRandom_.resize(static_cast<std::size_t>(Accumulator::streamsPerChunk()));
  scratch_.resize(static_cast<std::size_t>(threads));
  scale_ = pointScale(p_);
}

PointScale pointScale(const PointProjection& p) {
  // One point's D in its pixel: (volume inside the mesh) / (points · pixel footprint), lengths in
  // grid sides (flame/image.h). The footprint grows with the view depth squared in perspective.
  const GridGeometry& g = p.grid;
  const double side = g.voxelSize * std::max({g.size.x, g.size.y, g.size.z, 1});
  const double scale = std::max(std::abs(p.camera.projection[1][1]), 1e-12);
  const double pixelAtUnitDepth = 2.0 / (scale * p.height) / side;
  const double volume = std::max(p.insideVoxels, 1.0) * std::pow(g.voxelSize / side, 3.0);
  const double pointDensity = volume / (std::max(p.totalPoints, 1.0) * pixelAtUnitDepth * pixelAtUnitDepth);
  // A point at the depth of the grid's centre adds up to 1024 counts: rounding to whole counts is
  // noise far below the point's own (a point is one sample: even 16 counts add under 0.1% to its
  // variance). Fewer when the points are many, so that one pixel can hold 1% of them all before its
  // count saturates: an attractor's slow spots gather millions of points in a pixel of a 16K print.
  // (Depths are in world units, so the count is set where the points are, not at unit depth.)
  const double centreDepth = p.camera.orthographic ? 1.0 : std::max(viewDepth(p.camera, p.grid.box().center()), 1e-9);
  const double countsPerPoint =
      std::clamp(static_cast<double>(std::numeric_limits<std::uint32_t>::max()) / (0.01 * std::max(p.totalPoints, 1.0)),
                 16.0, 1024.0);
  return {pointDensity, pointDensity / (countsPerPoint * (p.camera.orthographic ? 1.0 : centreDepth * centreDepth)),
          p.fog / side};
}

namespace {

// Histogram cells hold uint32 counts as bit patterns (see PointProjector::histograms_).
inline void addCount(float& cell, std::uint32_t add) {
  cell = std::bit_cast<float>(saturatingAdd(std::bit_cast<std::uint32_t>(cell), add));
}

// The fixed-point count of `value` counts: its whole part, plus one with the probability of its
// fraction (dither uniform in [0, 1)), so the expected count is the value itself.
inline std::uint32_t ditheredCount(float value, float dither) {
  const float counted = std::clamp(value + dither, 0.0f, 4294967040.0f);  // the largest float below 2^32
  return static_cast<std::uint32_t>(counted);
}

}  // namespace

void PointProjector::consume(int thread, const AcceptedPoints& points) {
  std::vector<float>& histogram = histograms_[static_cast<std::size_t>(thread)];
  StreamRandom& random = streamRandom_[points.stream % streamRandom_.size()];
  if (random.stream != points.stream) {
    random.stream = points.stream;
    random.state = mixSeed(mixSeed(p_.seed, 0x6c656e73ULL), points.stream);
  }
  std::uint64_t& rng = random.state;
  const glm::mat4 view(p_.camera.view);
  const glm::mat4 projection(p_.camera.projection);
  const glm::vec3 origin(p_.grid.origin);
  const auto voxelSize = static_cast<float>(p_.grid.voxelSize);
  const bool orthographic = p_.camera.orthographic;
  const auto nearPlane = static_cast<float>(p_.camera.nearPlane);
  const float width = static_cast<float>(p_.width), height = static_cast<float>(p_.height);
  const auto aperture = static_cast<float>(p_.dofAperture);
  const auto focus = static_cast<float>(std::max(p_.dofFocusDepth, 1e-9));
  const auto fogPerDepth = static_cast<float>(scale_.fogPerDepth);
  const auto fogStart = static_cast<float>(p_.fogStart);
  const ShadowVolume* shadow = p_.shadow;
  const int shadowDownsample = std::max(1, p_.shadowDownsample);
  const auto lightStrength = static_cast<float>(p_.lightStrength);
  const auto pointDensity = static_cast<float>(scale_.pointDensity / scale_.unit);  // in counts
  const ViewTransmittance* transmittance = p_.transmittance;
  std::vector<Projected>& batch = scratch_[static_cast<std::size_t>(thread)];
  batch.clear();
  batch.reserve(points.count);
  for (std::size_t i = 0; i < points.count; ++i) {
    const glm::vec3 world = origin + voxelSize * glm::vec3(points.x[i], points.y[i], points.z[i]);
    glm::vec4 eye = view * glm::vec4(world, 1.0f);
    const float depth = -eye.z;
    if (depth <= nearPlane) continue;
    if (aperture > 0.0f) {
      // A thin lens: seen from a random point of the lens disc, refocused at `focus`, a point
      // away from the focal plane spreads into a disc.
      rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
      const float radius = aperture * std::sqrt(static_cast<float>(rng >> 40) * (1.0f / 16777216.0f));
      rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
      const float angle = 6.28318530718f * static_cast<float>(rng >> 40) * (1.0f / 16777216.0f);
      const float shift = depth / focus - 1.0f;
      eye.x += radius * std::cos(angle) * shift;
      eye.y += radius * std::sin(angle) * shift;
    }
    const glm::vec4 clip = projection * eye;
    const float u = (clip.x / clip.w * 0.5f + 0.5f), v = (0.5f - clip.y / clip.w * 0.5f);
    const float px = u * width, py = v * height;
    if (!(px >= 0.0f && py >= 0.0f && px < width && py < height)) continue;
    float weight = orthographic ? pointDensity : pointDensity / (depth * depth);
    // Jitters of ±half a cell for the transmittance and shadow lookups, four 16-bit uniforms
    // from one generator step: their expected value interpolates between cells (see
    // ViewTransmittance::at), so neither volume's cells show in the image.
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    const auto uniform = [&rng](int part) {
      return static_cast<float>((rng >> (16 * part)) & 0xffffu) * (1.0f / 65536.0f) - 0.5f;
    };
    Projected entry{static_cast<std::uint32_t>(static_cast<std::size_t>(py) * static_cast<std::size_t>(p_.width) +
                                               static_cast<std::size_t>(px)),
                    0.0f,
                    ViewTransmittance::kNoLookup,
                    0.0f,
                    points.rgb[i],
                    0.0f};
    if (transmittance) entry.transmittance = transmittance->lookup(u, v, depth, uniform(1), uniform(2), entry.fraction);
    if (shadow) {
      // Shadow cells hold the light's transmittance of shadowDownsample³ voxels each.
      rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
      const float toCell = 1.0f / static_cast<float>(shadowDownsample);
      const glm::ivec3 cell = glm::clamp(
          glm::ivec3(glm::floor(glm::vec3(points.x[i] * toCell + uniform(1), points.y[i] * toCell + uniform(2),
                                          points.z[i] * toCell + uniform(3)))),
          glm::ivec3(0), shadow->size - 1);
      const float lit =
          static_cast<float>(shadow->transmittance[static_cast<std::size_t>(cell.x) +
                                                   static_cast<std::size_t>(shadow->size.x) *
                                                       (cell.y + static_cast<std::size_t>(shadow->size.y) * cell.z)]) *
          (1.0f / 255.0f);
      weight *= 1.0f + lightStrength * (lit - 1.0f);
    }
    if (fogPerDepth > 0.0f) weight *= std::exp(-fogPerDepth * std::max(0.0f, depth - fogStart));
    entry.weight = weight;
    rng = rng * 6364136223846793005ULL + 1442695040888963407ULL;
    entry.dither = static_cast<float>(rng >> 40) * (1.0f / 16777216.0f);
    batch.push_back(entry);
  }
  // Second pass: the histogram (16 bytes a pixel, hundreds of MB at 4K) and the transmittance
  // are far larger than the caches, so each point misses twice; prefetching kAhead points ahead
  // keeps many of those misses in flight at once.
  constexpr std::size_t kAhead = 16;
  const float* transmittanceValues = transmittance ? transmittance->values.data() : nullptr;
  for (std::size_t i = 0; i < batch.size(); ++i) {
    if (i + kAhead < batch.size()) {
      const Projected& next = batch[i + kAhead];
      __builtin_prefetch(&histogram[4 * static_cast<std::size_t>(next.pixel)], 1);
      if (next.transmittance != ViewTransmittance::kNoLookup)
        __builtin_prefetch(&transmittanceValues[next.transmittance], 0);
    }
    const Projected& entry = batch[i];
    float weight = entry.weight;
    if (entry.transmittance != ViewTransmittance::kNoLookup) {
      const float* slices = &transmittanceValues[entry.transmittance];
      weight *= slices[0] + entry.fraction * (slices[1] - slices[0]);
    }
    const std::uint32_t rgb = entry.rgb;
    float* bucket = &histogram[4 * static_cast<std::size_t>(entry.pixel)];
    const float dither = entry.dither;
    addCount(bucket[0], ditheredCount(weight * static_cast<float>(rgb & 0xffu) * (1.0f / 255.0f), dither));
    addCount(bucket[1], ditheredCount(weight * static_cast<float>((rgb >> 8) & 0xffu) * (1.0f / 255.0f), dither));
    addCount(bucket[2], ditheredCount(weight * static_cast<float>((rgb >> 16) & 0xffu) * (1.0f / 255.0f), dither));
    addCount(bucket[3], ditheredCount(weight, dither));
  }
  projected_.fetch_add(batch.size(), std::memory_order_relaxed);
}

DensityImage PointProjector::merge() {
  DensityImage image;
  image.width = p_.width;
  image.height = p_.height;
  image.hitsPerUnitDensity = hitsPerUnitDensity(p_.camera, p_.grid, p_.totalPoints, p_.insideVoxels, p_.height);
  // The first thread's histogram becomes the image and the others are added to it and freed one
  // by one, so a 16K print never holds a third full-size histogram; then its counts turn into
  // densities in place.
  image.values = std::move(histograms_.front());
  image.values.resize(4 * static_cast<std::size_t>(p_.width) * static_cast<std::size_t>(p_.height), 0.0f);
  for (std::size_t t = 1; t < histograms_.size(); ++t) {
    const std::vector<float>& histogram = histograms_[t];
    for (std::size_t i = 0; i < histogram.size(); ++i)
      addCount(image.values[i], std::bit_cast<std::uint32_t>(histogram[i]));
    std::vector<float>().swap(histograms_[t]);
  }
  histograms_.clear();
  for (float& value : image.values) value = densityOfCount(std::bit_cast<std::uint32_t>(value), scale_.unit);
  return image;
}

ImageSums PointProjector::takeSums() {
  ImageSums sums;
  sums.reset(p_.width, p_.height, scale_.unit);
  for (std::vector<float>& histogram : histograms_) {
    for (std::size_t i = 0; i < histogram.size(); ++i) {
      sums.counts[i] = saturatingAdd(sums.counts[i], std::bit_cast<std::uint32_t>(histogram[i]));
      histogram[i] = 0.0f;
    }
  }
  return sums;
}

DensityImage projectScenePoints(const Scene& scene, std::shared_ptr<const InsideMask> mask, const PackedVolume& volume,
                                const CameraFrame& camera, int width, int height, const PointsPassOptions& options) {
  const std::uint64_t target = options.points ? options.points : scene.points;
  const int cells = std::max(1, options.transmittanceCells);
  // Building costs cells × slices samples of the grid; past a few hundred cells across, a cell is
  // finer than the grid's voxels anyway.
  constexpr int kMaxCells = 320;
  const double absorption = std::max(0.0, scene.tone.opacity) * kAbsorptionPerDensity;
  // The transmittance needs detail along depth more than across: a slice per voxel of the grid's
  // longest side is enough, and across a cell of a few pixels.
  const int slices =
      std::clamp(std::max({volume.geometry.size.x, volume.geometry.size.y, volume.geometry.size.z}), 16, 384);
  const ViewTransmittance transmittance =
      buildViewTransmittance(volume, camera, absorption, std::min((width + cells - 1) / cells, kMaxCells),
                             std::min((height + cells - 1) / cells, kMaxCells), slices);
  ShadowVolume shadow;
  constexpr int kShadowDownsample = 2;
  if (scene.render.lighting)
    computeShadowVolume(volume, lightDirection(scene.render.lightAzimuthDeg, scene.render.lightElevationDeg),
                        kAbsorptionPerDensity, kShadowDownsample, shadow);

  const int threads =
      options.threads > 0 ? options.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  PointProjection projection;
  projection.grid = mask->geometry;
  projection.camera = camera;
  projection.width = width;
  projection.height = height;
  projection.totalPoints = static_cast<double>(target);
  projection.insideVoxels = volume.insideVoxels;
  projection.transmittance = absorption > 0.0 ? &transmittance : nullptr;
  projection.shadow = scene.render.lighting ? &shadow : nullptr;
  projection.shadowDownsample = kShadowDownsample;
  projection.lightStrength = scene.render.lightStrength;
  const double radius = 0.5 * glm::length(mask->geometry.box().extent());  // the camera's distance unit
  const double targetDepth = viewDepth(camera, mask->geometry.box().center());
  projection.dofAperture = scene.render.dofAperture * radius;
  projection.dofFocusDepth = scene.render.dofFocusDistance > 0.0 ? scene.render.dofFocusDistance * radius : targetDepth;
  projection.fog = scene.render.fog;
  projection.fogStart = transmittance.nearDepth;
  projection.seed = scene.seed;
  const PointScale pointUnits = pointScale(projection);
  // The CPU's projector, fed by an Accumulator; or a backend that projects its points itself, whose
  // sums are taken chunk by chunk.
  std::optional<PointProjector> projector;
  if (!options.projectingBackend) projector.emplace(projection, threads);
  const int chunks = std::max(1, options.chunks);
  std::vector<int> chunkList;
  if (options.chunkList)
    chunkList = *options.chunkList;
  else
    for (int chunk = 0; chunk < chunks; ++chunk) chunkList.push_back(chunk);
  // With chunkDone (or a projecting backend) each chunk's sums are taken as it finishes and added
  // here (with those of chunks rendered earlier); else the projector's histograms hold every chunk's points.
  ImageSums total;
  const bool perChunk = static_cast<bool>(options.chunkDone) || !projector;
  if (perChunk) {
    if (options.earlierSums) {
      total = *options.earlierSums;
      if (total.width != width || total.height != height || total.unit != pointUnits.unit)
        throw Error("the chunks rendered earlier are of another image");
    } else {
      total.reset(width, height, pointUnits.unit);
    }
  }
  AccumulatorStats stats;
  std::uint64_t pointsInside = perChunk ? total.points : 0, iterations = perChunk ? total.iterations : 0;
  {
    std::unique_ptr<ProjectingBackend> projecting;
    std::unique_ptr<Accumulator> cpu;
    RefinementBackend* accumulator = nullptr;
    if (projector) {
      cpu = std::make_unique<Accumulator>(mask, threads);
      cpu->setPointSink(&*projector);
      accumulator = cpu.get();
    } else {
      projecting = options.projectingBackend(mask, projection, threads);
      accumulator = &projecting->backend();
    }
    accumulator->setHeld(true);  // nothing runs until the first chunk's streams are set
    accumulator->setTargetPoints(1);
    accumulator->setDeepSeeds(true);
    accumulator->setPaletteMode(scene.flat.paletteMode);
    accumulator->setPattern(scene.layers, scene.seed);
    // A pattern that mostly misses the mesh would never reach its target: stop after as many
    // iterations as the grid pass allows.
    const std::uint64_t iterationLimit = 40 * target + 50'000'000;
    std::size_t chunksDone = 0;
    for (const int chunk : chunkList) {
      const std::uint64_t chunkTarget = chunkPoints(target, chunks, chunk);
      const std::uint64_t iterationsBefore = accumulator->stats().iterations;
      const std::uint64_t pointsBefore = accumulator->stats().points;
      accumulator->setChunk(static_cast<std::uint64_t>(chunk), false);
      accumulator->setTargetPoints(chunkTarget);
      accumulator->setHeld(false);
      while (!accumulator->waitUntilDone(options.progressInterval)) {
        stats = accumulator->stats();
        const double done = (static_cast<double>(chunksDone) +
                             std::min(1.0, static_cast<double>(stats.points - pointsBefore) /
                                               static_cast<double>(std::max<std::uint64_t>(chunkTarget, 1)))) /
                            static_cast<double>(chunkList.size());
        if (options.progress) options.progress(done);
        if (stats.iterations - iterationsBefore > iterationLimit / static_cast<std::uint64_t>(chunks) + 50'000'000 ||
            !stats.problem.empty())
          break;
      }
      accumulator->setHeld(true);
      stats = accumulator->stats();
      if (!stats.problem.empty()) break;
      ++chunksDone;
      if (perChunk) {
        // Held, the workers finish the batch they are in before the next chunk's streams are set;
        // the chunk reached its target, so there is none.
        ImageSums sums = projector ? projector->takeSums() : projecting->takeSums();
        sums.points = stats.points - pointsBefore;
        sums.iterations = stats.iterations - iterationsBefore;
        if (options.chunkDone) options.chunkDone(chunk, sums);
        if (options.makeImage) total.add(sums);
      }
      if (options.chunkFinished) options.chunkFinished(static_cast<int>(chunksDone));
    }
    stats = accumulator->stats();
  }  // the workers are joined here: no point arrives after this
  if (!stats.problem.empty()) throw Error(stats.problem);
  if (!perChunk) {
    pointsInside = stats.points;
    iterations = stats.iterations;
  } else {
    pointsInside = total.points;
    iterations = total.iterations;
  }
  if (options.pointsInside) *options.pointsInside = pointsInside;
  if (options.iterations) *options.iterations = iterations;
  if (!options.makeImage) return {};
  DensityImage image;
  if (perChunk) {
    image.width = width;
    image.height = height;
    image.hitsPerUnitDensity =
        hitsPerUnitDensity(camera, mask->geometry, projection.totalPoints, projection.insideVoxels, height);
    image.values.resize(total.counts.size());
    for (std::size_t i = 0; i < total.counts.size(); ++i) image.values[i] = densityOfCount(total.counts[i], total.unit);
  } else {
    image = projector->merge();
  }
  // Each point's share of D assumed `target` points; the batches overshoot it a little (or a
  // pattern that barely meets the mesh falls short), so the image is scaled to what landed.
  if (pointsInside > 0 && pointsInside != target) {
    const float scale = static_cast<float>(static_cast<double>(target) / static_cast<double>(pointsInside));
    for (float& value : image.values) value *= scale;
  }
  return image;
}

std::uint64_t chunkPoints(std::uint64_t points, int chunks, int chunk) {
  const auto k = static_cast<std::uint64_t>(std::max(1, chunks));
  return points / k + (static_cast<std::uint64_t>(chunk) < points % k ? 1 : 0);
}

}  // namespace voxflame::core
