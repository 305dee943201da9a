// The accumulator's memory layout: hit counts per voxel, colour sums per colour cell (2×2×2 voxels
// above 256³), colour that stays right however many points a voxel gets, packing straight from the
// grid, and a snapshot thread that cycles two packed volumes instead of allocating more.
#include <gtest/gtest.h>

#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <memory>
#include <thread>
#include <vector>

#include "core/refinement/accumulator.h"
#include "core/attractor.h"
#include "core/color.h"
#include "core/inside_mask.h"
#include "core/packed_volume.h"
#include "core/scene_io.h"
#include "core/refinement/snapshot_publisher.h"
#include "wait_for.h"

using namespace voxflame::core;
using voxflame::test::waitFor;

namespace {

std::shared_ptr<const InsideMask> fullMask(glm::ivec3 size) {
  auto mask = std::make_shared<InsideMask>();
  mask->geometry.size = size;
  mask->inside.assign(mask->geometry.voxelCount(), 1);
  return mask;
}

// x' = -x, y' = -y, z' = -z (Sprott's quadratic map reduced): every orbit alternates between two
// points, which a locked fit puts at gridCenter ± (1, 1, 1) voxels.
PatternLayer twoPointLayer(const InsideMask& mask, glm::dvec3 gridCenter, glm::vec3 colour) {
  const AttractorInfo& info = attractorOrThrow("sprott_quadratic");
  PatternLayer layer;
  layer.attractor = info.id;
  layer.step = info.defaultStep;
  layer.integrator = info.defaultIntegrator;
  layer.params.assign(30, 0.0);
  layer.params[1] = layer.params[15] = layer.params[28] = -1.0;
  layer.transform.lockFit = true;
  layer.transform.lockedCenter = glm::dvec3(0.0);
  layer.transform.lockedScale = 10.0;
  const glm::dvec3 size(mask.geometry.size);
  layer.transform.offset = (gridCenter - 0.5 * size) / std::max({size.x, size.y, size.z});
  layer.color.palette.clear();
  layer.color.gradient = {GradientStop{0.0f, colour}, GradientStop{1.0f, colour}};
  return layer;
}

struct Accumulated {
  VolumeSnapshot snapshot;
  PackedVolume packed;
};

Accumulated accumulate(const std::shared_ptr<const InsideMask>& mask, const std::vector<PatternLayer>& layers,
                       std::uint64_t points, int threads) {
  Accumulator accumulator(mask, threads);
  accumulator.setTargetPoints(points);
  accumulator.setPattern(layers, 3);
  EXPECT_TRUE(accumulator.waitUntilDone(120.0));
  Accumulated result;
  accumulator.snapshot(result.snapshot);
  packVolume(accumulator, result.packed);
  return result;
}

}  // namespace

TEST(ColourLayout, CellsSpanTwoVoxelsOnlyAbove256Cubed) {
  GridGeometry grid;
  grid.size = {256, 256, 256};
  EXPECT_EQ(ColourLayout::of(grid).shift, 0);
  EXPECT_EQ(ColourLayout::of(grid).size, grid.size);
  grid.size = {257, 256, 256};
  const ColourLayout coarse = ColourLayout::of(grid);
  EXPECT_EQ(coarse.shift, 1);
  EXPECT_EQ(coarse.size, glm::ivec3(129, 128, 128));
  // 512³: 4 bytes of hits a voxel and 16 per 8 voxels, a third of the 16 bytes a voxel it was.
  grid.size = glm::ivec3(512);
  EXPECT_LE(accumulatorBytes(grid), 6 * grid.voxelCount() + (1u << 20));
  // Packed: a half float of density a voxel, 8 bytes of colour per 8 voxels, and per brick of 4³
  // voxels its occupancy and empty distance.
  EXPECT_LE(packedVolumeBytes(grid), 3 * grid.voxelCount() + grid.voxelCount() / 32);
}

// 2^24 points of a colour fill a voxel's colour count; more must neither overflow the sums (255 ×
// 2^24 is past 2^32) nor change the mean. Two voxels get half of 40 million points each.
TEST(GridLayout, AVoxelKeepsItsColourPastTwoToThe24Points) {
  const auto mask = fullMask(glm::ivec3(6));
  const glm::vec3 colour(0.9f, 0.35f, 0.7f);
  const Accumulated few = accumulate(mask, {twoPointLayer(*mask, {3.5, 3.5, 3.5}, colour)}, 100'000, 2);
  const Accumulated many = accumulate(mask, {twoPointLayer(*mask, {3.5, 3.5, 3.5}, colour)}, 40'000'000, 2);
  const GridGeometry& g = many.snapshot.geometry;
  for (const std::size_t v : {g.index(4, 4, 4), g.index(2, 2, 2)}) {
    ASSERT_GT(many.snapshot.density[v], 17'000'000.0f);
    for (int c = 0; c < 3; ++c) {
      EXPECT_EQ(many.snapshot.rgba[4 * v + c], few.snapshot.rgba[4 * v + c]) << "channel " << c;
      const float packed = halfToFloat(many.packed.colours[4 * v + c]) / halfToFloat(many.packed.colours[4 * v + 3]);
      EXPECT_NEAR(packed * 255.0f, static_cast<float>(few.snapshot.rgba[4 * v + c]), 0.6f) << "channel " << c;
    }
  }
}

// Above 256³ colour cells span 2×2×2 voxels: the grid is still the same for a seed on any number
// of threads, the density keeps every voxel, and packing straight from the accumulator agrees
// with packing its snapshot.
TEST(GridLayout, ACoarseColourGridIsDeterministicAndPacksLikeItsSnapshot) {
  const auto mask = fullMask(glm::ivec3(258));
  ASSERT_EQ(ColourLayout::of(mask->geometry).shift, 1);
  const std::vector<PatternLayer> layers = defaultScene().layers;
  const Accumulated one = accumulate(mask, layers, 2'000'000, 1);
  const Accumulated two = accumulate(mask, layers, 2'000'000, 2);
  EXPECT_TRUE(one.snapshot.density == two.snapshot.density);
  EXPECT_TRUE(one.snapshot.rgba == two.snapshot.rgba);
  EXPECT_TRUE(one.packed.density == two.packed.density);
  EXPECT_TRUE(one.packed.colours == two.packed.colours);

  const GridGeometry& g = one.snapshot.geometry;
  const PackedVolume& packed = one.packed;
  ASSERT_EQ(packed.colour.shift, 1);
  ASSERT_EQ(packed.colours.size(), 4 * static_cast<std::size_t>(129 * 129 * 129));
  PackedVolume fromSnapshot;
  packVolume(one.snapshot, fromSnapshot);
  EXPECT_DOUBLE_EQ(packed.referenceDensity, fromSnapshot.referenceDensity);
  EXPECT_TRUE(packed.density == fromSnapshot.density);
  EXPECT_TRUE(packed.occupancy == fromSnapshot.occupancy);
  std::size_t checked = 0;
  for (int k = 0; k < g.size.z; k += 3)
    for (int j = 0; j < g.size.y; j += 3)
      for (int i = 0; i < g.size.x; i += 3) {
        const std::size_t v = g.index(i, j, k);
        if (one.snapshot.density[v] <= 0.0f) continue;
        const std::size_t cell = static_cast<std::size_t>(i / 2) +
                                 129 * (static_cast<std::size_t>(j / 2) + 129 * static_cast<std::size_t>(k / 2));
        const float weight = halfToFloat(packed.colours[4 * cell + 3]);
        ASSERT_GT(weight, 0.0f);
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(halfToFloat(packed.colours[4 * cell + c]) / weight * 255.0f,
                      static_cast<float>(one.snapshot.rgba[4 * v + c]), 1.5f)
              << "voxel " << i << " " << j << " " << k << " channel " << c;
        ++checked;
      }
  EXPECT_GT(checked, 1000u);
}

// The snapshot thread packs into the buffer the taker handed back: two volumes' worth of memory
// cycle between them, never a third.
TEST(SnapshotPublisher, TwoPackedVolumesCycleBetweenThePublisherAndItsTaker) {
  const auto mask = fullMask(glm::ivec3(32));
  Accumulator accumulator(mask, 1);
  accumulator.setPattern(defaultScene().layers, 1);  // refines without end
  EventCounter published;                            // before the publisher, which notifies it until it is joined
  SnapshotPublisher publisher(accumulator, std::chrono::milliseconds(2));
  publisher.setObserver(&published);
  auto takeNext = [&](PackedVolume& out) { return waitFor(published, [&] { return publisher.takeIfNewer(out); }); };
  PackedVolume shown;
  ASSERT_TRUE(takeNext(shown));
  const std::uint16_t* first = shown.density.data();
  ASSERT_TRUE(takeNext(shown));
  const std::uint16_t* second = shown.density.data();
  EXPECT_NE(first, second);
  std::uint64_t version = shown.version;
  for (int round = 0; round < 4; ++round) {
    ASSERT_TRUE(takeNext(shown));
    EXPECT_EQ(shown.density.data(), round % 2 == 0 ? first : second);
    EXPECT_GT(shown.version, version);
    version = shown.version;
  }
}

// A volume packed and not yet taken is not packed over while its pattern refines, so a taker that
// comes once a frame finds it, not a pack in progress; a new pattern's volume replaces it.
TEST(SnapshotPublisher, AFreshVolumeWaitsForItsTakerUntilThePatternChanges) {
  // A pack of a millisecond or more, against a 1 ms interval (and far longer under a sanitizer,
  // where the frames below wait for packs of this size: a larger grid only makes them longer).
  const auto mask = fullMask(glm::ivec3(64));
  Accumulator accumulator(mask, 1);
  accumulator.setPattern(defaultScene().layers, 1);  // refines without end
  EventCounter published;
  SnapshotPublisher publisher(accumulator, std::chrono::milliseconds(1));
  publisher.setObserver(&published);
  PackedVolume volume;
  ASSERT_TRUE(waitFor(published, [&] { return publisher.takeIfNewer(volume); }));
  ASSERT_GT(volume.points, 0u);
  // A taker that comes late (a frame far apart): once a fresh volume is packed, the publisher
  // looks at the newer points that keep landing, twice, and packs nothing over it; the taker then
  // finds that volume. Waited for by the publisher's own looks, not by a guess at how long a pack
  // takes (a sanitizer's are many times longer).
  std::uint64_t taken = publisher.packs();
  for (int frame = 0; frame < 10; ++frame) {
    std::uint64_t fresh = 0, looks = 0;
    ASSERT_TRUE(waitFor(published,
                        [&] {
                          fresh = publisher.packs();
                          looks = publisher.wakeUps();
                          return fresh > taken;
                        }))
        << "frame " << frame << ": no fresh volume";
    const std::uint64_t points = accumulator.version();
    ASSERT_TRUE(waitFor(published, [&] { return publisher.wakeUps() >= looks + 2 && accumulator.version() > points; }));
    EXPECT_EQ(publisher.packs(), fresh) << "frame " << frame << ": a fresh volume was packed over";
    const std::uint64_t before = volume.version;
    // The taker finds the lock free (the publisher only checks the volume under it, briefly).
    ASSERT_TRUE(waitFor(published, [&] { return publisher.takeIfNewer(volume); })) << "frame " << frame;
    EXPECT_GT(volume.version, before);
    taken = fresh;
  }
  // A fresh volume of pattern 1 waits for its taker; the new pattern's replaces it.
  ASSERT_TRUE(waitFor(published, [&] { return publisher.packs() > taken; }));
  accumulator.setPattern(defaultScene().layers, 2);
  EXPECT_TRUE(waitFor(published, [&] {
    return publisher.takeIfNewer(volume) && volume.generation == accumulator.generation();
  })) << "the new pattern's volume replaces the waiting one";
}

// A 40³ grid inside everywhere, and one inside only in its lower half, both filled alike.
struct TwoGrids {
  std::shared_ptr<const InsideMask> full = fullMask(glm::ivec3(40));
  std::shared_ptr<const InsideMask> lowerHalf = lowerHalfOf(*full);
  Accumulator everywhere{full, 2}, below{lowerHalf, 2};
  static std::shared_ptr<const InsideMask> lowerHalfOf(const InsideMask& mask) {
    auto half = std::make_shared<InsideMask>(mask);
    for (int k = mask.geometry.size.z / 2; k < mask.geometry.size.z; ++k)
      for (int j = 0; j < mask.geometry.size.y; ++j)
        for (int i = 0; i < mask.geometry.size.x; ++i) half->inside[half->geometry.index(i, j, k)] = 0;
    return half;
  }
  bool fill() {
    for (Accumulator* accumulator : {&everywhere, &below}) {
      accumulator->setTargetPoints(300'000);
      accumulator->setPattern(defaultScene().layers, 2);
      if (!accumulator->waitUntilDone(60.0)) return false;
    }
    return true;
  }
};

// A recycled buffer skips the rows its grid's mask leaves empty (they hold zeros from the last
// pack); one last packed from another grid of the same size must not keep that grid's density there.
TEST(GridLayout, ARecycledBufferPacksLikeAFreshOne) {
  TwoGrids grids;
  ASSERT_TRUE(grids.fill());
  const InsideMask* full = grids.full.get();
  Accumulator &everywhere = grids.everywhere, &below = grids.below;
  PackedVolume recycled;
  packVolume(everywhere, recycled);
  std::size_t upperDensity = 0;
  for (std::size_t v = full->geometry.index(0, 0, 20); v < recycled.density.size(); ++v)
    upperDensity += recycled.density[v] != 0;
  ASSERT_GT(upperDensity, 100u);  // the full grid has density where the other mask has none
  for (int round = 0; round < 2; ++round) {
    packVolume(below, recycled);  // first from the other grid's pack, then from its own
    PackedVolume fresh;
    packVolume(below, fresh);
    EXPECT_TRUE(recycled.density == fresh.density) << "round " << round;
    EXPECT_TRUE(recycled.colours == fresh.colours) << "round " << round;
    EXPECT_TRUE(recycled.occupancy == fresh.occupancy) << "round " << round;
  }
}

// A cancelled pack says so, and leaves a buffer that the next pack still fills completely: one last
// packed from another grid keeps that grid's density nowhere, one of its own grid skips its empty
// rows as before.
TEST(GridLayout, ACancelledPackIsNotAVolumeAndTheNextPackIsWhole) {
  TwoGrids grids;
  ASSERT_TRUE(grids.fill());
  Accumulator& below = grids.below;
  PackedVolume fresh;
  ASSERT_TRUE(packVolume(below, fresh));
  const std::atomic<bool> cancel{true}, goOn{false};
  for (Accumulator* before : {&grids.everywhere, &below}) {
    PackedVolume recycled;
    ASSERT_TRUE(packVolume(*before, recycled, &goOn));
    EXPECT_FALSE(packVolume(below, recycled, &cancel)) << "a cancelled pack is no volume";
    ASSERT_TRUE(packVolume(below, recycled));
    EXPECT_TRUE(recycled.density == fresh.density);
    EXPECT_TRUE(recycled.colours == fresh.colours);
    EXPECT_EQ(recycled.version, fresh.version);
  }
}

// A volume that would not be shown is not packed: one below the minimum while its grid still
// refines, and none while the publisher is held; a grid that stopped below the minimum still is.
TEST(SnapshotPublisher, PacksNothingBelowTheMinimumWhileRefiningNorWhileHeld) {
  const auto mask = fullMask(glm::ivec3(32));
  Accumulator accumulator(mask, 1);
  accumulator.setTargetPoints(200'000);
  EventCounter looked;
  SnapshotPublisher publisher(accumulator, std::chrono::milliseconds(2));
  publisher.setObserver(&looked);
  publisher.setHeld(true);
  accumulator.setPattern(defaultScene().layers, 1);
  ASSERT_TRUE(accumulator.waitUntilDone(60.0));
  // Asked to look at the finished grid, the held publisher does, and packs nothing.
  const std::uint64_t looksBefore = publisher.wakeUps();
  publisher.requestNow();
  ASSERT_TRUE(waitFor(looked, [&] { return publisher.wakeUps() > looksBefore; }));
  PackedVolume volume;
  EXPECT_FALSE(publisher.takeIfNewer(volume)) << "held";
  EXPECT_EQ(publisher.packs(), 0u) << "held";
  publisher.setMinimumPoints(1'000'000'000);
  publisher.setHeld(false);
  auto take = [&] { return waitFor(looked, [&] { return publisher.takeIfNewer(volume); }); };
  ASSERT_TRUE(take()) << "a grid that stopped below the minimum is packed";
  EXPECT_GE(volume.points, 200'000u);

  accumulator.setTargetPoints(0);  // refine without end, far below the minimum for a long while
  const std::uint64_t packsBefore = publisher.packs();
  accumulator.setPattern(defaultScene().layers, 2);
  // Two looks at the new pattern's points, each of which finds them below the minimum.
  ASSERT_TRUE(waitFor(looked, [&] { return accumulator.stats().points > 0; }));
  const std::uint64_t looksWithPoints = publisher.wakeUps();
  ASSERT_TRUE(waitFor(looked, [&] { return publisher.wakeUps() >= looksWithPoints + 2; }));
  EXPECT_FALSE(publisher.takeIfNewer(volume)) << "a refining grid below the minimum is not packed";
  EXPECT_EQ(publisher.packs(), packsBefore) << "a refining grid below the minimum is not packed";
  publisher.setMinimumPoints(1);
  EXPECT_TRUE(take());
  EXPECT_EQ(volume.generation, accumulator.generation());
}

// An accumulator that rests (its target reached, or held) never wakes its publisher: no timer
// runs. Progress wakes it, a request too.
TEST(SnapshotPublisher, MakesNoWakeUpsWhileItsAccumulatorRests) {
  // Two accumulators, so that one window shows both kinds of rest: one that reached its target,
  // and one held with work left.
  const auto mask = fullMask(glm::ivec3(32));
  Accumulator resting(mask, 2), held(mask, 2);
  EventCounter looked;
  SnapshotPublisher restingPublisher(resting, std::chrono::milliseconds(1)),
      heldPublisher(held, std::chrono::milliseconds(1));
  for (SnapshotPublisher* publisher : {&restingPublisher, &heldPublisher}) publisher->setObserver(&looked);
  for (Accumulator* accumulator : {&resting, &held}) {
    accumulator->setTargetPoints(100'000);
    accumulator->setPattern(defaultScene().layers, 1);
  }
  ASSERT_TRUE(resting.waitUntilDone(60.0));
  ASSERT_TRUE(held.waitUntilDone(60.0));
  PackedVolume volume;
  ASSERT_TRUE(waitFor(looked, [&] {
    restingPublisher.takeIfNewer(volume);
    return restingPublisher.caughtUp();
  }));
  EXPECT_GE(volume.points, 100'000u);
  const std::uint64_t atRest = restingPublisher.wakeUps();
  EXPECT_GT(atRest, 0u);

  // Held with work left (the hold first, so no worker starts a batch for the new target): whatever
  // that stirred up has been looked at once the publisher answers a request made after it (a
  // request wakes it). From then on nothing may wake it.
  held.setHeld(true);
  held.setTargetPoints(0);
  const std::uint64_t beforeRequest = heldPublisher.wakeUps();
  heldPublisher.requestNow();
  ASSERT_TRUE(waitFor(looked, [&] { return heldPublisher.wakeUps() > beforeRequest; })) << "a request wakes it";
  const std::uint64_t whileHeld = heldPublisher.wakeUps();
  // A fixed wait, as this proves that something does NOT happen: a publisher on a timer of its
  // 1 ms interval would wake hundreds of times within it.
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(restingPublisher.wakeUps(), atRest) << "woken while the accumulator had reached its target";
  EXPECT_EQ(heldPublisher.wakeUps(), whileHeld) << "woken while the accumulator was held";
}

// The first batch after a pause is packed as soon as it lands, not when a timer next fires: the
// interval (long here) only spaces packs while points keep coming. On the way: a held accumulator
// starts no batch, even for a pattern set while it is held; released, it refines.
TEST(SnapshotPublisher, PicksUpABatchPromptlyWithoutATimer) {
  using namespace std::chrono_literals;
  const auto mask = fullMask(glm::ivec3(32));
  Accumulator accumulator(mask, 1);
  accumulator.setHeld(true);
  accumulator.setTargetPoints(50'000);
  accumulator.setPattern(defaultScene().layers, 1);
  const auto interval = 2s;
  EventCounter looked;
  SnapshotPublisher publisher(accumulator, interval);
  publisher.setObserver(&looked);
  // The publisher looks once, finds a held pattern without points (nothing to pack), and sleeps.
  PackedVolume volume;
  ASSERT_TRUE(waitFor(looked, [&] { return publisher.wakeUps() > 0; }));
  // A fixed wait, as this tests a timer: the publisher's pause of one interval after a look runs
  // out, so what follows is the first batch after a pause (a timer of the interval would fire
  // well after the release).
  std::this_thread::sleep_for(interval + 100ms);
  EXPECT_FALSE(publisher.takeIfNewer(volume)) << "a held grid without points was packed";
  EXPECT_EQ(accumulator.stats().points, 0u) << "a held accumulator added points";
  EXPECT_EQ(accumulator.stats().iterations, 0u) << "a held accumulator ran a batch";

  const std::uint64_t before = accumulator.version();
  accumulator.setHeld(false);
  ASSERT_TRUE(waitFor(accumulator.progress(), [&] { return accumulator.version() > before; }));
  const auto landed = std::chrono::steady_clock::now();
  ASSERT_GT(accumulator.stats().points, 0u);
  waitFor(
      looked, [&] { return publisher.takeIfNewer(volume); }, interval);
  EXPECT_GT(volume.points, 0u);
  EXPECT_LT(std::chrono::steady_clock::now() - landed, interval / 2) << "the batch waited for a timer";
  ASSERT_TRUE(accumulator.waitUntilDone(60.0));
  EXPECT_GE(accumulator.stats().points, 50'000u) << "released, it refines to its target";
}

// Two accumulators sharing one core (the explorer's grid and its proxy) both refine to their
// targets, a publisher's packs taking the core in turn with them, and the core is free again after.
TEST(Accumulator, AccumulatorsSharingACoreBudgetBothFinish) {
  const auto cores = std::make_shared<CoreBudget>(1);
  const auto mask = fullMask(glm::ivec3(24));
  Accumulator first(mask, 2, cores), second(mask, 2, cores);
  EXPECT_EQ(first.coreBudget(), cores.get());
  EventCounter looked;
  SnapshotPublisher publisher(first, std::chrono::milliseconds(1));
  publisher.setObserver(&looked);
  for (Accumulator* accumulator : {&first, &second}) {
    accumulator->setTargetPoints(200'000);
    accumulator->setPattern(defaultScene().layers, 3);
  }
  ASSERT_TRUE(first.waitUntilDone(60.0));
  ASSERT_TRUE(second.waitUntilDone(60.0));
  EXPECT_GE(first.stats().points, 200'000u);
  EXPECT_GE(second.stats().points, 200'000u);
  PackedVolume volume;
  EXPECT_TRUE(waitFor(looked, [&] {
    publisher.takeIfNewer(volume);
    return publisher.caughtUp();
  }));
  ASSERT_TRUE(cores->try_acquire()) << "a batch or a pack kept its core";
  EXPECT_FALSE(cores->try_acquire());
  cores->release();
}

// The refinement's threads are batch work (SCHED_BATCH): a worker handed a core by another must not
// preempt the giver before it sleeps, nor a pack the frame's thread. Read from /proc, as the
// scheduler sees them.
TEST(Accumulator, WorkersAndPacksRunAsBatchThreads) {
  const auto mask = fullMask(glm::ivec3(24));
  Accumulator accumulator(mask, 2);
  SnapshotPublisher publisher(accumulator, std::chrono::milliseconds(1));
  accumulator.setTargetPoints(50'000);
  accumulator.setPattern(defaultScene().layers, 3);
  ASSERT_TRUE(accumulator.waitUntilDone(60.0));
  std::map<std::string, std::vector<int>> policies;  // by thread name
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream stat(task.path() / "stat");
    std::string line;
    if (!std::getline(stat, line)) continue;
    // "tid (name) state ...": the policy is the 41st field, the 39th after the name.
    const std::size_t open = line.find('('), close = line.rfind(')');
    std::istringstream rest(line.substr(close + 2));
    std::string field;
    for (int i = 3; i <= 41 && rest >> field; ++i) {
    }
    policies[line.substr(open + 1, close - open - 1)].push_back(std::stoi(field));
  }
  ASSERT_EQ(policies["vf-accumulate"].size(), 2u);
  for (int policy : policies["vf-accumulate"]) EXPECT_EQ(policy, SCHED_BATCH);
  ASSERT_EQ(policies["vf-publish"].size(), 1u);
  EXPECT_EQ(policies["vf-publish"][0], SCHED_BATCH);
}

// The ray-marcher leaps a cube of empty bricks at once on the strength of the empty distances, so
// every brick's distance must be exactly the Chebyshev distance (in bricks) to the nearest brick
// the density reaches, grown by the one voxel trilinear filtering reads: a distance too large
// would skip density, one too small only wastes steps. Checked against brute force on a grid whose
// sides are not multiples of a brick, with density at its corners, edges and inside.
TEST(PackedVolume, EmptyDistancesAreTheChebyshevDistanceToTheNearestOccupiedBrick) {
  VolumeSnapshot snapshot;
  snapshot.geometry.size = {41, 30, 37};
  const GridGeometry& g = snapshot.geometry;
  snapshot.density.assign(g.voxelCount(), 0.0f);
  snapshot.rgba.assign(4 * g.voxelCount(), 255);
  const glm::ivec3 dense[] = {{0, 0, 0}, {40, 29, 36}, {20, 3, 17}, {21, 3, 17}, {7, 29, 2}, {33, 12, 30}};
  for (const glm::ivec3& v : dense) snapshot.density[g.index(v.x, v.y, v.z)] = 3.0f;
  snapshot.points = 18;
  PackedVolume packed;
  packVolume(snapshot, packed);
  const glm::ivec3 bricks = packed.brickCount;
  ASSERT_EQ(bricks, (g.size + kBrickSize - 1) / kBrickSize);
  auto brickIndex = [&](glm::ivec3 b) {
    return static_cast<std::size_t>(b.x) +
           static_cast<std::size_t>(bricks.x) * (b.y + static_cast<std::size_t>(bricks.y) * b.z);
  };
  // The occupied bricks: those within a voxel of a dense one.
  std::vector<std::uint8_t> occupied(packed.occupancy.size(), 0);
  for (const glm::ivec3& v : dense)
    for (int dz = -1; dz <= 1; ++dz)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const glm::ivec3 w = glm::clamp(v + glm::ivec3(dx, dy, dz), glm::ivec3(0), g.size - 1);
          occupied[brickIndex(w / kBrickSize)] = 1;
        }
  EXPECT_EQ(packed.occupancy, occupied);
  ASSERT_EQ(packed.emptyDistance.size(), occupied.size());
  int leaps = 0;
  for (int z = 0; z < bricks.z; ++z)
    for (int y = 0; y < bricks.y; ++y)
      for (int x = 0; x < bricks.x; ++x) {
        int nearest = kMaxEmptyDistance;
        for (int k = 0; k < bricks.z; ++k)
          for (int j = 0; j < bricks.y; ++j)
            for (int i = 0; i < bricks.x; ++i)
              if (occupied[brickIndex({i, j, k})])
                nearest = std::min(nearest, std::max({std::abs(i - x), std::abs(j - y), std::abs(k - z)}));
        ASSERT_EQ(packed.emptyDistance[brickIndex({x, y, z})], nearest) << "brick " << x << " " << y << " " << z;
        leaps += nearest > 1;
      }
  EXPECT_GT(leaps, 0) << "some bricks leap further than themselves";
}

TEST(PackedVolume, AnEmptyGridIsEmptyAsFarAsTheDistancesReach) {
  VolumeSnapshot snapshot;
  snapshot.geometry.size = {16, 16, 16};
  snapshot.density.assign(snapshot.geometry.voxelCount(), 0.0f);
  snapshot.rgba.assign(4 * snapshot.geometry.voxelCount(), 0);
  PackedVolume packed;
  packVolume(snapshot, packed);
  ASSERT_FALSE(packed.emptyDistance.empty());
  for (const std::uint8_t distance : packed.emptyDistance) EXPECT_EQ(distance, kMaxEmptyDistance);
}
