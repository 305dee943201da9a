// The window loop's controller of the panels' requests (app::PanelRequests), driven headless as
// the window loop drives it after each live frame: save as takes the picture the live view just
// drew, at its place in the framebuffer, as the thumbnail; Save in the quit prompt quits once it
// worked and only then; refine further reaches the session; without a preset library or an export
// job a request leaves a notice.
#include <gtest/gtest.h>
#include <epoxy/gl.h>

#include <chrono>
#include <filesystem>

#include "core/packed_volume.h"
#include "core/scene.h"
#include "core/scene_io.h"
#include "explorer_session.h"
#include "explorer_ui.h"
#include "export_job.h"
#include "gl/canvas.h"
#include "gl/headless_context.h"
#include "live_view.h"
#include "panel_requests.h"
#include "preset_library.h"
#include "test_support.h"
#include "wait_for.h"

using namespace voxflame;
using voxflame::test::TemporaryFolder;

namespace {

constexpr int kWidth = 160, kHeight = 96;

class PanelRequestsTest : public ::testing::Test {
 protected:
  gl::HeadlessContext context;
  gl::Canvas canvas{kWidth, kHeight};
  app::ExplorerSession session{1, std::chrono::milliseconds(100)};
  app::ExplorerState state;
  TemporaryFolder folder;

  void SetUp() override {
    ASSERT_TRUE(canvas.complete());
    core::Scene scene = core::defaultScene();
    scene.gridResolution = 32;
    app::resetExplorerState(state, scene);
  }
};

// Fills `rect` (x, y from the bottom, width, height) of the bound framebuffer with one colour.
void paint(glm::ivec4 rect, float r, float g, float b) {
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect.x, rect.y, rect.z, rect.w);
  glClearColor(r, g, b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
}

TEST_F(PanelRequestsTest, SaveAsTakesThePictureJustDrawnInTheViewsPlaceAsItsThumbnail) {
  app::PresetLibrary presets(folder.path() / "shipped", folder.path() / "mine");
  app::LiveView view(session);
  app::PanelRequests requests(session, &presets, nullptr);
  // The space the docked panels leave; the live frame draws there and records it.
  const glm::ivec4 place(24, 12, 112, 72);
  state.frame.viewRect = place;
  app::liveFrame(view, state, kWidth, kHeight, canvas.framebuffer());
  // What the frame drew, made recognisable: green around the view, the view's upper half red and
  // its lower half blue (GL counts rows from the bottom; a thumbnail's run top to bottom).
  glBindFramebuffer(GL_FRAMEBUFFER, canvas.framebuffer());
  paint({0, 0, kWidth, kHeight}, 0.0f, 1.0f, 0.0f);
  paint({place.x, place.y + place.w / 2, place.z, place.w / 2}, 1.0f, 0.0f, 0.0f);
  paint({place.x, place.y, place.z, place.w / 2}, 0.0f, 0.0f, 1.0f);

  state.frame.requests.saveAs = "Red over blue";
  requests.serve(state, view, canvas.framebuffer());
  EXPECT_FALSE(state.frame.requests.saveAs) << "the request was served";
  ASSERT_EQ(state.panels.scene.presetMessage.rfind("saved ", 0), 0u)
      << state.panels.scene.presetMessage << state.panels.prompts.notice;
  const std::filesystem::path saved = state.panels.scene.presetMessage.substr(6);
  EXPECT_EQ(state.document.scene.name, "Red over blue");
  EXPECT_FALSE(app::hasUnsavedChanges(state)) << "the document is the preset just saved";

  std::filesystem::path png = saved;
  png.replace_extension(".png");
  const app::Thumbnail thumbnail = app::decodeThumbnail(png, app::kSavedThumbnailWidth);
  ASSERT_EQ(thumbnail.width, place.z) << "the view's rectangle, not the framebuffer";
  ASSERT_EQ(thumbnail.height, place.w);
  int red = 0, blue = 0, other = 0;
  for (int y = 0; y < thumbnail.height; ++y)
    for (int x = 0; x < thumbnail.width; ++x) {
      const std::uint8_t* p = &thumbnail.rgba[4 * (static_cast<std::size_t>(y) * thumbnail.width + x)];
      const bool isRed = p[0] > 200 && p[1] < 50 && p[2] < 50, isBlue = p[0] < 50 && p[1] < 50 && p[2] > 200;
      const bool upper = y < thumbnail.height / 2;
      red += upper && isRed;
      blue += !upper && isBlue;
      other += !(upper ? isRed : isBlue);
    }
  EXPECT_EQ(other, 0) << red << " red and " << blue << " blue pixels where they belong";
  EXPECT_EQ(red + blue, place.z * place.w);
}

TEST_F(PanelRequestsTest, SaveInTheQuitPromptQuitsOnceTheSaveWorkedAndOnlyThen) {
  app::PresetLibrary presets(folder.path() / "shipped", folder.path() / "mine");
  app::LiveView view(session);
  app::PanelRequests requests(session, &presets, nullptr);
  app::liveFrame(view, state, kWidth, kHeight, canvas.framebuffer());
  state.frame.requests.saveAs = "Kept";
  requests.serve(state, view, canvas.framebuffer());
  ASSERT_EQ(state.document.scene.name, "Kept") << state.panels.prompts.notice;
  EXPECT_FALSE(state.frame.requests.quit) << "a save outside the quit prompt does not quit";

  // Save chosen in the quit prompt, under a name that is taken and not to be replaced: the save
  // fails, the notice says why, and the explorer stays.
  state.document.replace([&] {
    core::Scene changed = state.document.scene;
    changed.seed += 1;
    return changed;
  }());
  state.panels.prompts.quitAfterSave = true;
  state.frame.requests.saveAs = "Kept";
  requests.serve(state, view, canvas.framebuffer());
  EXPECT_FALSE(state.frame.requests.quit) << "quit although the changes were not saved";
  EXPECT_FALSE(state.panels.prompts.quitAfterSave);
  EXPECT_NE(state.panels.prompts.notice.find("already exists"), std::string::npos) << state.panels.prompts.notice;
  EXPECT_TRUE(app::hasUnsavedChanges(state));

  // Replacing it works, and then the prompt's Save quits.
  state.panels.prompts.quitAfterSave = true;
  state.frame.requests.saveAs = "Kept";
  state.frame.requests.saveReplacing = true;
  requests.serve(state, view, canvas.framebuffer());
  EXPECT_TRUE(state.frame.requests.quit);
  EXPECT_FALSE(app::hasUnsavedChanges(state));
}

TEST_F(PanelRequestsTest, WithoutAPresetLibraryOrAnExportJobARequestLeavesANotice) {
  app::LiveView view(session);
  app::PanelRequests requests(session, nullptr, nullptr);
  app::liveFrame(view, state, kWidth, kHeight, canvas.framebuffer());
  const std::string name = state.document.scene.name;
  state.frame.requests.saveAs = "Nowhere";
  requests.serve(state, view, canvas.framebuffer());
  EXPECT_FALSE(state.frame.requests.saveAs);
  EXPECT_EQ(state.panels.prompts.notice, "there is no preset library to save into");
  EXPECT_EQ(state.document.scene.name, name);

  state.frame.requests.exportStill = app::ExportRequest{};
  requests.serve(state, view, canvas.framebuffer());
  EXPECT_FALSE(state.frame.requests.exportStill);
  EXPECT_EQ(state.panels.prompts.notice, "exports are not available here");
}

// "Refine further" goes to the session: a grid resting at its cap refines on to twice its points.
TEST_F(PanelRequestsTest, RefineFurtherReachesTheSession) {
  app::LiveView view(session);
  app::PanelRequests requests(session, nullptr, nullptr);
  core::Scene scene = state.document.scene;
  scene.gridResolution = 32;  // the smallest grid: its cap of points is reached within seconds
  session.setRefinement(1e-6, false);
  session.post(scene);
  // The volumes are taken as the live view takes them: a session rests once its last is taken.
  core::PackedVolume volume;
  const auto rests = [&] {
    session.takeVolumeIfNewer(volume);
    return session.status().resting;
  };
  ASSERT_TRUE(test::waitForSession(session, rests)) << session.status().stats.points << " points";
  const app::SessionStatus capped = session.status();
  ASSERT_TRUE(capped.capped);
  state.frame.requests.refineFurther = true;
  requests.serve(state, view, canvas.framebuffer());
  EXPECT_FALSE(state.frame.requests.refineFurther) << "the request was served";
  EXPECT_TRUE(test::waitForSession(session,
                                   [&] { return rests() && session.status().stats.points >= 2 * capped.stats.points; }))
      << session.status().stats.points << " points after " << capped.stats.points;
}

}  // namespace
