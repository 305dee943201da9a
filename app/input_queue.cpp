#include "input_queue.h"

#include <imgui.h>

#include <cfloat>

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

void InputQueue::applyTo(ImGuiIO& io) {
  std::bitset<kKeys> keysChanged;
  std::array<bool, kButtons> buttonsChanged{};
  bool anyButtonChanged = false;
  while (!events_.empty()) {
    const Event& event = events_.front();
    const auto index = static_cast<std::size_t>(event.code);
    if (event.kind == Kind::Key) {
      if (io.KeysDown[index] != event.down) {
        if (keysChanged[index]) break;  // the second transition of this key: next frame
        keysChanged[index] = true;
        io.KeysDown[index] = event.down;
      }
    } else if (event.kind == Kind::Button) {
      if (buttons_[index] != event.down) {
        if (buttonsChanged[index]) break;
        buttonsChanged[index] = anyButtonChanged = true;
        buttons_[index] = event.down;
      }
    } else if (event.kind == Kind::Cursor) {
      // ImGui takes a click where the pointer is in the frame the button goes down: a move after
      // a press or release waits, so the click lands where it was made.
      if (anyButtonChanged) break;
      pointer_ = {static_cast<float>(event.x), static_cast<float>(event.y)};
    } else if (event.kind == Kind::Scroll) {
      io.MouseWheelH += static_cast<float>(event.x);
      io.MouseWheel += static_cast<float>(event.y);
    } else {
      io.AddInputCharacter(static_cast<unsigned>(event.code));
    }
    events_.pop_front();
  }
  for (std::size_t i = 0; i < kButtons; ++i) io.MouseDown[i] = buttons_[i];
  if (pointer_ && io.MousePos.x != -FLT_MAX) io.MousePos = ImVec2((*pointer_)[0], (*pointer_)[1]);
  io.KeyCtrl = io.KeysDown[kKeyLeftControl] || io.KeysDown[kKeyRightControl];
  io.KeyShift = io.KeysDown[kKeyLeftShift] || io.KeysDown[kKeyRightShift];
  io.KeyAlt = io.KeysDown[kKeyLeftAlt] || io.KeysDown[kKeyRightAlt];
  io.KeySuper = io.KeysDown[kKeyLeftSuper] || io.KeysDown[kKeyRightSuper];
}

}  // namespace voxflame::app
