// The explorer's frame body (app::LiveView) driven headless, exactly as the window loop and
// `bench explorer` drive it: a pattern edit reaches the screen tagged with its post, the sample
// average restarts only for changes a ray sees, and save-as and export requests are answered
// whether or not a volume is shown.
#include <functional>
#include <gtest/gtest.h>
#include <epoxy/gl.h>

#include <chrono>
#include <optional>
#include <cstdlib>
#include <fstream>

#include "core/camera.h"
#include "core/image_io.h"
#include "core/image_metrics.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "explorer_session.h"
#include "export_job.h"
#include "gl_test_support.h"
#include "gl/canvas.h"
#include "gl/gpu_accumulator.h"
#include "gl/headless_context.h"
#include "gl/read_back.h"
#include "live_view.h"
#include "panel_requests.h"
#include "pipeline.h"
#include "preset_library.h"
#include "test_support.h"
#include "wait_for.h"

using namespace voxflame;
using voxflame::test::TemporaryFolder;

namespace {

constexpr int kWidth = 160, kHeight = 96;

// An offscreen colour buffer standing in for the window's, so the picture can be read back.
class Canvas : public gl::Canvas {
 public:
  Canvas() : gl::Canvas(kWidth, kHeight) {}
  // The mean of all channels over the picture, 0–255.
  double meanBrightness() const {
    const std::vector<std::uint8_t> rgba = pixels();
    double sum = 0.0;
    for (std::size_t i = 0; i < rgba.size(); i += 4) sum += rgba[i] + rgba[i + 1] + rgba[i + 2];
    return sum / (3.0 * kWidth * kHeight);
  }
  // Writes the picture as a PNG when VOXFLAME_TEST_IMAGES names a folder (to look at by eye).
  void save(const std::string& name) const {
    const char* folder = std::getenv("VOXFLAME_TEST_IMAGES");
    if (!folder) return;
    const std::vector<std::uint8_t> rgba = pixels();
    core::ImageRGBA image;
    image.width = kWidth;
    image.height = kHeight;
    image.pixels.resize(rgba.size());
    for (int y = 0; y < kHeight; ++y)  // read back bottom row first
      for (int x = 0; x < 4 * kWidth; ++x)
        image.pixels[static_cast<std::size_t>((kHeight - 1 - y) * 4 * kWidth + x)] =
            rgba[static_cast<std::size_t>(y * 4 * kWidth + x)] / 255.0f;
    core::writePng(std::filesystem::path(folder) / (name + ".png"), image, 8, {});
  }
  // The brightest channel value in the picture.
  int brightest() const {
    const std::vector<std::uint8_t> rgba = pixels();
    int most = 0;
    for (std::size_t i = 0; i < rgba.size(); i += 4)
      most = std::max({most, int(rgba[i]), int(rgba[i + 1]), int(rgba[i + 2])});
    return most;
  }
};

// Frames until the view and the session rest (three frames in a row at rest), or two minutes.
bool runUntilRest(app::ExplorerSession& session, app::LiveView& view, const std::function<void()>& frame);

class LiveViewTest : public ::testing::Test {
 protected:
  gl::HeadlessContext context;
  Canvas canvas;
  // Snapshots come when a pattern is applied and then twice a second.
  app::ExplorerSession session{1, std::chrono::milliseconds(500)};
  app::ExplorerState state;

  void SetUp() override {
    ASSERT_TRUE(canvas.complete());
    core::Scene scene = core::defaultScene();
    scene.gridResolution = 48;
    scene.tone.background = glm::vec3(0.0f);
    app::resetExplorerState(state, scene);
  }
  // A change to the scene as the panels make one: reported to the document with what it affects.
  void edit(const std::function<void(core::Scene&)>& change) {
    core::Scene changed = state.document.scene;
    change(changed);
    state.document.replace(changed);
  }
  // The view at rest with the explorer's "refine on" set to the CPU, then to the GPU, each in a
  // session of its own (`check` looks at each at rest; its pictures are saved as name_cpu and
  // name_gpu): how far apart the two pictures lie, as the summed channel differences over the CPU
  // picture's sum (1 where it is black).
  using RestCheck = std::function<void(app::BackendChoice, const app::SessionStatus&, const app::LiveView&)>;
  double restingPicturesApart(const std::string& name, const RestCheck& check) {
    std::vector<std::uint8_t> pictures[2];
    for (const app::BackendChoice choice : {app::BackendChoice::Cpu, app::BackendChoice::Gpu}) {
      SCOPED_TRACE(std::string(app::toString(choice)));
      app::ExplorerSession refining{1, std::chrono::milliseconds(50)};
      state.services.settings.refinementBackend = choice;
      app::LiveView view(refining);
      const bool rested =
          runUntilRest(refining, view, [&] { app::liveFrame(view, state, kWidth, kHeight, canvas.framebuffer()); });
      EXPECT_TRUE(rested);
      const app::SessionStatus status = refining.status();
      EXPECT_EQ(status.backend, choice == app::BackendChoice::Gpu ? core::BackendKind::Gpu : core::BackendKind::Cpu);
      check(choice, status, view);
      canvas.save(name + "_" + std::string(app::toString(choice)));
      pictures[choice == app::BackendChoice::Gpu ? 1 : 0] = canvas.pixels();
    }
    state.services.settings.refinementBackend = app::BackendChoice::Cpu;
    double difference = 0.0, total = 0.0;
    for (std::size_t i = 0; i < pictures[0].size(); i += 4)
      for (std::size_t c = 0; c < 3; ++c) {
        difference += std::abs(static_cast<int>(pictures[0][i + c]) - static_cast<int>(pictures[1][i + c]));
        total += pictures[0][i + c];
      }
    return total > 0.0 ? difference / total : 1.0;
  }
  // The panels' requests, served after each frame as the window loop serves them (when set).
  app::PanelRequests* panelRequests = nullptr;
  app::LiveFrame frame(app::LiveView& view) {
    const app::LiveFrame drawn = app::liveFrame(view, state, kWidth, kHeight, canvas.framebuffer());
    if (panelRequests) panelRequests->serve(state, view, canvas.framebuffer());
    return drawn;
  }
  // Runs a few frames, then on until the picture shown is a whole pass at the full scale (a
  // still view's first pass takes a few frames of bands, and a view change, such as the mesh
  // arriving, shows a lowered-scale picture until then).
  void refineAtFullScale(app::LiveView& view) {
    for (int i = 0; i < 400; ++i) {
      frame(view);
      if (i >= 6 && state.frame.metrics.marchScale == state.panels.scene.renderScale && state.frame.samples >= 1)
        return;
    }
  }
  // Runs frames as the window loop does until `done(frame)` holds: while the view has work of its
  // own (samples to march, an upload, the shadow or points thread) one frame follows another; once
  // it rests, the next frame waits for the session's news (a volume packed, a status changed), as
  // anything else would draw the same picture. False after the timeout.
  bool framesUntil(app::LiveView& view, const std::function<bool(const app::LiveFrame&)>& done,
                   std::chrono::duration<double> timeout = test::kEventTimeout) {
    const auto deadline = test::deadlineAfter(timeout);
    for (;;) {
      const std::uint64_t seen = session.news();
      if (done(frame(view))) return true;
      const std::chrono::duration<double> left = deadline - std::chrono::steady_clock::now();
      if (left.count() <= 0.0) return false;
      if (view.resting()) session.waitForNews(seen, left.count());
    }
  }
  // Runs frames until a volume of the newest post is on screen; false after 60 s.
  bool runUntilShown(app::LiveView& view) {
    return framesUntil(view, [&](const app::LiveFrame& shown) {
      return shown.newVolumeShown && shown.shownPost == session.status().requestedGeneration;
    });
  }
};

TEST_F(LiveViewTest, AnEditReachesTheScreenTaggedWithItsPost) {
  app::LiveView view(session);
  const app::LiveFrame first = frame(view);
  EXPECT_TRUE(first.patternPosted) << "the first frame posts the scene";
  EXPECT_FALSE(first.volumeDrawn);
  ASSERT_TRUE(runUntilShown(view));
  EXPECT_TRUE(view.hasVolume());
  // The first snapshot comes as the pattern starts; a later one has points to show.
  EXPECT_TRUE(framesUntil(view, [&](const app::LiveFrame&) { return canvas.brightest() > 40; }))
      << "the pattern is drawn into the framebuffer given";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  // A parameter edit: posted by the next frame, shown later with the edit-to-frame metrics.
  edit([&](core::Scene& scene) { scene.layers[0].params[0] *= 1.02; });
  const app::LiveFrame edited = frame(view);
  EXPECT_TRUE(edited.patternPosted);
  ASSERT_TRUE(runUntilShown(view));
  EXPECT_GE(state.frame.metrics.changeToFrameFrames, 1);
  EXPECT_GE(state.frame.metrics.changeToFrameMs, 0.0);

  // A tone edit is not a pattern edit.
  edit([&](core::Scene& scene) { scene.tone.gamma += 0.3; });
  EXPECT_FALSE(frame(view).patternPosted);
}

TEST_F(LiveViewTest, LiveFramesReadNothingBack) {
  // The finish runs on the GPU: a frame that marches, finishes and draws (with the mesh ghost and
  // silhouette, and after a tone edit) never waits for the GPU to hand pixels back, except to see
  // whether a still picture has settled (once per doubling of its samples).
  app::LiveView view(session);
  frame(view);
  ASSERT_TRUE(runUntilShown(view));
  const std::uint64_t before = gl::readBackCount();
  const int checksBefore = view.settledChecks();
  int drawn = 0;
  for (int i = 0; i < 12; ++i) {
    if (i == 4) edit([&](core::Scene& scene) { scene.render.meshDisplay = core::MeshDisplay::Ghost; });
    if (i == 8) edit([&](core::Scene& scene) { scene.render.meshDisplay = core::MeshDisplay::Silhouette; });
    if (i == 10) edit([&](core::Scene& scene) { scene.tone.gamma += 0.3; });
    drawn += frame(view).volumeDrawn ? 1 : 0;
  }
  EXPECT_GT(drawn, 0);
  const std::uint64_t checked = before + static_cast<std::uint64_t>(view.settledChecks() - checksBefore);
  EXPECT_EQ(gl::readBackCount(), checked) << "a live frame read pixels back";
  EXPECT_GT(canvas.brightest(), 0);
  EXPECT_EQ(gl::readBackCount(), checked + 1) << "the counter counts a read-back";
}

TEST_F(LiveViewTest, SamplesRestartForTheCameraButNotForTheTone) {
  app::LiveView view(session);
  frame(view);
  ASSERT_TRUE(runUntilShown(view));
  // Frames until the still view has added up a few samples: the shadow job landing, a fresh
  // snapshot or the frame budget settling may each restart the average once on the way.
  framesUntil(view, [&](const app::LiveFrame&) { return state.frame.samples >= 3; });
  const int refined = state.frame.samples;
  ASSERT_GT(refined, 1);
  edit([&](core::Scene& scene) { scene.tone.gamma += 0.5; });
  frame(view);
  // Either the average went on (a still view refines in bands, so a frame may end no pass), or a
  // fresh snapshot restarted it: never because of the tone.
  const int afterTone = state.frame.samples;
  edit([&](core::Scene& scene) { scene.camera.azimuthDeg += 20.0; });
  frame(view);
  EXPECT_EQ(state.frame.samples, 1) << "a new camera starts the average over";
  EXPECT_TRUE(afterTone >= refined || afterTone <= 1);
}

TEST_F(LiveViewTest, SaveAsAndExportAreAnsweredBeforeAnyVolumeIsShown) {
  TemporaryFolder folder;
  // A mesh that cannot load: no shape, no volume, ever.
  const auto bad = folder.path() / "bad.obj";
  std::ofstream(bad) << "this is not a mesh\n";
  edit([&](core::Scene& scene) { scene.meshPath = bad.string(); });
  edit([&](core::Scene& scene) { scene.embedded = false; });
  app::PresetLibrary presets(folder.path() / "shipped", folder.path() / "mine");
  app::ExportJob exports;
  app::LiveView view(session);
  app::PanelRequests requests(session, &presets, &exports);
  panelRequests = &requests;
  frame(view);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  frame(view);
  ASSERT_FALSE(view.hasVolume());

  state.frame.requests.saveAs = "Saved while broken";
  const app::LiveFrame saved = frame(view);
  EXPECT_FALSE(saved.volumeDrawn);
  EXPECT_FALSE(state.frame.requests.saveAs.has_value()) << "the request was served";
  EXPECT_NE(state.panels.scene.presetMessage.find("saved"), std::string::npos)
      << state.panels.scene.presetMessage << state.panels.prompts.notice;
  int savedPresets = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder.path() / "mine"))
    if (entry.path().extension() == ".json") {
      ++savedPresets;
      EXPECT_EQ(core::loadScene(entry.path()).name, "Saved while broken");
    }
  EXPECT_EQ(savedPresets, 1) << state.panels.scene.presetMessage;

  app::ExportRequest request;
  request.scene = core::defaultScene();
  request.scene.gridResolution = 32;
  request.settings.width = 32;
  request.settings.height = 24;
  request.settings.samples = 1;
  request.settings.points = 50'000;
  request.output = folder.path() / "still.png";
  request.executable = VOXFLAME_BINARY;
  state.frame.requests.exportStill = request;
  frame(view);
  EXPECT_FALSE(state.frame.requests.exportStill.has_value());
  EXPECT_NE(exports.poll().state, app::ExportState::Idle) << state.panels.prompts.notice;
}

TEST_F(LiveViewTest, TheProxyShowsAnEditFirstAndTheFullGridReplacesItAtTheSameBrightness) {
  // A grid large enough to have a proxy; a still view, refined at the full scale.
  edit([&](core::Scene& scene) { scene.gridResolution = 2 * app::ExplorerSession::kProxyAbove; });
  app::LiveView view(session);
  frame(view);
  ASSERT_TRUE(session.waitUntilApplied(120.0));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);

  // Frames until the full grid shows the newest post, noting what came first. With `measure`, the
  // proxy's picture and the full grid's are each refined a little and their brightness kept.
  struct Handover {
    bool proxyFirst = false;
    bool fullShown = false;
    double proxyBrightness = 0.0;
    double fullBrightness = 0.0;
  };
  const auto watch = [&](bool measure) {
    const std::uint64_t post = session.status().requestedGeneration;
    Handover seen;
    bool anyShown = false;
    int framesSinceNewVolume = 0;
    while (std::chrono::steady_clock::now() < deadline) {
      const app::LiveFrame shown = frame(view);
      ++framesSinceNewVolume;
      // A volume of the post before can still arrive while the worker takes up this one.
      if (shown.newVolumeShown && shown.shownPost < post) continue;
      if (shown.newVolumeShown) {
        EXPECT_EQ(shown.shownPost, post) << "only volumes of the newest post are shown";
        if (!anyShown) seen.proxyFirst = !shown.fullShown;
        anyShown = true;
        framesSinceNewVolume = 0;
      }
      if (!anyShown) continue;
      seen.fullShown = seen.fullShown || shown.fullShown;
      if (!measure) {
        if (seen.fullShown) break;
        continue;
      }
      // Each picture as a user would see it: refined a little at the full scale. The proxy may be
      // replaced before that; its brightness then stays unmeasured.
      const bool refined = framesSinceNewVolume >= 1 && shown.volumeDrawn &&
                           state.frame.metrics.marchScale == state.panels.scene.renderScale && state.frame.samples >= 1;
      if (!refined) continue;
      if (shown.fullShown) {
        seen.fullBrightness = canvas.meanBrightness();
        canvas.save("full");
        break;
      }
      if (seen.proxyBrightness == 0.0) {
        seen.proxyBrightness = canvas.meanBrightness();
        canvas.save("proxy");
      }
    }
    return seen;
  };
  // A new post: the pattern nudged, so the large grid starts over.
  const auto nudge = [&] {
    edit([&](core::Scene& scene) { scene.layers[0].params[0] *= 1.02; });
    return frame(view).patternPosted;
  };

  // The proxy fills in tens of milliseconds, the large grid in hundreds, so the proxy normally
  // shows first. On a machine loaded by other work a frame can come late enough that the large
  // grid is ready too; it then rightly replaces the proxy in that same frame, and a new edit tries
  // again. A live view that never showed the proxy first would fail every try.
  Handover first = watch(true);
  for (int retry = 0; retry < 3 && first.fullShown && (!first.proxyFirst || first.proxyBrightness == 0.0); ++retry) {
    ASSERT_TRUE(nudge());
    first = watch(true);
  }
  EXPECT_TRUE(first.proxyFirst) << "the first image after a post comes from the proxy";
  ASSERT_TRUE(first.fullShown) << "the full grid replaces the proxy";
  ASSERT_GT(first.proxyBrightness, 2.0) << "the proxy drew the pattern";
  // The same pattern on a grid eight times finer: a sharper picture, not a brighter or darker one.
  EXPECT_NEAR(first.fullBrightness / first.proxyBrightness, 1.0, 0.2)
      << first.proxyBrightness << " vs " << first.fullBrightness;
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));

  // Once the full grid shows a pattern, an edit again shows the proxy of the new post before the
  // full grid shows it.
  Handover edited;
  for (int attempt = 0; attempt < 4 && !edited.proxyFirst; ++attempt) {
    ASSERT_TRUE(nudge());
    edited = watch(false);
    ASSERT_TRUE(edited.fullShown) << "the full grid shows the edit";
  }
  EXPECT_TRUE(edited.proxyFirst);
}

// The first edit of a slider drag (the panels say a widget is held) already finds the large grid
// held: only the proxy runs it, and the large grid gets the pattern the drag ends on.
TEST_F(LiveViewTest, TheFirstEditOfADragLeavesTheLargeGridHeld) {
  edit([&](core::Scene& scene) { scene.gridResolution = 2 * app::ExplorerSession::kProxyAbove; });
  app::LiveView view(session);
  frame(view);
  ASSERT_TRUE(session.waitUntilApplied(120.0));
  ASSERT_TRUE(runUntilShown(view));
  const std::uint64_t generation = session.status().stats.generation;
  const std::uint64_t proxyGeneration = session.proxyStats().value().generation;

  state.frame.interacting = true;  // the slider is pressed on this frame and moves at once
  edit([&](core::Scene& scene) { scene.layers[0].params[0] *= 1.02; });
  ASSERT_TRUE(frame(view).patternPosted);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  // The proxy runs the drag's edit to the end of its burst; all that while, and after, the large
  // grid stays on the pattern before the drag.
  ASSERT_TRUE(test::waitForSession(session, [&] {
    const std::optional<core::AccumulatorStats> proxy = session.proxyStats();
    return proxy && proxy->generation > proxyGeneration && proxy->done;
  }));
  EXPECT_EQ(session.status().stats.generation, generation) << "the large grid never started on the drag's edit";

  // The next frame without an edit ends the drag, and the large grid takes the pattern.
  framesUntil(view, [&](const app::LiveFrame&) { return session.status().stats.generation != generation; });
  EXPECT_GT(session.status().stats.generation, generation) << "the grid refines the pattern the drag stopped on";
  EXPECT_TRUE(runUntilShown(view));
}

TEST_F(LiveViewTest, SlowFramesWhileTheCameraMovesLowerTheMarchScale) {
  state.panels.scene.renderScale = 1.0f;
  state.panels.scene.frameBudgetMs = 10.0f;
  app::LiveView view(session);
  frame(view);
  ASSERT_TRUE(runUntilShown(view));
  for (int i = 0; i < app::FrameBudget::kQuietFrames + 1; ++i) frame(view);
  EXPECT_EQ(state.frame.metrics.marchScale, 1.0f) << "a still view is marched at the preview scale";
  // An orbit whose frames take far longer than the budget (a slow machine: each is taken to cost
  // 60 ms more, which the frame after it measures).
  for (int i = 0; i < 4; ++i) {
    edit([&](core::Scene& scene) { scene.camera.azimuthDeg += 3.0; });
    frame(view);
    view.addFrameCostForTesting(60.0);
  }
  EXPECT_LT(state.frame.metrics.marchScale, 0.5f);
  EXPECT_GE(state.frame.metrics.marchScale, app::FrameBudget::kDefaultFloor);
  // Let go: the still view goes back to the preview scale and refines (its first frame measures
  // the orbit's last).
  frame(view);
  view.addFrameCostForTesting(0.0);
  for (int i = 1; i < app::FrameBudget::kQuietFrames + 2; ++i) frame(view);
  EXPECT_EQ(state.frame.metrics.marchScale, 1.0f);
  // Samples add up there. A fresh snapshot of the volume restarts them, and on a slow machine (a
  // sanitizer build) a pass of bands can take longer than the snapshots' half second: so frames
  // go on until the second sample or a generous deadline, by which the grid has stopped refining.
  const auto deadline = test::deadlineAfter(test::kEventTimeout);
  while (state.frame.samples <= 1 && std::chrono::steady_clock::now() < deadline) frame(view);
  EXPECT_GT(state.frame.samples, 1);
  EXPECT_EQ(state.frame.metrics.marchScale, 1.0f);
}

// Playback is not held to the preview scale (a still view's, half the pixels on software GL):
// frames within their budget go as sharp as the whole window; an orbit stays under the preview scale.
TEST_F(LiveViewTest, PlaybackFramesWithinTheirBudgetGoSharperThanThePreviewScale) {
  state.panels.scene.renderScale = 0.5f;
  state.panels.scene.frameBudgetMs = 2000.0f;  // every frame of this small picture is well within it
  app::LiveView view(session);
  frame(view);
  ASSERT_TRUE(runUntilShown(view));
  float orbitScale = 0.0f;
  for (int i = 0; i < 12; ++i) {
    edit([&](core::Scene& scene) { scene.camera.azimuthDeg += 3.0; });
    frame(view);
    orbitScale = std::max(orbitScale, state.frame.metrics.marchScale);
  }
  EXPECT_LE(orbitScale, 0.5f) << "changes outside playback stay at or under the preview scale";
  state.panels.timeline.playing = true;
  float playScale = 0.0f;
  for (int i = 0; i < 12; ++i) {
    edit([&](core::Scene& scene) { scene.camera.azimuthDeg += 3.0; });  // what playing a keyed orbit does each frame
    frame(view);
    playScale = state.frame.metrics.marchScale;
  }
  EXPECT_EQ(playScale, 1.0f) << "within budget, playback marches every pixel";
  // Over its budget, playback's scale comes down like any change's.
  state.panels.scene.frameBudgetMs = 5.0f;
  for (int i = 0; i < 6; ++i) {
    edit([&](core::Scene& scene) { scene.camera.azimuthDeg += 3.0; });
    frame(view);
    view.addFrameCostForTesting(40.0);  // a slow machine, as above
  }
  EXPECT_LT(state.frame.metrics.marchScale, 0.5f);
}

TEST_F(LiveViewTest, ASlowStillViewRefinesInBandsWithinItsBudgetUntilEveryBandHasItsSamples) {
  // A slow GPU, played by a march that costs 1 ms a row (96 ms for the whole 96-row target), under
  // a 20 ms budget: a still frame marches a few bands, never the whole target, and the bands
  // still all reach kMaxSamples. The session rests at a noise easily reached, so no new volume
  // restarts the average on the way.
  state.panels.scene.renderScale = 1.0f;
  state.panels.scene.frameBudgetMs = 20.0f;
  state.services.settings.refineUntilNoisePercent = 40.0;
  app::LiveView view(session);
  view.addMarchCostForTesting(1.0);
  frame(view);
  ASSERT_TRUE(runUntilShown(view));
  int bandFrames = 0, widestBand = 0, passEnds = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!view.resting() && std::chrono::steady_clock::now() < deadline) {
    const int before = view.refineBands().samples();
    frame(view);
    if (view.marchMs() >= 0.0) {  // a still frame, marched in bands
      ++bandFrames;
      widestBand = std::max(widestBand, view.marchedRows());
      passEnds += view.refineBands().samples() > before ? 1 : 0;
    }
  }
  ASSERT_TRUE(view.resting()) << "the picture did not converge: " << state.frame.samples << " samples";
  // Refining stops once a doubling of the samples changes no pixel visibly, at a power of two
  // from twice the first check on, and kMaxSamples at most.
  const int samples = state.frame.samples;
  EXPECT_GE(samples, 2 * app::LiveView::kFirstSettledCheck);
  EXPECT_LE(samples, app::LiveView::kMaxSamples);
  EXPECT_EQ(samples & (samples - 1), 0);
  EXPECT_TRUE(samples == app::LiveView::kMaxSamples || view.lastSettledShare() <= app::LiveView::kSettledShare);
  EXPECT_EQ(view.refineBands().samples(), samples);
  // The last doubling is finished in strips over the frames after its pass, and the bands of the
  // next pass go on meanwhile (should that picture not have settled, they are not lost): the view
  // rests on the finished picture, with every band at its samples and the first few a pass ahead.
  for (int row = 0; row < view.targetRows(); row += app::RefineBands::kBandRows) {
    EXPECT_GE(view.refineBands().samplesOfRow(row), samples) << "row " << row;
    EXPECT_LE(view.refineBands().samplesOfRow(row), samples + 1) << "row " << row;
  }
  EXPECT_EQ(view.targetRows(), kHeight);
  // 20 ms at 1 ms a row leaves room for a band or two, never the whole target.
  EXPECT_LT(widestBand, kHeight / 2);
  EXPECT_GE(bandFrames, 2 * samples) << "each pass took several frames";
  EXPECT_GE(passEnds, samples / 2);
  // Resting: no more marching.
  frame(view);
  EXPECT_EQ(view.marchedRows(), 0);
  EXPECT_GT(canvas.brightest(), 40) << "the converged picture is shown";
  canvas.save("live-view-bands-converged");
}

TEST_F(LiveViewTest, FresherVolumesComingFasterThanAPassStillGetShown) {
  // A march of 12 ms a row: a pass over the 96 rows takes longer than the session's 500 ms between
  // snapshots of the refining grid. Each fresher volume lets the pass under way finish (and be
  // shown) before the samples start over, so the picture keeps up with the grid.
  state.panels.scene.renderScale = 1.0f;
  state.panels.scene.frameBudgetMs = 20.0f;
  state.services.settings.refineUntilNoisePercent = 0.0;  // refine on: a fresh volume every snapshot
  app::LiveView view(session);
  view.addMarchCostForTesting(12.0);
  frame(view);
  ASSERT_TRUE(runUntilShown(view));
  int passesShown = 0, freshVolumes = 0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(8);
  while (std::chrono::steady_clock::now() < end) {
    // The grid's cap of points per voxel would end refinement within the window on this small grid.
    if (session.status().capped) session.refineFurther();
    const int before = view.refineBands().samples();
    const app::LiveFrame shown = frame(view);
    freshVolumes += shown.newVolumeShown ? 1 : 0;
    if (view.marchMs() >= 0.0 && view.refineBands().samples() != before) ++passesShown;
    if (view.marchMs() >= 0.0) {
      EXPECT_LT(view.marchedRows(), kHeight) << "a still frame marches bands";
    }
  }
  ASSERT_GE(freshVolumes, 3) << "the grid refined on";
  EXPECT_GE(passesShown, 3) << "whole passes were shown while fresher volumes kept coming (" << freshVolumes << ")";
}

// The lit pixels (any channel above `threshold` of 255) of an RGBA8 read-back (rows top down).
std::vector<bool> litFromReadBack(const std::vector<std::uint8_t>& rgba, int width, int height, int threshold) {
  std::vector<bool> lit(static_cast<std::size_t>(width) * height);
  for (std::size_t i = 0; i < lit.size(); ++i)
    lit[i] = std::max({rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2]}) > threshold;
  return lit;
}

double intersectionOverUnion(const std::vector<bool>& a, const std::vector<bool>& b) {
  std::size_t both = 0, either = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    both += a[i] && b[i];
    either += a[i] || b[i];
  }
  return either ? static_cast<double>(both) / static_cast<double>(either) : 0.0;
}

// An export uses the scene's camera exactly (zoomed with the wheel, panned), as the view shows it:
// at the view's size its lit area is the view's, and a wider picture is what the thin frame in
// the view holds (the view widens its field so the whole picture shows within it).
TEST_F(LiveViewTest, AnExportFramesWhatTheViewShows) {
  edit([&](core::Scene& scene) { scene.camera.distance *= 0.8; });  // what the wheel does
  edit([&](core::Scene& scene) { scene.camera.target = glm::dvec3(0.08, -0.05, 0.0); });
  state.frame.viewRect = glm::ivec4(24, 12, 112, 72);  // the space the docked panels leave
  const glm::ivec4 rect = state.frame.viewRect;
  app::LiveView view(session);
  // The view's refined picture for an export of width × height, as lit pixels (rows top down).
  auto viewLit = [&](int width, int height) {
    state.services.settings.lastExport.width = width;
    state.services.settings.lastExport.height = height;
    for (int i = 0; i < 3; ++i) frame(view);
    refineAtFullScale(view);
    for (int i = 0; i < 60; ++i) frame(view);
    const std::vector<std::uint8_t> shown =
        gl::readRgba8(canvas.framebuffer(), {rect.x, rect.y, rect.z, rect.w}, gl::ReadAlpha::Opaque);
    return litFromReadBack(shown, rect.z, rect.w, 30);
  };
  auto exportedLit = [&](int width, int height, int rows, int columns, double step) {
    app::StillOptions options;
    options.width = width;
    options.height = height;
    options.points = 4'000'000;
    const core::ImageRGBA image = app::renderStill(state.document.scene, options).image;
    std::vector<bool> lit(static_cast<std::size_t>(columns) * rows);
    for (int y = 0; y < rows; ++y)
      for (int x = 0; x < columns; ++x) {
        const float* p = image.at(std::min(image.width - 1, static_cast<int>((x + 0.5) * step)),
                                  std::min(image.height - 1, static_cast<int>((y + 0.5) * step)));
        lit[static_cast<std::size_t>(y) * columns + x] = 255.0f * std::max({p[0], p[1], p[2]}) > 30.0f;
      }
    return lit;
  };
  ASSERT_TRUE(runUntilShown(view));
  framesUntil(view, [&](const app::LiveFrame&) {
    const app::SessionStatus status = session.status();
    return (status.resting && status.stats.points >= 2'000'000) || status.stats.points > 20'000'000;
  });

  // The view's pictures first: a still render makes a GL context of its own current.
  const std::vector<bool> same = viewLit(rect.z, rect.w);
  const std::vector<bool> wideView = viewLit(2 * rect.z, rect.z);  // twice as wide as high
  std::size_t litCount = 0;
  for (bool lit : same) litCount += lit;
  EXPECT_GT(litCount, same.size() / 10) << "the view shows the pattern";
  EXPECT_GE(intersectionOverUnion(same, exportedLit(rect.z, rect.w, rect.w, rect.z, 1.0)), 0.95)
      << "an export at the view's size frames another picture";

  // The wide picture's frame spans the view's width and its middle rows.
  const glm::dvec4 frameRect = core::exportFrame(glm::dvec2(rect.z, rect.w), 2.0);
  const int top = static_cast<int>(std::lround(rect.w - frameRect.y - frameRect.w));
  const int rows = static_cast<int>(std::lround(frameRect.w));
  std::vector<bool> framed;
  for (int y = top; y < top + rows; ++y)
    for (int x = 0; x < rect.z; ++x) framed.push_back(wideView[static_cast<std::size_t>(y) * rect.z + x]);
  EXPECT_GE(intersectionOverUnion(framed, exportedLit(2 * rect.z, rect.z, rows, rect.z, 2.0)), 0.9)
      << "a wider export shows what its frame in the view shows";
}

// The canvas as an image (rows top to bottom, values in [0, 1]).
core::ImageRGBA canvasImage(const Canvas& canvas) {
  const std::vector<std::uint8_t> rgba = canvas.pixels();
  core::ImageRGBA image;
  image.width = kWidth;
  image.height = kHeight;
  image.pixels.resize(rgba.size());
  for (std::size_t i = 0; i < rgba.size(); ++i) image.pixels[i] = rgba[i] / 255.0f;  // rows top to bottom
  return image;
}

TEST_F(LiveViewTest, AStillViewMarchesAtFullResolutionWhateverThePreviewScale) {
  // Software GL previews at half the pixels while something moves; once still, the view refines
  // every pixel, as an export of it does.
  state.panels.scene.renderScale = 0.5f;
  app::LiveView view(session);
  frame(view);
  ASSERT_TRUE(runUntilShown(view));
  edit([&](core::Scene& scene) { scene.camera.azimuthDeg += 20.0; });
  frame(view);
  EXPECT_LT(view.targetRows(), kHeight) << "a moving view marches at the preview scale or below";
  for (int i = 0; i < 400 && !(state.frame.samples >= 2 && view.targetRows() == kHeight); ++i) frame(view);
  EXPECT_EQ(view.targetRows(), kHeight) << "a still view marches at the full resolution";
  EXPECT_EQ(state.frame.metrics.marchScale, 1.0f);
  EXPECT_GE(state.frame.samples, 2);
}

// Runs the view and the session until both rest (as the window loop sees it) for three frames in
// a row; false after 120 s.
bool runUntilRest(app::ExplorerSession& session, app::LiveView& view, const std::function<void()>& frame) {
  const auto deadline = test::deadlineAfter(std::chrono::seconds(120));
  int restingFrames = 0;
  while (std::chrono::steady_clock::now() < deadline && restingFrames < 3) {
    const std::uint64_t seen = session.news();
    frame();
    const bool sessionRests = session.status().resting;
    restingFrames = view.resting() && sessionRests ? restingFrames + 1 : 0;
    // A view at rest beside a session still at work: nothing to draw until the session has news.
    if (view.resting() && !sessionRests)
      session.waitForNews(seen, std::chrono::duration<double>(deadline - std::chrono::steady_clock::now()).count());
  }
  return restingFrames >= 3;
}

TEST_F(LiveViewTest, AVolumeViewAtRestIsAnExportOfTheView) {
  app::LiveView view(session);
  ASSERT_TRUE(runUntilRest(session, view, [&] { frame(view); }));
  // At rest nothing of the view's works, and the status line says so only now.
  EXPECT_EQ(app::convergenceText(session.status(), state.frame.view).rfind("at rest", 0), 0u)
      << app::convergenceText(session.status(), state.frame.view);
  EXPECT_GE(state.frame.samples, app::LiveView::kFirstSettledCheck);
  const core::ImageRGBA shown = canvasImage(canvas);
  canvas.save("volume-view-at-rest");
  // The view's picture first: a still render makes a GL context of its own current.
  app::StillOptions options;
  options.width = kWidth;
  options.height = kHeight;
  options.points = session.status().stats.points;
  core::Scene exported = state.document.scene;
  exported.render.samples = state.frame.samples;
  const core::ImageRGBA image = app::renderStill(exported, options).image;
  if (const char* folder = std::getenv("VOXFLAME_TEST_IMAGES"))
    core::writePng(std::filesystem::path(folder) / "volume-export-of-the-view.png", image, 8, {});
  EXPECT_GE(core::ssimLuma(shown, image), 0.98);
  const double ratio = core::meanLinearLuminance(shown) / core::meanLinearLuminance(image);
  EXPECT_GT(ratio, 0.97);
  EXPECT_LT(ratio, 1.03);
}

TEST_F(LiveViewTest, APointsViewBuildsUpRestartsWhenTheCameraMovesAndAtRestIsAnExportOfTheView) {
  edit([&](core::Scene& scene) {
    scene.render.method = core::RenderMethod::Points;
    scene.points = 3'000'000;
  });
  app::LiveView view(session);
  ASSERT_TRUE(runUntilRest(session, view, [&] { frame(view); }));
  ASSERT_TRUE(view.pointsProgress().finished);
  EXPECT_TRUE(state.frame.view.pointsShown) << "the points picture replaced the volume picture";
  EXPECT_GE(view.pointsProgress().points, 3'000'000u);
  EXPECT_EQ(session.status().stats.points <= app::kGridPointsForPointsMethod + 2'000'000, true)
      << "the grid stops where an export's does";
  EXPECT_EQ(app::convergenceText(session.status(), state.frame.view).rfind("at rest", 0), 0u);
  const core::ImageRGBA shown = canvasImage(canvas);
  canvas.save("points-view-at-rest");

  // The camera moves: the volume preview takes over at once, and the points start again.
  edit([&](core::Scene& scene) { scene.camera.azimuthDeg += 30.0; });
  frame(view);
  EXPECT_FALSE(state.frame.view.pointsShown);
  EXPECT_FALSE(view.resting());
  bool buildingShown = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (std::chrono::steady_clock::now() < deadline && !view.resting()) {
    frame(view);  // the view works (its points thread): frames follow each other
    const std::string status = app::convergenceText(session.status(), state.frame.view);
    if (status.rfind("points: ", 0) == 0) buildingShown = true;
    if (!state.frame.view.resting) {
      EXPECT_NE(status.rfind("at rest", 0), 0u) << "at rest while the view still works";
    }
  }
  EXPECT_TRUE(buildingShown) << "the status line shows the points coming in";
  EXPECT_TRUE(state.frame.view.pointsShown);
  EXPECT_TRUE(view.pointsProgress().finished);

  app::StillOptions options;
  options.width = kWidth;
  options.height = kHeight;
  const core::ImageRGBA image = app::renderStill(state.document.scene, options).image;
  core::Scene before = state.document.scene;
  before.camera.azimuthDeg -= 30.0;
  const core::ImageRGBA imageBefore = app::renderStill(before, options).image;
  EXPECT_GE(core::ssimLuma(shown, imageBefore), 0.98);
  const double ratio = core::meanLinearLuminance(shown) / core::meanLinearLuminance(imageBefore);
  EXPECT_GT(ratio, 0.97);
  EXPECT_LT(ratio, 1.03);
  EXPECT_LT(core::ssimLuma(shown, image), core::ssimLuma(shown, imageBefore)) << "the turned view is another picture";
}

TEST_F(LiveViewTest, APointsViewWhosePatternEscapesRestsOnTheLastBoundedVolume) {
  // The grid keeps the last bounded pattern while the scene's escapes (b = 1.55 on escapes with
  // the default preset's step): the points cannot be projected, so the volume picture refines and
  // the view comes to rest on it.
  edit([&](core::Scene& scene) {
    scene.render.method = core::RenderMethod::Points;
    scene.points = 2'000'000;
  });
  app::LiveView view(session);
  ASSERT_TRUE(runUntilRest(session, view, [&] { frame(view); }));
  ASSERT_TRUE(state.frame.view.pointsShown);
  edit([&](core::Scene& scene) { scene.layers[0].params[1] = 2.0; });
  ASSERT_TRUE(runUntilRest(session, view, [&] { frame(view); })) << "the view never rested";
  EXPECT_FALSE(session.status().escapeNote.empty());
  EXPECT_FALSE(state.frame.view.pointsShown) << "the points of a pattern that escapes were shown";
  EXPECT_GT(canvas.brightest(), 40) << "the last bounded volume is shown";
}

}  // namespace

// The explorer's "refine on" setting reaches the session: with the GPU chosen, an attractor's
// large grid refines on the GPU backend and its volume reaches the view; a flame refines on the
// CPU and the status says why; back on the CPU the note goes.
TEST_F(LiveViewTest, TheRefinementBackendSettingPicksWhatRefinesTheLargeGrid) {
  app::ExplorerSession gpuSession{1, std::chrono::milliseconds(50)};
  gpuSession.setBackendChoice(app::BackendChoice::Gpu);
  core::Scene scene = core::defaultScene();
  scene.gridResolution = 48;
  gpuSession.post(scene);
  ASSERT_TRUE(gpuSession.waitUntilApplied(120.0));
  EXPECT_EQ(gpuSession.status().backend, core::BackendKind::Gpu) << gpuSession.status().backendNote;
  EXPECT_TRUE(gpuSession.status().backendNote.empty());
  core::PackedVolume volume;
  ASSERT_TRUE(test::waitForSession(gpuSession, [&] {
    return gpuSession.takeVolumeIfNewer(volume) && volume.points > 0 && volume.maxDensity > 0.0f;
  }));

  // A flame of the GPU's variations refines there; one with what it lacks (a weighting field on crackle's
  // parameters) falls back to the CPU, saying why.
  core::Scene flame = scene;
  flame.layers.front().kind = core::PatternKind::Flame;
  flame.layers.front().flame = core::defaultFlame();
  flame.layers.front().color.mode = core::ColorMode::Index;
  gpuSession.post(flame);
  ASSERT_TRUE(gpuSession.waitUntilApplied(120.0));
  EXPECT_EQ(gpuSession.status().backend, core::BackendKind::Gpu) << gpuSession.status().backendNote;
  core::Scene lacking = flame;
  test::addWhatTheGpuLacks(lacking.layers.front().flame.xforms.front());
  gpuSession.post(lacking);
  ASSERT_TRUE(gpuSession.waitUntilApplied(120.0));
  EXPECT_EQ(gpuSession.status().backend, core::BackendKind::Cpu);
  EXPECT_NE(gpuSession.status().backendNote.find("refining on the CPU"), std::string::npos)
      << gpuSession.status().backendNote;

  gpuSession.post(scene);
  ASSERT_TRUE(gpuSession.waitUntilApplied(120.0));
  EXPECT_EQ(gpuSession.status().backend, core::BackendKind::Gpu);
  gpuSession.setBackendChoice(app::BackendChoice::Cpu);  // posts the scene again itself
  ASSERT_TRUE(gpuSession.waitUntilApplied(120.0));
  EXPECT_EQ(gpuSession.status().backend, core::BackendKind::Cpu);
  EXPECT_TRUE(gpuSession.status().backendNote.empty());
}

// With the GPU backend the grid never leaves the device: the backend shares the view's context,
// packs its grid there, and the view copies it and sweeps its shadow there. The picture at rest is
// the one the CPU backend's grid gives (another sampling of the same pattern), lit alike.
TEST_F(LiveViewTest, TheGpuBackendsGridReachesTheViewOnTheGpuAndLooksLikeTheCpus) {
  // llvmpipe packs on the host otherwise.
  struct DevicePath {
    DevicePath() { gl::GpuAccumulator::setPackOnDeviceWithSoftwareRenderer(true); }
    ~DevicePath() { gl::GpuAccumulator::setPackOnDeviceWithSoftwareRenderer(false); }
  } devicePath;
  edit([&](core::Scene& scene) {
    scene.render.lighting = true;
    scene.points = 3'000'000;
  });
  const double apart = restingPicturesApart(
      "gpu_grid", [](app::BackendChoice choice, const app::SessionStatus& status, const app::LiveView&) {
        EXPECT_EQ(status.gridOnDevice, choice == app::BackendChoice::Gpu);
      });
  EXPECT_LT(apart, 0.08) << "the GPU's grid drew another picture";
}

// Under the points method a GPU session's grid is read back to host memory, where the points are
// dimmed by it (a hardware GPU projects them with gl::makeGpuProjectingBackend, which
// gpu_backend_test.cpp holds to the CPU's projector; llvmpipe projects on the CPU): the picture at
// rest is the CPU session's (another sampling of the same points), and the status names the GPU.
TEST_F(LiveViewTest, ThePointsViewOnTheGpuBackendIsTheCpusPicture) {
  struct DevicePath {  // the grid would reach the view on the GPU under the volume method
    DevicePath() { gl::GpuAccumulator::setPackOnDeviceWithSoftwareRenderer(true); }
    ~DevicePath() { gl::GpuAccumulator::setPackOnDeviceWithSoftwareRenderer(false); }
  } devicePath;
  edit([&](core::Scene& scene) {
    scene.render.method = core::RenderMethod::Points;
    scene.render.lighting = true;
    scene.points = 2'000'000;
  });
  const double apart = restingPicturesApart(
      "gpu_points", [&](app::BackendChoice, const app::SessionStatus& status, const app::LiveView& view) {
        EXPECT_FALSE(status.gridOnDevice) << "the points are dimmed by the grid in host memory";
        EXPECT_TRUE(view.pointsProgress().finished) << view.pointsProgress().error;
        EXPECT_TRUE(state.frame.view.pointsShown);
      });
  EXPECT_LT(apart, 0.08) << "the GPU's points drew another picture";
}

// The session's gridIdle on either backend (RefinementBackend::idle): false while the large grid
// refines, true once a hold has let the work under way land, and from then on the grid adds
// nothing for as long as the hold lasts (checked at the session's next news: a steer of its
// control thread, a look of its publishers).
TEST_F(LiveViewTest, AHeldGridOnEitherBackendBecomesIdleAndAddsNothing) {
  for (const app::BackendChoice choice : {app::BackendChoice::Cpu, app::BackendChoice::Gpu}) {
    app::ExplorerSession refining{1, std::chrono::milliseconds(50)};
    refining.setBackendChoice(choice);
    refining.setRefinement(0.0, false);  // refine until the next edit
    core::Scene scene = core::defaultScene();
    scene.gridResolution = 48;  // no proxy: the large grid is the only one
    refining.post(scene);
    ASSERT_TRUE(refining.waitUntilApplied(120.0));
    SCOPED_TRACE(std::string(core::toString(refining.status().backend)));
    ASSERT_TRUE(test::waitForSession(refining, [&] { return refining.status().stats.points > 100'000; }));
    EXPECT_FALSE(refining.gridIdle()) << "idle while it refines";
    refining.setRefinement(0.0, false, true, true);  // an orbit holds even a grid without a proxy
    ASSERT_TRUE(test::waitForSession(refining, [&] { return refining.gridIdle(); })) << "the held grid kept working";
    const std::uint64_t held = refining.status().stats.points;
    const std::uint64_t seen = refining.news();
    ASSERT_TRUE(refining.waitForNews(seen, 60.0));
    EXPECT_EQ(refining.status().stats.points, held) << "an idle grid added points";
    EXPECT_TRUE(refining.gridIdle());
    refining.setRefinement(0.0, false);  // the orbit ends: it refines again
    ASSERT_TRUE(test::waitForSession(refining, [&] { return refining.status().stats.points > held; }));
  }
}
