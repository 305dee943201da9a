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

void FrameBudget::measured(double frameMs, float scale, bool marched, bool predicted) {
  // A gap of seconds is a stall elsewhere (a window drag, a debugger), not the march's cost; a
  // prediction of a whole pass may be that long on a software GL.
  if (!marched || scale <= 0.0f || !(frameMs > 0.0) || (frameMs > 2000.0 && !predicted)) return;
  lastMs_ = frameMs;
  lastScale_ = scale;
  lastPredicted_ = predicted;
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
    const double fastest = lastPredicted_ ? 0.0 : 0.5;
    const double factor = ratio > 1.0 || ratio < 0.6 ? std::clamp(std::sqrt(0.85 / ratio), fastest, 1.25) : 1.0;
    interactive_ = quantise(static_cast<float>(lastScale_ * factor));
    lastMs_ = 0.0;
  }
  interactive_ = std::clamp(interactive_, floor_, top);
  return interactive_;
}

}  // namespace voxflame::app

namespace voxflame::app {

void RefineBands::restart(int width, int height) {
  width = std::max(1, width);
  height = std::max(1, height);
  pass_ = 0;
  nextBand_ = 0;
  width_ = width;
  height_ = height;
}

int RefineBands::rowsOfBand(int band) const {
  return std::min(kBandRows, height_ - band * kBandRows);
}

double RefineBands::bandEstimate(int band) const {
  const bool learnt = width_ == costWidth_ && height_ == costHeight_;
  const double known = learnt ? bandMs_[static_cast<std::size_t>(band)] : -1.0;
  if (known >= 0.0) return known;
  const double rate = learnt ? std::max(peakMsPerPixel_, msPerPixel_) : msPerPixel_;
  return rate >= 0.0 ? rate * width_ * rowsOfBand(band) : -1.0;
}

double RefineBands::passMs() const {
  double total = 0.0;
  for (int band = 0; band < bandCount(); ++band) total += std::max(0.0, bandEstimate(band));
  return total;
}

RefineBands::Span RefineBands::next(double budgetMs) const {
  Span span;
  span.firstRow = nextBand_ * kBandRows;
  span.samples = pass_;
  if (bandCount() == 0) return span;
  const double available = kAim * budgetMs - std::max(0.0, otherMs_);
  const bool learnt = width_ == costWidth_ && height_ == costHeight_;
  const int mostUnknown = std::max(1, 2 * lastSpanBands_);
  double cost = 0.0;
  int unknown = 0;
  int band = nextBand_;
  for (; band < bandCount(); ++band) {
    const double estimate = bandEstimate(band);
    const bool known = learnt && bandMs_[static_cast<std::size_t>(band)] >= 0.0;
    if (band > nextBand_) {
      // Nothing known yet: one band, to learn what a band costs.
      if (estimate < 0.0 || (!known && unknown >= mostUnknown)) break;
      const bool last = band + 1 == bandCount();
      if (cost + estimate + (last ? finishMs_ : 0.0) > available) break;
    }
    cost += std::max(0.0, estimate);
    unknown += known ? 0 : 1;
  }
  span.rows = std::min(height_, band * kBandRows) - span.firstRow;
  span.endsPass = band == bandCount();
  return span;
}

RefineBands::Span RefineBands::rest() const {
  const int firstRow = nextBand_ * kBandRows;
  return Span{firstRow, height_ - firstRow, pass_, true};
}

void RefineBands::marched(const Span& span, double marchMs) {
  if (span.rows <= 0 || span.samples != pass_ || span.firstRow != nextBand_ * kBandRows) return;
  const int first = span.firstRow / kBandRows;
  const int end = std::min(bandCount(), (span.firstRow + span.rows + kBandRows - 1) / kBandRows);
  if (marchMs >= 0.0 && marchMs < 2000.0) {
    if (width_ != costWidth_ || height_ != costHeight_) {
      costWidth_ = width_;
      costHeight_ = height_;
      bandMs_.assign(static_cast<std::size_t>(bandCount()), -1.0);
      peakMsPerPixel_ = msPerPixel_;
    }
    // The time is shared out as the bands' estimates were (a band of the picture's middle keeps
    // costing more than one of its edge); bands not yet known share it by their pixels.
    double predicted = 0.0;
    bool allKnown = true;
    for (int band = first; band < end; ++band) {
      const double known = bandMs_[static_cast<std::size_t>(band)];
      allKnown = allKnown && known > 0.0;
      predicted += known;
    }
    const double pixels = static_cast<double>(width_) * span.rows;
    for (int band = first; band < end; ++band) {
      double& estimate = bandMs_[static_cast<std::size_t>(band)];
      const double share = allKnown ? estimate / predicted : static_cast<double>(width_) * rowsOfBand(band) / pixels;
      // Halfway to the new measurement when the band was known: one frame's time on a shared
      // machine is noisy.
      estimate = estimate > 0.0 ? 0.5 * (estimate + share * marchMs) : share * marchMs;
    }
    const double perPixel = marchMs / pixels;
    msPerPixel_ = msPerPixel_ < 0.0 ? perPixel : 0.5 * (msPerPixel_ + perPixel);
    peakMsPerPixel_ = std::max(peakMsPerPixel_, perPixel);
    lastSpanBands_ = end - first;
  }
  nextBand_ = end;
  if (nextBand_ >= bandCount()) {
    nextBand_ = 0;
    ++pass_;
  }
}

void RefineBands::frameMeasured(double frameMs, double marchMs, double finishMs) {
  // A gap of seconds is a stall elsewhere (a window drag, a debugger), not the frame's cost.
  if (!(frameMs > 0.0) || frameMs > 2000.0) return;
  const double other = std::max(0.0, frameMs - marchMs - finishMs);
  otherMs_ = otherMs_ < 0.0 ? other : 0.5 * (otherMs_ + other);
  if (finishMs > 0.0) finishMs_ = finishMs_ > 0.0 ? 0.5 * (finishMs_ + finishMs) : finishMs;
}

}  // namespace voxflame::app
