// The explorer's UI logic, driven like a user would: a headless ImGui context (no window, no GL)
// gets mouse and key input, the panels run, and the tests look at the Scene and the session.
#include <gtest/gtest.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <optional>
#include <functional>
#include <fstream>
#include <thread>
#include <set>
#include <sstream>
#include <filesystem>
#include <iterator>
#include <cmath>

#include "core/attractor.h"
#include "core/flame/search.h"
#include "core/flame/variations.h"
#include "core/scene_io.h"
#include "core/scene_schema.h"
#include "core/scene.h"
#include "explorer_session.h"
#include "explorer_ui.h"
#include "key_codes.h"
#include "preset_library.h"
#include "test_support.h"
#include "wait_for.h"

using namespace voxflame;
using voxflame::test::TemporaryFolder;

namespace {

class ExplorerUi : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280, 1600);  // tall, so every panel fits without scrolling
    io.DeltaTime = 1.0f / 60.0f;
    app::applyUiScale(1.0f);
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);  // what a renderer backend does
    // Nothing outside the window: the mouse starts over empty space in the middle.
    io.MousePos = ImVec2(640, 360);
    state.frame.probe = &probe;
    // Every frame of every test checks that the panels reported each edit they made, with what it
    // affects (the live view acts on those reports alone).
    state.frame.checkEditReports = true;
    app::resetExplorerState(state, core::defaultScene());
    frame();
    frame();
  }
  void TearDown() override { ImGui::DestroyContext(); }

  // A change to the scene made outside the panels, as the window loop or an import makes one:
  // reported to the document with what it affects.
  void edit(const std::function<void(core::Scene&)>& change) {
    core::Scene changed = state.document.scene;
    change(changed);
    state.document.replace(changed);
  }
  // Drags every widget drawn whose probe name starts with one of `prefixes` a little to the right
  // (a click, for buttons and check boxes), one at a time, with the frames checking the edit
  // reports (checkEditReports): a widget that changes the scene without saying what it affects
  // makes the frame throw. Returns how many widgets changed the scene.
  int dragEveryWidget(const std::vector<std::string>& prefixes, const std::vector<std::string>& skip) {
    std::vector<std::string> names;
    for (const auto& [name, rect] : probe.items)
      for (const std::string& prefix : prefixes)
        if (name.rfind(prefix, 0) == 0 && std::find(skip.begin(), skip.end(), name) == skip.end())
          names.push_back(name);
    int changed = 0;
    for (const std::string& name : names) {
      const auto found = probe.items.find(name);
      if (found == probe.items.end()) continue;  // gone since an earlier widget's edit
      const core::Scene before = state.document.scene;
      const std::uint64_t reports = state.document.revisions().any;
      drag(found->second.centerX(), found->second.centerY(), 12.0f, 0.0f);
      if (ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId)) {
        ImGui::GetIO().KeysDown[app::kKeyEscape] = true;  // close what the click opened (a combo)
        frame();
        ImGui::GetIO().KeysDown[app::kKeyEscape] = false;
        frame();
      }
      if (!(state.document.scene == before)) {
        ++changed;
        EXPECT_GT(state.document.revisions().any, reports) << name;
      }
    }
    return changed;
  }

  void frame(int count = 1) {
    for (int i = 0; i < count; ++i) {
      ImGui::NewFrame();
      app::explorerUiFrame(state);
      ImGui::Render();
    }
  }
  // Runs frames until `done()` holds, and between them sleeps until a background job whose result
  // a frame takes (search, analysis, flat render) has finished: a frame before that would change
  // nothing. A few frames run while no job is running (a frame may start one, or take a finished
  // one's result); false when that changes nothing, or after the timeout.
  bool framesUntil(const std::function<bool()>& done, std::chrono::duration<double> timeout = test::kEventTimeout) {
    const auto deadline = test::deadlineAfter(timeout);
    int idleFrames = 0;
    for (;;) {
      frame();
      if (done()) return true;
      const std::chrono::duration<double> left = deadline - std::chrono::steady_clock::now();
      if (left.count() <= 0.0) return false;
      app::Services& jobs = state.services;
      if (jobs.search.busy() && !jobs.search.ready()) {
        jobs.search.waitUntilReady(left);
      } else if (jobs.analysis.busy() && !jobs.analysis.ready()) {
        jobs.analysis.waitUntilReady(left);
      } else if (jobs.flatRender.busy() && !jobs.flatRender.ready()) {
        jobs.flatRender.waitUntilReady(left);
      } else if (++idleFrames > 3) {
        return done();
      } else {
        continue;
      }
      idleFrames = 0;
    }
  }
  app::UiProbe::Rect item(const std::string& name) {
    const auto found = probe.items.find(name);
    if (found == probe.items.end()) throw std::runtime_error("no widget named " + name + " was drawn");
    return found->second;
  }
  void moveTo(float x, float y) {
    ImGui::GetIO().MousePos = ImVec2(x, y);
    frame();
  }
  // Presses the button at the pointer, moves by (dx, dy) in a few steps, releases. A slider
  // jumps to where it is pressed; `pressed` runs right then, to note the value the drag starts from.
  void drag(float x, float y, float dx, float dy, int button = 0, const std::function<void()>& pressed = {}) {
    ImGuiIO& io = ImGui::GetIO();
    moveTo(x, y);
    io.MouseDown[button] = true;
    frame();
    if (pressed) pressed();
    for (int step = 1; step <= 4; ++step)
      moveTo(x + dx * static_cast<float>(step) / 4, y + dy * static_cast<float>(step) / 4);
    io.MouseDown[button] = false;
    frame(2);
  }
  void click(const std::string& name) {
    const auto& rect = item(name);
    ImGuiIO& io = ImGui::GetIO();
    moveTo(rect.centerX(), rect.centerY());
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame(2);
  }
  // Clicks a widget and stops right after the release frame, while the frame's requests to the
  // window loop (open a file, save) are still there to see.
  void clickForRequest(const std::string& name) {
    const auto rect = item(name);
    ImGuiIO& io = ImGui::GetIO();
    moveTo(rect.centerX(), rect.centerY());
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame();
  }
  void pressKey(int key, bool ctrl = false, bool shift = false) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = ctrl;
    io.KeyShift = shift;
    io.KeysDown[key] = true;
    frame();
    io.KeysDown[key] = false;
    io.KeyCtrl = io.KeyShift = false;
    frame(2);
  }

  app::UiProbe probe;
  app::ExplorerState state;
};

TEST_F(ExplorerUi, DraggingAParameterSliderChangesThePatternAndIsOneUndoStep) {
  const double before = state.document.scene.layers[0].params[0];
  const core::Scene keyBefore = state.document.scene;
  const auto& slider = item("layer0/a");
  double pressedAt = 0.0;
  bool interactingWhilePressed = false;
  drag(slider.minX + 4, slider.centerY(), 60.0f, 0.0f, 0, [&] {
    pressedAt = state.document.scene.layers[0].params[0];
    interactingWhilePressed = state.frame.interacting;
  });
  const double after = state.document.scene.layers[0].params[0];
  EXPECT_GT(after, pressedAt) << "dragging right raises the value";
  EXPECT_TRUE(interactingWhilePressed) << "from the frame it is pressed, a held slider tells the view a drag is on";
  EXPECT_FALSE(state.frame.interacting) << "and no longer once released";
  EXPECT_TRUE(core::diff(keyBefore, state.document.scene).pattern()) << "a parameter change restarts the accumulation";

  pressKey('Z', true);
  EXPECT_DOUBLE_EQ(state.document.scene.layers[0].params[0], before) << "the whole drag is one undo step";
  pressKey('Z', true, true);
  EXPECT_DOUBLE_EQ(state.document.scene.layers[0].params[0], after) << "Ctrl+Shift+Z redoes it";
}

TEST_F(ExplorerUi, ToneSlidersChangeTheLookButNotThePattern) {
  const core::Scene keyBefore = state.document.scene;
  double gamma = 0.0;
  const auto& slider = item("tone/gamma");
  drag(slider.centerX(), slider.centerY(), -50.0f, 0.0f, 0, [&] { gamma = state.document.scene.tone.gamma; });
  EXPECT_LT(state.document.scene.tone.gamma, gamma);
  EXPECT_FALSE(core::diff(keyBefore, state.document.scene).pattern()) << "tone mapping must not restart accumulation";
}

TEST_F(ExplorerUi, MouseOrbitsPansAndZoomsOutsideThePanels) {
  const core::CameraSettings before = state.document.scene.camera;
  bool interactingWhileOrbiting = false;
  drag(640, 360, 40, 0, 0, [&] { interactingWhileOrbiting = state.frame.interacting; });
  EXPECT_NE(state.document.scene.camera.azimuthDeg, before.azimuthDeg) << "left drag orbits";
  EXPECT_TRUE(interactingWhileOrbiting);
  EXPECT_FALSE(state.frame.interacting);
  drag(640, 360, 30, 20, 1);
  EXPECT_GT(glm::length(state.document.scene.camera.target - before.target), 0.0) << "right drag pans";
  ImGui::GetIO().MouseWheel = 1.0f;
  frame();
  ImGui::GetIO().MouseWheel = 0.0f;
  EXPECT_LT(state.document.scene.camera.distance, before.distance) << "the wheel zooms in";

  // The same drag starting on a panel belongs to the panel.
  const double azimuth = state.document.scene.camera.azimuthDeg;
  const auto& label = item("layer0/Reset parameters");
  drag(label.maxX + 120, label.centerY(), 40, 0);
  EXPECT_DOUBLE_EQ(state.document.scene.camera.azimuthDeg, azimuth);
}

TEST_F(ExplorerUi, LayersCanBeAddedWeightedAndRemoved) {
  click("Add layer");
  ASSERT_EQ(state.document.scene.layers.size(), 2u);
  EXPECT_NE(state.document.scene.layers[1].attractor, state.document.scene.layers[0].attractor);
  double weight = 0.0;
  const auto& slider = item("layer1/weight");
  drag(slider.minX + 4, slider.centerY(), 40, 0, 0, [&] { weight = state.document.scene.layers[1].weight; });
  EXPECT_GT(state.document.scene.layers[1].weight, weight);
  click("layer1/Remove layer");
  EXPECT_EQ(state.document.scene.layers.size(), 1u);
}

TEST_F(ExplorerUi, ResetParametersRestoresTheCatalogueDefaults) {
  const auto defaults = core::attractorOrThrow(state.document.scene.layers[0].attractor).defaultParams();
  edit([&](core::Scene& scene) { scene.layers[0].params[1] += 0.2; });
  frame();
  click("layer0/Reset parameters");
  EXPECT_EQ(state.document.scene.layers[0].params, defaults);
}

TEST_F(ExplorerUi, GradientStopsCanBeAddedAndMoved) {
  const std::size_t stops = state.document.scene.layers[0].color.gradient.size();
  click("layer0/Add stop");
  EXPECT_EQ(state.document.scene.layers[0].color.gradient.size(), stops + 1);
  EXPECT_TRUE(state.document.scene.layers[0].color.palette.empty()) << "an edited gradient is custom";
  for (std::size_t s = 1; s < state.document.scene.layers[0].color.gradient.size(); ++s)
    EXPECT_LE(state.document.scene.layers[0].color.gradient[s - 1].position,
              state.document.scene.layers[0].color.gradient[s].position);
}

TEST_F(ExplorerUi, GridResolutionChangesOnlyWhenTheSliderIsReleased) {
  const int before = state.document.scene.gridResolution;
  const auto& slider = item("mesh/grid");
  ImGuiIO& io = ImGui::GetIO();
  moveTo(slider.minX + 4, slider.centerY());
  io.MouseDown[0] = true;
  frame();
  moveTo(slider.minX + 10, slider.centerY());
  EXPECT_EQ(state.document.scene.gridResolution, before) << "no mask rebuild while dragging";
  io.MouseDown[0] = false;
  frame(2);
  EXPECT_NE(state.document.scene.gridResolution, before);
  EXPECT_GE(state.document.scene.gridResolution, 32);
  EXPECT_LT(state.document.scene.gridResolution, before) << "the left part of the slider is below the default";
}

TEST_F(ExplorerUi, SearchFindsAChaoticSetAndTheHistoryGoesBackAndForward) {
  const auto start = state.document.scene.layers[0].params;
  click("Search (F3)");
  framesUntil([&] { return !state.panels.explore.visited.empty(); });
  ASSERT_EQ(state.panels.explore.visited.size(), 2u) << state.panels.explore.searchMessage;
  const auto found = state.document.scene.layers[0].params;
  EXPECT_NE(found, start);
  const std::string foundLine = state.panels.explore.searchMessage;
  EXPECT_EQ(foundLine.rfind("found: ", 0), 0u) << foundLine;
  EXPECT_NE(foundLine.find("tries"), std::string::npos) << "it says how many it tried";
  click("< Back");
  EXPECT_EQ(state.document.scene.layers[0].params, start);
  EXPECT_EQ(state.panels.explore.searchMessage.rfind("found: ", 0), std::string::npos) << "the found line follows Back";
  click("Forward >");
  EXPECT_EQ(state.document.scene.layers[0].params, found);
  EXPECT_EQ(state.panels.explore.searchMessage, foundLine) << "and Forward";
}

// Issue 38: the default preset's first F3 said "largest Lyapunov exponent 0.133" and handed back
// parameters that escape in the live view: bounded only from a start near the attractor's, which
// a layer cannot hold. What Search hands back runs bounded in a session as the live view posts it:
// the first F3 on the default preset, and F3 with search seeds that, unchecked, handed back
// parameters that escape (about one search in six from the default preset did).
TEST_F(ExplorerUi, WhatSearchHandsBackRunsBoundedInTheLiveView) {
  edit([&](core::Scene& scene) { scene.gridResolution = 48; });
  frame();
  const core::Scene start = state.document.scene;
  app::ExplorerSession session(1);
  for (const std::uint64_t seed : {1, 232, 246, 324, 349}) {
    if (seed != 1) {
      edit([&](core::Scene& scene) { scene.layers = start.layers; });
      state.panels.explore.searchSeed = seed;
    }
    frame();
    pressKey(app::kKeyF3);
    ASSERT_TRUE(framesUntil([&] { return !state.services.search.busy(); })) << "seed " << seed;
    frame();
    ASSERT_EQ(state.panels.explore.searchMessage.rfind("found: ", 0), 0u) << state.panels.explore.searchMessage;
    ASSERT_NE(state.document.scene.layers[0].params, start.layers[0].params) << "seed " << seed;
    ASSERT_TRUE(session.postIfPatternChanged(state.document.scene));
    ASSERT_TRUE(session.waitUntilApplied(60.0));
    const app::SessionStatus status = session.status();
    EXPECT_TRUE(status.stats.problem.empty())
        << "seed " << seed << ": " << status.stats.problem << " (" << state.panels.explore.searchMessage << ")";
    EXPECT_TRUE(status.escapeNote.empty()) << status.escapeNote;
    EXPECT_FALSE(status.showingLastBounded);
  }
}

// A search shows what it has tried and can be cancelled: around a periodic Thomas nothing is
// near, and it widens instead of running on in silence.
TEST_F(ExplorerUi, ASearchShowsItsProgressAndCanBeCancelled) {
  edit([&](core::Scene& scene) { scene.layers[0].attractor = "thomas"; });
  edit([&](core::Scene& scene) { scene.layers[0].params = {0.32}; });
  frame();
  click("Search (F3)");
  ASSERT_TRUE(state.services.search.busy());
  ASSERT_TRUE(state.services.searchProgress);
  test::waitFor(*state.services.searchProgress, [&] { return state.services.searchTried->load() >= 3; });
  frame();
  EXPECT_GE(state.services.searchTried->load(), 3) << "its tries are counted";
  frame();
  click("explore/Cancel search");
  EXPECT_FALSE(state.services.search.busy());
  EXPECT_EQ(state.panels.explore.searchMessage.rfind("search cancelled after ", 0), 0u)
      << state.panels.explore.searchMessage;
  EXPECT_DOUBLE_EQ(state.document.scene.layers[0].params[0], 0.32) << "nothing was applied";
}

TEST_F(ExplorerUi, OpeningFilesKeepsWorkSafe) {
  TemporaryFolder folder;
  const auto pattern = state.document.scene.layers[0].params;
  // A mesh replaces the shape and keeps the pattern; it is one undoable edit.
  ASSERT_TRUE(app::openFile(state, test::meshPath("teapot.obj"))) << state.panels.prompts.notice;
  EXPECT_NE(state.document.scene.meshPath.find("teapot.obj"), std::string::npos);
  EXPECT_EQ(state.document.scene.layers[0].params, pattern);
  EXPECT_FALSE(state.services.settings.recent.empty());
  frame(2);
  pressKey('Z', true);
  EXPECT_EQ(state.document.scene.meshPath.find("teapot.obj"), std::string::npos) << "undo goes back to the bunny";

  // A broken preset leaves the scene as it was and says why.
  const auto broken = folder.path() / "broken.json";
  std::ofstream(broken) << "{ \"schema_version\": 1, \"name\": ";
  const std::string meshBefore = state.document.scene.meshPath;
  EXPECT_FALSE(app::openFile(state, broken));
  EXPECT_NE(state.panels.prompts.notice.find("broken.json"), std::string::npos) << state.panels.prompts.notice;
  EXPECT_EQ(state.document.scene.meshPath, meshBefore);
  frame(3);
  click("notice/Dismiss");
  EXPECT_TRUE(state.panels.prompts.notice.empty());
}

// A flame file opened or dropped replaces the pattern, keeps the mesh, shows its warnings and is
// one undoable edit; a broken one changes nothing and is named.
TEST_F(ExplorerUi, OpeningAFlameFileKeepsTheMeshAndCanBeUndone) {
  TemporaryFolder folder;
  ASSERT_TRUE(app::openFile(state, test::meshPath("teapot.obj"))) << state.panels.prompts.notice;
  frame(2);
  const auto flame = folder.path() / "swirl.flame";
  std::ofstream(flame) << "<flame name=\"swirl\"><xform weight=\"1\" color=\"0\" swirl=\"1\" mystery=\"1\" "
                          "coefs=\"0.5 0 0 0.5 0.2 0\"/><xform weight=\"1\" color=\"1\" linear=\"1\" "
                          "coefs=\"0.5 0 0 0.5 -0.2 0\"/></flame>";
  ASSERT_TRUE(app::openFile(state, flame)) << state.panels.prompts.notice;
  ASSERT_EQ(state.document.scene.layers.size(), 1u);
  EXPECT_EQ(state.document.scene.layers[0].kind, core::PatternKind::Flame);
  EXPECT_EQ(state.document.scene.name, "swirl");
  EXPECT_NE(state.document.scene.meshPath.find("teapot.obj"), std::string::npos);
  EXPECT_NE(state.panels.prompts.notice.find("mystery"), std::string::npos) << state.panels.prompts.notice;
  // What a frame does once the edit settles (frames are not run here: the Pattern panel of this
  // branch does not draw flame layers yet): the flame is one step, and undo leaves only it.
  ASSERT_TRUE(state.document.history->record(state.document.scene));
  const auto undone = state.document.history->undo();
  ASSERT_TRUE(undone.has_value());
  EXPECT_EQ(undone->layers.at(0).kind, core::PatternKind::Attractor) << "undo brings the attractor back";
  EXPECT_NE(undone->meshPath.find("teapot.obj"), std::string::npos);

  const auto broken = folder.path() / "broken.flam3";
  std::ofstream(broken) << "<flame><xform weight=\"1\" coefs=\"inf 0 0 1 0 0\"/></flame>";
  const std::string before = core::sceneToJson(state.document.scene);
  EXPECT_FALSE(app::openFile(state, broken));
  EXPECT_NE(state.panels.prompts.notice.find("broken.flam3"), std::string::npos) << state.panels.prompts.notice;
  EXPECT_EQ(core::sceneToJson(state.document.scene), before);
}

// The session restarts accumulation (a new generation) when the UI changes a parameter, and
// does not when only the tone changes.
TEST_F(ExplorerUi, AParameterChangeBumpsTheGenerationOfTheSession) {
  edit([&](core::Scene& scene) { scene.gridResolution = 48; });
  app::ExplorerSession session(1);
  ASSERT_TRUE(session.postIfPatternChanged(state.document.scene));
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  ASSERT_TRUE(session.status().error.empty()) << session.status().error;
  const auto generation = session.status().stats.generation;

  const auto& tone = item("tone/brightness");
  drag(tone.centerX(), tone.centerY(), 30, 0);
  EXPECT_FALSE(session.postIfPatternChanged(state.document.scene));

  const auto& slider = item("layer0/b");
  // From b near 1.3 to near 1.4: bounded. (From b = 1.55 on, the default preset's Euler step escapes.)
  drag(slider.minX + 0.32f * (slider.maxX - slider.minX), slider.centerY(), 10, 0);
  ASSERT_TRUE(session.postIfPatternChanged(state.document.scene));
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  EXPECT_EQ(session.status().stats.generation, generation + 1) << session.status().escapeNote;

  // The new generation's volume arrives, tagged with the post that asked for it.
  core::PackedVolume volume;
  std::uint64_t reflects = 0;
  test::waitForSession(session, [&] {
    session.takeVolumeIfNewer(volume, &reflects);
    return reflects == session.status().requestedGeneration;
  });
  EXPECT_EQ(reflects, session.status().requestedGeneration);
}

TEST_F(ExplorerUi, AnEscapingPatternIsShownWithAWayOut) {
  edit([&](core::Scene& scene) { scene.gridResolution = 48; });
  edit([&](core::Scene& scene) { scene.layers[0].attractor = "polynomial_b"; });
  edit([&](core::Scene& scene) {
    scene.layers[0].params = core::attractorOrThrow("polynomial_b").alternative("seed")->values;
  });
  app::ExplorerSession session(1);
  session.postIfPatternChanged(state.document.scene);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  state.frame.session = session.status();
  ASSERT_FALSE(state.frame.session.stats.problem.empty());
  frame();
  EXPECT_NO_THROW(item("Find a nearby one"));
}

TEST_F(ExplorerUi, ABadMeshIsReportedAndTheOldShapeStays) {
  edit([&](core::Scene& scene) { scene.gridResolution = 48; });
  app::ExplorerSession session(1);
  session.postIfPatternChanged(state.document.scene);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  TemporaryFolder folder;
  const auto bad = folder.path() / "bad.obj";
  std::ofstream(bad) << "this is not a mesh\n";
  ASSERT_TRUE(app::openFile(state, bad));
  frame(2);
  session.postIfPatternChanged(state.document.scene);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  const app::SessionStatus status = session.status();
  EXPECT_NE(status.error.find("bad.obj"), std::string::npos) << status.error;
  EXPECT_TRUE(status.hasShape) << "the bunny's grid keeps refining";
  // Undo returns to the good mesh and clears the message.
  pressKey('Z', true);
  session.postIfPatternChanged(state.document.scene);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  EXPECT_TRUE(session.status().error.empty()) << session.status().error;
}

}  // namespace

namespace {

TEST_F(ExplorerUi, TimelineKeysScrubsAndPlaysAnAnimation) {
  // Key the camera at 0 s and, turned, at 2 s; the middle of the timeline is halfway.
  edit([&](core::Scene& scene) { scene.animation.duration = 2.0; });
  edit([&](core::Scene& scene) { scene.camera.azimuthDeg = 0.0; });
  frame();
  click("timeline/Key");
  ASSERT_EQ(state.document.scene.keyframes.size(), 1u);
  EXPECT_EQ(state.document.scene.keyframes[0].path, "/camera/azimuth_deg");
  const auto& scrubber = item("timeline/time");
  drag(scrubber.minX + 2, scrubber.centerY(), scrubber.maxX - scrubber.minX, 0);
  EXPECT_NEAR(state.document.scene.animation.time, 2.0, 1e-9);
  edit([&](core::Scene& scene) { scene.camera.azimuthDeg = 90.0; });
  frame();
  click("timeline/Key");
  ASSERT_EQ(state.document.scene.keyframes[0].keys.size(), 2u);

  // Scrubbing to the middle shows the interpolated value; the camera is not the pattern.
  const core::Scene pattern = state.document.scene;
  drag(scrubber.minX + 2, scrubber.centerY(), 0.5f * (scrubber.maxX - scrubber.minX) - 2, 0);
  EXPECT_GT(state.document.scene.animation.time, 0.5);
  EXPECT_LT(state.document.scene.animation.time, 1.5);
  EXPECT_GT(state.document.scene.camera.azimuthDeg, 10.0);
  EXPECT_LT(state.document.scene.camera.azimuthDeg, 80.0);
  EXPECT_FALSE(core::diff(pattern, state.document.scene).pattern());

  // Play moves time forward frame by frame and the camera with it.
  const double time = state.document.scene.animation.time, azimuth = state.document.scene.camera.azimuthDeg;
  click("timeline/Play");
  frame(10);
  EXPECT_GT(state.document.scene.animation.time, time);
  EXPECT_GT(state.document.scene.camera.azimuthDeg, azimuth);
  click("timeline/Pause");
  EXPECT_FALSE(state.panels.timeline.playing);
}

// The Timeline lists its animated values by name with their keys; a value with one key says it
// holds still; Key says what it keyed; Play stops at the end unless the animation loops.
TEST_F(ExplorerUi, TheTimelineListsItsTracksAndPlayStopsAtTheEnd) {
  edit([&](core::Scene& scene) { scene.animation.duration = 0.5; });
  edit([&](core::Scene& scene) { scene.layers[0].params[0] *= 1.02; });
  edit([&](core::Scene& scene) { scene.camera.azimuthDeg += 10.0; });
  frame();
  click("timeline/Key");
  ASSERT_EQ(state.document.scene.keyframes.size(), 2u);
  EXPECT_NE(state.panels.timeline.timelineMessage.find("layer 1 a"), std::string::npos)
      << state.panels.timeline.timelineMessage;
  EXPECT_NE(state.panels.timeline.timelineMessage.find("camera azimuth deg"), std::string::npos)
      << state.panels.timeline.timelineMessage;
  EXPECT_EQ(state.panels.timeline.timelineMessage.find("animated values"), std::string::npos);
  item("timeline/track//layers/0/params/a");
  item("timeline/track//camera/azimuth_deg");
  item("timeline/track//camera/azimuth_deg/holds");  // one key: it holds still
  item("timeline/track//layers/0/params/a/holds");

  // A second key at the end, after turning the camera: every animated value gets one there.
  const auto& scrubber = item("timeline/time");
  drag(scrubber.minX + 2, scrubber.centerY(), scrubber.maxX - scrubber.minX, 0);
  edit([&](core::Scene& scene) { scene.camera.azimuthDeg += 30.0; });
  frame();
  click("timeline/Key");
  EXPECT_NE(state.panels.timeline.timelineMessage.find("camera azimuth deg"), std::string::npos)
      << state.panels.timeline.timelineMessage;
  EXPECT_NE(state.panels.timeline.timelineMessage.find("at 0.50 s"), std::string::npos)
      << state.panels.timeline.timelineMessage;
  frame();
  EXPECT_EQ(probe.items.count("timeline/track//camera/azimuth_deg/holds"), 0u) << "two keys: it moves";

  // Keyed values carry a mark on their sliders.
  item("layer0/a/keyed");
  EXPECT_EQ(probe.items.count("layer0/b/keyed"), 0u) << "b has no keys";
  EXPECT_EQ(probe.items.count("tone/gamma/keyed"), 0u);

  // Play runs to the end and stops there with the loop off.
  edit([&](core::Scene& scene) { scene.animation.loop = false; });
  click("timeline/Play");  // at the end: starts over
  EXPECT_LT(state.document.scene.animation.time, 0.1);
  for (int i = 0; i < 120 && state.panels.timeline.playing; ++i) frame();
  EXPECT_FALSE(state.panels.timeline.playing) << "played on past the end with the loop off";
  EXPECT_DOUBLE_EQ(state.document.scene.animation.time, 0.5);
  // With the loop on it goes round.
  edit([&](core::Scene& scene) { scene.animation.loop = true; });
  click("timeline/Play");
  for (int i = 0; i < 60; ++i) frame();
  EXPECT_TRUE(state.panels.timeline.playing);
  click("timeline/Pause");
}

// Issue 38: the Timeline's key marks sat on its words: the scrubber's ticks on the time it shows,
// and the tracks' keys on names longer than their column. Marks keep clear of every text, in a
// wide Timeline and in a narrow one (where a long name is shortened, whole in its tooltip).
TEST_F(ExplorerUi, TheTimelinesKeyMarksCoverNoText) {
  edit([&](core::Scene& scene) { scene.layers[0].transform.rotationDeg.x += 20.0; });
  edit([&](core::Scene& scene) { scene.camera.azimuthDeg += 10.0; });
  frame();
  click("timeline/Key");
  const auto& scrubber = item("timeline/time");
  drag(scrubber.minX + 2, scrubber.centerY(), scrubber.maxX - scrubber.minX, 0);
  edit([&](core::Scene& scene) { scene.layers[0].transform.rotationDeg.x += 20.0; });
  edit([&](core::Scene& scene) { scene.tone.brightness *= 1.5; });  // one key: it holds still
  frame();
  click("timeline/Key");
  ASSERT_EQ(state.document.scene.keyframes.size(), 3u);
  for (const float width : {1280.0f, 1000.0f}) {
    ImGui::GetIO().DisplaySize.x = width;
    frame(3);
    const auto time = item("timeline/time"), ticks = item("timeline/ticks");
    EXPECT_GE(ticks.minY, time.maxY) << "the scrubber's ticks lie under it, not on its time";
    std::size_t holding = 0;
    for (const core::KeyframeTrack& track : state.document.scene.keyframes) {
      const std::string name = "timeline/track/" + track.path;
      const auto keys = item(name + "/keys");
      EXPECT_GT(keys.maxX - keys.minX, 50.0f) << name << " at " << width;
      EXPECT_GE(keys.minX, item(name).maxX) << name << " at " << width;
      if (probe.items.count(name + "/holds")) {
        ++holding;
        EXPECT_GE(keys.minX, item(name + "/holds").maxX) << name << " at " << width;
      }
    }
    EXPECT_EQ(holding, 1u);
  }
  const std::string& shortened = probe.texts["timeline/track//layers/0/transform/rotation_deg"];
  EXPECT_TRUE(shortened.ends_with("…")) << shortened << ": a long name is shortened in a narrow Timeline";
}

TEST_F(ExplorerUi, KeyingAParameterAnimatesThePattern) {
  edit([&](core::Scene& scene) { scene.animation.duration = 1.0; });
  const double start = state.document.scene.layers[0].params[0];
  edit([&](core::Scene& scene) { scene.animation.time = 1.0; });
  edit([&](core::Scene& scene) { scene.layers[0].params[0] = start * 1.05; });
  frame();
  click("timeline/Key");
  ASSERT_EQ(state.document.scene.keyframes.size(), 1u);
  EXPECT_EQ(state.document.scene.keyframes[0].path, "/layers/0/params/a");
  const core::Scene patternAtEnd = state.document.scene;
  const auto& scrubber = item("timeline/time");
  drag(scrubber.minX + 2, scrubber.centerY(), -40, 0);
  edit([&](core::Scene& scene) { scene.layers[0].params[0] = start; });
  frame();
  click("timeline/Key");
  ASSERT_EQ(state.document.scene.keyframes[0].keys.size(), 2u);
  drag(scrubber.minX + 2, scrubber.centerY(), 0.5f * (scrubber.maxX - scrubber.minX) - 2, 0);
  const double middle = state.document.scene.layers[0].params[0];
  EXPECT_GT(middle, start);
  EXPECT_LT(middle, start * 1.05);
  EXPECT_TRUE(core::diff(patternAtEnd, state.document.scene).pattern())
      << "an animated parameter restarts the accumulation";
  // Deleting the key at the current time needs the time on a key: go to the next one.
  click("timeline/>|");
  EXPECT_DOUBLE_EQ(state.document.scene.animation.time, 1.0);
  click("timeline/Delete key");
  EXPECT_EQ(state.document.scene.keyframes[0].keys.size(), 1u);
}

}  // namespace

namespace {

TEST_F(ExplorerUi, PresetsPanelListsThumbnailsOpensAndSaves) {
  TemporaryFolder user;
  app::PresetLibrary library(test::sourcePath("presets"), user.path());
  state.services.presets = &library;
  ASSERT_TRUE(library.waitUntilIdle(60.0));
  ASSERT_TRUE(library.entries());
  // Stand-in texture names: the panel only passes them to ImGui.
  unsigned name = 1;
  for (const app::PresetEntry& entry : *library.entries())
    if (entry.thumbnail) state.frame.thumbnailTextures[entry.path] = name++;
  click("header/Presets");
  // The click's request is read by the window loop in the frame it was made; do what it does.
  clickForRequest("preset/lorenz-heart");
  ASSERT_TRUE(state.frame.requests.open.has_value());
  EXPECT_EQ(state.frame.requests.open->filename(), "lorenz-heart.json");
  ASSERT_TRUE(app::openFile(state, *state.frame.requests.open));
  EXPECT_EQ(state.document.scene.layers[0].attractor, "lorenz");

  // Save as: the name box and the button ask the window loop, which owns the pixels.
  std::snprintf(state.panels.scene.saveName, sizeof state.panels.scene.saveName, "My heart");
  frame();
  clickForRequest("preset/Save as");
  ASSERT_TRUE(state.frame.requests.saveAs.has_value());
  const auto saved = library.saveAs(state.document.scene, *state.frame.requests.saveAs, {});
  EXPECT_TRUE(std::filesystem::exists(saved));
  EXPECT_EQ(core::loadScene(saved).name, "My heart");
}

TEST_F(ExplorerUi, ExportPanelRendersInAChildWithProgressAndShowsThePath) {
  TemporaryFolder folder;
  app::ExportJob job;
  state.services.exportJob = &job;
  state.services.executable = VOXFLAME_BINARY;
  edit([&](core::Scene& scene) { scene.gridResolution = 48; });
  state.services.settings.lastExport.width = 64;
  state.services.settings.lastExport.height = 48;
  state.services.settings.lastExport.samples = 1;
  state.services.settings.lastExport.points = 200'000;
  const auto output = folder.path() / "still.png";
  std::snprintf(state.panels.scene.exportPath, sizeof state.panels.scene.exportPath, "%s", output.string().c_str());
  click("header/Export");
  // The panel asks; the window loop (app::PanelRequests) starts the job. Do what it does.
  clickForRequest("export/Export now");
  ASSERT_TRUE(state.frame.requests.exportStill.has_value());
  app::startExport(state, job, *state.frame.requests.exportStill);
  // A frame (which polls the child) whenever the child has news or ends.
  bool sawProgress = false;
  const auto deadline = test::deadlineAfter(std::chrono::seconds(120));
  while (state.services.exportStatus.state != app::ExportState::Done &&
         state.services.exportStatus.state != app::ExportState::Failed && std::chrono::steady_clock::now() < deadline) {
    job.waitForChange(
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now()));
    frame();
    sawProgress |= state.services.exportStatus.state == app::ExportState::Running;
  }
  ASSERT_EQ(state.services.exportStatus.state, app::ExportState::Done)
      << state.services.exportStatus.error << state.panels.prompts.notice;
  EXPECT_TRUE(sawProgress) << "the panel showed a progress bar while the child ran";
  EXPECT_TRUE(std::filesystem::exists(output));
  EXPECT_EQ(state.services.exportStatus.output, output);
}

// Quitting asks only when changes are unsaved: Save (the window loop saves, then quits), Discard
// (quits) or Cancel (stays), by button or by S, D and Escape. The title says what is unsaved.
TEST_F(ExplorerUi, QuittingWithUnsavedChangesAsksAndEachAnswerDoesWhatItSays) {
  ImGuiIO& io = ImGui::GetIO();
  // Ctrl+Q held for one frame: whether that frame asks to quit, or opens the prompt.
  auto ctrlQ = [&] {
    io.KeyCtrl = true;
    io.KeysDown['Q'] = true;
    frame();
    const bool quit = state.frame.requests.quit;
    io.KeysDown['Q'] = false;
    io.KeyCtrl = false;
    frame();
    return quit;
  };
  EXPECT_FALSE(app::hasUnsavedChanges(state)) << "a scene just opened";
  EXPECT_EQ(app::windowTitle(state), "voxflame — " + state.document.scene.name);
  EXPECT_TRUE(ctrlQ()) << "nothing unsaved: Ctrl+Q quits at once";
  EXPECT_FALSE(state.panels.prompts.quitPrompt);

  edit([&](core::Scene& scene) { scene.tone.gamma = 3.0; });
  frame();
  EXPECT_TRUE(app::hasUnsavedChanges(state));
  EXPECT_EQ(app::windowTitle(state), "voxflame — " + state.document.scene.name + " (unsaved)");
  EXPECT_FALSE(ctrlQ()) << "unsaved changes: Ctrl+Q asks first";
  EXPECT_TRUE(state.panels.prompts.quitPrompt);
  frame();
  click("quit/Cancel");
  EXPECT_FALSE(state.panels.prompts.quitPrompt);
  EXPECT_DOUBLE_EQ(state.document.scene.tone.gamma, 3.0) << "Cancel keeps the changes";

  ctrlQ();
  frame();
  clickForRequest("quit/Discard");
  EXPECT_TRUE(state.frame.requests.quit) << "Discard quits";
  EXPECT_FALSE(state.frame.requests.saveAs);

  state.panels.prompts.quitPrompt = false;
  frame();
  ctrlQ();
  frame();
  clickForRequest("quit/Save");
  ASSERT_TRUE(state.frame.requests.saveAs) << "Save asks the window loop to save";
  EXPECT_EQ(*state.frame.requests.saveAs, state.document.scene.name);
  EXPECT_TRUE(state.frame.requests.saveReplacing) << "the user's preset of the document's name is replaced";
  EXPECT_TRUE(state.panels.prompts.quitAfterSave) << "and to quit once saved";
  EXPECT_FALSE(state.frame.requests.quit) << "not before";

  // The keyboard answers: Escape stays, D discards.
  state.panels.prompts.quitAfterSave = false;
  ctrlQ();
  pressKey(256);  // Escape
  EXPECT_FALSE(state.panels.prompts.quitPrompt);
  ctrlQ();
  io.KeysDown['D'] = true;
  frame();
  EXPECT_TRUE(state.frame.requests.quit) << "D discards";
  io.KeysDown['D'] = false;
  frame();
  EXPECT_DOUBLE_EQ(state.document.scene.camera.target.x, core::defaultScene().camera.target.x)
      << "keys the prompt answers do not fly the camera";
}

// The window's title is the document's: an undone change of name takes the title back with it.
TEST_F(ExplorerUi, CtrlSSavesTheSceneAsThePresetOfItsName) {
  edit([&](core::Scene& scene) { scene.name = "my bunny"; });
  ImGuiIO& io = ImGui::GetIO();
  io.KeyCtrl = true;
  io.KeysDown['S'] = true;
  frame();
  EXPECT_EQ(state.frame.requests.saveAs, std::optional<std::string>("my bunny"));
  EXPECT_TRUE(state.frame.requests.saveReplacing) << "a save replaces the preset of that name";
  io.KeysDown['S'] = false;
  io.KeyCtrl = false;
  frame();
  EXPECT_FALSE(state.frame.requests.saveAs);
}

TEST_F(ExplorerUi, TheTitleFollowsTheDocumentThroughUndo) {
  const std::string original = state.document.scene.name;
  edit([&](core::Scene& scene) { scene.name = "imported flame"; });
  frame(3);
  EXPECT_EQ(app::windowTitle(state), "voxflame — imported flame (unsaved)");
  pressKey('Z', true);
  EXPECT_EQ(state.document.scene.name, original);
  EXPECT_EQ(app::windowTitle(state), "voxflame — " + original);
}

// The Export panel names the file after the document and follows a rename (save-as) until the
// user types another name; it asks before replacing a file; "view size" exports the view's pixels.
TEST_F(ExplorerUi, TheExportFileFollowsTheDocumentAndReplacingOneAsksFirst) {
  TemporaryFolder folder;
  app::ExportJob job;
  state.services.exportJob = &job;
  state.services.settings.lastExportFolder = folder.path();
  click("header/Export");
  EXPECT_EQ(std::filesystem::path(state.panels.scene.exportPath).filename(),
            app::sanitizePresetName(state.document.scene.name) + ".png");
  edit([&](core::Scene& scene) { scene.name = "Night bunny"; });  // what a save-as does to the document
  frame();
  EXPECT_EQ(std::filesystem::path(state.panels.scene.exportPath).filename(),
            app::sanitizePresetName("Night bunny") + ".png");

  click("export/view size");
  ASSERT_GT(state.frame.viewRect.z, 0);
  EXPECT_EQ(state.services.settings.lastExport.width, state.frame.viewRect.z);
  EXPECT_EQ(state.services.settings.lastExport.height, state.frame.viewRect.w);

  {
    std::ofstream existing(state.panels.scene.exportPath);
    existing << "an earlier export";
  }
  clickForRequest("export/Export now");
  EXPECT_FALSE(state.frame.requests.exportStill) << "an existing file is replaced without asking";
  ASSERT_TRUE(state.panels.scene.exportToConfirm);
  frame();
  clickForRequest("export/Keep it");
  EXPECT_FALSE(state.frame.requests.exportStill);
  EXPECT_FALSE(state.panels.scene.exportToConfirm);
  clickForRequest("export/Export now");
  frame();
  clickForRequest("export/Replace it");
  ASSERT_TRUE(state.frame.requests.exportStill) << "Replace it exports";
  EXPECT_EQ(state.frame.requests.exportStill->output, std::filesystem::path(state.panels.scene.exportPath));

  std::snprintf(state.panels.scene.exportPath, sizeof state.panels.scene.exportPath, "%s",
                (folder / "mine.png").c_str());
  edit([&](core::Scene& scene) { scene.name = "Renamed again"; });
  frame();
  EXPECT_EQ(std::filesystem::path(state.panels.scene.exportPath).filename(), "mine.png") << "a typed name stays";
}

// Wide-range values move on a logarithmic scale: the middle of the brightness slider is the
// geometric mean of its ends, not the arithmetic one. Every schema slider resets on right-click.
TEST_F(ExplorerUi, WideRangeSlidersAreLogarithmicAndEverySliderResetsToItsDefault) {
  const auto& brightness = item("tone/brightness");
  ImGuiIO& io = ImGui::GetIO();
  auto clickAt = [&](float x) {
    moveTo(x, brightness.centerY());
    io.MouseDown[0] = true;
    frame();
    io.MouseDown[0] = false;
    frame(2);
    return state.document.scene.tone.brightness;
  };
  // Equal steps of the pointer multiply the value by equal factors.
  const double first = clickAt(brightness.minX + 30), second = clickAt(brightness.minX + 60),
               third = clickAt(brightness.minX + 90);
  ASSERT_GT(first, 0.0);
  EXPECT_NEAR(std::log(second / first), std::log(third / second), 0.15) << first << " " << second << " " << third;
  EXPECT_GT(third - second, 1.5 * (second - first)) << "equal steps, not equal factors";
  // A right-click resets at once, with no menu to confirm it (issue 38), and Ctrl+Z brings the
  // value back.
  const auto rightClick = [&](const std::string& name) {
    const auto& rect = item(name);
    moveTo(rect.centerX(), rect.centerY());
    io.MouseDown[1] = true;
    frame();
    io.MouseDown[1] = false;
    frame(2);
  };
  edit([&](core::Scene& scene) { scene.tone.gamma = 3.7; });
  frame();
  rightClick("tone/gamma");
  EXPECT_FALSE(ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId)) << "no menu";
  EXPECT_DOUBLE_EQ(state.document.scene.tone.gamma, core::ToneMapSettings{}.gamma)
      << "the Render panel's sliders reset too";
  pressKey('Z', true);
  EXPECT_DOUBLE_EQ(state.document.scene.tone.gamma, 3.7) << "one undo step";
  const core::ParamInfo& b = core::attractorOrThrow(state.document.scene.layers[0].attractor).params[1];
  edit([&](core::Scene& scene) { scene.layers[0].params[1] = b.defaultValue + 0.05; });
  frame();
  rightClick("layer0/" + b.name);
  EXPECT_DOUBLE_EQ(state.document.scene.layers[0].params[1], b.defaultValue) << "an attractor's parameter resets too";
  edit([&](core::Scene& scene) { scene.tone.background = glm::vec3(0.5f, 0.1f, 0.2f); });
  frame();
  rightClick("tone/background");
  EXPECT_FALSE(ImGui::IsPopupOpen(nullptr, ImGuiPopupFlags_AnyPopupId)) << "not the colour editor's own menu";
  EXPECT_EQ(state.document.scene.tone.background, core::ToneMapSettings{}.background) << "a colour resets too";
}

// Issue 38: labels were cut at the panels' edges. Every label of a schema widget (and the Render
// section's own) shows whole inside its panel: beside its widget where it fits, else above it.
TEST_F(ExplorerUi, EveryLabelShowsWholeInsideItsPanel) {
  click("header/Camera");
  frame(2);
  const float patternRight = state.frame.layout.left, sceneRight = ImGui::GetIO().DisplaySize.x;
  int checked = 0;
  for (const auto& [name, text] : probe.texts) {
    const float right = name.rfind("layer", 0) == 0 ? patternRight : sceneRight;
    const auto label = probe.items.find(name + "/label");
    const auto& rect = label != probe.items.end() ? label->second : item(name);
    EXPECT_LE(rect.maxX, right) << name << " (\"" << text << "\") is cut at its panel's edge";
    ++checked;
  }
  EXPECT_GT(checked, 30);
  EXPECT_TRUE(probe.texts.count("render/stop_refining_at_noise"));
  EXPECT_TRUE(std::any_of(probe.texts.begin(), probe.texts.end(), [](const auto& entry) {
    return entry.first.rfind("camera/", 0) == 0;
  })) << "the Camera section's too";
}

// Typing words of a name into the attractor filter and pressing Enter picks the first match.
TEST_F(ExplorerUi, TheAttractorFilterPicksItsFirstMatchOnEnter) {
  ImGuiIO& io = ImGui::GetIO();
  io.KeyMap[ImGuiKey_Enter] = app::kKeyEnter;  // as the GLFW backend maps it
  click("attractor/filter");
  for (const char c : std::string("sprott quadratic")) io.AddInputCharacter(static_cast<unsigned>(c));
  frame(2);
  EXPECT_STREQ(state.panels.pattern.attractorFilter, "sprott quadratic");
  pressKey(257);
  frame(2);
  EXPECT_EQ(state.document.scene.layers[0].attractor, "sprott_quadratic")
      << "every word matches, in the id or the name";
  EXPECT_STREQ(state.panels.pattern.attractorFilter, "") << "the filter clears once it has picked";
}

// A flame file with several flames asks which one to import, by name, instead of taking the
// first silently; Cancel imports none.
TEST_F(ExplorerUi, OpeningAFileOfSeveralFlamesAsksWhichOne) {
  const std::filesystem::path file = std::filesystem::path(VOXFLAME_TEST_FLAMES) /
                                     "earthbound19__electric_sheep_genomes__electricsheep.242.01930.flam3";
  const core::Scene before = state.document.scene;
  ASSERT_TRUE(app::openFile(state, file)) << state.panels.prompts.notice;
  ASSERT_TRUE(state.panels.prompts.flameChoice);
  ASSERT_EQ(state.panels.prompts.flameChoice->names.size(), 2u);
  EXPECT_EQ(state.document.scene, before) << "nothing is imported before the choice";
  frame(2);
  click("flame/" + state.panels.prompts.flameChoice->names[1]);
  EXPECT_FALSE(state.panels.prompts.flameChoice);
  EXPECT_EQ(state.document.scene.layers[0].kind, core::PatternKind::Flame);
  EXPECT_EQ(state.document.scene.name, "electricsheep.242.01826") << "the second flame, as chosen";
  // Its 256-colour palette shows as one strip, its stops behind "edit the 256 stops".
  frame(2);
  ASSERT_GT(state.document.scene.layers[0].color.gradient.size(), 16u);
  std::size_t stripsWithHiddenStops = 0, stopRows = 0;
  for (const auto& [name, rect] : probe.items) {
    stripsWithHiddenStops += name.ends_with("edit stops");
    stopRows += name.starts_with("layer0/stop");
  }
  EXPECT_EQ(stripsWithHiddenStops, 1u);
  EXPECT_EQ(stopRows, 0u) << "256 rows of stops";

  ASSERT_TRUE(app::openFile(state, file));
  frame(2);
  const core::Scene imported = state.document.scene;
  click("flame/Cancel");
  EXPECT_FALSE(state.panels.prompts.flameChoice);
  EXPECT_EQ(state.document.scene, imported) << "Cancel imports nothing";
}

// Issue 38: the flame chooser's filter has the keyboard as soon as it opens (no click first), and
// Enter takes the one flame the filter leaves; while several are left Enter takes none.
TEST_F(ExplorerUi, TheFlameChoosersFilterHasTheKeyboardAndEnterTakesTheOnlyMatch) {
  ImGuiIO& io = ImGui::GetIO();
  io.KeyMap[ImGuiKey_Enter] = app::kKeyEnter;  // as the GLFW backend maps it
  const std::filesystem::path file = std::filesystem::path(VOXFLAME_TEST_FLAMES) /
                                     "earthbound19__electric_sheep_genomes__electricsheep.242.01930.flam3";
  ASSERT_TRUE(app::openFile(state, file)) << state.panels.prompts.notice;
  ASSERT_TRUE(state.panels.prompts.flameChoice);
  const std::vector<std::string> names = state.panels.prompts.flameChoice->names;
  ASSERT_EQ(names.size(), 2u);
  frame(2);
  io.AddInputCharactersUTF8("electricsheep");  // both names hold it
  frame(2);
  EXPECT_STREQ(state.panels.prompts.flameChoice->filter, "electricsheep") << "typed without a click first";
  pressKey(app::kKeyEnter);
  ASSERT_TRUE(state.panels.prompts.flameChoice) << "two flames match: Enter takes neither";
  const std::string wanted = names[1];
  io.AddInputCharactersUTF8((" " + wanted.substr(wanted.size() - 5)).c_str());  // the second's own end
  frame(2);
  EXPECT_EQ(state.panels.prompts.flameChoice->filter, "electricsheep " + wanted.substr(wanted.size() - 5))
      << "the filter keeps the keyboard after an Enter that took nothing";
  pressKey(app::kKeyEnter);
  EXPECT_FALSE(state.panels.prompts.flameChoice);
  EXPECT_EQ(state.document.scene.name, wanted) << "the only match, taken by Enter";
}

TEST_F(ExplorerUi, AutosavedWorkIsOfferedBackAndRestored) {
  app::Recoverable recoverable;
  core::Scene lost = core::defaultScene();
  lost.name = "lost work";
  lost.layers[0].params[0] = 1.2;
  recoverable.scene = lost;
  state.services.recoverable.push_back(recoverable);
  frame(2);
  click("recover/Restore");
  EXPECT_EQ(state.document.scene.name, "lost work");
  EXPECT_DOUBLE_EQ(state.document.scene.layers[0].params[0], 1.2);
  EXPECT_TRUE(state.services.recoverable.empty());
}

}  // namespace

TEST_F(ExplorerUi, DensityEstimationAndStillMethodAreLookOnlyAndTheFitRestartsThePattern) {
  const core::Scene keyBefore = state.document.scene;
  double radius = 0.0;
  const auto& slider = item("tone/estimator radius");
  drag(slider.centerX(), slider.centerY(), -60.0f, 0.0f, 0,
       [&] { radius = state.document.scene.tone.estimatorRadius; });
  EXPECT_LT(state.document.scene.tone.estimatorRadius, radius);
  EXPECT_NO_THROW(item("render/method"));
  EXPECT_NO_THROW(item("layer0/fit"));
  edit([&](core::Scene& scene) { scene.render.method = core::RenderMethod::Points; });
  frame();
  EXPECT_NO_THROW(item("render/lens aperture")) << "the points method's depth of field shows with it";
  EXPECT_FALSE(core::diff(keyBefore, state.document.scene).pattern())
      << "tone and still method never restart accumulation";
  edit([&](core::Scene& scene) { scene.layers[0].transform.fit = core::FitMode::Cover; });
  EXPECT_TRUE(core::diff(keyBefore, state.document.scene).pattern()) << "a new fit moves the points";
}

TEST_F(ExplorerUi, CopiesOfALayerAreAddedTurnedAndRemoved) {
  const core::Scene keyBefore = state.document.scene;
  const std::size_t before = state.document.scene.layers[0].transform.copies.size();
  click("layer0/Add copy");
  ASSERT_EQ(state.document.scene.layers[0].transform.copies.size(), before + 1);
  EXPECT_NE(state.document.scene.layers[0].transform.copies.back(), glm::dvec3(0.0)) << "a new copy is turned";
  EXPECT_TRUE(core::diff(keyBefore, state.document.scene).pattern()) << "a copy changes the pattern";
  const std::string label = "layer0/copy " + std::to_string(before + 1);
  EXPECT_NO_THROW(item(label));
  click(label + " remove");
  EXPECT_EQ(state.document.scene.layers[0].transform.copies.size(), before);
  EXPECT_FALSE(core::diff(keyBefore, state.document.scene).pattern());
}

// ---------------------------------------------------------------------------------------------
// Chaos-game layers: the kind choice, the flame transform editor, the Julia set's sliders, and
// Search and Mutate on them.

namespace {

class ExplorerFlameUi : public ExplorerUi {
 protected:
  // Layer 0 as the default flame, opened fresh (its own history), as a flame preset would be.
  void useFlameLayer() {
    core::Scene scene = core::defaultScene();
    core::PatternLayer& layer = scene.layers[0];
    layer.kind = core::PatternKind::Flame;
    layer.attractor.clear();
    layer.params.clear();
    layer.flame = core::defaultFlame();
    layer.color.mode = core::ColorMode::Index;
    app::resetExplorerState(state, scene);
    frame(2);
  }
  core::FlameGenome& flame() { return state.document.scene.layers[0].flame; }
  void waitForSearch(std::size_t visited) {
    framesUntil([&] { return state.panels.explore.visited.size() >= visited; });
  }
  static double rowLength(const core::Affine3& a, int row) {
    const auto r = static_cast<std::size_t>(row * 4);
    return std::sqrt(a.m[r] * a.m[r] + a.m[r + 1] * a.m[r + 1] + a.m[r + 2] * a.m[r + 2]);
  }
};

// Every edit reports what it affects (Document): the live view posts patterns and restarts its
// samples on those reports alone, so a widget that edits without reporting would leave the
// picture stale. Each widget of the panels is dragged once with every frame checking the reports.
TEST_F(ExplorerUi, EveryWidgetOfThePanelsReportsWhatItsEditAffects) {
  const std::vector<std::string> skip = {"layer0/Remove layer"};
  const int changed = dragEveryWidget({"layer0/", "tone/", "render/", "camera/", "mesh/", "timeline/"}, skip);
  EXPECT_GE(changed, 20) << "the sweep must reach the panels' sliders";
}

TEST_F(ExplorerFlameUi, EveryWidgetOfTheFlameEditorReportsWhatItsEditAffects) {
  useFlameLayer();
  click("layer0/Xaos");
  const int changed = dragEveryWidget({"layer0/"}, {"layer0/Remove layer", "layer0/pattern"});
  EXPECT_GE(changed, 15) << "the sweep must reach the transform editor";
}

TEST_F(ExplorerFlameUi, SwitchingALayerToFlameStartsFromTheDefaultFlame) {
  const core::Scene keyBefore = state.document.scene;
  click("layer0/pattern");
  click("layer0/pattern/flame");
  ASSERT_EQ(state.document.scene.layers[0].kind, core::PatternKind::Flame);
  EXPECT_EQ(flame(), core::defaultFlame());
  EXPECT_EQ(state.document.scene.layers[0].color.mode, core::ColorMode::Index) << "a flame colours by flam3's index";
  EXPECT_EQ(state.document.scene.render.method, core::RenderMethod::Points) << "a flame shows its filaments as points";
  EXPECT_TRUE(core::diff(keyBefore, state.document.scene).pattern());
  frame();
  EXPECT_NO_THROW(item("layer0/xform/transform weight"));
  EXPECT_NO_THROW(item("layer0/xform/rotate"));
  EXPECT_NE(state.panels.explore.lyapunovText.find("flame"), std::string::npos) << "the status line names the kind";
  pressKey('Z', true);
  EXPECT_EQ(state.document.scene.layers[0].kind, core::PatternKind::Attractor) << "switching is one undo step";
  EXPECT_EQ(state.document.scene.render.method, keyBefore.render.method) << "... the method's change with it";
  EXPECT_FALSE(state.document.scene.layers[0].params.empty());
}

TEST_F(ExplorerFlameUi, TransformsAreAddedDuplicatedAndRemoved) {
  useFlameLayer();
  const std::size_t count = flame().xforms.size();
  click("layer0/Add transform");
  ASSERT_EQ(flame().xforms.size(), count + 1);
  EXPECT_NO_THROW(core::validateFlame(flame(), "added"));
  EXPECT_NO_THROW(item("layer0/xform " + std::to_string(count + 1))) << "the new transform has a button";
  click("layer0/xform 2");
  click("layer0/Duplicate");
  ASSERT_EQ(flame().xforms.size(), count + 2);
  EXPECT_EQ(flame().xforms[2], flame().xforms[1]) << "the copy goes right after the original";
  click("layer0/Remove");
  EXPECT_EQ(flame().xforms.size(), count + 1);
  pressKey('Z', true);
  EXPECT_EQ(flame().xforms.size(), count + 2) << "each button press is one undo step";

  // The last transform cannot go: a flame needs one.
  useFlameLayer();
  while (flame().xforms.size() > 1) click("layer0/Remove");
  click("layer0/Remove");
  EXPECT_EQ(flame().xforms.size(), 1u);

  // The final transform switches on with the same editor, and off again.
  click("layer0/final transform");
  EXPECT_TRUE(flame().hasFinal);
  EXPECT_NO_THROW(item("layer0/final/rotate"));
  EXPECT_THROW(item("layer0/final/transform weight"), std::runtime_error) << "a final transform has no weight";
  click("layer0/final transform");
  EXPECT_FALSE(flame().hasFinal);
}

TEST_F(ExplorerFlameUi, DraggingATransformWeightIsOneUndoStep) {
  useFlameLayer();
  click("layer0/xform 2");
  const core::FlameGenome before = flame();
  const core::Scene keyBefore = state.document.scene;
  const auto slider = item("layer0/xform/transform weight");
  double pressedAt = 0.0;
  drag(slider.minX + 4, slider.centerY(), 80, 0, 0, [&] { pressedAt = flame().xforms[1].weight; });
  EXPECT_GT(flame().xforms[1].weight, pressedAt);
  EXPECT_EQ(flame().xforms[0], before.xforms[0]) << "only the selected transform moves";
  EXPECT_TRUE(core::diff(keyBefore, state.document.scene).pattern()) << "a genome edit restarts the accumulation";
  pressKey('Z', true);
  EXPECT_EQ(flame(), before) << "the whole drag is one undo step";
}

// The xaos matrix (issue 25): row = the transform just applied, column = the next one. Dragging
// one cell sets that one factor (the rest of its row filled with 1, the others untouched), and the
// whole drag is one undo step; the row's and the matrix's resets are one step each.
TEST_F(ExplorerFlameUi, DraggingAnXaosMatrixCellSetsThatPairAndIsOneUndoStep) {
  useFlameLayer();
  ASSERT_EQ(flame().xforms.size(), 3u);
  ASSERT_FALSE(core::hasXaos(flame()));
  click("layer0/Xaos");
  const core::FlameGenome before = flame();
  const std::size_t stepsBefore = state.document.history->size();
  const auto cell = item("layer0/xaos 2 to 3");
  drag(cell.centerX(), cell.centerY(), 40, 0);
  ASSERT_EQ(flame().xforms[1].xaos.size(), 3u);
  EXPECT_GT(flame().xforms[1].xaos[2], 1.0) << "dragging right raises transform 3's factor after transform 2";
  EXPECT_LE(flame().xforms[1].xaos[2], 5.0);
  EXPECT_EQ(flame().xforms[1].xaos[0], 1.0);
  EXPECT_EQ(flame().xforms[1].xaos[1], 1.0);
  EXPECT_TRUE(flame().xforms[0].xaos.empty()) << "other rows are untouched";
  EXPECT_TRUE(flame().xforms[2].xaos.empty());
  EXPECT_NO_THROW(core::validateFlame(flame(), "xaos edited"));
  EXPECT_EQ(state.document.history->size(), stepsBefore + 1) << "the whole drag is one undo step";
  const core::FlameGenome dragged = flame();

  pressKey('Z', true);
  EXPECT_EQ(flame(), before) << "undo restores the matrix";
  pressKey('Z', true, true);
  EXPECT_EQ(flame(), dragged) << "redo brings the drag back";

  // Dragged far left, a cell stops at 0 (the step is forbidden), never below.
  const auto forbid = item("layer0/xaos 1 to 1");
  drag(forbid.centerX(), forbid.centerY(), -400, 0);
  ASSERT_EQ(flame().xforms[0].xaos.size(), 1u);
  EXPECT_EQ(flame().xforms[0].xaos[0], 0.0);

  click("layer0/xaos reset 2");
  EXPECT_TRUE(flame().xforms[1].xaos.empty()) << "a row resets alone";
  EXPECT_FALSE(flame().xforms[0].xaos.empty());
  pressKey('Z', true);
  EXPECT_EQ(flame().xforms[1].xaos, dragged.xforms[1].xaos) << "a row reset is one undo step";
  click("layer0/Reset xaos");
  EXPECT_FALSE(core::hasXaos(flame()));
  for (const core::FlameXform& x : flame().xforms) EXPECT_TRUE(x.xaos.empty());
}

// ImGui tables hold at most 64 columns and a flame up to 128 transforms: a wide flame's matrix
// shows its columns a page at a time, and a cell of a later page edits its own column.
TEST_F(ExplorerFlameUi, AWideFlamesXaosMatrixPagesItsColumns) {
  useFlameLayer();
  core::Scene scene = state.document.scene;
  scene.layers[0].flame.xforms.resize(40, scene.layers[0].flame.xforms[0]);
  app::resetExplorerState(state, scene);
  frame(2);
  click("layer0/Xaos");
  EXPECT_NO_THROW(item("layer0/xaos 1 to 32"));
  EXPECT_THROW(item("layer0/xaos 1 to 33"), std::runtime_error) << "the first page holds 32 columns";
  click("layer0/xaos columns");
  click("layer0/xaos columns/to 33–40");
  probe.items.clear();
  frame();
  EXPECT_THROW(item("layer0/xaos 1 to 32"), std::runtime_error);
  const auto cell = item("layer0/xaos 1 to 35");
  drag(cell.centerX(), cell.centerY(), 40, 0);
  ASSERT_EQ(flame().xforms[0].xaos.size(), 35u);
  EXPECT_GT(flame().xforms[0].xaos[34], 1.0);
  EXPECT_EQ(std::count(flame().xforms[0].xaos.begin(), flame().xforms[0].xaos.end(), 1.0), 34);
  EXPECT_NO_THROW(core::validateFlame(flame(), "wide xaos"));
}

TEST_F(ExplorerFlameUi, TheRotateHandleTurnsTheMapAndBumpsTheGeneration) {
  useFlameLayer();
  edit([&](core::Scene& scene) { scene.gridResolution = 48; });
  app::ExplorerSession session(1);
  ASSERT_TRUE(session.postIfPatternChanged(state.document.scene));
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  ASSERT_TRUE(session.status().error.empty()) << session.status().error;
  const auto generation = session.status().stats.generation;
  frame();
  state.document.history->record(state.document.scene);

  const core::Affine3 before = flame().xforms[0].affine;
  const auto handle = item("layer0/xform/rotate");
  const float third = (handle.maxX - handle.minX) / 3.0f;
  // The first of the three angles, pressed at its middle (0°) and dragged right.
  drag(handle.minX + 0.5f * third, handle.centerY(), 0.3f * third, 0);
  const core::Affine3& after = flame().xforms[0].affine;
  EXPECT_NE(after, before);
  for (int row = 0; row < 3; ++row)
    EXPECT_NEAR(rowLength(after, row), rowLength(before, row), 1e-9) << "a rotation of the map's own frame";
  EXPECT_EQ(after.m[3], before.m[3]);
  EXPECT_EQ(after.m[7], before.m[7]);
  EXPECT_EQ(after.m[11], before.m[11]) << "the offset stays";
  // The handle is relative: back at +0° after the drag, it says what the drag turned.
  EXPECT_NO_THROW(item("layer0/xform/turned")) << "a line says what the drag turned";
  EXPECT_GT(state.panels.pattern.turnedAngles[0], 0.0);
  EXPECT_EQ(state.panels.pattern.rotateAngles[0], 0.0);
  ASSERT_TRUE(session.postIfPatternChanged(state.document.scene));
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  EXPECT_EQ(session.status().stats.generation, generation + 1);
  EXPECT_TRUE(session.status().error.empty()) << session.status().error;
  pressKey('Z', true);
  EXPECT_EQ(flame().xforms[0].affine, before) << "the whole drag is one undo step";
  EXPECT_THROW(item("layer0/xform/turned"), std::runtime_error) << "undone, the turn is no longer said";

  // The translate handle moves the offset only.
  const auto translate = item("layer0/xform/translate");
  drag(translate.minX + 4, translate.centerY(), 30, 0);
  EXPECT_NE(flame().xforms[0].affine.m[3], before.m[3]);
  EXPECT_EQ(flame().xforms[0].affine.m[0], before.m[0]);
}

TEST_F(ExplorerFlameUi, VariationsAreAddedWeightedAndRemoved) {
  useFlameLayer();
  const std::size_t terms = flame().xforms[0].variations.size();
  click("layer0/xform/add variation");
  click("layer0/xform/add/swirl");
  ASSERT_EQ(flame().xforms[0].variations.size(), terms + 1);
  EXPECT_EQ(flame().xforms[0].variations.back().name, "swirl");
  EXPECT_NO_THROW(core::validateFlame(flame(), "with swirl"));

  const std::string weightName = "layer0/xform/var" + std::to_string(terms) + "/weight";
  const auto weight = item(weightName);
  double pressedAt = 0.0;
  drag(weight.centerX(), weight.centerY(), 30, 0, 0, [&] { pressedAt = flame().xforms[0].variations.back().weight; });
  EXPECT_GT(flame().xforms[0].variations.back().weight, pressedAt);
  click("layer0/xform/var" + std::to_string(terms) + "/remove");
  EXPECT_EQ(flame().xforms[0].variations.size(), terms);

  // A variation with parameters shows them as sliders over the catalogue's range.
  const core::VariationInfo* withParams = nullptr;
  for (const core::VariationInfo& info : core::variationCatalogue())
    if (!info.params.empty() && !withParams) withParams = &info;
  if (!withParams) GTEST_SKIP() << "the catalogue has no variation with parameters yet";
  click("layer0/xform/add variation");
  // The list is longer than its popup: filter it to the name, as a user would type it.
  ImGui::GetIO().AddInputCharactersUTF8(withParams->name.c_str());  // the filter has the keyboard focus
  frame(2);
  click("layer0/xform/add/" + withParams->name);
  ASSERT_EQ(flame().xforms[0].variations.back().name, withParams->name);
  EXPECT_EQ(flame().xforms[0].variations.back().params, withParams->defaultParams());
  const core::VariationParam& param = withParams->params[0];
  const auto slider = item("layer0/xform/var" + std::to_string(terms) + "/" + param.name);
  const core::FlameGenome before = flame();
  drag(slider.minX + 2, slider.centerY(), slider.maxX - slider.minX + 40, 0);
  EXPECT_DOUBLE_EQ(flame().xforms[0].variations.back().params[0],
                   param.integer ? std::floor(param.sliderMax) : param.sliderMax)
      << "dragged past the end, the slider stops at its maximum";
  pressKey('Z', true);
  EXPECT_EQ(flame(), before);
}

// Issue 38: pre_falloff3's centre read "pre_falloff3 center" three times, cut at the panel's edge
// with the axis gone. Each variation's labels show whole inside the panel (beside the slider, or
// above it when too long), and its parameters' labels tell them apart ("center x").
TEST_F(ExplorerFlameUi, VariationLabelsShowWholeInsideThePanelAndApart) {
  useFlameLayer();
  const core::VariationInfo* falloff3 = core::findVariation("pre_falloff3");
  ASSERT_NE(falloff3, nullptr);
  // And the longest name of the catalogue, in its pre_ form.
  std::string longest;
  for (const core::VariationInfo& info : core::variationCatalogue())
    if (info.name.size() > longest.size()) longest = info.name;
  const core::VariationInfo* longestInfo = core::findVariation("pre_" + longest);
  ASSERT_NE(longestInfo, nullptr) << longest;
  const std::size_t first = flame().xforms[0].variations.size();
  edit([&](core::Scene& scene) {
    auto& variations = scene.layers[0].flame.xforms[0].variations;
    variations.push_back({"pre_falloff3", 0.25, falloff3->defaultParams()});
    variations.push_back({"pre_" + longest, 0.25, longestInfo->defaultParams()});
  });
  frame(2);
  const float panelRight = state.frame.layout.left;
  const auto inside = [&](const std::string& name) {
    EXPECT_LE(item(name).maxX, panelRight) << name << " (" << probe.texts[name] << ") is cut at the panel's edge";
    const auto label = probe.items.find(name + "/label");
    if (label != probe.items.end()) {
      EXPECT_LE(label->second.maxX, panelRight) << name << "/label";
    }
  };
  for (const auto& [index, info] : {std::pair{first, falloff3}, std::pair{first + 1, longestInfo}}) {
    const std::string scope = "layer0/xform/var" + std::to_string(index) + "/";
    EXPECT_EQ(probe.texts[scope + "weight"], flame().xforms[0].variations[index].name);
    inside(scope + "weight");
    std::set<std::string> labels;
    for (const core::VariationParam& param : info->params) {
      inside(scope + param.name);
      labels.insert(probe.texts[scope + param.name]);
    }
    EXPECT_EQ(labels.size(), info->params.size()) << info->name << ": every parameter's label differs";
  }
  const std::string scope = "layer0/xform/var" + std::to_string(first) + "/";
  EXPECT_EQ(probe.texts[scope + "center_x"], "center x");
  EXPECT_EQ(probe.texts[scope + "center_z"], "center z");
}

TEST_F(ExplorerFlameUi, SearchAndMutateOnAFlameKeepTheKindAndBackRestoresTheGenome) {
  useFlameLayer();
  const core::FlameGenome start = flame();
  click("Search (F3)");
  waitForSearch(2);
  ASSERT_EQ(state.panels.explore.visited.size(), 2u) << state.panels.explore.searchMessage;
  ASSERT_EQ(state.document.scene.layers[0].kind, core::PatternKind::Flame);
  const core::FlameGenome found = flame();
  EXPECT_NE(found, start);
  EXPECT_NO_THROW(core::validateFlame(found, "found"));
  EXPECT_TRUE(core::measureFlameFill(found, 1).passes);
  EXPECT_NE(state.panels.explore.searchMessage.find("fills"), std::string::npos) << state.panels.explore.searchMessage;

  click("Mutate");
  waitForSearch(3);
  ASSERT_EQ(state.panels.explore.visited.size(), 3u) << state.panels.explore.searchMessage;
  EXPECT_NE(flame(), found);
  EXPECT_NO_THROW(core::validateFlame(flame(), "mutated"));

  click("< Back");
  EXPECT_EQ(flame(), found);
  click("< Back");
  EXPECT_EQ(flame(), start);
  click("Forward >");
  EXPECT_EQ(flame(), found);
}

TEST_F(ExplorerFlameUi, QuaternionJuliaHasSlidersForItsConstantAndView) {
  click("layer0/pattern");
  click("layer0/pattern/quaternion Julia");
  ASSERT_EQ(state.document.scene.layers[0].kind, core::PatternKind::QuaternionJulia);
  frame();
  const core::QuaternionJuliaSettings before = state.document.scene.layers[0].julia;
  const core::Scene keyBefore = state.document.scene;
  const auto slider = item("layer0/c (j)");
  double pressedAt = 0.0;
  drag(slider.centerX(), slider.centerY(), 25, 0, 0, [&] { pressedAt = state.document.scene.layers[0].julia.c.z; });
  EXPECT_GT(state.document.scene.layers[0].julia.c.z, pressedAt);
  EXPECT_EQ(state.document.scene.layers[0].julia.c.x, before.c.x);
  EXPECT_TRUE(core::diff(keyBefore, state.document.scene).pattern());
  pressKey('Z', true);
  EXPECT_EQ(state.document.scene.layers[0].julia, before);
  EXPECT_NO_THROW(item("layer0/turn"));
  EXPECT_THROW(item("layer0/slice w"), std::runtime_error) << "the slice sliders show in slice view only";
  edit([&](core::Scene& scene) { scene.layers[0].julia.view = core::QuaternionView::Slice; });
  frame();
  EXPECT_NO_THROW(item("layer0/slice w"));
  EXPECT_NO_THROW(item("layer0/thickness"));

  click("Mutate");
  waitForSearch(2);
  ASSERT_EQ(state.panels.explore.visited.size(), 2u) << state.panels.explore.searchMessage;
  EXPECT_EQ(state.document.scene.layers[0].kind, core::PatternKind::QuaternionJulia);
  EXPECT_NE(state.document.scene.layers[0].julia.c, before.c);
  EXPECT_EQ(state.document.scene.layers[0].julia.view, core::QuaternionView::Slice) << "the search keeps the view";
}

}  // namespace

namespace {

// CPU time (clock ticks) that every thread of this process has used so far.
long long processThreadTicks() {
  long long ticks = 0;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
    std::ifstream in(task.path() / "stat");
    std::string stat((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Fields after the parenthesised name: state is field 3, utime 14 and stime 15.
    std::istringstream fields(stat.substr(stat.rfind(')') + 2));
    std::string field;
    for (int i = 3; i <= 15 && fields >> field; ++i)
      if (i >= 14) ticks += std::stoll(field);
  }
  return ticks;
}

// Takes volumes as the frame loop would (the session rests only once the last one is taken)
// until `done` holds, checking again whenever the session has news; false after `seconds`.
bool waitForSession(app::ExplorerSession& session, const std::function<bool(const app::SessionStatus&)>& done,
                    double seconds = 60.0) {
  core::PackedVolume volume;
  return test::waitForSession(
      session,
      [&] {
        session.takeVolumeIfNewer(volume);
        return done(session.status());
      },
      std::chrono::duration<double>(seconds));
}

}  // namespace

// The convergence meter falls as points grow; at the target the workers stop and sleep: points
// stop growing and the process's threads use no CPU while nothing changes. A lower target or a
// new pattern wakes them.
TEST_F(ExplorerUi, RefinementStopsAtTheNoiseTargetAndTheWorkersSleep) {
  edit([&](core::Scene& scene) { scene.gridResolution = 64; });
  // Pickover's estimate falls within a few measurements. The default Lorenz-84's (and
  // polynomial_a's) rises for hundreds of millions of points on this small grid before it falls,
  // so with it whether the estimate halves within a minute depended on when it was first measured.
  // One worker on a 64³ grid: Pickover (its sines vectorised) reached the 48³ grid's cap on two
  // cores within a second, a measurement after the first, before the estimate could halve or the
  // target be met twice.
  core::PatternLayer& layer = state.document.scene.layers[0];
  layer.attractor = "pickover";
  layer.params = core::attractorOrThrow(layer.attractor).defaultParams();
  app::ExplorerSession session(1);
  session.setRefinement(0.0, false);
  session.post(state.document.scene);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  // The estimate may rise over its first measurements (an orbit dwelling in one part of the
  // attractor) before it falls: it must come to fall well under the highest it reached.
  double highest = 0.0;
  ASSERT_TRUE(waitForSession(session, [&](const app::SessionStatus& s) {
    if (std::isfinite(s.noise)) highest = std::max(highest, s.noise);
    return highest > 0.0 && s.noise < 0.7 * highest;
  })) << "the noise estimate falls while the volume refines";
  EXPECT_FALSE(session.status().converged) << "\"never\" never stops";

  session.setRefinement(0.08, false);
  ASSERT_TRUE(waitForSession(session, [](const app::SessionStatus& s) { return s.converged && s.resting; }))
      << "noise " << session.status().noise;
  const app::SessionStatus rested = session.status();
  EXPECT_LE(rested.noise, 0.08);
  EXPECT_TRUE(rested.stats.done);
  EXPECT_EQ(app::convergenceText(rested).rfind("at rest: the noise reached its target", 0), 0u)
      << app::convergenceText(rested);
  const long long ticks = processThreadTicks();
  // A fixed wait, as this proves that something does NOT happen: no points and no CPU at rest.
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  EXPECT_EQ(session.status().stats.points, rested.stats.points) << "no points are added at rest";
  // Two busy workers would use about 120 ticks in that time; sleeping ones use none.
  EXPECT_LE(processThreadTicks() - ticks, 3) << "the threads sleep once the target is reached";

  session.setRefinement(0.0001, false);
  // The points grow as soon as the target is lowered, a moment before the status stops saying
  // "converged": both are waited for.
  ASSERT_TRUE(waitForSession(
      session, [&](const app::SessionStatus& s) { return s.stats.points > rested.stats.points && !s.converged; }))
      << "a lower target starts refining again (rested at " << rested.pointsPerVoxel << " of "
      << rested.capPointsPerVoxel << " points per voxel)";
  EXPECT_EQ(app::convergenceText(session.status()).rfind("refining: ", 0), 0u)
      << app::convergenceText(session.status());
}

// The default preset, on a small grid and with the explorer's default noise target, comes to rest
// by itself: the noise target or the grid's cap, whichever is first, and the status line says so.
TEST_F(ExplorerUi, TheDefaultPresetComesToRest) {
  edit([&](core::Scene& scene) { scene.gridResolution = 48; });
  app::ExplorerSession session(2);
  session.setRefinement(0.01 * app::kDefaultRefineUntilNoisePercent, false);
  session.post(state.document.scene);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  ASSERT_TRUE(waitForSession(
      session, [](const app::SessionStatus& s) { return s.resting; }, 240.0))
      << "points per voxel " << session.status().pointsPerVoxel << " of " << session.status().capPointsPerVoxel;
  const app::SessionStatus rested = session.status();
  EXPECT_TRUE(rested.converged || rested.capped);
  EXPECT_EQ(app::convergenceText(rested).rfind("at rest: ", 0), 0u) << app::convergenceText(rested);
  EXPECT_LE(rested.pointsPerVoxel, rested.capPointsPerVoxel * 1.05);
}

// The cap is points per pixel in disguise: it falls with the square of the grid's side, and a mesh
// twice as thick (eight times the inside voxels) needs half the points per voxel, within [½, 2].
TEST(RestCap, FallsWithTheGridAndTheMeshesThickness) {
  core::GridGeometry grid192, grid384;
  grid192.size = {192, 192, 192};
  grid384.size = {384, 384, 384};
  const std::uint64_t bunny = 1'367'631;  // 111³: the reference thickness at 192
  const auto cap = app::ExplorerSession::restCapPointsPerVoxel;
  EXPECT_NEAR(cap(grid192, bunny), app::ExplorerSession::kRestCapPointsPerVoxel, 0.5);
  EXPECT_NEAR(cap(grid192, bunny * 8), cap(grid192, bunny) / 2.0, 0.5);
  EXPECT_NEAR(cap(grid192, bunny / 8), cap(grid192, bunny) * 2.0, 1.0);
  EXPECT_NEAR(cap(grid192, bunny / 1000), cap(grid192, bunny) * 2.0, 1.0) << "the factor stops at 2";
  EXPECT_NEAR(cap(grid384, bunny * 8), cap(grid192, bunny) / 4.0, 0.5) << "the same mesh on a grid twice as fine";
}

// A target the noise never reaches (here far below what any flow's estimate gets to) still ends:
// refinement stops at the grid's cap of points per voxel, adds nothing after, and the threads sleep.
// "Refine further" then goes on from those points to twice as many, in the same generation.
// A 32-voxel grid (no proxy, as at 40): the cap per voxel is at its maximum on both, so the cap
// is reached with half the points (11M, then 22M further, instead of 22M and 45M at 40).
TEST_F(ExplorerUi, TheCapEndsAFlowThatNeverReachesItsTargetAndRefineFurtherKeepsItsPoints) {
  edit([&](core::Scene& scene) { scene.gridResolution = 32; });
  app::ExplorerSession session(2);
  session.setRefinement(1e-6, false);
  session.post(state.document.scene);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  ASSERT_TRUE(waitForSession(
      session, [](const app::SessionStatus& s) { return s.resting; }, 240.0))
      << "points per voxel " << session.status().pointsPerVoxel << " of " << session.status().capPointsPerVoxel;
  const app::SessionStatus capped = session.status();
  EXPECT_TRUE(capped.capped);
  EXPECT_FALSE(capped.converged);
  EXPECT_NEAR(capped.capPointsPerVoxel, app::ExplorerSession::restCapPointsPerVoxel(capped.grid, capped.insideVoxels),
              0.01 * capped.capPointsPerVoxel);
  EXPECT_GE(capped.pointsPerVoxel, capped.capPointsPerVoxel);
  EXPECT_LE(capped.pointsPerVoxel, capped.capPointsPerVoxel * 1.05) << "it stops at the cap";
  EXPECT_EQ(app::convergenceText(capped).rfind("at rest: the cap of ", 0), 0u) << app::convergenceText(capped);
  const long long ticks = processThreadTicks();
  // A fixed wait, as this proves that something does NOT happen: no points and no CPU at the cap.
  std::this_thread::sleep_for(std::chrono::milliseconds(600));
  EXPECT_EQ(session.status().stats.points, capped.stats.points) << "no points are added at rest";
  EXPECT_LE(processThreadTicks() - ticks, 3) << "the threads sleep at the cap";

  session.refineFurther();
  std::uint64_t fewest = capped.stats.points;
  ASSERT_TRUE(waitForSession(
      session,
      [&](const app::SessionStatus& s) {
        fewest = std::min(fewest, s.stats.points);
        return s.resting && s.stats.points >= 2 * capped.stats.points;
      },
      240.0));
  const app::SessionStatus further = session.status();
  EXPECT_EQ(fewest, capped.stats.points) << "refining further never starts from zero";
  EXPECT_EQ(further.stats.generation, capped.stats.generation) << "the same accumulation goes on";
  EXPECT_LE(further.stats.points, 2 * capped.stats.points * 105 / 100);
  EXPECT_TRUE(further.capped) << "it rests again at the raised cap";
}

// The rule needs two measurements in a row under the target: one alone may dip under it by chance.
TEST(ConvergenceRule, TwoMeasurementsInARowAreNeeded) {
  core::ConvergenceMeter meter;
  EXPECT_FALSE(meter.twoMeasurementsWithin(1.0));
  core::DensitySample sample;
  sample.generation = 1;
  sample.hits.assign(4096, 0);
  std::uint64_t points = 0;
  // Counts that grow in proportion: every measurement is (nearly) 0.
  for (int round = 1; round <= 3; ++round) {
    for (std::size_t v = 0; v < sample.hits.size(); ++v)
      sample.hits[v] = static_cast<std::uint32_t>((4 << round) * (v % 7 + 1));
    points = 0;
    for (std::uint32_t h : sample.hits) points += h;
    sample.points = points;
    meter.update(sample);
    if (round == 2) {
      EXPECT_EQ(meter.measurements(), 1);
      EXPECT_FALSE(meter.twoMeasurementsWithin(0.01)) << "one measurement is not enough";
    }
  }
  EXPECT_EQ(meter.measurements(), 2);
  EXPECT_TRUE(meter.twoMeasurementsWithin(0.01));
  meter.reset();
  EXPECT_FALSE(meter.twoMeasurementsWithin(0.01));
}

// While an export runs refinement is held (the two would fight over the cores); it resumes after.
TEST_F(ExplorerUi, RefinementPausesWhileAnExportRuns) {
  edit([&](core::Scene& scene) { scene.gridResolution = 48; });
  app::ExplorerSession session(2);
  session.setRefinement(0.0, true);
  session.post(state.document.scene);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  ASSERT_TRUE(waitForSession(session, [](const app::SessionStatus& s) { return s.paused && s.resting; }));
  const std::uint64_t held = session.status().stats.points;
  EXPECT_GE(held, app::ExplorerSession::kPausedPreviewPoints) << "a pattern edited during an export still shows";
  EXPECT_EQ(app::convergenceText(session.status()), "refining paused for the export");
  session.setRefinement(0.0, false);
  ASSERT_TRUE(waitForSession(session, [&](const app::SessionStatus& s) { return s.stats.points > held; }));
  EXPECT_FALSE(session.status().paused);
}

// While the user drags a slider (edits in consecutive frames) the large grid holds: the proxy shows
// each edit and gets the cores; the grid refines the pattern the user stops on.
TEST_F(ExplorerUi, TheLargeGridHoldsWhileTheUserDragsAndTheProxyShowsEachEdit) {
  edit([&](core::Scene& scene) { scene.gridResolution = 128; });  // above kProxyAbove: the grid has a proxy
  app::ExplorerSession session(2);
  session.setRefinement(0.0, false, true);
  session.post(state.document.scene);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  // Takes volumes (the proxy's or the large grid's) until one shows post 1; the post it last saw.
  using Take = bool (app::ExplorerSession::*)(core::PackedVolume&, std::uint64_t*);
  core::PackedVolume volume;
  auto postShown = [&](Take take) {
    std::uint64_t reflects = 0;
    test::waitForSession(session, [&] { return (session.*take)(volume, &reflects) && reflects == 1; });
    return reflects;
  };
  EXPECT_EQ(postShown(&app::ExplorerSession::takeProxyIfNewer), 1u) << "the proxy shows the edit while the grid holds";
  // The proxy's burst is the drag's smaller one (the frame needs the cores more than the proxy
  // needs smoothness): it reaches the drag's count (however slow the build, a sanitizer's say) and
  // then stops well short of the full burst.
  const double insideVoxels = volume.insideVoxels;
  EXPECT_GE(static_cast<double>(volume.points), app::ExplorerSession::kProxyShownPointsPerVoxel * insideVoxels)
      << "no proxy volume is packed with too few points to be shown";
  const double dragBurst = app::ExplorerSession::kProxyDragPointsPerVoxel * insideVoxels * 0.9;
  test::waitForSession(session, [&] {
    session.takeProxyIfNewer(volume);
    return static_cast<double>(volume.points) >= dragBurst;
  });
  EXPECT_GE(static_cast<double>(volume.points), dragBurst);
  // The burst ends: the proxy's backend is done, its workers asleep at their target, and no more
  // points come until the target changes. It ended well short of the full burst.
  ASSERT_TRUE(test::waitForSession(session, [&] {
    const std::optional<core::AccumulatorStats> proxy = session.proxyStats();
    return proxy && proxy->done;
  }));
  EXPECT_LT(static_cast<double>(session.proxyStats()->points),
            0.5 * app::ExplorerSession::kProxyPointsPerVoxel * insideVoxels)
      << "a drag's proxy burst is a third of the full one";
  const std::uint64_t held = session.status().stats.points;
  EXPECT_EQ(held, 0u) << "the large grid adds nothing while the user drags";
  EXPECT_FALSE(session.takeVolumeIfNewer(volume)) << "nor is it packed for upload";
  session.setRefinement(0.0, false, false);
  ASSERT_TRUE(waitForSession(session, [&](const app::SessionStatus& s) { return s.stats.points > held + 1'000'000; }))
      << "once the drag ends the grid refines";
  EXPECT_EQ(postShown(&app::ExplorerSession::takeVolumeIfNewer), 1u)
      << "the pattern the drag stopped on, set on the grid after the drag";
  test::waitForSession(session, [&] {
    return session.takeProxyIfNewer(volume) &&
           static_cast<double>(volume.points) >= app::ExplorerSession::kProxyPointsPerVoxel * insideVoxels * 0.99;
  });
  EXPECT_GE(static_cast<double>(volume.points), app::ExplorerSession::kProxyPointsPerVoxel * insideVoxels * 0.99)
      << "once the drag ends the proxy's burst goes on to the full count";
}

// While only the view moves (an orbit) even a grid without a proxy holds: the frames get the cores.
// A pattern edit ends the hold, since that grid is then the only one to show it.
TEST_F(ExplorerUi, AnOrbitHoldsEvenAGridWithoutAProxyAndAnEditEndsIt) {
  edit([&](core::Scene& scene) { scene.gridResolution = 48; });  // no proxy
  app::ExplorerSession session(2);
  session.setRefinement(0.0, false);
  session.post(state.document.scene);
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  ASSERT_TRUE(waitForSession(session, [](const app::SessionStatus& s) { return s.stats.points > 100'000; }));
  session.setRefinement(0.0, false, true, true);
  // The batches under way when the hold came land, and the workers go to sleep: the backend is idle.
  ASSERT_TRUE(test::waitForSession(session, [&] { return session.gridIdle(); })) << "the held grid kept working";
  const std::uint64_t held = session.status().stats.points;
  // A fixed wait, as this proves that something does NOT happen: points added while the view moves.
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  EXPECT_EQ(session.status().stats.points, held) << "the grid adds nothing while the view moves";

  const std::uint64_t generation = session.status().stats.generation;
  edit([&](core::Scene& scene) { scene.layers[0].params[0] *= 1.01; });
  session.post(state.document.scene, true);  // an edit in the middle of the orbit
  ASSERT_TRUE(session.waitUntilApplied(60.0));
  ASSERT_TRUE(waitForSession(session, [&](const app::SessionStatus& s) {
    return s.stats.generation > generation && s.stats.points > 10'000;
  })) << "the edit refines at once on a grid without a proxy";
}

// The Render panel has the setting; the window loop waits for input only when everything rests.
TEST_F(ExplorerUi, TheNoiseTargetIsASettingAndTheLoopRestsOnlyWhenNothingMoves) {
  EXPECT_DOUBLE_EQ(state.services.settings.refineUntilNoisePercent, app::kDefaultRefineUntilNoisePercent);
  const auto& slider = item("render/stop_refining_at_noise");
  drag(slider.centerX(), slider.centerY(), -2000.0f, 0.0f);
  EXPECT_DOUBLE_EQ(state.services.settings.refineUntilNoisePercent, 0.0) << "the left end is \"never\"";
  drag(slider.minX + 2, slider.centerY(), 80.0f, 0.0f);
  EXPECT_GT(state.services.settings.refineUntilNoisePercent, 0.0);

  app::SessionStatus status;
  status.hasShape = true;
  status.noise = 0.012;
  status.noiseTarget = 0.005;
  status.stats.points = 65'000'000;
  EXPECT_EQ(app::convergenceText(status), "refining: 65 M points, noise 1.2% of 0.5%");
  status.noiseTarget = 0.0;
  EXPECT_EQ(app::convergenceText(status), "refining: 65 M points, noise 1.2%");
  status.backend = core::BackendKind::Gpu;
  status.gridOnDevice = true;
  EXPECT_EQ(app::convergenceText(status), "refining on the GPU: 65 M points, noise 1.2%");
  // Where the grid cannot stay on the GPU (a GLX window, a software renderer), the status says so.
  status.gridOnDevice = false;
  EXPECT_EQ(app::convergenceText(status), "refining on the GPU (grid read back): 65 M points, noise 1.2%");
  status.backend = core::BackendKind::Cpu;

  // The Lyapunov analysis of the pattern runs in the background at first: that is not rest.
  ASSERT_TRUE(framesUntil([&] { return !state.services.analysis.busy() && !state.services.search.busy(); }));
  state.frame.session.resting = false;
  EXPECT_EQ(app::frameWaitSeconds(state, true, 10), 0.0) << "refining: every frame is drawn";
  state.frame.session.resting = true;
  EXPECT_EQ(app::frameWaitSeconds(state, false, 10), 0.0) << "samples still to march";
  EXPECT_EQ(app::frameWaitSeconds(state, true, 1), 0.0) << "input settles first";
  EXPECT_GT(app::frameWaitSeconds(state, true, 10), 0.0);
  state.services.exportStatus.state = app::ExportState::Running;
  EXPECT_GT(app::frameWaitSeconds(state, false, 0), 0.0) << "an export's frames are throttled";
}

// The flat view (issue 25): the checkbox's state renders the flame layer in 2D off the main thread,
// at the flame's framing, again after an edit, and stops when turned off. Issue 38: it was drawn
// over the whole window, under the side panels, its caption hidden under the left one, and
// stretched soft from a small render. It fills the view's rectangle between the panels (the flame's
// aspect fitted into it), rendered at that rectangle's pixel size and drawn a texel a pixel, with
// its caption inside the rectangle; a new size of the rectangle renders it again.
TEST_F(ExplorerFlameUi, FlatViewRendersTheFlameLayerInTheViewAtItsSizeAndFollowsEdits) {
  useFlameLayer();
  edit([&](core::Scene& scene) { scene.flat.width = 80; });
  edit([&](core::Scene& scene) { scene.flat.height = 60; });
  edit([&](core::Scene& scene) { scene.flat.scale = 20.0; });
  edit([&](core::Scene& scene) { scene.flat.quality = 2.0; });
  state.panels.flat.on = true;
  const auto waitForImage = [&] { framesUntil([&] { return state.frame.flatImagePending; }); };
  // As the window loop's upload does: the image becomes the texture drawn.
  const auto upload = [&] {
    state.frame.flatImagePending = false;
    state.frame.flatTexture = 1;
    state.frame.flatTextureWidth = state.frame.flatImage.width;
    state.frame.flatTextureHeight = state.frame.flatImage.height;
    frame();
  };
  // The picture and its caption lie in the view's rectangle, between the panels and above the
  // Timeline; the picture is the image's size, filling the rectangle's width or height.
  const auto checkPlacement = [&] {
    const glm::ivec4 view = state.frame.viewRect;
    const app::FrameOutputs::PanelEdges& edges = state.frame.layout;
    const auto image = item("flat/image"), caption = item("flat/caption");
    EXPECT_FLOAT_EQ(image.maxX - image.minX, static_cast<float>(state.frame.flatImage.width));
    EXPECT_FLOAT_EQ(image.maxY - image.minY, static_cast<float>(state.frame.flatImage.height));
    EXPECT_TRUE(state.frame.flatImage.width == view.z || state.frame.flatImage.height == view.w)
        << state.frame.flatImage.width << "×" << state.frame.flatImage.height << " in " << view.z << "×" << view.w;
    for (const auto& [name, rect] : {std::pair{"image", image}, std::pair{"caption", caption}}) {
      EXPECT_GE(rect.minX, edges.left) << name << " under the Pattern panel";
      EXPECT_LE(rect.maxX, edges.right) << name << " under the Scene panel";
      EXPECT_LE(rect.maxY, edges.bottom) << name << " under the Timeline";
      EXPECT_GE(rect.minY, 0.0f) << name;
    }
    EXPECT_EQ(probe.texts["flat/caption"], "flat view (as flam3 renders it)");
  };
  frame();
  waitForImage();
  ASSERT_TRUE(state.frame.flatImagePending) << state.panels.flat.message;
  EXPECT_NEAR(state.frame.flatImage.width * 60, state.frame.flatImage.height * 80, 80) << "the flame's aspect";
  EXPECT_GT(state.frame.flatImage.width, 400) << "the view's size, not the flame's 80 × 60";
  EXPECT_EQ(app::frameWaitSeconds(state, true, 10), 0.0) << "the window loop must upload the new image";
  upload();
  checkPlacement();

  edit([&](core::Scene& scene) { scene.flat.width = 20; });
  frame();
  waitForImage();
  ASSERT_TRUE(state.frame.flatImagePending) << state.panels.flat.message;
  EXPECT_EQ(state.frame.flatImage.height, state.frame.viewRect.w) << "a tall flame fills the view's height";
  EXPECT_NEAR(state.frame.flatImage.width * 60, state.frame.flatImage.height * 20, 60);
  upload();
  checkPlacement();

  // A smaller window: the view's rectangle shrinks, and the picture is rendered again at its size.
  const int before = state.frame.flatImage.height;
  ImGui::GetIO().DisplaySize.y = 1000.0f;
  frame(2);
  waitForImage();
  ASSERT_TRUE(state.frame.flatImagePending) << state.panels.flat.message;
  EXPECT_LT(state.frame.flatImage.height, before);
  EXPECT_EQ(state.frame.flatImage.height, state.frame.viewRect.w);
  upload();
  checkPlacement();

  state.panels.flat.on = false;
  frame();
  EXPECT_FALSE(state.services.flatRender.busy());
}

// Issue 28: a drag that passes through an escape. The slider keeps following the mouse (the
// notice that appears must not take it), the picture keeps the last bounded pattern with one
// message naming the value, and the status line and the panel say the same; dragging back brings
// the pattern back.
TEST_F(ExplorerUi, ADragThroughAnEscapeKeepsFollowingTheMouseAndComesBack) {
  edit([&](core::Scene& scene) { scene.gridResolution = 48; });
  const core::AttractorInfo& aizawa = core::attractorOrThrow("aizawa");
  edit([&](core::Scene& scene) { scene.layers[0].attractor = aizawa.id; });
  edit([&](core::Scene& scene) { scene.layers[0].params = aizawa.defaultParams(); });
  edit([&](core::Scene& scene) { scene.layers[0].step = aizawa.defaultStep; });
  edit([&](core::Scene& scene) { scene.layers[0].integrator = aizawa.defaultIntegrator; });
  frame(2);
  app::ExplorerSession session(1);
  const auto settle = [&] {
    session.postIfPatternChanged(state.document.scene, state.frame.interacting);
    ASSERT_TRUE(session.waitUntilApplied(60.0));
    // A bounded pattern has points to keep before the drag moves on.
    ASSERT_TRUE(waitForSession(
        session, [](const app::SessionStatus& s) { return !s.escapeNote.empty() || s.stats.points > 0; }));
    state.frame.session = session.status();
    frame();
  };
  settle();
  ASSERT_TRUE(state.frame.session.escapeNote.empty()) << state.frame.session.escapeNote;

  const auto slider = item("layer0/a");
  const float width = slider.maxX - slider.minX;
  ImGuiIO& io = ImGui::GetIO();
  moveTo(slider.minX + 0.3f * width, slider.centerY());
  io.MouseDown[0] = true;
  frame();
  settle();
  std::vector<double> values;
  bool escaped = false, lastBoundedKept = false, agreed = true;
  std::string note;
  const auto step = [&](float fraction) {
    moveTo(slider.minX + fraction * width, slider.centerY());
    settle();
    values.push_back(state.document.scene.layers[0].params[0]);
    if (!state.frame.session.escapeNote.empty()) {
      escaped = true;
      lastBoundedKept = lastBoundedKept || state.frame.session.showingLastBounded;
      note = state.frame.session.escapeNote;
      agreed = agreed && app::convergenceText(state.frame.session) == note;
    }
  };
  for (float f = 0.35f; f <= 0.96f; f += 0.05f) step(f);
  const std::vector<double> outward = values;
  values.clear();
  for (float f = 0.9f; f >= 0.29f; f -= 0.1f) step(f);
  io.MouseDown[0] = false;
  frame(2);

  for (std::size_t i = 1; i < outward.size(); ++i)
    EXPECT_GT(outward[i], outward[i - 1]) << "the slider follows the mouse right, step " << i;
  for (std::size_t i = 1; i < values.size(); ++i) EXPECT_LT(values[i], values[i - 1]) << "and back left, step " << i;
  ASSERT_TRUE(escaped) << "Aizawa escapes before a = " << outward.back();
  EXPECT_TRUE(lastBoundedKept) << "the last bounded pattern stays on screen";
  EXPECT_EQ(note.rfind("escapes at a = ", 0), 0u) << note;
  EXPECT_NE(note.find("showing the last bounded value"), std::string::npos) << note;
  EXPECT_TRUE(agreed) << "the status line says what the notice says";
  EXPECT_TRUE(state.frame.session.escapeNote.empty()) << "dragged back, the pattern is bounded again";
  EXPECT_FALSE(state.frame.session.showingLastBounded);
  EXPECT_TRUE(state.frame.session.stats.problem.empty());
}
