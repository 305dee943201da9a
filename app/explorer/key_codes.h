// GLFW's key codes that the explorer's input reads, in one place. ImGui 1.86's GLFW backend
// indexes io.KeysDown by GLFW key code (letters are their ASCII capitals, 'Q'), and the input
// queue does the same. Kept free of GLFW's header so the panels and their headless tests need no
// window library; explorer.cpp checks every value against GLFW's header at compile time.
#pragma once

namespace voxflame::app {

inline constexpr int kKeyEscape = 256, kKeyEnter = 257, kKeyBackspace = 259, kKeyRight = 262, kKeyLeft = 263,
                     kKeyF3 = 292;
inline constexpr int kKeyLeftShift = 340, kKeyLeftControl = 341, kKeyLeftAlt = 342, kKeyLeftSuper = 343,
                     kKeyRightShift = 344, kKeyRightControl = 345, kKeyRightAlt = 346, kKeyRightSuper = 347;

}  // namespace voxflame::app
