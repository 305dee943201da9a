#include "renderer_kind.h"

#include <epoxy/gl.h>

#include <string_view>

namespace voxflame::gl {

bool softwareRasteriser() {
  const auto* text = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!text) return false;
  const std::string_view renderer(text);
  for (std::string_view name : {"llvmpipe", "softpipe", "SwiftShader", "GDI Generic"})
    if (renderer.find(name) != std::string_view::npos) return true;
  return false;
}

}  // namespace voxflame::gl
