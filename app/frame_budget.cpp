#include "frame_budget.h"

#include <algorithm>
#include <cmath>

namespace voxflame::app {

namespace {

// Scales are kept to steps of 1/32 so that small wobbles in frame time do not reallocate the
// image (and restart its samples) every frame.
float quantise(float scale) {
  return std::round(scale * 32.0f) / 32.0f;
}

}  // namespace

FrameBudget::FrameBudget(double budgetMs, float floor) : budgetMs_(std::max(1.0, budgetMs)), floor_(floor) {}

void FrameBudget::setBudget(double budgetMs) {
  budgetMs_ = std::max(1.0, budgetMs);
}

void FrameBudget::measured(double frameMs, float scale, bool marched) {
  // A gap of seconds is a stall elsewhere (a window drag, a debugger), not the march's cost.
  if (!marched || scale <= 0.0f || !(frameMs > 0.0) || frameMs > 2000.0) return;
  lastMs_ = frameMs;
  lastScale_ = scale;
}

float FrameBudget::stepStretch(float scale, float ceiling) {
  if (!(scale > 0.0f) || !(ceiling > scale)) return 1.0f;
  return std::min(ceiling / scale, kMaxStepStretch);
}

float FrameBudget::next(bool changing, float ceiling) {
  const float top = std::max(floor_, std::min(1.0f, ceiling));
  if (!changing) {
    quietFrames_ = std::min(quietFrames_ + 1, kQuietFrames);
    if (quiet()) return top;
  } else {
    quietFrames_ = 0;
  }
  if (lastMs_ > 0.0) {
    // The march costs about the number of pixels, the square of the scale. Aim a little under
    // the budget, leave a band around it alone (no hunting) and move at most by half or a
    // quarter per frame, because each measurement is of a frame that has already gone.
    // A still frame at the full scale measured last tells what the first frame of a drag may
    // afford, so a drag starts near the right scale.
    const double ratio = lastMs_ / budgetMs_;
    const double factor = ratio > 1.0 || ratio < 0.6 ? std::clamp(std::sqrt(0.85 / ratio), 0.5, 1.25) : 1.0;
    interactive_ = quantise(static_cast<float>(lastScale_ * factor));
    lastMs_ = 0.0;
  }
  interactive_ = std::clamp(interactive_, floor_, top);
  return interactive_;
}

}  // namespace voxflame::app
