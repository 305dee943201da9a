#include "x11_watch.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#define GLFW_EXPOSE_NATIVE_X11
#include <GLFW/glfw3native.h>
#include <X11/Xlib.h>

#include <atomic>
#include <cstdio>

namespace voxflame::app {

namespace {

// Xlib calls its handlers from whichever thread made the failing call (here the main thread, which
// owns GLFW); atomics keep the record sound all the same.
std::atomic<unsigned> errorCount{0};
std::atomic<int> lastErrorCode{0}, lastRequestCode{0};
std::atomic<bool> connectionLostFlag{false};
XErrorHandler previousErrorHandler = nullptr;
XIOErrorHandler previousIoErrorHandler = nullptr;

int recordError(Display*, XErrorEvent* event) {
  lastErrorCode = event->error_code;
  lastRequestCode = event->request_code;
  errorCount.fetch_add(1);
  return 0;
}

// Called when the connection breaks. Returning would make Xlib exit(1), unless the exit handler
// below is set: then Xlib marks the display dead, and its later calls do nothing.
int recordIoError(Display*) {
  connectionLostFlag = true;
  return 0;
}

void continueAfterIoError(Display*, void*) {
  connectionLostFlag = true;
}

}  // namespace

X11Watch::X11Watch() {
  Display* display = glfwGetX11Display();
  if (!display) return;  // not X11: nothing to watch
  display_ = display;
  errorCount = 0;
  connectionLostFlag = false;
  previousErrorHandler = XSetErrorHandler(recordError);
  previousIoErrorHandler = XSetIOErrorHandler(recordIoError);
  XSetIOErrorExitHandler(display, continueAfterIoError, nullptr);
}

X11Watch::~X11Watch() {
  if (!display_) return;
  // The display may be closed by now: its exit handler went with it.
  XSetErrorHandler(previousErrorHandler);
  XSetIOErrorHandler(previousIoErrorHandler);
}

void X11Watch::watch(GLFWwindow* window) {
  if (!display_) return;
  window_ = glfwGetX11Window(window);
  rearm();
}

void X11Watch::rearm() {
  if (display_) XSetErrorHandler(recordError);
}

bool X11Watch::windowGone() {
  if (!display_ || !window_ || gone_) return gone_;
  if (connectionLostFlag) return gone_ = true;
  const unsigned count = errorCount.load();
  if (count == errorsSeen_) return false;
  XWindowAttributes attributes;
  const bool exists = XGetWindowAttributes(static_cast<Display*>(display_), window_, &attributes) != 0;
  errorsSeen_ = errorCount.load();  // including the one a missing window just caused
  if (connectionLostFlag || !exists) return gone_ = true;
  std::fprintf(stderr, "voxflame: ignored an X error (error code %d, request %d)\n", lastErrorCode.load(),
               lastRequestCode.load());
  return false;
}

}  // namespace voxflame::app
