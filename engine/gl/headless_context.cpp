#include "headless_context.h"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdlib>
#include <vector>

#include "core/error.h"

namespace voxflame::gl {

namespace {

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  const std::string all = std::string(" ") + list + " ";
  return all.find(std::string(" ") + name + " ") != std::string::npos;
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

HeadlessContext::HeadlessContext() {
  std::string tried;
  EGLDisplay display = openDisplay(tried);
  if (display == EGL_NO_DISPLAY)
    throw core::Error("no headless OpenGL: EGL found no usable display (tried:" + tried +
                      "); install Mesa's EGL (libegl-mesa0, libgl1-mesa-dri)");
  display_ = display;
  if (!eglBindAPI(EGL_OPENGL_API)) {
    eglTerminate(display);
    throw core::Error("no headless OpenGL: this EGL cannot bind desktop OpenGL");
  }
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
  EGLConfig config = nullptr;
  EGLint configCount = 0;
  if (!eglChooseConfig(display, configAttributes, &config, 1, &configCount) || configCount == 0)
    config = nullptr;  // surfaceless contexts need no config where EGL_KHR_no_config_context exists

  for (const int minor : {6, 5, 3}) {
    const EGLint contextAttributes[] = {
        EGL_CONTEXT_MAJOR_VERSION,           4,       EGL_CONTEXT_MINOR_VERSION, minor, EGL_CONTEXT_OPENGL_PROFILE_MASK,
        EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT, EGL_NONE};
    EGLContext context =
        eglCreateContext(display, config ? config : EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, contextAttributes);
    if (context != EGL_NO_CONTEXT) {
      context_ = context;
      break;
    }
  }
  if (!context_) {
    eglTerminate(display);
    throw core::Error("no headless OpenGL: EGL could not create an OpenGL 4.3 core context");
  }
  if (!eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, static_cast<EGLContext>(context_))) {
    eglDestroyContext(display, static_cast<EGLContext>(context_));
    eglTerminate(display);
    throw core::Error("no headless OpenGL: EGL could not make a surfaceless context current");
  }
}

HeadlessContext::~HeadlessContext() {
  auto display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(display, static_cast<EGLContext>(context_));
  eglTerminate(display);
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
