// A linked GLSL program; compile and link errors become core::Error carrying the driver's log.
#pragma once

#include <epoxy/gl.h>

#include <string>

namespace voxflame::gl {

class ShaderProgram {
 public:
  ShaderProgram() = default;
  ShaderProgram(const std::string& vertexSource, const std::string& fragmentSource);
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
