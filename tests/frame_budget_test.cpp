// The explorer's frame-budget controller (app::FrameBudget): slow frames while something changes
// lower the march scale, quick ones raise it again, and a still view goes back to full scale.
#include <gtest/gtest.h>

#include "frame_budget.h"

using voxflame::app::FrameBudget;

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

}  // namespace
