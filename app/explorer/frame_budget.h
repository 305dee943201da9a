// Keeps the explorer interactive on slow GL: while the view or the pattern is changing, the
// fraction of the window's pixels that is ray-marched goes down when frames take longer than the
// budget and back up when they are quick; once nothing has changed for a few frames it returns
// to the full (user-chosen) scale so the sample average refines the picture. Plain arithmetic on
// the frame times it is told, without GL or a clock of its own, so tests can drive it.
#pragma once

#include <algorithm>
#include <vector>

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
  // `predicted`: not a frame that went but a whole pass's cost predicted from the bands a still
  // view marched (RefineBands), which is steady: the next scale may then drop to what it asks
  // at once, not by half (a still view marches at the full resolution, so the first frame of a
  // drag would otherwise march half its pixels, several budgets' worth on a software GL).
  void measured(double frameMs, float scale, bool marched, bool predicted = false);

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
  bool lastPredicted_ = false;
};

}  // namespace voxflame::app

namespace voxflame::app {

// Splits a still view's refinement into horizontal bands of the march target, so that a frame
// marches only the bands that fit its budget instead of the whole target (hundreds of
// milliseconds on software GL). Bands are marched in order, bottom to top; a pass ends at the top
// band, so every pixel holds n or n + 1 samples and the running average stays right per pixel.
// Once every band has the cap, each pixel has had exactly the samples (and sample indices) an
// untiled march would give it. What a band costs is learnt from the march times it is told, per
// band (a picture's middle costs more than its empty edges). Plain arithmetic on the times it is
// told, without GL or a clock, so tests can drive it.
class RefineBands {
 public:
  // Fine enough that one band is a small share of any budget, coarse enough that a frame issues
  // only a few draws.
  static constexpr int kBandRows = 8;
  // A frame aims this far under the budget: the estimates are of frames that have gone.
  static constexpr double kAim = 0.85;

  // Consecutive rows [firstRow, firstRow + rows) of the target (GL's rows, bottom up) to march
  // next, each pixel holding `samples` samples before; `endsPass`: the top band is in it, so after
  // it every pixel holds samples + 1.
  struct Span {
    int firstRow = 0, rows = 0, samples = 0;
    bool endsPass = false;
    bool operator==(const Span&) const = default;
  };

  // The target, `width` × `height` pixels, starts its samples over (a new view, volume or size).
  // What each band cost is kept for the size it was learnt at (a similar picture costs about the
  // same, and a still view returns to its size after a drag); at another size it is predicted
  // from the cost per pixel seen so far until relearnt.
  void restart(int width, int height);

  // The bands to march in a frame of `budgetMs`: as many as fit the budget after the rest of the
  // frame (the finish too, when the span ends a pass), always at least one band, never past the
  // pass's end.
  Span next(double budgetMs) const;
  // All that is left of the pass (for a frame that marches the whole target while something changes).
  Span rest() const;
  // `span` (as next() gave it) was marched, in `marchMs` (negative: not timed, e.g. a drag's
  // frame at a coarser step, whose cost says nothing of a still view's).
  void marched(const Span& span, double marchMs);
  // A whole frame that marched bands took `frameMs`, of which `marchMs` was the march and
  // `finishMs` the finish (resolve) of a new image (0: none was made, the one shown was only drawn
  // again): the rest is what a frame costs anyway.
  void frameMeasured(double frameMs, double marchMs, double finishMs);

  // The fewest samples a pixel holds: the picture's count. A pass in progress adds no sample.
  int samples() const { return pass_; }
  int bandCount() const { return (height_ + kBandRows - 1) / kBandRows; }
  // The band the next span starts at (0 at the start of a pass).
  int nextBand() const { return nextBand_; }
  int samplesOfRow(int row) const { return row / kBandRows < nextBand_ ? pass_ + 1 : pass_; }
  // The predicted cost of marching the whole target once (0 while nothing is known).
  double passMs() const;
  double otherMs() const { return std::max(0.0, otherMs_); }
  double finishMs() const { return finishMs_; }

 private:
  double bandEstimate(int band) const;
  int rowsOfBand(int band) const;

  int width_ = 0, height_ = 0;
  int pass_ = 0, nextBand_ = 0;
  int costWidth_ = 0, costHeight_ = 0;  // the size bandMs_ was learnt at
  std::vector<double> bandMs_;          // per band; negative while unknown
  double msPerPixel_ = -1.0;            // of any band marched so far (negative: none yet)
  // While a size's bands are learnt, the unknown ones are predicted at the costliest rate seen
  // at that size, and a frame takes at most twice as many of them as the last frame marched: a
  // picture's empty bottom rows would otherwise make its middle look cheap.
  double peakMsPerPixel_ = -1.0;
  int lastSpanBands_ = 0;
  double otherMs_ = -1.0;  // the rest of a frame that marched (negative: not measured yet)
  double finishMs_ = 0.0;  // the finish a pass's end brings
};

}  // namespace voxflame::app
