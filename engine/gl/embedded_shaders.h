// The GLSL files of engine/gl/shaders/, compiled into voxflame_gl at build time by
// cmake/embed_files.cmake (listed in engine/gl/CMakeLists.txt), looked up by their path relative to
// the repository root, e.g. "engine/gl/shaders/march.frag.glsl". ShaderProgram's embeddedShader()
// is the usual way in.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

namespace voxflame::gl {

std::optional<std::span<const std::byte>> embeddedShaderFile(std::string_view name);

}  // namespace voxflame::gl
