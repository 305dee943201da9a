#include "gpu_accumulator.h"

#include <epoxy/gl.h>
#include <pthread.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>
#include <optional>
#include <utility>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "core/chunk_sums.h"
#include "core/error.h"
#include "core/random.h"
#include "core/packed_volume.h"
#include "core/point_renderer.h"
#include "gl/flame_kernel.h"
#include "gl/gpu_volume.h"
#include "gl/headless_context.h"
#include "gl/renderer_kind.h"
#include "gl/shader_program.h"

namespace voxflame::gl {

namespace {

constexpr GLuint kOrbitsBinding = 0, kCellsBinding = 1, kHitsBinding = 2, kSeedsBinding = 3, kCountersBinding = 4,
                 kPaletteBinding = 5, kMaskBinding = 6, kSampleBinding = 7, kFlameDataBinding = 8,
                 kFlamePickBinding = 9, kDistanceInBinding = 10, kDistanceOutBinding = 11, kScreenBinding = 12,
                 kLaneMemoryBinding = 13;
// The points method's texture units (accumulate.comp.glsl's PROJECT_POINTS).
constexpr GLint kViewTransmittanceUnit = 0, kLightTransmittanceUnit = 1;
constexpr int kTransientSteps = 32;  // as the CPU's: steps an orbit takes before it may add a point
// accumulate.comp.glsl's Orbit: an attractor's, and a chaos game's with its state, colour and stream
// (112 bytes with a float state, 128 with a double one: the larger serves both).
constexpr int kOrbitBytes = 64, kChaosOrbitBytes = 128;

double nowSeconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// The attractors attractors.glsl knows, by catalogue id: its define is SYSTEM_ and the id in capitals.
constexpr std::array<const char*, 45> kGpuAttractors = {"lorenz",
                                                        "lorenz84",
                                                        "pickover",
                                                        "polynomial_a",
                                                        "polynomial_b",
                                                        "polynomial_c",
                                                        "rossler",
                                                        "aizawa",
                                                        "thomas",
                                                        "halvorsen",
                                                        "chen",
                                                        "lu_chen",
                                                        "dadras",
                                                        "rabinovich_fabrikant",
                                                        "chua",
                                                        "nose_hoover",
                                                        "arneodo",
                                                        "burke_shaw",
                                                        "dequan_li",
                                                        "four_wing",
                                                        "genesio_tesi",
                                                        "hadley",
                                                        "newton_leipnik",
                                                        "rucklidge",
                                                        "shimizu_morioka",
                                                        "sakarya",
                                                        "yu_wang",
                                                        "sprott_jerk",
                                                        "sprott_b",
                                                        "sprott_c",
                                                        "sprott_d",
                                                        "sprott_e",
                                                        "sprott_f",
                                                        "sprott_g",
                                                        "sprott_h",
                                                        "sprott_l",
                                                        "sprott_m",
                                                        "sprott_n",
                                                        "sprott_o",
                                                        "sprott_p",
                                                        "sprott_q",
                                                        "sprott_r",
                                                        "sprott_s",
                                                        "henon_3d",
                                                        "sprott_quadratic"};

bool gpuKnowsAttractor(const std::string& id) {
  return std::find_if(kGpuAttractors.begin(), kGpuAttractors.end(), [&](const char* known) { return id == known; }) !=
         kGpuAttractors.end();
}

std::string systemDefine(const std::string& id) {
  std::string define = "SYSTEM_";
  for (char c : id) define += static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
  return define;
}

std::uint32_t packRgb(const glm::u8vec3& c) {
  return std::uint32_t{c.r} | std::uint32_t{c.g} << 8 | std::uint32_t{c.b} << 16;
}

GLuint makeBuffer(GLuint binding, std::size_t bytes, const void* data = nullptr) {
  GLuint buffer = 0;
  glGenBuffers(1, &buffer);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
  // A binding is never empty, so a buffer holds at least 16 bytes; only the caller's bytes are read from data.
  glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 16)), nullptr,
               GL_DYNAMIC_DRAW);
  if (data != nullptr && bytes > 0) glBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), data);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buffer);
  return buffer;
}

// Every 32-bit word of `buffer` set to `word` (the buffer stays bound).
void fillBuffer(GLuint buffer, GLuint word) {
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
  glClearBufferData(GL_SHADER_STORAGE_BUFFER, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &word);
}

}  // namespace

std::string gpuUnsupportedReason(const std::vector<core::PatternLayer>& layers) {
  for (const core::PatternLayer& layer : layers) {
    if (layer.kind != core::PatternKind::Attractor) {
      const std::string lacking = flameKernelUnsupported(layer);
      if (!lacking.empty())
        return "a " + std::string(core::toString(layer.kind)) +
               " layer needs the CPU backend: the GPU backend does not have " + lacking;
      continue;
    }
    if (!gpuKnowsAttractor(layer.attractor))
      return "the GPU backend does not know attractor '" + layer.attractor + "'; it needs the CPU backend";
    if (layer.params.size() > 32)
      return "attractor '" + layer.attractor + "' has more parameters than the GPU backend takes";
  }
  return {};
}

bool hardwareGpuAvailable() {
  try {
    const HeadlessContext context;
    return !softwareRasteriser();
  } catch (const core::Error&) {
    return false;
  }
}

// One layer as the shader runs it.
struct LayerUniforms {
  std::string system;  // attractor layers: SYSTEM_<ID>
  bool chaos = false;  // a flame or quaternion Julia layer: the kernel below
  FlameKernel kernel;
  bool rk4 = false;
  std::vector<float> params;
  float step = 0.0f;
  glm::mat3 toGrid{1.0f};
  glm::vec3 offset{0.0f};
  float escapeRadius = 1e6f;
  float alongStep = 0.0f;
  int colorMode = 0;
  float colorScale = 1.0f, inversePeriod = 1.0f, axisOffset = 0.0f, hair = 0.0f;
  glm::vec3 axis{1.0f, 0.0f, 0.0f}, center{0.0f};
  std::array<std::uint32_t, 256> palette{};
  std::vector<glm::vec4> seeds;
  int stepShare = 1;  // steps per dispatch, of stepsPerDispatch, by its weight
  bool runs = false;  // bounded, with weight
  // Its program, compiled when the pattern is set (or the points method begins) rather than looked
  // up by its whole source at every dispatch. Device::programs owns it.
  const ShaderProgram* program = nullptr;
};

struct GpuAccumulator::Device {
  std::unique_ptr<HeadlessContext> context;
  GLuint cells = 0, hits = 0, counters = 0, mask = 0, sample = 0;
  // Per layer; laneMemory: what its variations keep per orbit (FlameKernel::laneMemory, at least 16 bytes).
  std::vector<GLuint> orbits, seeds, palettes, flameData, flamePicks, laneMemory;
  std::vector<LayerUniforms> layers;
  std::map<std::string, ShaderProgram> programs;  // by their defines
  bool hitsInCells = true;
  // The volumes packed for the renderer (packOnDevice): one is free to pack into again when only
  // this list holds it. The bricks' distance buffers of the pack, ping and pong.
  std::vector<std::shared_ptr<GpuVolume>> volumes;
  GLuint distance[2] = {0, 0};
  // The points method (projectPoints): the screen histogram, the camera's and the light's
  // transmittance (textures), and what the shader needs to know of them. The projection's pointers
  // to the host's volumes are not kept.
  struct Projection {
    core::PointProjection p;
    core::PointScale scale;
    bool dimmed = false, lit = false;
    glm::ivec3 viewCells{0};
    float viewNear = 0.0f, viewDepthScale = 1.0f;
    glm::ivec3 shadowSize{0};
  };
  std::optional<Projection> projection;
  GLuint screen = 0, viewTransmittance = 0, lightTransmittance = 0;

  ~Device() {
    for (const std::shared_ptr<GpuVolume>& volume : volumes) deleteVolume(*volume);
    for (GLuint* b : {&cells, &hits, &counters, &mask, &sample, &distance[0], &distance[1], &screen})
      if (*b) glDeleteBuffers(1, b);
    for (GLuint* t : {&viewTransmittance, &lightTransmittance})
      if (*t) glDeleteTextures(1, t);
    for (auto* list : {&orbits, &seeds, &palettes, &flameData, &flamePicks, &laneMemory})
      if (!list->empty()) glDeleteBuffers(static_cast<GLsizei>(list->size()), list->data());
    programs.clear();
  }

  const ShaderProgram& program(const std::string& file, const std::string& defines, bool withAttractors) {
    return program(file, defines, withAttractors ? embeddedShader("attractors.glsl").text : std::string());
  }
  // `prelude`: GLSL put before the file (the attractor catalogue, or a chaos game's variations and kernel).
  const ShaderProgram& program(const std::string& file, const std::string& defines, const std::string& prelude) {
    const std::string key = file + "|" + defines + "|" + prelude;
    auto found = programs.find(key);
    if (found != programs.end()) return found->second;
    const ShaderSource body = embeddedShader(file);
    std::string text = "#version 430 core\n" + defines + (hitsInCells ? "#define HITS_IN_CELLS\n" : "");
    text += prelude + "\n";
    text += "#line 1 0\n" + body.text;  // string 0: the file (the preludes number theirs)
    return programs.emplace(key, ShaderProgram(ShaderSource{body.file, std::move(text)})).first->second;
  }
  // The program that runs one layer's steps.
  const ShaderProgram& layerProgram(const LayerUniforms& u) {
    const std::string projecting = projection ? "#define PROJECT_POINTS\n" : "";
    if (u.chaos) {
      // gLane's and gFieldBlock's sizes come before the variations, which declare them.
      std::string lane =
          u.kernel.laneMemory > 0 ? "#define LANE_MEMORY " + std::to_string(u.kernel.laneMemory) + "\n" : "";
      if (u.kernel.fieldBlock > 0) lane += "#define FIELD_BLOCK " + std::to_string(u.kernel.fieldBlock) + "\n";
      return program("accumulate.comp.glsl", projecting,
                     lane + gpuVariationSource(u.kernel.variations) + "\n#line 1 99\n" + u.kernel.source);
    }
    return program("accumulate.comp.glsl",
                   projecting + "#define " + u.system + "\n" + (u.rk4 ? "#define INTEGRATOR_RK4\n" : ""), true);
  }

  void bindGrid() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCellsBinding, cells);
    if (hits) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kHitsBinding, hits);
  }

  // Deletes a volume's textures once no copy of them is under way or pending: a renderer still
  // holding the volume then finds it gone (GpuVolume::alive) and copies nothing.
  static void deleteVolume(GpuVolume& volume) {
    GLsync copied = nullptr;
    {
      std::lock_guard lock(volume.mutex);
      volume.alive = false;
      copied = std::exchange(volume.copied, nullptr);
    }
    if (copied) {
      // The copy was flushed with its sync (VolumeRenderer), so this wait ends; a second bounds a lost device.
      glClientWaitSync(copied, GL_SYNC_FLUSH_COMMANDS_BIT, 1'000'000'000);
      glDeleteSync(copied);
    }
    if (volume.packed) glDeleteSync(std::exchange(volume.packed, nullptr));
    for (GLuint* texture : {&volume.colour, &volume.density, &volume.emptyDistance})
      if (*texture) glDeleteTextures(1, texture);
  }

  // A volume of these sizes to pack into: a free one, else a new one (volumes of other sizes,
  // from before a change of grid, are deleted once free).
  GpuVolume& freeVolume(glm::ivec3 size, glm::ivec3 colourSize, glm::ivec3 brickCount) {
    std::shared_ptr<GpuVolume> found;
    for (auto it = volumes.begin(); it != volumes.end();) {
      const bool free = it->use_count() == 1;
      const bool fits = (*it)->size == size && (*it)->colourSize == colourSize;
      if (free && fits && !found) {
        found = *it;
      } else if (free && !fits) {
        deleteVolume(**it);
        it = volumes.erase(it);
        continue;
      }
      ++it;
    }
    if (found) return *found;
    auto volume = std::make_shared<GpuVolume>();
    volume->size = size;
    volume->colourSize = colourSize;
    volume->brickCount = brickCount;
    auto texture = [](GLenum format, glm::ivec3 extent) {
      GLuint id = 0;
      glGenTextures(1, &id);
      glBindTexture(GL_TEXTURE_3D, id);
      glTexStorage3D(GL_TEXTURE_3D, 1, format, extent.x, extent.y, extent.z);
      glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      return id;
    };
    volume->colour = texture(GL_RGBA16F, colourSize);
    volume->density = texture(GL_R16F, size);
    volume->emptyDistance = texture(GL_R8UI, brickCount);
    glBindTexture(GL_TEXTURE_3D, 0);
    volumes.push_back(volume);
    return *volume;
  }
};

GpuAccumulator::GpuAccumulator(std::shared_ptr<const core::InsideMask> mask, ShareGroup shareWith)
    : mask_(std::move(mask)), shareWith_(shareWith) {
  if (!mask_) throw core::Error("the GPU backend needs an inside mask");
  const core::GridGeometry& g = mask_->geometry;
  const std::size_t voxels = g.voxelCount();
  if (voxels == 0 || voxels >= (std::size_t{1} << 31))
    throw core::Error("the accumulation grid must have 1 to 2^31 voxels");
  colour_ = core::ColourLayout::of(g);
  gridId_ = core::nextGridId();
  rowInside_.assign(static_cast<std::size_t>(g.size.y) * g.size.z, 0);
  for (int k = 0; k < g.size.z; ++k)
    for (int j = 0; j < g.size.y; ++j)
      for (int i = 0; i < g.size.x; ++i)
        if (mask_->at(i, j, k)) {
          rowInside_[static_cast<std::size_t>(j) + static_cast<std::size_t>(g.size.y) * k] = 1;
          ++insideVoxels_;
        }
  insideBox_ = core::insideBox(*mask_);

  std::exception_ptr startError;
  std::mutex startMutex;
  std::condition_variable started;
  bool ready = false;
  thread_ = std::jthread([this, &startError, &startMutex, &started, &ready](std::stop_token stop) {
    loop(stop, &startError, &startMutex, &started, &ready);
  });
  std::unique_lock lock(startMutex);
  started.wait(lock, [&] { return ready; });
  if (startError) {
    lock.unlock();
    thread_.request_stop();
    thread_.join();
    std::rethrow_exception(startError);
  }
}

GpuAccumulator::~GpuAccumulator() {
  thread_.request_stop();
  {
    std::lock_guard lock(mutex_);
    wake_.notify_all();
  }
  if (thread_.joinable()) thread_.join();
}

std::size_t GpuAccumulator::gridBytes() const {
  const std::size_t voxels = mask_->geometry.voxelCount();
  const std::size_t hits = colour_.shift == 0 ? 0 : voxels * sizeof(std::uint32_t);
  return hits + colour_.cellCount() * sizeof(core::detail::ColourCell) + voxels / 8 +
         std::size_t{orbits_} * kChaosOrbitBytes * std::max<std::size_t>(layers_.size(), 1);
}

void GpuAccumulator::loop(std::stop_token stop, std::exception_ptr* startError, std::mutex* startMutex,
                          std::condition_variable* started, bool* ready) {
  pthread_setname_np(pthread_self(), "vf-gpu");
  std::unique_ptr<Device> device;
  try {
    device = std::make_unique<Device>();
    if (!shareWith_.empty()) {
      // Where the renderer's context cannot share (another process's display, a driver that
      // refuses), the backend still runs, and its grid reaches the renderer through host memory.
      try {
        device->context = std::make_unique<HeadlessContext>(shareWith_);
        sharesWithRenderer_ = true;
      } catch (const core::Error&) {
        device->context.reset();
      }
    }
    if (!device->context) device->context = std::make_unique<HeadlessContext>();
    renderer_ = device->context->renderer();
    software_ = softwareRasteriser();
    // A software rasteriser runs a dispatch on the CPU's cores: as many orbits as the CPU backend
    // has (16 streams of 256) keep a dispatch at milliseconds. A GPU wants a million in flight.
    orbits_ = software_ ? 4096u : 1u << 20;  // whole workgroups of 256 (GROUP_CHOICE's)
    stepsPerDispatch_ = software_ ? 64 : 256;
    const core::GridGeometry& g = mask_->geometry;
    const std::size_t voxels = g.voxelCount();
    GLint maxBlock = 0;
    glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
    const auto blockLimit = static_cast<std::size_t>(static_cast<GLuint>(maxBlock));
    // The CPU's layout where it fits what the device binds at once; else colour cells of 2×2×2
    // voxels (the CPU's own layout above 256³), which readers take from colourLayout().
    if (colour_.shift == 0 && colour_.cellCount() * sizeof(core::detail::ColourCell) > blockLimit) {
      colour_.shift = 1;
      colour_.size = (g.size + 1) / 2;
    }
    device->hitsInCells = colour_.shift == 0;
    const std::size_t cellBytes = colour_.cellCount() * sizeof(core::detail::ColourCell);
    const std::size_t hitBytes = device->hitsInCells ? 0 : voxels * sizeof(std::uint32_t);
    if (std::max(cellBytes, hitBytes) > blockLimit)
      throw core::Error("the grid is too large for the GPU backend on " + renderer_ + ": its " +
                        std::to_string(std::max(cellBytes, hitBytes) >> 20) + " MiB of sums exceed the " +
                        std::to_string(blockLimit >> 20) +
                        " MiB it binds at once; use a smaller grid or the CPU backend");
    device->cells = makeBuffer(kCellsBinding, cellBytes);
    if (!device->hitsInCells) device->hits = makeBuffer(kHitsBinding, voxels * sizeof(std::uint32_t));
    std::vector<std::uint32_t> bits((voxels + 31) / 32, 0u);
    for (std::size_t v = 0; v < voxels; ++v)
      if (mask_->inside[v]) bits[v >> 5] |= 1u << (v & 31u);
    device->mask = makeBuffer(kMaskBinding, bits.size() * sizeof(std::uint32_t), bits.data());
    device->counters = makeBuffer(kCountersBinding, 4 * sizeof(std::uint32_t));
    device->sample = makeBuffer(kSampleBinding, (core::kConvergenceSampleVoxels * 2 + 64) * sizeof(std::uint32_t));
    // Compile the grid passes now, so a driver without compute shaders fails here, with a message.
    device->program("accumulate_grid.comp.glsl", "#define CLEAR_GRID\n", false);
    if (glGetError() != GL_NO_ERROR) throw core::Error("the GPU backend could not allocate its grid");
  } catch (...) {
    device.reset();
    std::lock_guard lock(*startMutex);
    *startError = std::current_exception();
    *ready = true;
    started->notify_all();
    return;
  }
  {
    std::lock_guard lock(*startMutex);
    *ready = true;
    started->notify_all();
  }

  std::unique_lock lock(mutex_);
  while (!stop.stop_requested()) {
    if (!tasks_.empty()) {
      auto task = std::move(tasks_.front());
      tasks_.pop_front();
      lock.unlock();
      task(*device);
      lock.lock();
      continue;
    }
    if (active_.load() && !held_.load() && !targetReached()) {
      dispatching_ = true;
      lock.unlock();
      dispatchRound(*device);
      lock.lock();
      dispatching_ = false;
      continue;
    }
    wake_.wait(lock, stop, [&] { return !tasks_.empty() || (active_.load() && !held_.load() && !targetReached()); });
  }
  // Tasks still queued belong to callers that are being destroyed with us; their waits end with
  // the stop (runOnDevice is never called concurrently with the destructor).
  tasks_.clear();
  lock.unlock();
  device.reset();  // GL objects go while the context is current
}

bool GpuAccumulator::idle() const {
  std::lock_guard lock(mutex_);
  // No round of dispatches under way or due, and no change of the grid queued or running. A reader's
  // task (a read-back, a pack) may run meanwhile: it changes nothing a waiter on idle() looks at.
  return !dispatching_ && changingTasks_ == 0 && !(active_.load() && !held_.load() && !targetReached());
}

void GpuAccumulator::runOnDevice(const std::function<void(Device&)>& task, bool changesGrid) const {
  std::mutex doneMutex;
  std::condition_variable doneCondition;
  bool done = false;
  std::exception_ptr error;
  {
    std::lock_guard lock(mutex_);
    if (changesGrid) ++changingTasks_;
    tasks_.emplace_back([&, changesGrid](Device& device) {
      try {
        task(device);
      } catch (...) {
        error = std::current_exception();
      }
      if (changesGrid) {
        std::lock_guard taskLock(mutex_);
        --changingTasks_;
      }
      std::lock_guard doneLock(doneMutex);
      done = true;
      doneCondition.notify_all();
    });
    wake_.notify_all();
  }
  std::unique_lock doneLock(doneMutex);
  doneCondition.wait(doneLock, [&] { return done; });
  if (error) std::rethrow_exception(error);
}

bool GpuAccumulator::targetReached() const {
  const std::uint64_t target = targetPoints_.load();
  return target > 0 && chunkPoints_.load() >= target;
}

void GpuAccumulator::notifyWorkChanged() {
  {
    std::lock_guard lock(mutex_);
    wake_.notify_all();
    doneSignal_.notify_all();
  }
  progress_.notify();
}

void GpuAccumulator::setDeposit(core::Deposit deposit) {
  deposit_ = deposit;
}

void GpuAccumulator::setPaletteMode(core::PaletteMode mode) {
  // Only colour index layers (flames, quaternion Julia sets) read it, at the next dispatch.
  linearPalette_ = mode == core::PaletteMode::Linear;
}

void GpuAccumulator::setHeld(bool held) {
  if (held_.exchange(held) != held) notifyWorkChanged();
}

void GpuAccumulator::setTargetPoints(std::uint64_t target) {
  if (targetPoints_.exchange(target) == target) return;
  notifyWorkChanged();
}

bool GpuAccumulator::waitUntilDone(double timeoutSeconds) {
  std::unique_lock lock(mutex_);
  return doneSignal_.wait_for(lock, std::chrono::duration<double>(timeoutSeconds),
                              [&] { return !active_.load() || targetReached(); });
}

core::AccumulatorStats GpuAccumulator::stats() const {
  core::AccumulatorStats s;
  s.generation = generation_.load();
  s.iterations = iterations_.load();
  s.points = points_.load();
  s.outside = outside_.load();
  s.escapes = escapes_.load();
  const double elapsed = nowSeconds() - generationStart_.load();
  s.pointsPerSecond = elapsed > 0.0 ? static_cast<double>(s.iterations) / elapsed : 0.0;
  s.done = !active_.load() || targetReached();
  std::lock_guard lock(mutex_);
  s.problem = problem_;
  s.showingLastBounded = showingLastBounded_;
  return s;
}

void GpuAccumulator::setPattern(const std::vector<core::PatternLayer>& layers, std::uint64_t seed,
                                WhenEscaping whenEscaping) {
  // Copies (LayerTransform::copies) share their layer's kind and attractor: the layers as given say it.
  const std::string unsupported = gpuUnsupportedReason(layers);
  std::vector<core::PreparedLayer> prepared;
  std::string problem = unsupported;
  if (unsupported.empty()) {
    prepared = core::prepareLayers(layers, *mask_, insideBox_, seed, deepSeeds_.load());
    problem = core::escapeProblem(prepared);
  }
  const auto anyBounded = [](const std::vector<core::PreparedLayer>& set) {
    return std::any_of(set.begin(), set.end(), [](const core::PreparedLayer& l) { return l.bounded; });
  };
  std::vector<LayerUniforms> uniforms;
  for (const core::PreparedLayer& layer : prepared) {
    LayerUniforms u;
    u.chaos = layer.game != nullptr;
    u.runs = layer.bounded && layer.layer.weight > 0.0 && (u.chaos || !layer.seeds.empty());
    if (u.chaos)
      u.kernel = makeFlameKernel(layer.layer, *layer.game, groupChoice_.load());
    else
      u.system = systemDefine(layer.layer.attractor);
    u.rk4 = layer.layer.integrator == core::Integrator::RK4;
    for (double v : layer.layer.params) u.params.push_back(static_cast<float>(v));
    u.step = static_cast<float>(layer.layer.step);
    const glm::dvec3 axisScale = layer.fit.axisScale * layer.fit.scale;
    const glm::dmat3 m =
        layer.fit.rotation * glm::dmat3(glm::dvec3(axisScale.x, 0.0, 0.0), glm::dvec3(0.0, axisScale.y, 0.0),
                                        glm::dvec3(0.0, 0.0, axisScale.z));
    u.toGrid = glm::mat3(m);
    u.offset = glm::vec3(layer.fit.gridCenter - m * layer.fit.attractorCenter);
    u.escapeRadius = static_cast<float>(std::min(layer.escapeRadius, 1e30));
    const bool flow = layer.info && layer.info->kind == core::AttractorKind::Flow;
    u.alongStep = flow ? 1.0f : 0.0f;
    u.hair = flow ? 1e-5f : 1e-7f;  // as the CPU's orbits start (core's accumulator.cpp says why)
    const core::ColorSettings& color = layer.layer.color;
    double scale = color.scale;
    switch (color.mode) {
      case core::ColorMode::Speed:
        u.colorMode = 0, scale /= layer.speedReference;
        break;
      case core::ColorMode::Curvature:
        u.colorMode = 1, scale /= layer.curvatureReference;
        break;
      case core::ColorMode::Time:
        u.colorMode = 2;
        break;
      case core::ColorMode::Axis:
        u.colorMode = 3, scale /= (layer.axisHigh - layer.axisLow);
        break;
      case core::ColorMode::Distance:
        u.colorMode = 4, scale /= layer.distanceReference;
        break;
      case core::ColorMode::Index:
        // flam3's lookup takes entry ⌊256 c⌋, as the CPU's kernel does (accumulator.cpp says why).
        u.colorMode = 5, scale *= 256.0 / 255.0;
        break;
    }
    u.colorScale = static_cast<float>(scale);
    u.inversePeriod = static_cast<float>(1.0 / color.period);
    u.axis = glm::vec3(glm::normalize(color.axis));
    u.axisOffset = static_cast<float>(layer.axisLow);
    u.center = glm::vec3(layer.center);
    for (std::size_t c = 0; c < 256 && c < layer.palette.size(); ++c) u.palette[c] = packRgb(layer.palette[c]);
    for (const glm::dvec3& s : layer.seeds) u.seeds.emplace_back(glm::vec3(s), 0.0f);
    uniforms.push_back(std::move(u));
  }
  double maxWeight = 0.0;
  for (const core::PreparedLayer& l : prepared) maxWeight = std::max(maxWeight, l.layer.weight);
  for (std::size_t i = 0; i < prepared.size(); ++i)
    uniforms[i].stepShare =
        std::max(1, static_cast<int>(std::lround(stepsPerDispatch_ *
                                                 (maxWeight > 0.0 ? prepared[i].layer.weight / maxWeight : 0.0))));

  bool keepLastBounded = false;
  {
    std::lock_guard lock(mutex_);
    keepLastBounded = whenEscaping == WhenEscaping::KeepLastBounded && unsupported.empty() && !anyBounded(prepared) &&
                      anyBounded(layers_) && points_.load() > 0;
    // Kept: the grid and its counts stay the last bounded pattern's, and only the refinement
    // stops. Otherwise nothing runs until the device has the new layers and an empty grid.
    problem_ = problem;
    showingLastBounded_ = keepLastBounded;
    active_ = false;
  }
  if (keepLastBounded) {
    notifyWorkChanged();
    return;
  }
  runOnDevice(
      [&](Device& device) {
        for (auto* list : {&device.orbits, &device.seeds, &device.palettes, &device.flameData, &device.flamePicks,
                           &device.laneMemory})
          if (!list->empty()) {
            glDeleteBuffers(static_cast<GLsizei>(list->size()), list->data());
            list->clear();
          }
        device.layers = std::move(uniforms);
        for (LayerUniforms& u : device.layers) {
          device.orbits.push_back(
              makeBuffer(kOrbitsBinding, std::size_t{orbits_} * (u.chaos ? kChaosOrbitBytes : kOrbitBytes)));
          device.seeds.push_back(makeBuffer(kSeedsBinding, u.seeds.size() * sizeof(glm::vec4), u.seeds.data()));
          device.palettes.push_back(makeBuffer(kPaletteBinding, sizeof(u.palette), u.palette.data()));
          device.flameData.push_back(
              makeBuffer(kFlameDataBinding, u.kernel.data.size() * sizeof(float), u.kernel.data.data()));
          device.flamePicks.push_back(
              makeBuffer(kFlamePickBinding, u.kernel.pick.size() * sizeof(std::uint32_t), u.kernel.pick.data()));
          // All ones: every orbit reads as unseeded (state.y) and seeds itself at its first step.
          fillBuffer(device.orbits.back(), 0xFFFFFFFFu);
          device.laneMemory.push_back(
              makeBuffer(kLaneMemoryBinding, std::size_t{orbits_} * u.kernel.laneMemory * sizeof(double)));
          fillBuffer(device.laneMemory.back(), 0);  // Fractorium's and the CPU's memory starts at 0
          if (u.runs) u.program = &device.layerProgram(u);
        }
        clearGrid(device);
        if (glGetError() != GL_NO_ERROR) throw core::Error("the GPU backend could not set up the pattern's buffers");
        std::lock_guard lock(mutex_);
        layers_ = std::move(prepared);
        seed_ = seed;
        chunk_ = 0;
        orbitsFresh_ = true;
        pointsPerStep_ = 0.0;
        iterations_ = 0;
        points_ = 0;
        chunkPoints_ = 0;
        outside_ = 0;
        escapes_ = 0;
        generationStart_ = nowSeconds();
        active_ = anyBounded(layers_) && unsupported.empty();
        generation_.fetch_add(1, std::memory_order_acq_rel);
        version_.fetch_add(1, std::memory_order_acq_rel);
      },
      /*changesGrid=*/true);
  notifyWorkChanged();
}

void GpuAccumulator::clearGrid(Device& device) const {
  const core::GridGeometry& g = mask_->geometry;
  const ShaderProgram& clear = device.program("accumulate_grid.comp.glsl", "#define CLEAR_GRID\n", false);
  glUseProgram(clear.id());
  device.bindGrid();
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kMaskBinding, device.mask);
  const auto voxels = static_cast<GLuint>(g.voxelCount());
  const auto cells = static_cast<GLuint>(colour_.cellCount());
  glUniform1ui(clear.uniform("uCount"), voxels);
  glUniform1ui(clear.uniform("uCellCount"), cells);
  glDispatchCompute((std::max(voxels, cells) + 255u) / 256u, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
}

void GpuAccumulator::setChunk(std::uint64_t chunk, bool clearGrid) {
  runOnDevice(
      [&](Device& device) {
        for (GLuint orbits : device.orbits) fillBuffer(orbits, 0xFFFFFFFFu);
        for (GLuint memory : device.laneMemory) fillBuffer(memory, 0);  // fresh orbits remember nothing
        if (clearGrid) this->clearGrid(device);
        std::lock_guard lock(mutex_);
        chunk_ = chunk;
        orbitsFresh_ = true;
        pointsPerStep_ = 0.0;
        chunkPoints_ = 0;
        if (clearGrid) {
          iterations_ = 0;
          points_ = 0;
          outside_ = 0;
          escapes_ = 0;
          generationStart_ = nowSeconds();
          generation_.fetch_add(1, std::memory_order_acq_rel);
        }
        version_.fetch_add(1, std::memory_order_acq_rel);
      },
      /*changesGrid=*/true);
  notifyWorkChanged();
}

void GpuAccumulator::dispatchRound(Device& device) {
  std::uint64_t seed = 0, chunk = 0;
  bool fresh = false;
  double pointsPerStep = 0.0;
  {
    std::lock_guard lock(mutex_);
    seed = seed_;
    chunk = chunk_;
    fresh = orbitsFresh_;
    pointsPerStep = pointsPerStep_;
  }
  // The last round a target needs is cut short in proportion (as the CPU cuts its last batch), so
  // a still's chunk overshoots its share by little. The cut follows from the counts alone.
  double stepFraction = 1.0;
  const std::uint64_t target = targetPoints_.load(), done = chunkPoints_.load();
  if (target > 0 && target > done) {
    const auto remaining = static_cast<double>(target - done);
    const double perRound = pointsPerStep * stepsPerDispatch_;
    stepFraction = !fresh && perRound > 0.0
                       ? 1.1 * remaining / perRound
                       : (kTransientSteps + 1.1 * remaining / static_cast<double>(orbits_) + 1.0) / stepsPerDispatch_;
    stepFraction = std::clamp(stepFraction, 1.0 / stepsPerDispatch_, 1.0);
  }
  fillBuffer(device.counters, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kCountersBinding, device.counters);
  device.bindGrid();
  std::uint64_t iterations = 0;
  int roundSteps = 0;
  for (std::size_t li = 0; li < device.layers.size(); ++li) {
    const LayerUniforms& u = device.layers[li];
    if (!u.runs) continue;
    const int steps = std::max(1, static_cast<int>(std::ceil(u.stepShare * stepFraction)));
    roundSteps = std::max(roundSteps, steps);
    const ShaderProgram& program = *u.program;
    const GLuint id = program.id();
    glUseProgram(id);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kOrbitsBinding, device.orbits[li]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSeedsBinding, device.seeds[li]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kPaletteBinding, device.palettes[li]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFlameDataBinding, device.flameData[li]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kFlamePickBinding, device.flamePicks[li]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kLaneMemoryBinding, device.laneMemory[li]);
    if (!u.chaos) {
      std::array<float, 32> params{};
      std::copy(u.params.begin(), u.params.end(), params.begin());
      glUniform1fv(program.uniform("uParams"), 32, params.data());
    }
    glUniform1f(program.uniform("uIndexDither"), linearPalette_.load() ? 1.0f : 0.0f);
    glUniform1ui(program.uniform("uOrbitCount"), orbits_);
    glUniform1i(program.uniform("uSteps"), steps);
    glUniform1f(program.uniform("uStep"), u.step);
    const std::uint64_t streamSeed = core::mixSeed(core::mixSeed(seed, chunk), li);
    glUniform1ui(program.uniform("uStreamSeed"), static_cast<GLuint>(streamSeed ^ (streamSeed >> 32)));
    glUniform1ui(program.uniform("uSeedCount"), static_cast<GLuint>(u.seeds.size()));
    glUniform1f(program.uniform("uHair"), u.hair);
    glUniformMatrix3fv(program.uniform("uToGrid"), 1, GL_FALSE, &u.toGrid[0][0]);
    glUniform3fv(program.uniform("uGridOffset"), 1, &u.offset[0]);
    const glm::ivec3 size = mask_->geometry.size;
    glUniform3i(program.uniform("uGridSize"), size.x, size.y, size.z);
    glUniform1i(program.uniform("uColourShift"), colour_.shift);
    glUniform2i(program.uniform("uCellStrides"), colour_.size.x, colour_.size.x * colour_.size.y);
    glUniform1f(program.uniform("uEscapeRadius"), u.escapeRadius);
    glUniform1f(program.uniform("uAlongStep"), u.alongStep);
    glUniform1i(program.uniform("uColorMode"), u.colorMode);
    glUniform1f(program.uniform("uColorScale"), u.colorScale);
    glUniform1f(program.uniform("uInversePeriod"), u.inversePeriod);
    glUniform3fv(program.uniform("uAxis"), 1, &u.axis[0]);
    glUniform1f(program.uniform("uAxisOffset"), u.axisOffset);
    glUniform3fv(program.uniform("uCenter"), 1, &u.center[0]);
    glUniform1i(program.uniform("uJittered"), deposit_.load() == core::Deposit::Jittered ? 1 : 0);
    if (device.projection) setProjectionUniforms(device, program);
    const GLuint workgroup = u.kernel.groupChoice ? 256u : 64u;  // accumulate.comp.glsl's local size
    glDispatchCompute((orbits_ + workgroup - 1u) / workgroup, 1, 1);
    iterations += std::uint64_t{orbits_} * static_cast<std::uint64_t>(steps);
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  std::array<std::uint32_t, 4> counts{};
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, device.counters);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(counts), counts.data());  // waits for the round
  {
    std::lock_guard lock(mutex_);
    // What a step of every layer yields now, past the transient (fresh orbits spent it first).
    const int productive = roundSteps - (fresh ? kTransientSteps : 0);
    pointsPerStep_ = productive > 0 ? static_cast<double>(counts[0]) / productive : pointsPerStep_;
    orbitsFresh_ = false;
  }
  iterations_.fetch_add(iterations, std::memory_order_relaxed);
  points_.fetch_add(counts[0], std::memory_order_relaxed);
  chunkPoints_.fetch_add(counts[0], std::memory_order_relaxed);
  outside_.fetch_add(counts[1], std::memory_order_relaxed);
  escapes_.fetch_add(counts[2], std::memory_order_relaxed);
  version_.fetch_add(1, std::memory_order_release);
  {
    std::lock_guard lock(mutex_);
    doneSignal_.notify_all();
  }
  progress_.notify();
}

void GpuAccumulator::setProjectionUniforms(const Device& device, const ShaderProgram& program) const {
  const Device::Projection& projection = *device.projection;
  const core::PointProjection& p = projection.p;
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kScreenBinding, device.screen);
  glActiveTexture(GL_TEXTURE0 + kViewTransmittanceUnit);
  glBindTexture(GL_TEXTURE_3D, device.viewTransmittance);
  glActiveTexture(GL_TEXTURE0 + kLightTransmittanceUnit);
  glBindTexture(GL_TEXTURE_3D, device.lightTransmittance);
  glActiveTexture(GL_TEXTURE0);
  glUniform1i(program.uniform("uViewTransmittance"), kViewTransmittanceUnit);
  glUniform1i(program.uniform("uLightTransmittance"), kLightTransmittanceUnit);
  const glm::mat4 view(p.camera.view), projectionMatrix(p.camera.projection);
  glUniformMatrix4fv(program.uniform("uView"), 1, GL_FALSE, &view[0][0]);
  glUniformMatrix4fv(program.uniform("uProjection"), 1, GL_FALSE, &projectionMatrix[0][0]);
  const glm::vec3 origin(p.grid.origin);
  glUniform3fv(program.uniform("uOrigin"), 1, &origin[0]);
  glUniform1f(program.uniform("uVoxelSize"), static_cast<float>(p.grid.voxelSize));
  glUniform1i(program.uniform("uOrthographic"), p.camera.orthographic ? 1 : 0);
  glUniform1f(program.uniform("uNearPlane"), static_cast<float>(p.camera.nearPlane));
  glUniform2i(program.uniform("uScreenSize"), p.width, p.height);
  glUniform1f(program.uniform("uPointCounts"),
              static_cast<float>(projection.scale.pointDensity / projection.scale.unit));
  glUniform1f(program.uniform("uAperture"), static_cast<float>(p.dofAperture));
  glUniform1f(program.uniform("uFocus"), static_cast<float>(std::max(p.dofFocusDepth, 1e-9)));
  glUniform1f(program.uniform("uFogPerDepth"), static_cast<float>(projection.scale.fogPerDepth));
  glUniform1f(program.uniform("uFogStart"), static_cast<float>(p.fogStart));
  glUniform1i(program.uniform("uDimmed"), projection.dimmed ? 1 : 0);
  glUniform3i(program.uniform("uViewCells"), projection.viewCells.x, projection.viewCells.y, projection.viewCells.z);
  glUniform1f(program.uniform("uViewNear"), projection.viewNear);
  glUniform1f(program.uniform("uViewDepthScale"), projection.viewDepthScale);
  glUniform1i(program.uniform("uLit"), projection.lit ? 1 : 0);
  glUniform3i(program.uniform("uShadowSize"), projection.shadowSize.x, projection.shadowSize.y,
              projection.shadowSize.z);
  glUniform1f(program.uniform("uShadowToCell"), 1.0f / static_cast<float>(std::max(1, p.shadowDownsample)));
  glUniform1f(program.uniform("uLightStrength"), static_cast<float>(p.lightStrength));
}

void GpuAccumulator::projectPoints(const core::PointProjection& projection) {
  if (projection.width <= 0 || projection.height <= 0) throw core::Error("the points image must have a positive size");
  runOnDevice(
      [&](Device& device) {
        Device::Projection made;
        made.p = projection;
        made.p.transmittance = nullptr;
        made.p.shadow = nullptr;
        made.scale = core::pointScale(projection);
        const std::size_t bytes = 4 * sizeof(std::uint32_t) * static_cast<std::size_t>(projection.width) *
                                  static_cast<std::size_t>(projection.height);
        GLint maxBlock = 0;
        glGetIntegerv(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBlock);
        if (bytes > static_cast<std::size_t>(static_cast<GLuint>(maxBlock)))
          throw core::Error("the points image of " + std::to_string(projection.width) + "×" +
                            std::to_string(projection.height) + " supersampled pixels needs " +
                            std::to_string(bytes >> 20) + " MiB of sums, more than this GPU binds at once (" +
                            std::to_string(static_cast<GLuint>(maxBlock) >> 20) +
                            " MiB); render it smaller, with less oversampling, or on the CPU (--backend cpu)");
        if (device.screen) glDeleteBuffers(1, &device.screen);
        device.screen = makeBuffer(kScreenBinding, bytes);
        fillBuffer(device.screen, 0);
        const auto texture = [](GLuint& name, GLint format, GLenum type, glm::ivec3 size, const void* values) {
          if (!name) glGenTextures(1, &name);
          glBindTexture(GL_TEXTURE_3D, name);
          glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
          glTexImage3D(GL_TEXTURE_3D, 0, format, size.x, size.y, size.z, 0, GL_RED, type, values);
          glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
          glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
          glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 0);
          glBindTexture(GL_TEXTURE_3D, 0);
        };
        // An unused one gets a texel, so that every sampler names a complete texture.
        const float clear = 1.0f;
        const std::uint8_t lit = 255;
        if (const core::ViewTransmittance* t = projection.transmittance; t && !t->values.empty()) {
          made.dimmed = true;
          made.viewCells = {t->width, t->height, t->depth};
          made.viewNear = static_cast<float>(t->nearDepth);
          made.viewDepthScale = t->depthScale;
          texture(device.viewTransmittance, GL_R32F, GL_FLOAT, {t->depth + 1, t->width, t->height}, t->values.data());
        } else {
          texture(device.viewTransmittance, GL_R32F, GL_FLOAT, {1, 1, 1}, &clear);
        }
        if (const core::ShadowVolume* shadow = projection.shadow; shadow && !shadow->transmittance.empty()) {
          made.lit = true;
          made.shadowSize = shadow->size;
          texture(device.lightTransmittance, GL_R8, GL_UNSIGNED_BYTE, shadow->size, shadow->transmittance.data());
        } else {
          texture(device.lightTransmittance, GL_R8, GL_UNSIGNED_BYTE, {1, 1, 1}, &lit);
        }
        device.projection = made;
        // The layers' programs project from now on.
        for (LayerUniforms& u : device.layers)
          if (u.runs) u.program = &device.layerProgram(u);
      },
      true);
}

core::ImageSums GpuAccumulator::takeScreenSums() {
  core::ImageSums sums;
  runOnDevice([&](Device& device) {
    if (!device.projection) throw core::Error("this GPU backend projects no points");
    const core::PointProjection& p = device.projection->p;
    sums.reset(p.width, p.height, device.projection->scale.unit);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, device.screen);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(sums.counts.size() * sizeof(std::uint32_t)),
                       sums.counts.data());
    fillBuffer(device.screen, 0);
  });
  return sums;
}

namespace {

// The points method's backend on the GPU: a GpuAccumulator that projects its points.
class GpuProjectingBackend final : public core::ProjectingBackend {
 public:
  GpuProjectingBackend(std::shared_ptr<const core::InsideMask> mask, const core::PointProjection& projection)
      : backend_(std::move(mask)) {
    backend_.projectPoints(projection);
  }
  core::RefinementBackend& backend() override { return backend_; }
  core::ImageSums takeSums() override { return backend_.takeScreenSums(); }

 private:
  GpuAccumulator backend_;
};

}  // namespace

std::unique_ptr<core::ProjectingBackend> makeGpuProjectingBackend(std::shared_ptr<const core::InsideMask> mask,
                                                                  const core::PointProjection& projection) {
  return std::make_unique<GpuProjectingBackend>(std::move(mask), projection);
}

void GpuAccumulator::readSlabsImpl(core::GridReading& reading, void (*visit)(const core::GridSlabView&, void*),
                                   void* context) const {
  const core::GridGeometry& g = mask_->geometry;
  std::lock_guard hostLock(hostMutex_);
  runOnDevice([&](Device& device) {
    // Read under the device's order: what the reading says is what the copy holds.
    reading.geometry = g;
    reading.colour = colour_;
    reading.version = version_.load();
    reading.generation = generation_.load();
    reading.points = points_.load();
    reading.insideVoxels = insideVoxels_;
    reading.gridId = gridId_;
    hostCells_.resize(colour_.cellCount());
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, device.cells);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0,
                       static_cast<GLsizeiptr>(hostCells_.size() * sizeof(core::detail::ColourCell)),
                       hostCells_.data());
    if (device.hits) {
      hostHits_.resize(g.voxelCount());
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, device.hits);
      glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(hostHits_.size() * sizeof(std::uint32_t)),
                         hostHits_.data());
    }
  });
  core::GridSlabView slab;
  slab.firstZ = 0;
  slab.endZ = g.size.z;
  slab.hits = colour_.shift == 0 ? &hostCells_.front().count : hostHits_.data();
  slab.hitsStride = colour_.shift == 0 ? 4 : 1;
  slab.firstColourZ = 0;
  slab.endColourZ = colour_.size.z;
  slab.colours = hostCells_.data();
  slab.empty = false;
  slab.rowInside = rowInside_.data();
  visit(slab, context);
}

void GpuAccumulator::sampleDensity(core::DensitySample& out) const {
  const std::size_t voxels = mask_->geometry.voxelCount();
  const std::size_t stride = core::convergenceSampleStride(voxels);
  const std::size_t count = (voxels + stride - 1) / stride;
  out.hits.resize(count);
  runOnDevice([&](Device& device) {
    out.generation = generation_.load();
    out.points = points_.load();
    const ShaderProgram& sample = device.program("accumulate_grid.comp.glsl", "#define SAMPLE_DENSITY\n", false);
    glUseProgram(sample.id());
    device.bindGrid();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kSampleBinding, device.sample);
    glUniform1ui(sample.uniform("uCount"), static_cast<GLuint>(count));
    glUniform1ui(sample.uniform("uStride"), static_cast<GLuint>(stride));
    glDispatchCompute(static_cast<GLuint>((count + 255) / 256), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, device.sample);
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(count * sizeof(std::uint32_t)),
                       out.hits.data());
  });
}

bool GpuAccumulator::packOnDevice(core::PackedVolume& out) const {
  if (!packsOnDevice()) return false;
  // The volume this buffer held goes back to the pool first, so the pack can reuse its textures.
  out.device.reset();
  const core::GridGeometry& g = mask_->geometry;
  const glm::ivec3 bricks = (g.size + (core::kBrickSize - 1)) / core::kBrickSize;
  const std::size_t brickCount = static_cast<std::size_t>(bricks.x) * bricks.y * bricks.z;
  runOnDevice([&](Device& device) {
    out.geometry = g;
    out.colour = colour_;
    out.brickCount = bricks;
    out.version = version_.load();
    out.generation = generation_.load();
    out.points = points_.load();
    // Texels hold density relative to the mesh's mean, as core::packVolume's do.
    const double inside = static_cast<double>(std::max<std::uint64_t>(insideVoxels_, 1));
    out.referenceDensity = out.points > 0 ? static_cast<double>(out.points) / inside : 1.0;
    out.insideVoxels = inside;
    out.texelDensity = static_cast<float>(out.referenceDensity);
    const float inverseScale = 1.0f / out.texelDensity;

    GpuVolume& volume = device.freeVolume(g.size, colour_.size, bricks);
    {
      std::lock_guard lock(volume.mutex);
      // The renderer's last copy of these textures must be done before they are written again.
      if (volume.copied) {
        glWaitSync(volume.copied, 0, GL_TIMEOUT_IGNORED);
        glDeleteSync(std::exchange(volume.copied, nullptr));
      }
      if (volume.packed) glDeleteSync(std::exchange(volume.packed, nullptr));
    }
    for (GLuint& buffer : device.distance) {
      if (!buffer) glGenBuffers(1, &buffer);
      glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer);
      GLint64 bytes = 0;
      glGetBufferParameteri64v(GL_SHADER_STORAGE_BUFFER, GL_BUFFER_SIZE, &bytes);
      if (static_cast<std::size_t>(bytes) != brickCount * sizeof(GLuint))
        glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(brickCount * sizeof(GLuint)), nullptr,
                     GL_DYNAMIC_COPY);
    }
    fillBuffer(device.distance[0], core::kMaxEmptyDistance);

    auto bindPass = [&](const char* define) -> const ShaderProgram& {
      const ShaderProgram& program = device.program("pack_volume.comp.glsl", define, false);
      glUseProgram(program.id());
      glUniform3i(program.uniform("uSize"), g.size.x, g.size.y, g.size.z);
      glUniform3i(program.uniform("uColourSize"), colour_.size.x, colour_.size.y, colour_.size.z);
      glUniform1i(program.uniform("uColourShift"), colour_.shift);
      glUniform3i(program.uniform("uBricks"), bricks.x, bricks.y, bricks.z);
      glUniform1f(program.uniform("uInverseScale"), inverseScale);
      return program;
    };
    auto groups = [](std::size_t invocations) { return static_cast<GLuint>((invocations + 255) / 256); };
    device.bindGrid();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDistanceInBinding, device.distance[0]);
    glBindImageTexture(0, volume.density, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R16F);
    glBindImageTexture(1, volume.colour, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RGBA16F);
    glBindImageTexture(2, volume.emptyDistance, 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R8UI);
    bindPass("#define PACK_VOXELS\n");
    glDispatchCompute(groups(g.voxelCount()), 1, 1);
    bindPass("#define PACK_CELLS\n");
    glDispatchCompute(groups(colour_.cellCount()), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    const ShaderProgram& distance = bindPass("#define EMPTY_DISTANCE\n");
    for (int axis = 0; axis < 3; ++axis) {
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDistanceInBinding, device.distance[axis % 2]);
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, kDistanceOutBinding, device.distance[(axis + 1) % 2]);
      glUniform1i(distance.uniform("uAxis"), axis);
      glUniform1i(distance.uniform("uLastAxis"), axis == 2 ? 1 : 0);
      glDispatchCompute(groups(brickCount), 1, 1);
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    // Image stores are made visible to the renderer's copy by the barrier, then the sync it waits on.
    glMemoryBarrier(GL_ALL_BARRIER_BITS);
    {
      std::lock_guard lock(volume.mutex);
      volume.packed = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    }
    glFlush();  // the renderer's context waits on the sync: its commands must reach the device
    if (glGetError() != GL_NO_ERROR) throw core::Error("the GPU backend could not pack its grid for the renderer");
    for (const std::shared_ptr<GpuVolume>& held : device.volumes)
      if (held.get() == &volume) out.device = held;
  });
  out.packedFromGrid = 0;  // the host buffers hold nothing of it
  out.density.clear();
  out.colours.clear();
  out.occupancy.clear();
  out.emptyDistance.clear();
  out.maxDensity = 0.0f;
  out.meanDensity = 0.0f;
  return true;
}

void GpuAccumulator::snapshot(core::VolumeSnapshot& out) const {
  const core::GridSums sums = core::readGridSums(*this, stats());
  core::snapshotFromSums(sums, out);
  out.generation = generation_.load();
  out.version = version_.load();
}

}  // namespace voxflame::gl
