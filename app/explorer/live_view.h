// The explorer's frame body without a window: everything between "the UI has decided what the
// scene is" and "ImGui draws its panels on top". It posts pattern edits to the session, takes
// each new mesh and volume, uploads volumes a slice per frame, keeps the shadow volume in step on
// a background job, restarts the sample average when what a ray sees changes, marches the next
// bands of a sample (a whole pass while something changes, as many bands as the frame budget
// allows while the view is still), and resolves the last whole pass into the output framebuffer.
// Which grid's volume it shows, the proxy's or the main grid's, is the session's answer
// (ExplorerSession's takeover); the panels' requests are the window loop's (PanelRequests), which
// reads the picture just drawn through drawnPicture(). The explorer's window loop, `voxflame bench
// explorer` and the headless tests all run this very code, so the benchmark measures what users
// get. GL is touched only from the thread that calls frame() (the one whose context is current).
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>

#include "background_job.h"
#include "core/packed_volume.h"
#include "core/scene.h"
#include "core/shadow_volume.h"
#include "explorer_session.h"
#include "explorer_ui.h"
#include "frame_budget.h"
#include "gl/volume_renderer.h"
#include "live_points.h"

namespace voxflame::app {

// What one frame did, for the loop that called it.
struct LiveFrame {
  bool volumeDrawn = false;     // a volume was marched and resolved (else the background was cleared)
  bool newVolumeShown = false;  // this frame finished uploading a new volume
  std::uint64_t shownPost = 0;  // ... and the session post whose pattern it shows (0: an older one)
  bool patternPosted = false;   // the scene's pattern changed and was posted this frame
  bool fullShown = false;       // the volume drawn is the full grid (else the session's coarse proxy)
  int samples = 0;              // samples of the picture shown
  ViewRefinement view;          // which picture is shown, and whether it still refines
};

// What a frame draws from besides the scene: what the document has changed so far, the window's
// choices, and what the user is doing.
struct LiveInputs {
  // The document's edit counts: a new pattern count posts the scene to the session, a new view
  // count restarts the samples. Only these say that the scene changed; it is never compared.
  Document::Revisions revisions;
  core::CameraSettings camera;                 // the camera the view shows (viewCamera: widened to hold the export)
  glm::ivec4 viewRect{0};                      // where the picture goes (FrameOutputs::viewRect)
  float renderScale = 1.0f;                    // the march scale's ceiling for a still view
  float frameBudgetMs = 33.0f;                 // ... and the budget that lowers it while something changes
  bool playing = false;                        // playback: the ceiling is the whole window
  bool interacting = false;                    // a widget or the view is held: an edit now is one of a drag's
  double refineUntilNoise = 0.0;               // refinement rests at this noise (fraction; 0: never)
  bool exportRunning = false;                  // refinement pauses while an export uses the cores
  BackendChoice backend = BackendChoice::Cpu;  // what refines the large grid (the settings')
};

class LiveView {
 public:
  // Restarts the session's takeover: nothing of this view's is on screen yet.
  explicit LiveView(ExplorerSession& session);
  ~LiveView();  // cancels a shadow job still running
  LiveView(const LiveView&) = delete;
  LiveView& operator=(const LiveView&) = delete;

  // One frame of `scene` at width × height pixels into `framebuffer` (0: the window's); writes the
  // upload time, edit to frame and march scale into `metrics`. Never waits on the session or a
  // job. The time from one call to the next is taken as the frame's cost, so call it once per
  // displayed frame.
  LiveFrame frame(const core::Scene& scene, const LiveInputs& inputs, FrameMetrics& metrics, int width, int height,
                  unsigned framebuffer = 0);
  // The picture the last frame drew into `framebuffer` (its place there: the view rectangle),
  // read back (rows top to bottom, opaque): what a save's thumbnail shows. Call after frame(),
  // before the panels are drawn over it. A read-back, so only on request, never per frame.
  Thumbnail drawnPicture(unsigned framebuffer = 0) const;

  bool hasVolume() const { return renderer_.hasVolume(); }
  // The picture is final: the volume picture's samples stopped changing it visibly (or reached
  // kMaxSamples), or under the points method every point is in the points picture; no upload,
  // shadow or points thread is at work. With the session resting too, another frame would draw
  // the same pixels.
  bool resting() const;
  std::uint32_t frameCount() const { return frame_; }

  // Refining stops after this many samples of an unchanged view at most; usually sooner, once a
  // doubling of the samples changes no pixel visibly (see kSettledLevels).
  static constexpr int kMaxSamples = 64;
  // The volume picture is final once the picture shown after 2n samples differs from the one
  // after n by no more than this many 8-bit levels in any channel, at all but kSettledShare of
  // its pixels: the change still to come past 2n samples is about the same size again, which
  // nobody sees. Checked at n = kFirstSettledCheck, then at each doubling.
  static constexpr int kSettledLevels = 2;
  static constexpr double kSettledShare = 0.002;
  static constexpr int kFirstSettledCheck = 4;
  // The share of the view's pixels that moved by more than kSettledLevels at the last doubling
  // (negative: not measured yet), for the benchmark and the tests.
  double lastSettledShare() const { return lastSettledShare_; }
  // Read-backs made to see whether the picture settled: the only pixels a live frame reads back,
  // once per doubling of a still picture's samples from kFirstSettledCheck on.
  int settledChecks() const { return settledChecks_; }
  // The points picture replaces the volume picture once it holds this share of its points: it is
  // then already the closer of the two to the final picture (`bench view`: on flame-silk-bunny
  // the first points picture is at SSIM 0.976 of the final one where the volume preview it
  // replaces was at 0.911), and pixel-fine where the volume is voxel-coarse.
  static constexpr double kPointsShownShare = 1.0 / 16.0;
  // A still picture (points, or the volume's at the full resolution) is finished in strips of
  // this many rows, as many a frame as this share of the frame budget allows (at least one).
  static constexpr int kStripRows = 32;
  static constexpr double kFinishShareOfBudget = 0.8;
  // The points picture's progress (points method), for the benchmark and the tests.
  LivePointsProgress pointsProgress() const { return points_.progress(); }

  // What the last frame marched and what it cost, for the benchmark and the tests: the rows of
  // the march target it marched (0: none) of how many, the march's time (measured only for a
  // still view refining in bands, else negative) and the resolve's (finishing and drawing the
  // picture shown).
  int marchedRows() const { return marchedRows_; }
  int targetRows() const { return target_.height(); }
  double marchMs() const { return marchMs_; }
  double resolveMs() const { return resolveMs_; }
  const RefineBands& refineBands() const { return bands_; }
  // Tests play a slow GPU with this: each row marched in bands costs this much more time.
  void addMarchCostForTesting(double msPerRow) { testMsPerRow_ = msPerRow; }
  // And a slow machine with this: every frame is taken to have cost this much more time than it
  // did (the frame budget's measure), without anyone waiting for it.
  void addFrameCostForTesting(double ms) { testFrameMs_ = ms; }

 private:
  void takeVolume();
  // New content or a new view: the sample average starts over, band by band. `refinedContent`:
  // only a fresher volume or shadow of what is marched (see the .cpp).
  void restartSamples(bool refinedContent = false);
  // Marches the next bands of the target (all that are left of the pass while something
  // changes; as many as the budget allows while the view is still); true when that ended a pass,
  // whose picture is then the one shown.
  bool marchBands(const gl::RenderSettings& settings, bool still, double budgetMs);
  void keepShadowInStep(const core::RenderSettingsDoc& render);

  ExplorerSession& session_;
  gl::VolumeRenderer renderer_;
  gl::FrameTarget target_;
  // A still view refines target_ in bands over several frames; what is shown is the picture of
  // the last whole pass, copied here, so a frame never shows one band a sample ahead of the next
  // (nor a half-marched first pass) and the finish runs once a pass, not once a frame.
  gl::FrameTarget shownTarget_;
  bool showingTarget_ = false;     // target_ itself is shown (its last pass, marched while something changed, is whole)
  bool shownFinished_ = true;      // shownTarget_'s finish is whole (else strips of it are being finished)
  bool shownCopyOwed_ = false;     // a doubling of the samples waits for that finish to be shown
  bool shownWholeFinish_ = false;  // shownTarget_ holds a moving view's picture: finished whole at once
  bool shownHasPicture_ = false;   // shownTarget_ holds a whole pass
  RefineBands bands_;
  bool bandsRestart_ = true;
  bool restartAfterPass_ = false;  // the samples start over once the pass under way is whole
  int sampleBase_ = 0;             // the sample index of a pass-0 march: a band's pass n uses sampleBase_ + n
  int marchedRows_ = 0;
  double marchMs_ = -1.0, resolveMs_ = 0.0;
  bool lastInBands_ = false;   // the last frame refined a still view in bands
  double lastFinishMs_ = 0.0;  // ... and the finish of a new picture it ran (0: none)
  double testMsPerRow_ = 0.0;
  double testFrameMs_ = 0.0;
  // The volume picture stopped changing visibly: no more samples until the view or volume changes.
  bool settled_ = false;
  std::vector<std::uint8_t> settledReference_;  // the picture shown at the last check (RGBA8)
  double lastSettledShare_ = -1.0;
  int settledChecks_ = 0;
  // Compares the picture just drawn at `place` with the last check's (framebuffer bound).
  void checkSettled(unsigned framebuffer, glm::ivec4 place);
  // Finishes strips of `target` until it is whole or the frame begun at `frameStart` has used its
  // share of the budget (at least one strip); true when whole.
  bool finishStrips(const gl::FrameTarget& target, const gl::RenderSettings& settings,
                    std::chrono::steady_clock::time_point frameStart);

  // The points picture (points method): made on LivePoints' thread once the view and pattern are
  // still and the main grid shows the pattern, shown from pointsTarget_ once it has more points
  // than kPointsShownShare of its count.
  struct PointsKey {
    std::uint64_t pattern = 0, view = 0, points = 0, seed = 0;
    int width = 0, height = 0, oversample = 0;
    double fieldDeg = 0.0, orthoHeight = 0.0;
    // What only stills read (no view revision follows them) but the projection uses.
    double dofAperture = 0.0, dofFocusDistance = 0.0, fog = 0.0;
    bool operator==(const PointsKey&) const = default;
  };
  LivePoints points_;
  std::optional<PointsKey> pointsKey_;  // what the run under way (or done) projects
  gl::FrameTarget pointsTarget_;
  bool pointsHavePicture_ = false;  // pointsTarget_ holds a picture of the run under way
  bool pointsShown_ = false;
  bool pointsFailed_ = false;   // the run for pointsKey_ stopped on an error: the volume picture stays
  bool pointsBlocked_ = false;  // the pattern escapes: the grid shows the last bounded one, not the scene's
  bool pointsCurrent_ = true;   // the picture drawn is the newest taken, finished whole
  double pointsNextShare_ = kPointsShownShare;  // of the points, for the next picture taken
  bool pointsMethod_ = false;                   // of the last frame's scene
  std::uint64_t lastPost_ = 0;                  // the newest post made
  std::uint64_t pointsGridPoints_ = 0;          // the points of the grid the points run is dimmed by
  core::DensityImage pointsImage_;              // the newest points picture taken, before its upload
  void stopPoints();
  // Starts, stops and takes the points picture for this frame; true when a new one was uploaded
  // and is shown.
  bool updatePoints(const core::Scene& scene, const LiveInputs& inputs, const gl::RenderSettings& settings, bool still,
                    int width, int height);
  // The volume being uploaded or shown, shared with a shadow job that may still read it; the next
  // volume is swapped into it once uploaded (or into a fresh one while a shadow job holds it).
  std::shared_ptr<core::PackedVolume> shown_ = std::make_shared<core::PackedVolume>();
  bool uploadInProgress_ = false;
  std::size_t uploadedBytes_ = 0;  // of the volume uploading
  double uploadMsPerByte_ = -1.0;  // what uploads have cost (negative: none measured yet)
  bool changedLastFrame_ = false;  // the view or pattern changed in the previous frame
  std::uint64_t uploadingPost_ = 0;
  bool newVolumeShown_ = false;
  std::uint64_t shownPost_ = 0;  // the post of the volume drawn (main grid or proxy)
  // The main grid: the generation of its last complete volume (its post is the session's
  // shownMainPost()), and whether a volume of another generation is streaming into it.
  std::uint64_t mainGeneration_ = 0;
  bool mainMixed_ = false;
  bool mainMixedShown() const { return mainMixed_ && renderer_.marchedSource() == gl::VolumeRenderer::Source::Main; }
  // The proxy: shown after an edit until the main grid takes over.
  std::shared_ptr<core::PackedVolume> proxyShown_ = std::make_shared<core::PackedVolume>();
  std::shared_ptr<core::PackedVolume> proxySpare_ = std::make_shared<core::PackedVolume>();

  BackgroundJob<core::ShadowVolume> shadowJob_;
  struct ShadowInputs {
    bool proxy = false;
    std::uint64_t volumeVersion = 0;
    double azimuthDeg = 0.0, elevationDeg = 0.0;
    bool operator==(const ShadowInputs&) const = default;
  };
  std::optional<ShadowInputs> shadowShown_;  // what the uploaded (or computing) shadow was made from
  glm::ivec3 shadowSourceSize_{0};           // ... and the size of that volume's grid

  // The pattern count last posted to the session, and the view count the samples were started
  // for (none: start over, as after a new mesh).
  std::optional<std::uint64_t> postedPattern_;
  // What a ray sees besides the volume: when it changes, the sample average starts over.
  std::optional<std::uint64_t> shownView_;
  glm::ivec4 lastPlace_{0};  // where the last frame drew its picture
  int lastWidth_ = 0, lastHeight_ = 0;
  double lastFieldDeg_ = 0.0, lastOrthoHeight_ = 0.0;  // the view camera's field, widened for the export (viewCamera)
  float lastRenderScale_ = 0.0f;

  // The march scale follows the frame budget while something changes.
  FrameBudget budget_;
  std::optional<std::chrono::steady_clock::time_point> lastFrameStart_;
  float lastMarchScale_ = 0.0f;
  bool lastMarched_ = false;

  // Edit-to-frame timing: the post being waited for and when it was made.
  std::uint64_t waitingPost_ = 0;
  std::uint64_t waitingFullPost_ = 0;  // the same post, until the full grid shows it
  std::chrono::steady_clock::time_point waitingSince_;
  std::uint32_t waitingSinceFrame_ = 0;
  std::uint32_t frame_ = 0;
};

// The frame's inputs from the explorer's state.
LiveInputs liveInputs(const ExplorerState& state);
// The explorer's frame: LiveView::frame of the document with the state's inputs, its samples and
// metrics into state.frame. The panels' requests are served after it (PanelRequests::serve).
LiveFrame liveFrame(LiveView& view, ExplorerState& state, int width, int height, unsigned framebuffer = 0);

}  // namespace voxflame::app
