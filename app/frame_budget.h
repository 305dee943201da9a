// Keeps the explorer interactive on slow GL: while the view or the pattern is changing, the
// fraction of the window's pixels that is ray-marched goes down when frames take longer than the
// budget and back up when they are quick; once nothing has changed for a few frames it returns
// to the full (user-chosen) scale so the sample average refines the picture. Plain arithmetic on
// the frame times it is told, without GL or a clock of its own, so tests can drive it.
#pragma once

namespace voxflame::app {

class FrameBudget {
 public:
  static constexpr double kDefaultBudgetMs = 33.0;
  static constexpr float kDefaultFloor = 0.25f;
  // Frames without a change before the march goes back to the full scale: a slider drag or an
  // orbit changes something nearly every frame, and a short pause should not reset the scale.
  static constexpr int kQuietFrames = 4;

  explicit FrameBudget(double budgetMs = kDefaultBudgetMs, float floor = kDefaultFloor);

  void setBudget(double budgetMs);
  double budgetMs() const { return budgetMs_; }

  // What the previous frame cost (from the start of one frame to the start of the next, so the
  // GL work the swap waited on is in it) and the scale it marched at; marched false: it only
  // resolved an unchanged image, which says nothing about the cost of marching.
  void measured(double frameMs, float scale, bool marched);

  // The scale to march the next frame at, between the floor and `ceiling` (the scale a still
  // picture refines at). `changing`: the view or pattern changed in this frame.
  float next(bool changing, float ceiling);

  // How many times longer than the scene's a ray step is when marching at `scale` under a still
  // picture's `ceiling`: pixels ceiling/scale times wider than a still picture's are not worth
  // sampling finer along the ray than across it, so the step grows with them, up to
  // kMaxStepStretch (the march's cost is then about halved again at the floor). A still picture
  // marches at the scene's step.
  static float stepStretch(float scale, float ceiling);
  static constexpr float kMaxStepStretch = 2.0f;

  // The scale interaction settled on; the next change starts from it (not from the full scale).
  float interactiveScale() const { return interactive_; }
  bool quiet() const { return quietFrames_ >= kQuietFrames; }

 private:
  double budgetMs_;
  float floor_;
  float interactive_ = 1.0f;
  int quietFrames_ = kQuietFrames;
  double lastMs_ = 0.0;  // the newest marching frame's time and scale, not yet acted on
  float lastScale_ = 0.0f;
};

}  // namespace voxflame::app
