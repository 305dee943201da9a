// A linked GLSL program; compile and link errors become core::Error carrying the driver's log and
// the name of the shader file at fault.
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <string_view>

namespace voxflame::gl {

// GLSL source and the file it came from, so a compile error can say where to look.
struct ShaderSource {
  std::string file;  // e.g. "engine/gl/shaders/march.frag.glsl"
  std::string text;
};

// engine/gl/shaders/<name> (e.g. "march.frag.glsl") as embedded at build time. Throws core::Error
// when no such shader was embedded.
ShaderSource embeddedShader(std::string_view name);

// One compiled shader of `stage`; a compile error becomes core::Error naming the file. The caller
// attaches and deletes it (ShaderProgram does).
GLuint compileShader(GLenum stage, const ShaderSource& source);

class ShaderProgram {
 public:
  ShaderProgram() = default;
  ShaderProgram(const ShaderSource& vertex, const ShaderSource& fragment);
  explicit ShaderProgram(const ShaderSource& compute);  // a compute program
  ~ShaderProgram();
  ShaderProgram(ShaderProgram&& other) noexcept;
  ShaderProgram& operator=(ShaderProgram&& other) noexcept;
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  GLuint id() const { return program_; }
  GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }

 private:
  GLuint program_ = 0;
};

}  // namespace voxflame::gl
