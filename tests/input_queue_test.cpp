// The explorer's input queue (app/explorer/input_queue.h) fed like GLFW's callbacks would between two
// frames, and applied to a headless ImGui context running the explorer's panels.
#include <gtest/gtest.h>

#include <cctype>
#include <string>
#include <imgui.h>

#include "core/scene_io.h"
#include "explorer_ui.h"
#include "input_queue.h"
#include "key_codes.h"

using namespace voxflame;

namespace {

constexpr int kKeyQ = 'Q', kKeyZ = 'Z', kKeyBackspace = app::kKeyBackspace;  // GLFW_KEY_Q is 'Q'

class InputQueueTest : public ::testing::Test {
 protected:
  void SetUp() override {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(1280, 720);
    io.DeltaTime = 1.0f / 4.0f;  // a slow machine: 4 frames a second
    app::applyUiScale(1.0f);
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
    app::resetExplorerState(state, core::defaultScene());
    frame();
  }
  void TearDown() override { ImGui::DestroyContext(); }

  // A frame of a bare text field fed by the queue; `focus` gives it the keyboard.
  void textFieldFrame(char* text, std::size_t size, bool focus) {
    queue.applyTo(ImGui::GetIO());
    ImGui::NewFrame();
    ImGui::Begin("typing");
    if (focus) ImGui::SetKeyboardFocusHere();
    ImGui::InputText("field", text, size);
    ImGui::End();
    ImGui::Render();
  }
  // Gives the field the keyboard, with the editing keys mapped as the GLFW backend maps them.
  void focusTextField(char* text, std::size_t size) {
    ImGuiIO& io = ImGui::GetIO();
    io.KeyMap[ImGuiKey_Backspace] = app::kKeyBackspace;
    io.KeyMap[ImGuiKey_A] = 'A';
    textFieldFrame(text, size, true);
    for (int i = 0; i < 3; ++i) textFieldFrame(text, size, false);
    ASSERT_TRUE(ImGui::IsAnyItemActive()) << "the field has the keyboard";
  }

  // One explorer frame as the window loop runs it: the backend's pointer (over the window), the
  // queue, the panels. Returns whether the panels asked to quit.
  bool frame() {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(640, 360);
    queue.applyTo(io);
    ImGui::NewFrame();
    state.frame.requests = {};
    app::explorerUiFrame(state);
    ImGui::Render();
    return state.frame.requests.quit;
  }

  app::InputQueue queue;
  app::ExplorerState state;
};

TEST_F(InputQueueTest, CtrlQTappedWithinOneFrameQuits) {
  // What `xdotool keydown ctrl+q keyup ctrl+q` delivers between two frames.
  queue.key(app::kKeyLeftControl, true);
  queue.key(kKeyQ, true);
  queue.key(kKeyQ, false);
  queue.key(app::kKeyLeftControl, false);
  EXPECT_TRUE(frame()) << "the tap was lost";
  EXPECT_TRUE(ImGui::GetIO().KeysDown[kKeyQ]);
  EXPECT_TRUE(ImGui::GetIO().KeyCtrl);
  // The release waited for the next frame; then nothing is held and nothing more happens.
  EXPECT_FALSE(frame());
  EXPECT_FALSE(ImGui::GetIO().KeysDown[kKeyQ]);
  EXPECT_FALSE(ImGui::GetIO().KeyCtrl);
  EXPECT_FALSE(ImGui::GetIO().KeysDown[app::kKeyLeftControl]);
  EXPECT_EQ(queue.pending(), 0u);
  EXPECT_FALSE(frame());
}

TEST_F(InputQueueTest, WithoutTheQueueTheSameTapIsLost) {
  // What ImGui's own GLFW callbacks do: write the state as events come. The tap cancels out
  // before the frame looks, which is the bug the queue exists for.
  ImGuiIO& io = ImGui::GetIO();
  io.KeysDown[app::kKeyLeftControl] = io.KeyCtrl = true;
  io.KeysDown[kKeyQ] = true;
  io.KeysDown[kKeyQ] = false;
  io.KeysDown[app::kKeyLeftControl] = io.KeyCtrl = false;
  EXPECT_FALSE(frame());
}

TEST_F(InputQueueTest, ModifiersFollowTheOrderOfTheKeys) {
  // Ctrl released before Q is pressed is not Ctrl+Q, however quickly it all happened.
  queue.key(app::kKeyRightControl, true);
  queue.key(app::kKeyRightControl, false);
  queue.key(kKeyQ, true);
  queue.key(kKeyQ, false);
  for (int i = 0; i < 4; ++i) EXPECT_FALSE(frame()) << "frame " << i;
  EXPECT_EQ(queue.pending(), 0u);
  EXPECT_FALSE(ImGui::GetIO().KeyCtrl);
}

TEST_F(InputQueueTest, AClickWithinOneFrameIsDownForOneFrameWhereItWasMade) {
  ImGuiIO& io = ImGui::GetIO();
  queue.cursor(100, 200);
  queue.mouseButton(0, true);
  queue.cursor(300, 400);  // moved away before the release: waits, so the press lands at (100, 200)
  queue.mouseButton(0, false);
  frame();
  EXPECT_TRUE(io.MouseDown[0]);
  EXPECT_TRUE(ImGui::IsMouseClicked(0));
  EXPECT_FLOAT_EQ(io.MouseClickedPos[0].x, 100.0f);
  EXPECT_FLOAT_EQ(io.MouseClickedPos[0].y, 200.0f);
  frame();
  EXPECT_FALSE(io.MouseDown[0]);
  EXPECT_TRUE(ImGui::IsMouseReleased(0));
  EXPECT_FLOAT_EQ(io.MousePos.x, 300.0f);
  EXPECT_EQ(queue.pending(), 0u);
}

TEST_F(InputQueueTest, CharactersStayInOrderWithTheKeysAroundThem) {
  // "a", Backspace, "b" typed between two frames: the Backspace must come after the "a" and
  // before the "b", or the text would read differently from what was typed.
  ImGuiIO& io = ImGui::GetIO();
  queue.character('a');
  queue.key(kKeyBackspace, true);
  queue.key(kKeyBackspace, false);
  queue.character('b');
  queue.applyTo(io);
  ASSERT_EQ(io.InputQueueCharacters.Size, 1);
  EXPECT_EQ(io.InputQueueCharacters[0], 'a');
  EXPECT_TRUE(io.KeysDown[kKeyBackspace]);
  io.InputQueueCharacters.resize(0);  // what a frame does with them
  queue.applyTo(io);
  EXPECT_FALSE(io.KeysDown[kKeyBackspace]);
  ASSERT_EQ(io.InputQueueCharacters.Size, 1);
  EXPECT_EQ(io.InputQueueCharacters[0], 'b');
}

TEST_F(InputQueueTest, WheelStepsAndMovesAddUpWithoutFillingTheQueue) {
  for (int i = 0; i < 100; ++i) {
    queue.scroll(0.0, 1.0);
    queue.cursor(i, i);
  }
  // Alternating scroll and moves cannot merge; still, no transition stops the frame.
  ImGuiIO& io = ImGui::GetIO();
  io.MouseWheel = 0.0f;
  queue.applyTo(io);
  EXPECT_FLOAT_EQ(io.MouseWheel, 100.0f);
  EXPECT_EQ(queue.pending(), 0u);
  for (int i = 0; i < 100; ++i) queue.cursor(i, 2 * i);
  EXPECT_EQ(queue.pending(), 1u);
  queue.applyTo(io);
  EXPECT_FLOAT_EQ(io.MousePos.y, 198.0f);
}

}  // namespace

// What a fast typist (or xdotool) delivers between two frames: each letter's press, character and
// release. The characters all reach a text field within a couple of frames, not one a frame, and
// the text reads as typed, Backspace included.
TEST_F(InputQueueTest, TypedTextArrivesInAFrameOrTwoAsTyped) {
  char text[64] = "";
  const auto fieldFrame = [&](bool focus) { textFieldFrame(text, sizeof text, focus); };
  focusTextField(text, sizeof text);

  auto type = [&](const std::string& letters) {
    for (const char c : letters) {
      const int code = c == ' ' ? 32 : std::toupper(static_cast<unsigned char>(c));
      queue.key(code, true);
      queue.character(static_cast<unsigned>(c));
      queue.key(code, false);
    }
  };
  type("sprott quadratx");
  queue.key(kKeyBackspace, true);
  queue.key(kKeyBackspace, false);
  type("ic");
  int frames = 0;
  for (; frames < 40 && std::string(text) != "sprott quadratic"; ++frames) fieldFrame(false);
  EXPECT_STREQ(text, "sprott quadratic");
  EXPECT_LE(frames, 3) << "one character a frame would take 18";
  for (int i = 0; i < 40 && queue.pending() > 0; ++i) fieldFrame(false);  // the releases, a frame each
  EXPECT_EQ(queue.pending(), 0u);
  EXPECT_STREQ(text, "sprott quadratic");
}

// A resting explorer wakes on the first event, so a frame can start with Ctrl alone down; xdotool
// then releases Ctrl before A. A's press must still come with Ctrl held.
TEST_F(InputQueueTest, AModifierReleasedRightAfterAKeyPressWaitsForTheNextFrame) {
  ImGuiIO& io = ImGui::GetIO();
  queue.key(app::kKeyLeftControl, true);
  queue.applyTo(io);  // the frame the first event woke
  EXPECT_TRUE(io.KeyCtrl);
  queue.key('A', true);
  queue.key(app::kKeyLeftControl, false);
  queue.key('A', false);
  queue.applyTo(io);
  EXPECT_TRUE(io.KeysDown['A']);
  EXPECT_TRUE(io.KeyCtrl) << "A went down with Ctrl held: this frame is Ctrl+A";
  queue.applyTo(io);
  EXPECT_FALSE(io.KeyCtrl);
  EXPECT_FALSE(io.KeysDown['A']);
  EXPECT_EQ(queue.pending(), 0u);
}

// xdotool's "key ctrl+a" (Ctrl down, A down, A up, Ctrl up between two frames) selects the whole
// text of the field with the keyboard, so the Backspace after it empties the field.
TEST_F(InputQueueTest, AQuickCtrlASelectsTheWholeField) {
  char text[64] = "sprott quadratic";
  const auto fieldFrame = [&](bool focus) { textFieldFrame(text, sizeof text, focus); };
  focusTextField(text, sizeof text);
  queue.key(app::kKeyLeftControl, true);
  queue.key('A', true);
  queue.key('A', false);
  queue.key(app::kKeyLeftControl, false);
  queue.key(kKeyBackspace, true);
  queue.key(kKeyBackspace, false);
  for (int i = 0; i < 20 && queue.pending() > 0; ++i) fieldFrame(false);
  fieldFrame(false);
  EXPECT_STREQ(text, "");
}

// Ctrl+F, then a letter before the next frame: the frame that gives the field the keyboard drops
// its characters (ImGui 1.86), so the explorer holds them for that frame and the letter arrives.
TEST_F(InputQueueTest, ALetterTypedAsAFieldTakesTheKeyboardIsKept) {
  char text[64] = "";
  const auto fieldFrame = [&](bool focus, bool holdCharacters) {
    queue.applyTo(ImGui::GetIO(), holdCharacters);
    ImGui::NewFrame();
    ImGui::Begin("typing");
    if (focus) ImGui::SetKeyboardFocusHere();
    ImGui::InputText("field", text, sizeof text);
    ImGui::End();
    ImGui::Render();
  };
  fieldFrame(true, false);  // the focus is asked for here
  queue.key('S', true);
  queue.character('s');
  queue.key('S', false);
  fieldFrame(false, true);  // the field takes the keyboard: the letter waits
  EXPECT_STREQ(text, "");
  EXPECT_GT(queue.pending(), 0u);
  for (int i = 0; i < 4; ++i) fieldFrame(false, false);
  EXPECT_STREQ(text, "s") << "the letter typed while the field took the keyboard";
}

// A letter's release waits for the next frame while typing goes on, but a modifier does not
// overtake it: Z down, Z up, Ctrl down between two frames is not Ctrl+Z.
TEST_F(InputQueueTest, AWaitingReleaseIsNotOvertakenByAModifier) {
  ImGuiIO& io = ImGui::GetIO();
  queue.key(kKeyZ, true);
  queue.key(kKeyZ, false);
  queue.key(app::kKeyLeftControl, true);
  queue.applyTo(io);
  EXPECT_TRUE(io.KeysDown[kKeyZ]);
  EXPECT_FALSE(io.KeyCtrl) << "Ctrl went down after Z was released";
  queue.applyTo(io);
  EXPECT_FALSE(io.KeysDown[kKeyZ]);
  EXPECT_TRUE(io.KeyCtrl);
}
