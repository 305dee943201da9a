// The X server can take the explorer's window away: `xdotool windowclose`, a window manager's
// "destroy", or the server shutting down. GLFW's next calls on the window then fail, and Xlib's
// default handlers print "X Error of failed request" and exit(1) on the spot, losing the scene.
// While an X11Watch lives, its handlers record such errors instead, and the frame loop asks
// windowGone() to end cleanly: the scene autosaved, the dead window left alone, exit status 0.
// Xlib's handlers are per process, so only one X11Watch may exist at a time.
#pragma once

struct GLFWwindow;

namespace voxflame::app {

class X11Watch {
 public:
  // Call after glfwInit and before the window is created, so that an error about a window the
  // server destroys as soon as it is shown is recorded too. Does nothing when GLFW does not run
  // on X11 (then windowGone() stays false).
  X11Watch();
  // The window whose loss windowGone() reports; re-arms the handler (see rearm()).
  void watch(GLFWwindow* window);
  // Puts Xlib's previous handlers back. Destroy after glfwTerminate, which destroys a window
  // that may be gone and closes the display, so the errors that causes are still recorded.
  ~X11Watch();
  X11Watch(const X11Watch&) = delete;
  X11Watch& operator=(const X11Watch&) = delete;

  // GLFW 3.3 sets Xlib's default error handler back after each call it guards with its own
  // (window creation, some queries): call once a frame, before GLFW is called again.
  void rearm();

  // Whether the window no longer exists or the connection to the X server is lost. A round trip
  // to the server asks, only after an X error was reported since the last call; otherwise this
  // is one atomic read. An error about something else is reported on stderr once and ignored.
  bool windowGone();

 private:
  void* display_ = nullptr;   // Display*, kept out of this header with the rest of Xlib
  unsigned long window_ = 0;  // the X window's id
  bool gone_ = false;
  unsigned errorsSeen_ = 0;  // the handler's count when windowGone() last asked the server
};

}  // namespace voxflame::app
