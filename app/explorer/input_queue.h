// Input that is never lost. GLFW reports key presses, releases and clicks as events, but ImGui
// 1.86 reads input as state (io.KeysDown, io.MouseDown) once per frame, and its GLFW backend
// writes that state straight from the callbacks: a key pressed and released between two frames
// (a quick tap while frames are slow) is never seen down. The explorer's GLFW callbacks push
// events here instead; before each ImGui::NewFrame, applyTo() replays them in order, but at most
// one transition per key or mouse button per frame: the frame's share of the queue ends at the
// second transition, which waits for the next frame, and so does everything after it. Order is
// kept across keys (Ctrl down, Q down, Q up, Ctrl up is Ctrl+Q; Ctrl down, Ctrl up, Q down is
// not), and characters and scroll stay in order with the keys around them (typing "ab",
// Backspace, "c" edits the text as typed). Nothing here calls GLFW, so tests feed it directly.
#pragma once

#include <array>
#include <cstddef>
#include <deque>
#include <optional>

struct ImGuiIO;

namespace voxflame::app {

class InputQueue {
 public:
  // A key press or release by GLFW key code (repeats are not transitions; ImGui repeats itself).
  // Codes outside io.KeysDown (GLFW_KEY_UNKNOWN) are ignored.
  void key(int code, bool down);
  void mouseButton(int button, bool down);
  void character(unsigned codepoint);
  void scroll(double dx, double dy);
  // The pointer, in window coordinates. Consecutive moves merge: only the last one matters.
  void cursor(double x, double y);

  // Applies this frame's share of the queue to io: keys, buttons, characters, wheel, pointer and
  // the modifier flags (io.KeyCtrl and friends follow the keys applied, never a later state).
  // Call after the platform backend's NewFrame, which overwrites io.MouseDown and io.MousePos
  // from the current device state, and before ImGui::NewFrame. While the backend says the
  // pointer is unavailable (io.MousePos at -FLT_MAX), the pointer is left so.
  // `holdCharacters`: the keyboard moves to a text field in this frame (a focus asked for in the
  // last one). ImGui 1.86 drops the characters of the frame that activates a field, so they, and
  // everything after them, wait for the next frame: Ctrl+F then a quick letter keeps the letter.
  void applyTo(ImGuiIO& io, bool holdCharacters = false);

  // Events waiting for a later frame.
  std::size_t pending() const { return events_.size(); }

 private:
  enum class Kind { Key, Button, Character, Scroll, Cursor };
  struct Event {
    Kind kind = Kind::Key;
    int code = 0;  // key code, mouse button, or the character's code point
    bool down = false;
    double x = 0.0, y = 0.0;  // scroll offsets or pointer position
  };
  static constexpr std::size_t kKeys = 512;   // io.KeysDown's size in ImGui 1.86
  static constexpr std::size_t kButtons = 5;  // io.MouseDown's size

  std::deque<Event> events_;
  // The buttons as applied so far: the backend rewrites io.MouseDown from the device each frame.
  std::array<bool, kButtons> buttons_{};
  std::optional<std::array<float, 2>> pointer_;  // the last pointer position applied
};

}  // namespace voxflame::app
