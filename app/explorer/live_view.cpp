#include "live_view.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <thread>
#include <utility>

#include "core/camera.h"
#include "core/color.h"
#include "core/error.h"
#include "gl/read_back.h"
#include "pipeline.h"

namespace voxflame::app {

namespace {

// Shadows are smooth: a cell of 2³ voxels keeps them sharp enough at an eighth of the work.
constexpr int kShadowDownsample = 2;
// Keeps a frame's share of a volume upload to a few milliseconds while the user interacts; a
// still view does not march while a volume streams in, so its frames can take more of it.
constexpr std::size_t kUploadBytesPerFrame = 48u << 20;
constexpr std::size_t kStillUploadBytesPerFrame = 160u << 20;
// ... at most: a still frame uploads what its budget leaves room for at the rate uploads have
// gone (the march waits meanwhile, but the frame still has its budget to keep).
constexpr double kStillUploadShareOfBudget = 0.6;

// The view rectangle within a framebuffer of this size; an empty one is all of it.
glm::ivec4 placeWithin(glm::ivec4 rect, int width, int height) {
  if (rect.z <= 0 || rect.w <= 0) return {0, 0, width, height};
  const int x = std::clamp(rect.x, 0, width - 1), y = std::clamp(rect.y, 0, height - 1);
  return {x, y, std::clamp(rect.z, 1, width - x), std::clamp(rect.w, 1, height - y)};
}

// Clears the framebuffer outside `place` (all of it for an empty one) to the background: what the
// panels' translucent backgrounds show. Strips with a scissor each, so the picture's pixels are
// written once, by its own draw.
void clearAround(glm::ivec4 place, int width, int height, glm::vec3 background) {
  glClearColor(background.r, background.g, background.b, 1.0f);
  if (place.z <= 0 || place.w <= 0) {
    glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
  glEnable(GL_SCISSOR_TEST);
  const glm::ivec4 strips[] = {{0, 0, place.x, height},
                               {place.x + place.z, 0, width - place.x - place.z, height},
                               {place.x, 0, place.z, place.y},
                               {place.x, place.y + place.w, place.z, height - place.y - place.w}};
  for (const glm::ivec4& strip : strips) {
    if (strip.z <= 0 || strip.w <= 0) continue;
    glScissor(strip.x, strip.y, strip.z, strip.w);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  glDisable(GL_SCISSOR_TEST);
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

LiveView::LiveView(ExplorerSession& session) : session_(session) {
  session_.restartTakeover();  // nothing of this view's is on screen yet
  // A GPU backend made from now on fills textures this context reads (on this, the drawing thread).
  session_.setRendererShareGroup(gl::currentShareGroup());
}

LiveView::~LiveView() {
  session_.setRendererShareGroup({});  // this view's context goes with it
}

void LiveView::takeVolume() {
  newVolumeShown_ = false;
  // Which grid's volume is shown is the session's answer (its takeover); a proxy volume it shows
  // goes up whole (a few megabytes) and is marched until the main grid takes over.
  if (proxySpare_.use_count() > 1) proxySpare_ = std::make_shared<core::PackedVolume>();
  std::uint64_t proxyReflects = 0;
  if (session_.takeProxyIfNewer(*proxySpare_, &proxyReflects) &&
      session_.showProxyVolume(*proxySpare_, proxyReflects)) {
    std::swap(proxySpare_, proxyShown_);
    renderer_.uploadProxy(*proxyShown_);
    renderer_.marchFrom(gl::VolumeRenderer::Source::Proxy);
    newVolumeShown_ = true;
    shownPost_ = proxyReflects;
    restartSamples();
  }

  // The volume on screen is in the textures once uploaded, so its buffer goes back to the session
  // in the swap that brings the next one (which packs into it): two copies of the grid in all, not
  // three. One a shadow job still reads is left to it; the next volume then goes into a fresh one.
  std::uint64_t reflects = 0;
  if (!uploadInProgress_) {
    std::shared_ptr<core::PackedVolume> next = shown_.use_count() > 1 ? std::make_shared<core::PackedVolume>() : shown_;
    if (session_.takeVolumeIfNewer(*next, &reflects)) {
      shown_ = std::move(next);
      // One that would not replace the proxy on screen is not uploaded: at 512³ the upload alone
      // would cost several frames.
      if (session_.uploadMainVolume(*shown_, reflects)) {
        renderer_.beginUpload(*shown_);
        uploadInProgress_ = true;
        uploadedBytes_ = 0;
        uploadingPost_ = reflects;
      }
    }
  }
  const bool still = !changedLastFrame_ && target_.samples > 0;
  std::size_t uploadBytes = still ? kStillUploadBytesPerFrame : kUploadBytesPerFrame;
  if (still && uploadMsPerByte_ > 0.0)
    uploadBytes =
        std::clamp(static_cast<std::size_t>(kStillUploadShareOfBudget * budget_.budgetMs() / uploadMsPerByte_),
                   kUploadBytesPerFrame / 4, kStillUploadBytesPerFrame);
  const auto uploadStart = std::chrono::steady_clock::now();
  const bool uploaded = uploadInProgress_ && renderer_.continueUpload(uploadBytes);
  if (uploadInProgress_) {
    // The bytes the slabs held (uploaded, or copied on the GPU): the budget, or what was left of the volume.
    const std::size_t total = (shown_->geometry.voxelCount() + 4 * shown_->colour.cellCount()) * sizeof(std::uint16_t);
    const std::size_t bytes = std::min(uploadBytes, total - std::min(total, uploadedBytes_));
    uploadedBytes_ += bytes;
    if (bytes >= kUploadBytesPerFrame / 8) {
      const double msPerByte = millisecondsSince(uploadStart) / static_cast<double>(bytes);
      uploadMsPerByte_ = uploadMsPerByte_ > 0.0 ? 0.5 * (uploadMsPerByte_ + msPerByte) : msPerByte;
    }
  }
  if (uploaded) {
    uploadedBytes_ = 0;
    uploadInProgress_ = false;
    // A fresher volume of the pattern the main grid already shows.
    const bool refined = shown_->generation == mainGeneration_ &&
                         renderer_.marchedSource() == gl::VolumeRenderer::Source::Main &&
                         renderer_.hasVolume(gl::VolumeRenderer::Source::Main);
    mainGeneration_ = shown_->generation;
    if (session_.mainVolumeUploaded(*shown_, uploadingPost_)) {
      renderer_.marchFrom(gl::VolumeRenderer::Source::Main);
      newVolumeShown_ = true;
      shownPost_ = uploadingPost_;
      restartSamples(refined);  // new content: start refining the image afresh
    }
  }
  // While a volume of another pattern streams into the main grid, its slabs are of two patterns.
  mainMixed_ = uploadInProgress_ && shown_->generation != mainGeneration_;
}

void LiveView::keepShadowInStep(const core::RenderSettingsDoc& render) {
  // The shadow volume follows the volume shown and the light; it is computed on a job of its own
  // (tens of milliseconds at 256³) and uploaded when ready. It is looked up by position in the
  // grid box, so one made from the proxy lights the main grid well enough until its own is ready.
  if (shadowJob_.ready()) {
    try {
      const bool hadShadow = renderer_.hasShadow();
      renderer_.uploadShadow(*shadowJob_.take(), shadowShown_ && shadowShown_->proxy ? 1 : kShadowDownsample,
                             shadowSourceSize_);
      restartSamples(hadShadow);
    } catch (const core::Error&) {
      shadowShown_.reset();  // try again next frame
    }
  }
  const bool proxy = renderer_.marchedSource() == gl::VolumeRenderer::Source::Proxy;
  // A job for the volume no longer marched is stopped: the main grid's, started as its image
  // showed, when the user then drags and the proxy is marched, would take hundreds of milliseconds
  // of a core the drag's frames need (at 512³) for a shadow thrown away, and keep the proxy's
  // waiting.
  if (shadowJob_.busy() && !shadowJob_.ready() && shadowShown_ && shadowShown_->proxy != proxy) {
    shadowJob_.cancel();
    shadowShown_.reset();
  }
  const std::shared_ptr<core::PackedVolume>& volume = proxy ? proxyShown_ : shown_;
  const ShadowInputs wanted{proxy, proxy ? volume->version : renderer_.uploadedVersion(), render.lightAzimuthDeg,
                            render.lightElevationDeg};
  if (render.lighting && renderer_.hasVolume() && (proxy || !uploadInProgress_) && !shadowJob_.busy() &&
      shadowShown_ != wanted) {
    const glm::dvec3 light = core::lightDirection(render.lightAzimuthDeg, render.lightElevationDeg);
    // The proxy is small: full-resolution shadows cost little there.
    const int downsample = proxy ? 1 : kShadowDownsample;
    if (volume->onDevice()) {
      // Packed on the GPU, the volume has no host copy: its shadow is swept there too, from the
      // textures just copied (a millisecond or so on a GPU), in this frame.
      const bool hadShadow = renderer_.hasShadow();
      renderer_.computeShadow(renderer_.marchedSource(), light, core::kAbsorptionPerDensity, downsample);
      shadowShown_ = wanted;
      shadowSourceSize_ = volume->geometry.size;
      restartSamples(hadShadow);
      return;
    }
    shadowJob_.start([volume, light, downsample](std::stop_token stop) {
      core::ShadowVolume shadow;
      core::computeShadowVolume(*volume, light, core::kAbsorptionPerDensity, downsample, shadow, stop);
      return shadow;  // a stopped one is dropped by the cancel
    });
    shadowShown_ = wanted;
    shadowSourceSize_ = volume->geometry.size;
  }
}

void LiveView::restartSamples(bool refinedContent) {
  target_.samples = 0;
  settled_ = false;
  settledReference_.clear();
  // A fresher volume (or shadow) of what is already marched does not throw away a first pass
  // under way: the pass finishes on it and is shown, then the samples start over. The grid's
  // refinement brings one every few frames, faster than a slow GL marches a pass in bands, and
  // the picture would otherwise never change until the grid rests.
  if (refinedContent && !bandsRestart_ && bands_.samples() == 0 && bands_.nextBand() > 0) {
    restartAfterPass_ = true;
    return;
  }
  bandsRestart_ = true;
  restartAfterPass_ = false;
}

bool LiveView::marchBands(const gl::RenderSettings& settings, bool still, double budgetMs) {
  if (bandsRestart_) {
    bands_.restart(target_.width(), target_.height());
    sampleBase_ = static_cast<int>(frame_);
    bandsRestart_ = false;
  }
  const RefineBands::Span span = still ? bands_.next(budgetMs) : bands_.rest();
  const auto start = std::chrono::steady_clock::now();
  // Every band's n-th sample has the same index, so once all bands have their samples each pixel
  // holds what an untiled march would have given it.
  renderer_.marchRows(target_, settings, sampleBase_ + span.samples, span.firstRow, span.rows, span.samples);
  marchMs_ = -1.0;
  if (still) {
    // The budget needs the march's own cost. The resolve that follows reads the picture back and
    // would wait for the march anyway.
    if (testMsPerRow_ > 0.0)
      std::this_thread::sleep_for(std::chrono::duration<double, std::milli>(testMsPerRow_ * span.rows));
    glFinish();
    marchMs_ = millisecondsSince(start);
  }
  bands_.marched(span, marchMs_);
  marchedRows_ = span.rows;
  target_.samples = bands_.samples();
  // A still view's picture is shown at each doubling of its samples (1, 2, 4, ...: the steps the
  // eye sees), and finished in strips over the frames that follow (finishStrip): a whole finish
  // at the full resolution takes a software GL several budgets. A doubling that comes while the
  // last picture is still being finished is shown at the next pass that finds it done.
  bool copied = false;
  if (span.endsPass && still) {
    const int samples = bands_.samples();
    shownCopyOwed_ = shownCopyOwed_ || (samples & (samples - 1)) == 0;
    if (shownCopyOwed_ && shownFinished_) {
      shownTarget_.copyFrom(target_);
      shownHasPicture_ = true;
      shownCopyOwed_ = false;
      shownFinished_ = false;
      copied = true;
    }
  }
  // A whole pass marched while something changes is shown from the target itself: no copy.
  if (span.endsPass) showingTarget_ = !still;
  if (span.endsPass && restartAfterPass_) {
    target_.samples = 0;
    bandsRestart_ = true;
    restartAfterPass_ = false;
  }
  return still ? copied : span.endsPass;
}

bool LiveView::resting() const {
  if (uploadInProgress_ || shadowJob_.busy() || shadowJob_.ready() || points_.working()) return false;
  if (pointsMethod_ && !pointsFailed_ && !pointsBlocked_)
    return pointsShown_ && pointsCurrent_ && points_.progress().finished;
  return (settled_ || target_.samples >= kMaxSamples) && (shownFinished_ || !shownHasPicture_);
}

void LiveView::stopPoints() {
  points_.stop();
  pointsKey_.reset();
  pointsHavePicture_ = false;
  pointsShown_ = false;
  pointsFailed_ = false;
  pointsCurrent_ = true;
}

bool LiveView::updatePoints(const core::Scene& scene, const LiveInputs& inputs, const gl::RenderSettings& settings,
                            bool still, int width, int height) {
  pointsBlocked_ = false;
  if (!pointsMethod_) {
    if (pointsKey_) stopPoints();
    return false;
  }
  const int oversample = std::clamp(scene.render.oversample, 1, 4);
  PointsKey key;
  key.pattern = inputs.revisions.pattern;
  key.view = inputs.revisions.view;
  key.points = scene.points;
  key.seed = scene.seed;
  key.width = width;
  key.height = height;
  key.oversample = oversample;
  key.fieldDeg = inputs.camera.fovDeg;
  key.orthoHeight = inputs.camera.orthoHeight;
  key.dofAperture = scene.render.dofAperture;
  key.dofFocusDistance = scene.render.dofFocusDistance;
  key.fog = scene.render.fog;
  // While anything moves the volume preview takes over; once it stops, the points picture builds
  // up again from nothing.
  if (pointsKey_ && (*pointsKey_ != key || !still || inputs.interacting)) stopPoints();
  if (!still || inputs.interacting) return false;
  if (!pointsKey_) {
    // While the pattern escapes the grid shows the last bounded one, which the scene no longer
    // holds: the volume picture stays, refined and resting as under the volume method. (An escape
    // comes only with a new pattern, which stops a run under way.)
    const SessionStatus status = session_.status();
    pointsBlocked_ = status.showingLastBounded || !status.escapeNote.empty();
    if (pointsBlocked_) return false;
    // The points are dimmed by the grid in front of them: they start once the main grid shows the
    // pattern, whole (a proxy's or a half-uploaded grid's transmittance would be another picture's).
    const bool gridShowsPattern = renderer_.marchedSource() == gl::VolumeRenderer::Source::Main &&
                                  renderer_.hasVolume(gl::VolumeRenderer::Source::Main) &&
                                  session_.shownMainPost() >= lastPost_ && !mainMixed_ && !uploadInProgress_;
    std::shared_ptr<const core::InsideMask> mask = gridShowsPattern ? session_.mask() : nullptr;
    // A volume packed on the GPU has no host copy to dim the points by; the session refines on the
    // CPU under the points method, so one only shows until that grid's first volume.
    if (!mask || mask->geometry.size != shown_->geometry.size || shown_->onDevice()) return false;
    LivePointsRequest request;
    request.scene = scene;
    request.mask = std::move(mask);
    request.volume = shown_;  // shared: the next volume is packed into a fresh one meanwhile
    // The points are dimmed by this grid: refining it further meanwhile would only take the cores
    // the points need, so the session holds it here until the view or the pattern changes.
    pointsGridPoints_ = shown_->points;
    request.camera = settings.camera;
    // On a software rasteriser the GPU's projection runs on the CPU's cores beside the frame, as the
    // CPU's own would, and llvmpipe was seen to stall a compute context's read-back for minutes while
    // the frame's context drew: there the CPU projects.
    request.backend = renderer_.onSoftwareRasteriser() ? core::BackendKind::Cpu : status.backend;
    request.width = width * oversample;
    request.height = height * oversample;
    points_.start(std::move(request));
    pointsKey_ = key;
    pointsHavePicture_ = false;
    pointsShown_ = false;
    pointsNextShare_ = kPointsShownShare;
  }
  // A picture is taken when its points have doubled since the last one shown (from
  // kPointsShownShare on) and when it is whole: finishing a full-size picture of sparse points
  // costs a software GL hundreds of milliseconds, and each doubling is the visible step.
  const LivePointsProgress progress = points_.progress();
  // A run that failed (the pattern escapes, no memory for the histograms) leaves the volume
  // picture to refine and rest as under the volume method, until the next change.
  if (!progress.error.empty() && !pointsFailed_) {
    pointsFailed_ = true;
    pointsShown_ = false;
  }
  if (pointsFailed_) return false;
  const double share =
      static_cast<double>(progress.points) / static_cast<double>(std::max<std::uint64_t>(progress.target, 1));
  if (!(progress.finished || share >= pointsNextShare_) || !points_.takeIfNewer(pointsImage_)) return false;
  pointsTarget_.setSums(pointsImage_, oversample);
  if (!pointsHavePicture_) {
    renderer_.drawMesh(pointsTarget_, settings);
    pointsHavePicture_ = true;
  }
  pointsNextShare_ = std::max(pointsNextShare_, 2.0 * share);
  pointsCurrent_ = false;
  return true;
}

bool LiveView::finishStrips(const gl::FrameTarget& target, const gl::RenderSettings& settings,
                            std::chrono::steady_clock::time_point frameStart) {
  bool whole = false;
  do {
    whole = renderer_.finishStrip(target, settings, kStripRows);
    glFinish();  // the strips' cost is known only once they are done
  } while (!whole && millisecondsSince(frameStart) < kFinishShareOfBudget * budget_.budgetMs());
  return whole;
}

Thumbnail LiveView::drawnPicture(unsigned framebuffer) const {
  const glm::ivec4 place = lastPlace_;
  Thumbnail picture;
  picture.width = place.z;
  picture.height = place.w;
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  picture.rgba = gl::readRgba8(framebuffer, {place.x, place.y, place.z, place.w}, gl::ReadAlpha::Opaque);
  return picture;
}

void LiveView::checkSettled(unsigned framebuffer, glm::ivec4 place) {
  std::vector<std::uint8_t> picture =
      gl::readRgba8(framebuffer, {place.x, place.y, place.z, place.w}, gl::ReadAlpha::Opaque);
  if (settledReference_.size() == picture.size()) {
    std::size_t moved = 0;
    for (std::size_t i = 0; i < picture.size(); i += 4) {
      int largest = 0;
      for (std::size_t c = 0; c < 3; ++c)
        largest =
            std::max(largest, std::abs(static_cast<int>(picture[i + c]) - static_cast<int>(settledReference_[i + c])));
      if (largest > kSettledLevels) ++moved;
    }
    lastSettledShare_ = static_cast<double>(moved) / static_cast<double>(std::max<std::size_t>(picture.size() / 4, 1));
    if (lastSettledShare_ <= kSettledShare) settled_ = true;
  }
  settledReference_ = std::move(picture);
}

LiveFrame LiveView::frame(const core::Scene& scene, const LiveInputs& inputs, FrameMetrics& metrics,
                          int framebufferWidth, int framebufferHeight, unsigned framebuffer) {
  LiveFrame result;
  framebufferWidth = std::max(1, framebufferWidth);
  framebufferHeight = std::max(1, framebufferHeight);
  // The picture's place: the rectangle the docked panels leave (the whole framebuffer without one).
  const glm::ivec4 place = placeWithin(inputs.viewRect, framebufferWidth, framebufferHeight);
  const int width = place.z, height = place.w;
  const auto frameStart = std::chrono::steady_clock::now();
  if (lastFrameStart_) {
    const double lastFrameMs =
        std::chrono::duration<double, std::milli>(frameStart - *lastFrameStart_).count() + testFrameMs_;
    if (lastInBands_) {
      bands_.frameMeasured(lastFrameMs, std::max(0.0, marchMs_), lastFinishMs_);
      // A frame that marched a few bands says little of what a drag's first frame, which marches
      // the whole target, may afford: the bands' estimate of a whole pass does.
      budget_.measured(bands_.otherMs() + bands_.passMs() + bands_.finishMs(), lastMarchScale_, true, true);
    } else {
      budget_.measured(lastFrameMs, lastMarchScale_, lastMarched_);
    }
  }
  lastFrameStart_ = frameStart;
  pointsMethod_ = scene.render.method == core::RenderMethod::Points;
  lastMarched_ = false;
  lastInBands_ = false;
  lastFinishMs_ = 0.0;
  marchedRows_ = 0;
  marchMs_ = -1.0;
  // An edit while the user holds a widget or the view, or right after a frame that changed, is one
  // of a drag's: posted with the hold, so the large grid never starts on it.
  // The document counts its pattern edits (Document::Revisions): a new count is a pattern to post,
  // with no walk over the scene.
  if (postedPattern_ != inputs.revisions.pattern) {
    postedPattern_ = inputs.revisions.pattern;
    session_.post(scene, inputs.interacting || changedLastFrame_);
    result.patternPosted = true;
    waitingPost_ = session_.status().requestedGeneration;
    lastPost_ = waitingPost_;
    waitingFullPost_ = waitingPost_;
    waitingSince_ = std::chrono::steady_clock::now();
    waitingSinceFrame_ = frame_;
    metrics.worstFrameMs = 0.0;
  }
  if (auto mesh = session_.takeNewMesh()) {
    renderer_.setMesh(*mesh);
    shownView_.reset();
  }
  const auto uploadStart = std::chrono::steady_clock::now();
  takeVolume();
  metrics.uploadMs = millisecondsSince(uploadStart);
  keepShadowInStep(scene.render);

  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glViewport(0, 0, framebufferWidth, framebufferHeight);
  const glm::vec3 background = core::linearToSrgb(scene.tone.background);
  clearAround(place, framebufferWidth, framebufferHeight, background);
  glViewport(place.x, place.y, width, height);
  const std::optional<core::GridGeometry> grid = session_.geometry();
  bool changed = false;
  if (grid && renderer_.hasVolume()) {
    gl::RenderSettings settings;
    // The scene's camera, widened to hold the export's whole picture (viewCamera).
    const core::CameraSettings& camera = inputs.camera;
    settings.camera = core::orbitCamera(camera, grid->box(), static_cast<double>(width) / static_cast<double>(height));
    settings.tone = scene.tone;
    settings.render = scene.render;
    // Anything that changes what a ray sees restarts the sample average (the schema's "view"
    // class: camera, opacity, mesh display, lighting ...); tone alone only changes the resolve and
    // layers change the volume, which restarts it when the new generation arrives.
    const bool viewChanged = shownView_ != inputs.revisions.view || width != lastWidth_ || height != lastHeight_ ||
                             camera.fovDeg != lastFieldDeg_ || camera.orthoHeight != lastOrthoHeight_;
    // While the view or the pattern moves, fewer pixels keep the frame within its budget; a still
    // view refines at the scale the user chose.
    budget_.setBudget(inputs.frameBudgetMs);
    // The preview scale is the ceiling only while something moves. Playback is judged for its
    // motion, frame after frame: the budget alone decides how sharp its frames are, up to the full
    // window. A still view refines at the full resolution on every GL, software included: it is
    // the picture an export of the view makes, and its bands keep each frame within the budget.
    const float ceiling = inputs.playing ? 1.0f : std::min(1.0f, inputs.renderScale);
    float scale = budget_.next(viewChanged || result.patternPosted, ceiling);
    if (budget_.quiet()) scale = 1.0f;
    metrics.marchScale = scale;
    // Coarser pixels, coarser steps along the ray. A still view marches at its ceiling (stretch
    // 1), and a change of scale restarts the samples, so its samples are all of the scene's step.
    settings.render.stepVoxels *= FrameBudget::stepStretch(scale, ceiling);
    // A still view (one the budget has let go back to its full scale) refines in bands, as many
    // a frame as its budget allows; while something changes each frame marches a whole pass at
    // the budget's lowered scale, shown straight from the target. The first still frame keeps
    // that picture up (before a new size clears the target) while its bands' first pass builds.
    const bool still = budget_.quiet() && !viewChanged && !result.patternPosted;
    if (still && showingTarget_) {
      shownTarget_.copyFrom(target_);  // whole, even when new content has just restarted its samples
      shownHasPicture_ = true;
      showingTarget_ = false;
      // A picture of the moving view, coarse: finished whole at once, not left behind an older one.
      shownWholeFinish_ = true;
    }
    target_.resize(std::max(1, static_cast<int>(static_cast<float>(width) * scale)),
                   std::max(1, static_cast<int>(static_cast<float>(height) * scale)));
    if (viewChanged || scale != lastRenderScale_) {
      restartSamples();
      renderer_.drawMesh(target_, settings);
      shownView_ = inputs.revisions.view;
      lastWidth_ = width;
      lastHeight_ = height;
      lastFieldDeg_ = camera.fovDeg;
      lastOrthoHeight_ = camera.orthoHeight;
      lastRenderScale_ = scale;
    }
    // A main grid half of one pattern and half of another is not drawn: the last picture stays
    // until it is whole, unless the view moves. Nor does a still picture refine while a volume
    // streams in: the upload then has the frame to itself, and the new volume restarts the
    // samples anyway.
    const bool waitForUpload = uploadInProgress_ && target_.samples > 0 && !viewChanged;
    // A view that has just stopped changing keeps its last whole picture until the budget lets
    // the scale back up: samples marched at the lowered scale meanwhile would be thrown away then.
    const bool settling = !still && !viewChanged && !result.patternPosted && scale < ceiling && target_.samples >= 1;
    const bool pointsPicture = updatePoints(scene, inputs, settings, still, width, height);
    bool newPicture = false;
    // Once the points are being projected, the volume picture is not refined further: the points
    // picture replaces it within seconds, and its samples would only take the cores the points need.
    if (target_.samples < kMaxSamples && !settled_ && (!pointsKey_ || pointsFailed_) &&
        (!mainMixedShown() || viewChanged) && !waitForUpload && !settling) {
      newPicture = marchBands(settings, still, budget_.budgetMs());
      lastMarched_ = true;
      lastMarchScale_ = scale;
      lastInBands_ = still;
    }
    changed = viewChanged;
    // A points picture is finished a strip at a time, within the frame's budget (a software GL
    // takes hundreds of milliseconds over a whole one); the last whole one stays up meanwhile.
    const auto resolveStart = std::chrono::steady_clock::now();
    if (pointsHavePicture_ && !pointsFailed_) {
      pointsCurrent_ = finishStrips(pointsTarget_, settings, resolveStart);
      if (pointsCurrent_) pointsShown_ = true;
    }
    // Until the first pass over a new view or volume is whole, the last whole picture stays up.
    const bool fromShown = shownHasPicture_ && !showingTarget_;
    bool shownNowFinished = false, wholeFinish = false;
    if (!pointsShown_ && fromShown && still && !shownWholeFinish_ && !shownFinished_) {
      shownFinished_ = finishStrips(shownTarget_, settings, resolveStart);
      shownNowFinished = shownFinished_;
    }
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    if (!(pointsShown_ && renderer_.drawFinished(pointsTarget_, place)) &&
        !(fromShown && still && !shownWholeFinish_ && renderer_.drawFinished(shownTarget_, place))) {
      const gl::FrameTarget& shown = fromShown ? shownTarget_ : target_;
      renderer_.resolve(shown, settings, place, false);
      wholeFinish = newPicture || fromShown;
      if (fromShown) {
        shownFinished_ = true;
        shownWholeFinish_ = false;
      }
    }
    resolveMs_ = millisecondsSince(resolveStart);
    // A finish in strips is a cost of every frame while it lasts (the bands learn it as such); a
    // whole one comes with the pass it shows.
    if (wholeFinish || pointsPicture) lastFinishMs_ = resolveMs_;
    // A still volume picture whose samples doubled (from kFirstSettledCheck on), once finished and
    // drawn, is compared with the last one checked: once no pixel moves visibly, refining stops.
    if ((shownNowFinished || (wholeFinish && fromShown)) && still &&
        (!pointsMethod_ || pointsFailed_ || pointsBlocked_) && shownTarget_.samples >= kFirstSettledCheck &&
        scale == 1.0f && shownTarget_.width() == target_.width())
      checkSettled(framebuffer, place);
    result.volumeDrawn = true;
  } else {
    clearAround(glm::ivec4(0), framebufferWidth, framebufferHeight, background);
  }
  lastPlace_ = place;
  result.samples = target_.samples;
  const LivePointsProgress pointsProgress = points_.progress();
  result.view.points = pointsMethod_;
  result.view.pointsShown = pointsShown_;
  if (pointsFailed_) result.view.pointsError = pointsProgress.error;
  result.view.pointsDone = pointsProgress.points;
  result.view.pointsTarget = pointsMethod_ ? scene.points : 0;
  result.view.samples = target_.samples;
  result.view.resting = resting();
  // Nothing for the frames to do but wait for the points thread's next picture.
  result.view.waitingForPoints =
      points_.working() && pointsKey_ && pointsCurrent_ && !uploadInProgress_ && !changedLastFrame_;

  result.fullShown = renderer_.hasVolume() && renderer_.marchedSource() == gl::VolumeRenderer::Source::Main;
  if (newVolumeShown_) {
    result.newVolumeShown = true;
    result.shownPost = shownPost_;
    if (waitingPost_ != 0 && shownPost_ == waitingPost_) {
      metrics.changeToFrameMs = millisecondsSince(waitingSince_);
      metrics.changeToFrameFrames = static_cast<int>(frame_ - waitingSinceFrame_) + 1;
      metrics.worstChangeToFrameMs = std::max(metrics.worstChangeToFrameMs, metrics.changeToFrameMs);
      waitingPost_ = 0;
    }
    if (waitingFullPost_ != 0 && result.fullShown && shownPost_ == waitingFullPost_) {
      metrics.changeToFullMs = millisecondsSince(waitingSince_);
      waitingFullPost_ = 0;
    }
  }
  // Refinement rests at the user's noise target and while an export uses the cores; the large
  // grid also holds while the user drags or orbits (a change while a widget or the view is held,
  // or in this frame and the last: a single edit refines at once), until the first frame without
  // one. While only the view moves (an orbit, the light's slider) every grid holds, one without a
  // proxy too: at 64³ its refinement took the cores the orbit's frames needed.
  const bool viewOnly = changed && !result.patternPosted;
  changed = changed || result.patternPosted;
  const bool held = changed && (changedLastFrame_ || inputs.interacting);
  // Under the points method the grid only dims the points: it stops where an export's does, and
  // once the points are being projected, where it was when they started (they are dimmed by that
  // one; refining it further would only take their cores).
  session_.setBackendChoice(inputs.backend, scene.render.method);
  session_.setRefinement(inputs.refineUntilNoise, inputs.exportRunning, held, held && viewOnly,
                         !pointsMethod_                 ? 0
                         : pointsKey_ && !pointsFailed_ ? std::max<std::uint64_t>(pointsGridPoints_, 1)
                                                        : kGridPointsForPointsMethod);
  changedLastFrame_ = changed;
  ++frame_;
  return result;
}

LiveInputs liveInputs(const ExplorerState& state) {
  LiveInputs inputs;
  inputs.revisions = state.document.revisions();
  inputs.camera = viewCamera(state);
  inputs.viewRect = state.frame.viewRect;
  inputs.renderScale = state.panels.scene.renderScale;
  inputs.frameBudgetMs = state.panels.scene.frameBudgetMs;
  inputs.playing = state.panels.timeline.playing;
  inputs.interacting = state.frame.interacting;
  inputs.refineUntilNoise = 0.01 * state.services.settings.refineUntilNoisePercent;
  inputs.exportRunning = state.services.exportStatus.state == ExportState::Running;
  inputs.backend = state.services.settings.refinementBackend;
  return inputs;
}

LiveFrame liveFrame(LiveView& view, ExplorerState& state, int width, int height, unsigned framebuffer) {
  const LiveFrame result =
      view.frame(state.document.scene, liveInputs(state), state.frame.metrics, width, height, framebuffer);
  state.frame.samples = result.samples;
  state.frame.view = result.view;
  return result;
}

}  // namespace voxflame::app
