#include "input_queue.h"

#include <imgui.h>

#include <bitset>
#include <cfloat>

#include "key_codes.h"

namespace voxflame::app {

static_assert(sizeof(ImGuiIO::KeysDown) / sizeof(bool) >= 512 && sizeof(ImGuiIO::MouseDown) / sizeof(bool) >= 5,
              "InputQueue's key and button counts must fit ImGuiIO's arrays");

void InputQueue::key(int code, bool down) {
  if (code < 0 || static_cast<std::size_t>(code) >= kKeys) return;
  events_.push_back({.kind = Kind::Key, .code = code, .down = down});
}

void InputQueue::mouseButton(int button, bool down) {
  if (button < 0 || static_cast<std::size_t>(button) >= kButtons) return;
  events_.push_back({.kind = Kind::Button, .code = button, .down = down});
}

void InputQueue::character(unsigned codepoint) {
  events_.push_back({.kind = Kind::Character, .code = static_cast<int>(codepoint)});
}

void InputQueue::scroll(double dx, double dy) {
  // Consecutive wheel steps add up; merging them keeps a spun wheel from filling the queue.
  if (!events_.empty() && events_.back().kind == Kind::Scroll) {
    events_.back().x += dx;
    events_.back().y += dy;
    return;
  }
  events_.push_back({.kind = Kind::Scroll, .x = dx, .y = dy});
}

void InputQueue::cursor(double x, double y) {
  if (!events_.empty() && events_.back().kind == Kind::Cursor) {
    events_.back().x = x;
    events_.back().y = y;
    return;
  }
  events_.push_back({.kind = Kind::Cursor, .x = x, .y = y});
}

namespace {

// GLFW's printable keys (space to grave accent: letters, digits, punctuation) type characters,
// which arrive as events of their own; the others (Backspace, Enter, arrows, modifiers ...) edit
// or combine, and their place among the characters and modifiers matters.
bool typesCharacters(int code) {
  return code >= 32 && code <= 96;
}

bool isModifier(int code) {
  return code >= kKeyLeftShift && code <= kKeyRightSuper;
}

}  // namespace

void InputQueue::applyTo(ImGuiIO& io, bool holdCharacters) {
  std::bitset<kKeys> keysChanged;
  std::array<bool, kButtons> buttonsChanged{};
  bool anyButtonChanged = false;
  // Typing: a printable key's second transition (its release, while the next letters come in the
  // same frame) waits for the next frame without holding up what follows, so a fast typist's
  // characters all arrive in a frame or two rather than one a frame. Its later events wait with
  // it (a key's own events stay in order); anything whose order with them matters (a modifier, a
  // button, the pointer, the wheel) ends the frame's share.
  std::deque<Event> deferred;
  std::bitset<kKeys> keysDeferred;
  bool editingKeyChanged = false;
  bool keyPressed = false;  // a key other than a modifier went down in this frame
  while (!events_.empty()) {
    const Event& event = events_.front();
    const auto index = static_cast<std::size_t>(event.code);
    if (event.kind == Kind::Key) {
      const bool printable = typesCharacters(event.code);
      if (printable && (keysDeferred[index] || (keysChanged[index] && io.KeysDown[index] != event.down))) {
        keysDeferred[index] = true;
        deferred.push_back(event);
        events_.pop_front();
        continue;
      }
      // A modifier must not overtake a waiting release (Z down, Z up, Ctrl down is not Ctrl+Z).
      if (isModifier(event.code) && !deferred.empty() && io.KeysDown[index] != event.down) break;
      // Nor be released in the frame of a key pressed while it was held: xdotool's "key ctrl+a"
      // (and a quick hand) releases Ctrl before A, and a frame that began after Ctrl alone went
      // down (a resting loop wakes on the first event) would see A without Ctrl.
      if (isModifier(event.code) && !event.down && io.KeysDown[index] && keyPressed) break;
      if (io.KeysDown[index] != event.down) {
        if (keysChanged[index]) break;  // the second transition of this key: next frame
        keysChanged[index] = true;
        io.KeysDown[index] = event.down;
        if (!printable && event.down) editingKeyChanged = true;  // a press edits; a release does not
        if (event.down && !isModifier(event.code)) keyPressed = true;
      }
    } else if (event.kind == Kind::Button) {
      if (!deferred.empty()) break;
      if (buttons_[index] != event.down) {
        if (buttonsChanged[index]) break;
        buttonsChanged[index] = anyButtonChanged = true;
        buttons_[index] = event.down;
      }
    } else if (event.kind == Kind::Cursor) {
      // ImGui takes a click where the pointer is in the frame the button goes down: a move after
      // a press or release waits, so the click lands where it was made.
      if (anyButtonChanged || !deferred.empty()) break;
      pointer_ = {static_cast<float>(event.x), static_cast<float>(event.y)};
    } else if (event.kind == Kind::Scroll) {
      if (!deferred.empty()) break;
      io.MouseWheelH += static_cast<float>(event.x);
      io.MouseWheel += static_cast<float>(event.y);
    } else {
      // ImGui applies a frame's characters before its keys: a character typed after Backspace or
      // an arrow waits for the next frame, so the text is edited as typed.
      if (editingKeyChanged || holdCharacters) break;
      io.AddInputCharacter(static_cast<unsigned>(event.code));
    }
    events_.pop_front();
  }
  events_.insert(events_.begin(), deferred.begin(), deferred.end());
  for (std::size_t i = 0; i < kButtons; ++i) io.MouseDown[i] = buttons_[i];
  if (pointer_ && io.MousePos.x != -FLT_MAX) io.MousePos = ImVec2((*pointer_)[0], (*pointer_)[1]);
  io.KeyCtrl = io.KeysDown[kKeyLeftControl] || io.KeysDown[kKeyRightControl];
  io.KeyShift = io.KeysDown[kKeyLeftShift] || io.KeysDown[kKeyRightShift];
  io.KeyAlt = io.KeysDown[kKeyLeftAlt] || io.KeysDown[kKeyRightAlt];
  io.KeySuper = io.KeysDown[kKeyLeftSuper] || io.KeysDown[kKeyRightSuper];
}

}  // namespace voxflame::app
