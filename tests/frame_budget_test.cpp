// The explorer's frame-budget controller (app::FrameBudget): slow frames while something changes
// lower the march scale, quick ones raise it again, and a still view goes back to full scale.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "frame_budget.h"

using voxflame::app::FrameBudget;
using voxflame::app::RefineBands;

namespace {

// A march whose cost is `fixedMs` plus `fullMs` times the fraction of the pixels marched.
struct SimulatedFrames {
  double fixedMs, fullMs;
  double cost(float scale) const { return fixedMs + fullMs * double(scale) * double(scale); }
};

// Runs `frames` changing frames and returns the scale they end on.
float drag(FrameBudget& budget, const SimulatedFrames& gl, int frames, float ceiling = 1.0f) {
  float scale = budget.next(true, ceiling);
  for (int i = 0; i < frames; ++i) {
    budget.measured(gl.cost(scale), scale, true);
    scale = budget.next(true, ceiling);
  }
  return scale;
}

TEST(FrameBudgetTest, SlowFramesLowerTheScaleUntilTheyFitTheBudget) {
  FrameBudget budget(33.0);
  const SimulatedFrames slow{4.0, 200.0};  // the full scale takes 204 ms
  const float scale = drag(budget, slow, 12);
  EXPECT_LT(scale, 0.5f);
  EXPECT_LE(slow.cost(scale), 33.0) << "settles under the budget, scale " << scale;
  EXPECT_GT(slow.cost(scale), 0.5 * 33.0) << "without dropping far below it, scale " << scale;
}

TEST(FrameBudgetTest, TheFirstSlowFrameAlreadyReacts) {
  FrameBudget budget(33.0);
  EXPECT_EQ(budget.next(true, 1.0f), 1.0f);
  budget.measured(120.0, 1.0f, true);
  EXPECT_LE(budget.next(true, 1.0f), 0.5f) << "a frame of four budgets halves the scale at once";
}

TEST(FrameBudgetTest, APredictedPassCostSetsTheFirstMovingFrameScaleAtOnce) {
  // A still view refined at the full scale, whose whole pass the bands predict at 16 budgets:
  // the first frame of a drag marches at the scale that fits (a quarter of the side, the floor
  // here), not half of it, which a single frame that went would allow.
  FrameBudget budget(33.0);
  budget.measured(16.0 * 33.0, 1.0f, true, true);
  EXPECT_LE(budget.next(true, 0.5f), 0.25f);
  FrameBudget measuredOnly(33.0);
  measuredOnly.measured(16.0 * 33.0, 1.0f, true);
  EXPECT_EQ(measuredOnly.next(true, 0.5f), 0.5f) << "a frame that went moves the scale by half at most";
}

TEST(FrameBudgetTest, QuickFramesClimbBackAndStillFramesGoToTheCeiling) {
  FrameBudget budget(33.0);
  const float low = drag(budget, {4.0, 200.0}, 12);
  ASSERT_LT(low, 0.5f);
  // The machine got faster (a smaller window, say): the scale climbs while the drag goes on.
  const float recovered = drag(budget, {2.0, 20.0}, 20);
  EXPECT_EQ(recovered, 1.0f);

  // Slow again, then the user lets go: a few quiet frames later the full scale returns ...
  const float dragged = drag(budget, {4.0, 200.0}, 12);
  ASSERT_LT(dragged, 0.5f);
  float scale = dragged;
  for (int i = 0; i < FrameBudget::kQuietFrames; ++i) scale = budget.next(false, 0.75f);
  EXPECT_EQ(scale, 0.75f) << "a still view refines at the ceiling the user chose";
  // ... and frames that only resolve an unchanged image teach it nothing.
  budget.measured(1.0, 0.75f, false);
  EXPECT_EQ(budget.next(false, 0.75f), 0.75f);
  // The next drag starts from the scale the full-scale still frames imply, not from the ceiling.
  budget.measured(150.0, 0.75f, true);
  EXPECT_LE(budget.next(true, 0.75f), 0.375f);
}

TEST(FrameBudgetTest, TheScaleStaysBetweenTheFloorAndTheCeiling) {
  FrameBudget budget(33.0, 0.25f);
  EXPECT_EQ(drag(budget, {100.0, 1000.0}, 20), 0.25f) << "fixed costs over the budget stop at the floor";
  EXPECT_EQ(drag(budget, {0.5, 1.0}, 30, 0.6f), 0.6f);
  budget.setBudget(1000.0);
  EXPECT_EQ(budget.budgetMs(), 1000.0);
}

// Steps lengthen with the pixels while the scale is lowered, never beyond the stretch's limit, and
// a picture at its ceiling marches at the scene's step.
TEST(FrameBudgetTest, RayStepsGrowWithThePixelsUpToALimit) {
  EXPECT_EQ(FrameBudget::stepStretch(0.5f, 0.5f), 1.0f);
  EXPECT_EQ(FrameBudget::stepStretch(1.0f, 0.5f), 1.0f) << "a scale above the ceiling never shortens a step";
  EXPECT_FLOAT_EQ(FrameBudget::stepStretch(0.75f, 1.0f), 4.0f / 3.0f);
  EXPECT_EQ(FrameBudget::stepStretch(0.25f, 0.5f), 2.0f);
  EXPECT_EQ(FrameBudget::stepStretch(0.25f, 1.0f), FrameBudget::kMaxStepStretch);
  EXPECT_EQ(FrameBudget::stepStretch(0.0f, 1.0f), 1.0f);
}

TEST(FrameBudgetTest, StallsOfSecondsAreNotTakenForTheMarch) {
  FrameBudget budget(33.0);
  budget.next(true, 1.0f);
  budget.measured(5000.0, 1.0f, true);
  EXPECT_EQ(budget.next(true, 1.0f), 1.0f);
}

// A still view whose march costs `msPerRow(row)` per row of the target, plus `otherMs` for the
// rest of every frame and `finishMs` more on a frame that ends a pass (the new picture's finish).
struct SimulatedTarget {
  int width = 640, height = 360;
  double otherMs = 4.0, finishMs = 6.0;
  double (*msPerRow)(int row, int height) = [](int, int) { return 0.5; };
  double march(const RefineBands::Span& span) const {
    double ms = 0.0;
    for (int row = span.firstRow; row < span.firstRow + span.rows; ++row) ms += msPerRow(row, height);
    return ms;
  }
};

// Runs frames of `budgetMs` until every band holds `samples` (or `maxFrames`); returns the frame
// times and checks the bands never skip or repeat a row of a pass.
std::vector<double> refine(RefineBands& bands, const SimulatedTarget& gl, double budgetMs, int samples,
                           int maxFrames = 100000) {
  std::vector<double> frames;
  while (bands.samples() < samples && static_cast<int>(frames.size()) < maxFrames) {
    const RefineBands::Span span = bands.next(budgetMs);
    EXPECT_EQ(span.firstRow, bands.nextBand() * RefineBands::kBandRows);
    EXPECT_EQ(span.samples, bands.samples());
    EXPECT_GE(span.rows, 1);
    EXPECT_LE(span.firstRow + span.rows, gl.height);
    EXPECT_EQ(span.endsPass, span.firstRow + span.rows == gl.height);
    const double march = gl.march(span);
    const double finish = span.endsPass ? gl.finishMs : 0.0;
    bands.marched(span, march);
    bands.frameMeasured(gl.otherMs + march + finish, march, finish);
    frames.push_back(gl.otherMs + march + finish);
  }
  return frames;
}

TEST(RefineBandsTest, AFreshTargetMarchesOneBandToLearnItsCost) {
  RefineBands bands;
  bands.restart(640, 360);
  EXPECT_EQ(bands.bandCount(), 45);
  const RefineBands::Span first = bands.next(33.0);
  EXPECT_EQ(first, (RefineBands::Span{0, RefineBands::kBandRows, 0, false}));
  bands.marched(first, 2.0);  // 2 ms for 8 rows: the rest is predicted from its cost per pixel
  EXPECT_NEAR(bands.passMs(), 2.0 * 45, 1e-9);
  bands.frameMeasured(5.0, 2.0, 0.0);
  EXPECT_NEAR(bands.otherMs(), 3.0, 1e-9);
  // Bands not yet known: twice as many as the last frame's at most.
  const RefineBands::Span second = bands.next(33.0);
  EXPECT_EQ(second.firstRow, RefineBands::kBandRows);
  EXPECT_EQ(second.rows, 2 * RefineBands::kBandRows);
  bands.marched(second, 4.0);
  EXPECT_EQ(bands.next(33.0).rows, 4 * RefineBands::kBandRows);
  // Once a pass has taught every band's cost: 0.85 × 33 − 3 = 25 ms of marching, 12 bands of 2 ms.
  bands.marched(bands.rest(), 2.0 * 42);
  const RefineBands::Span learnt = bands.next(33.0);
  EXPECT_EQ(learnt.firstRow, 0);
  EXPECT_EQ(learnt.rows, 12 * RefineBands::kBandRows);
  bands.marched(learnt, 24.0);
  EXPECT_EQ(bands.samples(), 1) << "a pass in progress adds no sample";
  EXPECT_EQ(bands.samplesOfRow(0), 2);
  EXPECT_EQ(bands.samplesOfRow(12 * RefineBands::kBandRows), 1);
}

TEST(RefineBandsTest, EveryFrameKeepsTheBudgetAndEveryBandReachesItsSamples) {
  // The picture's middle costs ten times its edges (rays through the volume against empty
  // space); a whole pass costs 4 × 33 ms, so it must be spread over frames.
  SimulatedTarget gl;
  gl.msPerRow = [](int row, int height) { return std::abs(row - height / 2) < height / 4 ? 0.6 : 0.06; };
  double pass = 0.0;
  for (int row = 0; row < gl.height; ++row) pass += gl.msPerRow(row, gl.height);
  ASSERT_GT(pass, 3 * 33.0);
  RefineBands bands;
  bands.restart(gl.width, gl.height);
  const std::vector<double> frames = refine(bands, gl, 33.0, 64);
  EXPECT_EQ(bands.samples(), 64);
  for (int row = 0; row < gl.height; ++row) EXPECT_EQ(bands.samplesOfRow(row), 64);
  // The first pass learns the bands' costs; from then on no frame goes past the budget by half.
  int firstPassFrames = 0;
  for (double total = 0.0; total < pass; ++firstPassFrames) total += frames[firstPassFrames] - gl.otherMs;
  double worst = 0.0, sum = 0.0;
  for (std::size_t f = static_cast<std::size_t>(firstPassFrames); f < frames.size(); ++f) {
    worst = std::max(worst, frames[f]);
    sum += frames[f];
  }
  EXPECT_LE(worst, 1.5 * 33.0);
  // ... nor wastes most of it: the frames together take little more than the passes' work.
  EXPECT_LT(static_cast<double>(frames.size()), 1.5 * 64 * (pass + gl.finishMs) / (0.85 * 33.0 - gl.otherMs));
  EXPECT_GT(sum / static_cast<double>(frames.size() - firstPassFrames), 0.5 * 33.0);
}

TEST(RefineBandsTest, AQuickMarchTakesAWholePassAFrameAndNoMore) {
  SimulatedTarget gl;
  gl.msPerRow = [](int, int) { return 0.01; };  // 3.6 ms a pass
  RefineBands bands;
  bands.restart(gl.width, gl.height);
  const std::vector<double> frames = refine(bands, gl, 33.0, 64);
  // The first pass learns in 1, 2, 4, 8, 16 and the last 14 bands; then one pass a frame.
  EXPECT_EQ(frames.size(), 6u + 63u);
}

TEST(RefineBandsTest, ARestartKeepsWhatBandsCostAtTheSameSize) {
  SimulatedTarget gl;
  RefineBands bands;
  bands.restart(gl.width, gl.height);
  refine(bands, gl, 33.0, 2);
  const double pass = bands.passMs();
  EXPECT_NEAR(pass, 0.5 * gl.height, 0.05 * pass);
  bands.restart(gl.width, gl.height);
  EXPECT_EQ(bands.samples(), 0);
  EXPECT_EQ(bands.nextBand(), 0);
  EXPECT_EQ(bands.passMs(), pass);
  // A drag's smaller target is predicted from the cost per pixel; untimed marches teach nothing
  // and leave the still size's costs for when the view is still again.
  bands.restart(320, 180);
  EXPECT_NEAR(bands.passMs(), pass / 4, 0.1 * pass);
  const RefineBands::Span all = bands.rest();
  EXPECT_EQ(all, (RefineBands::Span{0, 180, 0, true}));
  bands.marched(all, -1.0);
  EXPECT_EQ(bands.samples(), 1);
  bands.restart(gl.width, gl.height);
  EXPECT_EQ(bands.passMs(), pass);
}

TEST(RefineBandsTest, APassEndLeavesRoomForTheFinish) {
  SimulatedTarget gl;
  gl.height = 16;  // two bands of 10 ms each
  gl.msPerRow = [](int, int) { return 10.0 / 8; };
  gl.otherMs = 3.0;
  gl.finishMs = 8.0;
  RefineBands bands;
  bands.restart(gl.width, gl.height);
  refine(bands, gl, 33.0, 1);
  ASSERT_NEAR(bands.finishMs(), 8.0, 1e-9);
  // 0.85 × 33 − 3 = 25 ms: both bands fit (20 ms), not with the finish (28 ms).
  EXPECT_EQ(bands.next(33.0).rows, 8);
  EXPECT_EQ(bands.next(40.0).rows, 16);
}

}  // namespace
