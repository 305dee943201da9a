#include "accumulator.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "error.h"
#include "random.h"

namespace voxflame::core {

namespace {

constexpr std::size_t kOrbitsPerBatch = 256;  // independent orbits advanced together per layer
constexpr int kStepsPerBatch = 64;            // steps per batch before checking for a new generation
constexpr int kTransientSteps = 32;           // steps an orbit takes before it may splat
constexpr int kProbeTransient = 2'000;
constexpr int kProbeSamples = 20'000;
constexpr std::size_t kSeedPoolSize = 1'024;

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

bool isFiniteAndNear(double x, double y, double z, double radius) {
  return std::abs(x) < radius && std::abs(y) < radius && std::abs(z) < radius;  // false for NaN
}

// Robust bounds: a fraction of outliers on each side is ignored so a rare excursion does not
// shrink the whole pattern, and a small parameter change moves the fit only a little.
void percentileBounds(std::vector<glm::dvec3>& samples, double fraction, glm::dvec3& low, glm::dvec3& high) {
  std::vector<double> axis(samples.size());
  for (int a = 0; a < 3; ++a) {
    for (std::size_t i = 0; i < samples.size(); ++i) axis[i] = samples[i][a];
    const auto lowIndex = static_cast<std::size_t>(fraction * static_cast<double>(axis.size() - 1));
    const auto highIndex = axis.size() - 1 - lowIndex;
    std::nth_element(axis.begin(), axis.begin() + static_cast<std::ptrdiff_t>(lowIndex), axis.end());
    low[a] = axis[lowIndex];
    std::nth_element(axis.begin(), axis.begin() + static_cast<std::ptrdiff_t>(highIndex), axis.end());
    high[a] = axis[highIndex];
  }
}

// The box of voxels inside the mask, in voxel units; the whole grid when the mask is empty.
void insideBounds(const InsideMask& mask, glm::dvec3& low, glm::dvec3& high) {
  const GridGeometry& g = mask.geometry;
  glm::ivec3 lo = g.size, hi(-1);
  for (int k = 0; k < g.size.z; ++k)
    for (int j = 0; j < g.size.y; ++j)
      for (int i = 0; i < g.size.x; ++i)
        if (mask.inside[g.index(i, j, k)]) {
          lo = glm::min(lo, glm::ivec3(i, j, k));
          hi = glm::max(hi, glm::ivec3(i, j, k));
        }
  if (hi.x < 0) {
    low = glm::dvec3(0.0);
    high = glm::dvec3(g.size);
    return;
  }
  low = glm::dvec3(lo);
  high = glm::dvec3(hi) + 1.0;
}

}  // namespace

PreparedLayer prepareLayer(const PatternLayer& layer, const InsideMask& mask, std::uint64_t seed) {
  PreparedLayer prepared;
  prepared.layer = layer;
  prepared.info = &attractorOrThrow(layer.attractor);
  const AttractorInfo& info = *prepared.info;
  if (layer.params.size() != info.params.size())
    throw Error("attractor '" + info.id + "' takes " + std::to_string(info.params.size()) + " parameters, got " +
                std::to_string(layer.params.size()));
  for (double p : layer.params)
    if (!std::isfinite(p)) throw Error("a parameter of attractor '" + info.id + "' is not a finite number");
  if (!std::isfinite(layer.step) || layer.step <= 0.0 || layer.step > 1.0)
    throw Error("the step of attractor '" + info.id + "' must be in (0, 1]");

  const AdvanceFn advance = info.advance(layer.integrator);
  SplitMix64 rng(mixSeed(seed, 0x70726f6265ULL));
  double x = info.start.x, y = info.start.y, z = info.start.z;
  constexpr double kProbeEscape = 1e8;
  std::vector<glm::dvec3> samples;
  samples.reserve(kProbeSamples);
  std::vector<double> speeds;
  speeds.reserve(kProbeSamples);
  bool escaped = false;
  for (int step = 0; step < kProbeTransient + kProbeSamples; ++step) {
    const double px = x, py = y, pz = z;
    advance(layer.params.data(), layer.step, &x, &y, &z, 1);
    if (!isFiniteAndNear(x, y, z, kProbeEscape)) {
      escaped = true;
      break;
    }
    if (step >= kProbeTransient) {
      samples.emplace_back(x, y, z);
      speeds.push_back(std::sqrt((x - px) * (x - px) + (y - py) * (y - py) + (z - pz) * (z - pz)));
    }
  }
  if (escaped || samples.empty()) return prepared;  // bounded stays false

  glm::dvec3 low, high;
  percentileBounds(samples, 0.005, low, high);
  const glm::dvec3 extent = glm::max(high - low, glm::dvec3(1e-9));
  if (std::max({extent.x, extent.y, extent.z}) < 1e-6) return prepared;  // collapsed to a point

  glm::dvec3 maskLow, maskHigh;
  insideBounds(mask, maskLow, maskHigh);
  const glm::dvec3 maskExtent = maskHigh - maskLow;
  // Scale so the attractor covers the shape along its best-filled axis; what spills over the
  // surface is cut away by the mask, which is what makes the pattern take the mesh's form.
  const glm::dvec3 ratios = maskExtent / extent;
  const double minRatio = std::min({ratios.x, ratios.y, ratios.z});
  const double maxRatio = std::max({ratios.x, ratios.y, ratios.z});
  prepared.fit.scale = std::min(maxRatio, 2.5 * minRatio);
  prepared.fit.attractorCenter = 0.5 * (low + high);
  prepared.fit.gridCenter = 0.5 * (maskLow + maskHigh);
  prepared.escapeRadius = 1e3 * (std::max({std::abs(low.x), std::abs(low.y), std::abs(low.z), std::abs(high.x),
                                           std::abs(high.y), std::abs(high.z)}) +
                                 1.0);

  prepared.seeds.reserve(kSeedPoolSize);
  for (std::size_t i = 0; i < kSeedPoolSize; ++i)
    prepared.seeds.push_back(samples[static_cast<std::size_t>(rng.uniform() * static_cast<double>(samples.size()))]);

  std::nth_element(speeds.begin(), speeds.begin() + static_cast<std::ptrdiff_t>(speeds.size() * 95 / 100),
                   speeds.end());
  prepared.speedReference = std::max(speeds[speeds.size() * 95 / 100], 1e-12);

  const Gradient gradient(layer.color.gradient);
  prepared.palette.resize(256);
  for (int i = 0; i < 256; ++i) {
    const glm::vec3 c = glm::clamp(gradient.at(static_cast<float>(i) / 255.0f), 0.0f, 1.0f) * 255.0f + 0.5f;
    prepared.palette[static_cast<std::size_t>(i)] = glm::u8vec3(c);
  }
  prepared.bounded = true;
  return prepared;
}

// Per-thread state of one layer's orbits, structure of arrays so the advance loop vectorises.
struct OrbitBatch {
  std::vector<double> x, y, z, px, py, pz;
  std::vector<int> warmup;
  SplitMix64 rng{0};
  std::uint64_t generation = ~std::uint64_t{0};
};

Accumulator::Accumulator(std::shared_ptr<const InsideMask> mask, int threads) : mask_(std::move(mask)) {
  if (!mask_) throw Error("the accumulator needs an inside mask");
  const std::size_t voxels = mask_->geometry.voxelCount();
  density_.assign(voxels, 0);
  colorSum_.assign(3 * voxels, 0);
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  threads_.reserve(static_cast<std::size_t>(threads));
  for (int t = 0; t < threads; ++t) threads_.emplace_back([this, t](std::stop_token stop) { workerLoop(stop, t); });
}

Accumulator::~Accumulator() {
  for (auto& thread : threads_) thread.request_stop();
  wake_.notify_all();
  threads_.clear();  // joins
}

void Accumulator::setPattern(const std::vector<PatternLayer>& layers, std::uint64_t seed) {
  // Probe outside the lock so running batches are not held up by it.
  std::vector<PreparedLayer> prepared;
  std::string problem;
  for (const auto& layer : layers) {
    prepared.push_back(prepareLayer(layer, *mask_, seed));
    if (!prepared.back().bounded)
      problem = "attractor '" + layer.attractor + "' escapes to infinity (or collapses) with these parameters";
  }
  {
    std::unique_lock lock(gridMutex_);
    layers_ = std::move(prepared);
    seed_ = seed;
    problem_ = problem;
    std::fill(density_.begin(), density_.end(), 0u);
    std::fill(colorSum_.begin(), colorSum_.end(), 0u);
    iterations_ = 0;
    points_ = 0;
    outside_ = 0;
    escapes_ = 0;
    generationStart_ = nowSeconds();
    const bool anyBounded = std::any_of(layers_.begin(), layers_.end(), [](const auto& l) { return l.bounded; });
    active_ = anyBounded;
    generation_.fetch_add(1, std::memory_order_acq_rel);
    version_.fetch_add(1, std::memory_order_acq_rel);
  }
  wake_.notify_all();
  doneSignal_.notify_all();
}

void Accumulator::setTargetPoints(std::uint64_t target) {
  targetPoints_ = target;
  wake_.notify_all();
}

bool Accumulator::waitUntilDone(double timeoutSeconds) {
  std::unique_lock lock(wakeMutex_);
  return doneSignal_.wait_for(lock, std::chrono::duration<double>(timeoutSeconds), [&] {
    const auto target = targetPoints_.load();
    return !active_.load() || (target > 0 && points_.load() >= target);
  });
}

AccumulatorStats Accumulator::stats() const {
  AccumulatorStats s;
  s.generation = generation_.load();
  s.iterations = iterations_.load();
  s.points = points_.load();
  s.outside = outside_.load();
  s.escapes = escapes_.load();
  const double elapsed = nowSeconds() - generationStart_.load();
  s.pointsPerSecond = elapsed > 0.0 ? static_cast<double>(s.iterations) / elapsed : 0.0;
  const auto target = targetPoints_.load();
  s.done = target > 0 && s.points >= target;
  std::shared_lock lock(gridMutex_);
  s.problem = problem_;
  return s;
}

void Accumulator::snapshot(VolumeSnapshot& out) const {
  std::shared_lock lock(gridMutex_);
  const std::size_t voxels = density_.size();
  out.geometry = mask_->geometry;
  out.density.resize(voxels);
  out.rgba.resize(4 * voxels);
  out.version = version_.load(std::memory_order_acquire);
  out.points = points_.load();
  float maxDensity = 0.0f;
  for (std::size_t v = 0; v < voxels; ++v) {
    // Workers keep adding while we copy: relaxed atomic loads make that well defined, and a
    // voxel read mid-update is at worst one hit behind.
    const std::uint32_t hits = std::atomic_ref<const std::uint32_t>(density_[v]).load(std::memory_order_relaxed);
    out.density[v] = static_cast<float>(hits);
    maxDensity = std::max(maxDensity, out.density[v]);
    if (hits == 0) {
      out.rgba[4 * v + 0] = out.rgba[4 * v + 1] = out.rgba[4 * v + 2] = 0;
    } else {
      for (int c = 0; c < 3; ++c) {
        const std::uint32_t sum = std::atomic_ref<const std::uint32_t>(colorSum_[3 * v + static_cast<std::size_t>(c)])
                                      .load(std::memory_order_relaxed);
        out.rgba[4 * v + static_cast<std::size_t>(c)] =
            static_cast<std::uint8_t>(std::min<std::uint32_t>(255u, sum / hits));
      }
    }
    out.rgba[4 * v + 3] = 255;
  }
  out.maxDensity = maxDensity;
}

void Accumulator::workerLoop(std::stop_token stop, int threadIndex) {
  std::vector<OrbitBatch> batches;
  while (!stop.stop_requested()) {
    const auto target = targetPoints_.load();
    const bool reachedTarget = target > 0 && points_.load() >= target;
    if (!active_.load() || reachedTarget) {
      doneSignal_.notify_all();
      std::unique_lock lock(wakeMutex_);
      wake_.wait_for(lock, stop, std::chrono::milliseconds(50), [&] {
        const auto t = targetPoints_.load();
        return active_.load() && !(t > 0 && points_.load() >= t);
      });
      continue;
    }
    runBatch(threadIndex, generation_.load(), batches);
  }
}

void Accumulator::runBatch(int threadIndex, std::uint64_t generation, std::vector<OrbitBatch>& batches) {
  std::shared_lock lock(gridMutex_);
  if (generation != generation_.load()) return;  // a new pattern arrived; pick it up next time
  const GridGeometry& grid = mask_->geometry;
  const std::uint8_t* inside = mask_->inside.data();
  batches.resize(layers_.size());

  double maxWeight = 0.0;
  for (const auto& l : layers_) maxWeight = std::max(maxWeight, l.layer.weight);

  std::uint64_t iterations = 0, points = 0, outside = 0, escapes = 0;
  for (std::size_t li = 0; li < layers_.size(); ++li) {
    const PreparedLayer& layer = layers_[li];
    if (!layer.bounded || maxWeight <= 0.0) continue;
    OrbitBatch& b = batches[li];
    if (b.generation != generation) {
      // New generation: restart this thread's orbits from the seed pool, reproducibly.
      b.generation = generation;
      b.rng = SplitMix64(mixSeed(seed_, (static_cast<std::uint64_t>(threadIndex) << 8) + li));
      for (auto* v : {&b.x, &b.y, &b.z, &b.px, &b.py, &b.pz}) v->assign(kOrbitsPerBatch, 0.0);
      b.warmup.assign(kOrbitsPerBatch, kTransientSteps);
      for (std::size_t i = 0; i < kOrbitsPerBatch; ++i) {
        const glm::dvec3 s = layer.seeds[b.rng.next() % layer.seeds.size()];
        b.x[i] = b.px[i] = s.x;
        b.y[i] = b.py[i] = s.y;
        b.z[i] = b.pz[i] = s.z;
      }
    }
    const AdvanceFn advance = layer.info->advance(layer.layer.integrator);
    const double* params = layer.layer.params.data();
    const double h = layer.layer.step;
    const int steps = std::max(1, static_cast<int>(std::lround(kStepsPerBatch * layer.layer.weight / maxWeight)));
    const double speedToIndex = 255.0 / layer.speedReference;
    const FitTransform fit = layer.fit;
    for (int s = 0; s < steps; ++s) {
      advance(params, h, b.x.data(), b.y.data(), b.z.data(), kOrbitsPerBatch);
      iterations += kOrbitsPerBatch;
      for (std::size_t i = 0; i < kOrbitsPerBatch; ++i) {
        const double x = b.x[i], y = b.y[i], z = b.z[i];
        if (!isFiniteAndNear(x, y, z, layer.escapeRadius)) {
          ++escapes;
          const glm::dvec3 seedPoint = layer.seeds[b.rng.next() % layer.seeds.size()];
          const double jitter = 1e-7 * (1.0 + std::abs(seedPoint.x));
          b.x[i] = b.px[i] = seedPoint.x + jitter * b.rng.symmetric();
          b.y[i] = b.py[i] = seedPoint.y;
          b.z[i] = b.pz[i] = seedPoint.z;
          b.warmup[i] = kTransientSteps;
          continue;
        }
        const double dx = x - b.px[i], dy = y - b.py[i], dz = z - b.pz[i];
        b.px[i] = x;
        b.py[i] = y;
        b.pz[i] = z;
        if (b.warmup[i] > 0) {
          --b.warmup[i];
          continue;
        }
        const glm::dvec3 g = fit.apply({x, y, z});
        const int vi = static_cast<int>(std::floor(g.x));
        const int vj = static_cast<int>(std::floor(g.y));
        const int vk = static_cast<int>(std::floor(g.z));
        if (vi < 0 || vj < 0 || vk < 0 || vi >= grid.size.x || vj >= grid.size.y || vk >= grid.size.z) {
          ++outside;
          continue;
        }
        const std::size_t voxel = grid.index(vi, vj, vk);
        if (!inside[voxel]) {
          ++outside;
          continue;
        }
        const double speed = std::sqrt(dx * dx + dy * dy + dz * dz);
        const auto paletteIndex = static_cast<std::size_t>(std::min(255.0, speed * speedToIndex));
        const glm::u8vec3 color = layer.palette[paletteIndex];
        std::atomic_ref<std::uint32_t>(density_[voxel]).fetch_add(1, std::memory_order_relaxed);
        std::atomic_ref<std::uint32_t>(colorSum_[3 * voxel + 0]).fetch_add(color.r, std::memory_order_relaxed);
        std::atomic_ref<std::uint32_t>(colorSum_[3 * voxel + 1]).fetch_add(color.g, std::memory_order_relaxed);
        std::atomic_ref<std::uint32_t>(colorSum_[3 * voxel + 2]).fetch_add(color.b, std::memory_order_relaxed);
        ++points;
      }
    }
  }
  iterations_.fetch_add(iterations, std::memory_order_relaxed);
  points_.fetch_add(points, std::memory_order_relaxed);
  outside_.fetch_add(outside, std::memory_order_relaxed);
  escapes_.fetch_add(escapes, std::memory_order_relaxed);
  version_.fetch_add(1, std::memory_order_release);
}

}  // namespace voxflame::core
