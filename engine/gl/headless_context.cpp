#include "headless_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <map>
#include <mutex>
#include <vector>

#include "core/error.h"

namespace voxflame::gl {

namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(std::string(" ") + name + " ") != std::string::npos;
}

// An EGL display is one per process and platform, shared by every context on it, and
// eglTerminate ends it for all of them: a context current on another thread (the GPU refinement
// backend's beside a render's, a test's beside a backend's) would lose its display. So contexts
// count their display's users, and the last one terminates it; the lock spans a context's making
// and its ending, so a display is never terminated between another's eglInitialize and its count.
std::mutex& displayMutex() {
  static std::mutex mutex;
  return mutex;
}
std::map<EGLDisplay, int>& displayUsers() {
  static std::map<EGLDisplay, int> users;
  return users;
}
// Under displayMutex(): terminates `display` unless a live context still uses it.
void releaseDisplay(EGLDisplay display) {
  const auto it = displayUsers().find(display);
  if (it != displayUsers().end() && it->second > 0) return;
  eglTerminate(display);
}

// Tries the platforms in order of how likely they are to give a working headless context.
EGLDisplay openDisplay(std::string& tried) {
  const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (hasExtension(clientExtensions, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
    tried += " surfaceless";
  }
  if (hasExtension(clientExtensions, "EGL_EXT_platform_device") &&
      hasExtension(clientExtensions, "EGL_EXT_device_enumeration")) {
    EGLint count = 0;
    eglQueryDevicesEXT(0, nullptr, &count);
    std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
    if (count > 0 && eglQueryDevicesEXT(count, devices.data(), &count)) {
      for (EGLint i = 0; i < count; ++i) {
        EGLDisplay display =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[static_cast<std::size_t>(i)], nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
      }
    }
    tried += " device";
  }
  EGLDisplay display = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) return display;
  tried += " default";
  return EGL_NO_DISPLAY;
}

}  // namespace

ShareGroup currentShareGroup() {
  ShareGroup group;
  const EGLContext context = eglGetCurrentContext();
  if (context == EGL_NO_CONTEXT) return group;
  group.display = eglGetCurrentDisplay();
  group.context = context;
  return group;
}

namespace {

// The config a shared context is made with: the share context's own, so the two are compatible.
EGLConfig configOf(EGLDisplay display, EGLContext context) {
  EGLint id = 0;
  if (!eglQueryContext(display, context, EGL_CONFIG_ID, &id) || id == 0) return nullptr;
  const EGLint attributes[] = {EGL_CONFIG_ID, id, EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(display, attributes, &config, 1, &count) || count == 0) return nullptr;
  return config;
}

}  // namespace

HeadlessContext::HeadlessContext(const ShareGroup& shareWith) {
  const std::lock_guard lock(displayMutex());
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLConfig config = nullptr;
  const auto share = static_cast<EGLContext>(shareWith.context);
  if (!shareWith.empty()) {
    // The share group's display is initialised already; it is counted only where this file opened
    // it (another HeadlessContext's), a window's belongs to the window.
    display = static_cast<EGLDisplay>(shareWith.display);
    countsDisplay_ = displayUsers().count(display) > 0;
    config = configOf(display, share);
  } else {
    std::string tried;
    display = openDisplay(tried);
    if (display == EGL_NO_DISPLAY)
      throw core::Error("no headless OpenGL: EGL found no usable display (tried:" + tried +
                        "); install Mesa's EGL (libegl-mesa0, libgl1-mesa-dri)");
  }
  display_ = display;
  auto giveUp = [&](const std::string& why) {
    if (countsDisplay_) releaseDisplay(display);
    throw core::Error(why);
  };
  if (!eglBindAPI(EGL_OPENGL_API)) giveUp("no headless OpenGL: this EGL cannot bind desktop OpenGL");
  if (shareWith.empty()) {
    const EGLint configAttributes[] = {EGL_SURFACE_TYPE,
                                       EGL_PBUFFER_BIT,
                                       EGL_RENDERABLE_TYPE,
                                       EGL_OPENGL_BIT,
                                       EGL_RED_SIZE,
                                       8,
                                       EGL_GREEN_SIZE,
                                       8,
                                       EGL_BLUE_SIZE,
                                       8,
                                       EGL_NONE};
    EGLint configCount = 0;
    if (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount == 0)
      config = nullptr;  // surfaceless contexts need no config where EGL_KHR_no_config_context exists
  }

  for (const int minor : {6, 5, 3}) {
    const EGLint contextAttributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, minor, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context = eglCreateContext(display, config ? config : EGL_NO_CONFIG_KHR,
                                          shareWith.empty() ? EGL_NO_CONTEXT : share, contextAttributes);
    if (context != EGL_NO_CONTEXT) {
      context_ = context;
      break;
    }
  }
  if (!context_)
    giveUp(shareWith.empty() ? "no headless OpenGL: EGL could not create an OpenGL 4.3 core context"
                             : "EGL could not create an OpenGL 4.3 core context sharing the renderer's");
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, static_cast<EGLContext>(context_))) {
    eglDestroyContext(display, static_cast<EGLContext>(context_));
    giveUp("no headless OpenGL: EGL could not make a surfaceless context current");
  }
  if (countsDisplay_) ++displayUsers()[display];
}

HeadlessContext::~HeadlessContext() {
  const std::lock_guard lock(displayMutex());
  auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  if (!countsDisplay_) return;
  if (--displayUsers()[display] <= 0) displayUsers().erase(display);
  releaseDisplay(display);
}

std::string HeadlessContext::renderer() const {
  const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return text ? text : "unknown";
}

std::string HeadlessContext::version() const {
  const auto* text = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return text ? text : "unknown";
}

}  // namespace voxflame::gl
